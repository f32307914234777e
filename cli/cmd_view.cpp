// SPDX-License-Identifier: GPL-3.0-or-later
// hrspace view DIR: the path of a design's interactive page (design.html,
// view/viewer.h), opened in the desktop's browser where there is one.
#include <spawn.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/commands.h"
#include "geometry/error.h"

extern char** environ;

namespace hrs::cli {

namespace {

constexpr const char* kUsage =
    "usage: hrspace view DIR [--print]\n\n"
    "Prints the path of DIR/design.html, the interactive page `hrspace design --out DIR`\n"
    "writes (the layout, each tour with the chair driving it, the annealing trace, the\n"
    "accessibility overlays; one file, no network), and opens it with xdg-open when a\n"
    "desktop session is running. For a run of --designs K, every DIR/k/design.html.\n\n"
    "  --print   only print the path(s), never open a browser\n";

bool has_display() {
  for (const char* v : {"DISPLAY", "WAYLAND_DISPLAY"}) {
    const char* value = std::getenv(v);
    if (value && *value) return true;
  }
  return false;
}

//! xdg-open PATH, not waited for beyond its own start (xdg-open returns
//! once the browser is asked). False when it cannot be started or fails.
bool open_in_browser(const std::string& path) {
  const std::string program = "xdg-open";
  std::vector<char*> argv{const_cast<char*>(program.c_str()), const_cast<char*>(path.c_str()),
                          nullptr};
  pid_t pid = 0;
  if (posix_spawnp(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    return false;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

int cmd_view(const Argv& argv) {
  const Args args(argv, {}, {"print"});
  if (args.help()) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  args.expect_positional(1, kUsage);
  namespace fs = std::filesystem;
  const fs::path dir = args.positional()[0];
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(dir.string() + ": not a directory (expected the --out DIR of hrspace design)");
  std::vector<fs::path> pages;
  if (fs::is_regular_file(dir / "design.html", ec)) {
    pages.push_back(dir / "design.html");
  } else {
    for (int k = 1; fs::is_regular_file(dir / std::to_string(k) / "design.html", ec); ++k)
      pages.push_back(dir / std::to_string(k) / "design.html");
  }
  if (pages.empty())
    throw InputError(dir.string() +
                     ": no design.html (write one with: hrspace design SCENE --out " +
                     dir.string() + ")");
  for (const fs::path& p : pages) std::printf("%s\n", fs::absolute(p).lexically_normal().c_str());
  if (!args.flag("print") && has_display()) {
    std::fflush(stdout);
    for (const fs::path& p : pages)
      if (!open_in_browser(fs::absolute(p).string()))
        std::fprintf(stderr, "hrspace view: could not open %s with xdg-open; open it in a browser\n",
                     p.c_str());
  }
  return 0;
}

}  // namespace hrs::cli
