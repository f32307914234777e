// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Scratch files and directories of a test: under the system's temporary
// directory, named per process, so that two runs of the suites at once (the
// default and the sanitizer builds, two clones) never share one.

#include <unistd.h>

#include <filesystem>
#include <string>

namespace hrs::test_support {

//! temp/hrspace_NAME_PID (not created).
inline std::filesystem::path scratch_path(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("hrspace_" + name + "_" + std::to_string(::getpid()));
}

}  // namespace hrs::test_support
