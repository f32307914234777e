// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The version of hrspace (CMake's project version) and the git commit it was
// built from (short hash, or "unknown" when built outside a git checkout).
// The command prints them (`hrspace --version`), report.json and the
// experiments' rows record them, and the Python module has __version__.

#include <string>

namespace hrs {

//! "0.9.0": the project version of CMakeLists.txt.
const char* version();
//! Short commit hash of the build ("abcdef1"), or "unknown".
const char* commit();
//! "hrspace 0.9.0 (commit abcdef1)".
std::string version_line();

}  // namespace hrs
