// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Errors at the boundary of hrspace (scene files, CLI arguments, output
// files). The CLI turns an InputError into one line on stderr and exit status
// 2, an OutputError (a write that failed: full disk, I/O error) into one line
// and exit status 1. Interrupted is a stop request (Ctrl-C) seen by a long
// computation before it had a result (`hrspace design`: exit 128 + signal).

#include <atomic>
#include <stdexcept>
#include <string>

namespace hrs {

//! Bad user input: the message names the file, the field and what is wrong.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! A write failed although its target was checked first (full disk, I/O
//! error): the message names the file and the system's reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! A long computation (the sequence enumeration, goal-pose generation) saw
//! its caller's stop flag set before it had a result: it throws this rather
//! than return a partial one. The message names the computation.
class Interrupted : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! Throws Interrupted("`what`: interrupted") when `stop` is non-null and set.
//! One relaxed atomic load: cheap enough for inner loops.
inline void throw_if_stopped(const std::atomic<bool>* stop, const char* what) {
  if (stop != nullptr && stop->load(std::memory_order_relaxed))
    throw Interrupted(std::string(what) + ": interrupted");
}

}  // namespace hrs
