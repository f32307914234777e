// SPDX-License-Identifier: GPL-3.0-or-later
// The only file that includes the generated version header, so that a new
// commit recompiles one file.

#include "geometry/version.h"

#include "hrspace_version_generated.h"

namespace hrs {

const char* version() { return HRSPACE_VERSION_STRING; }
const char* commit() { return HRSPACE_COMMIT_STRING; }
std::string version_line() {
  return std::string("hrspace ") + version() + " (commit " + commit() + ")";
}

}  // namespace hrs
