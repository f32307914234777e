// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small helpers shared by the whole-design benchmark runners.

#include <sstream>
#include <string>
#include <vector>

namespace hrs::bench {

//! The non-empty items of a comma list ("bedroom,office" → 2 items), or of
//! a semicolon list when `s` has a semicolon ("all;all,-budget" → 2 items).
inline std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  const char separator = s.find(';') != std::string::npos ? ';' : ',';
  for (std::string item; std::getline(in, item, separator);)
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace hrs::bench
