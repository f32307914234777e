// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Seeded randomness that gives the same numbers with every standard library:
// splitmix64 to derive independent seeds from (seed, index, ...) tuples, and
// uniform doubles from the top 53 bits of a 64-bit engine's output
// (std::uniform_real_distribution's sequence is implementation-defined).
// Reference: Steele, Lea, Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014 (the splitmix64 finalizer constants).

#include <cstddef>
#include <cstdint>
#include <random>

namespace hrs {

//! One step of splitmix64: a well-mixed 64-bit value from `x`.
inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

//! Uniform double in [0, 1) from the top 53 bits of one draw.
inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

//! Uniform index in [0, n), n >= 1, without modulo bias (draws again when
//! the draw falls in the incomplete last block of n values).
inline std::size_t uniform_index(std::mt19937_64& rng, std::size_t n) {
  const std::uint64_t m = static_cast<std::uint64_t>(n);
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % m;
  std::uint64_t x;
  do {
    x = rng();
  } while (x >= limit);
  return static_cast<std::size_t>(x % m);
}

}  // namespace hrs
