// SPDX-License-Identifier: GPL-3.0-or-later
// hrspace: the command-line entry point. Dispatches to the subcommands of
// docs/design-notes.md "The hrspace command"; exit 0 success, 2 bad input, 1 internal.

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "geometry/error.h"
#include "geometry/version.h"

namespace {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const hrs::cli::Argv&);
};

constexpr Command kCommands[] = {
    {"validate", "check a scene file and print its summary", hrs::cli::cmd_validate},
    {"collide", "collision and clearance of poses (CSV in, CSV out)", hrs::cli::cmd_collide},
    {"rs", "shortest Reeds-Shepp paths for pose pairs (CSV in, CSV out)", hrs::cli::cmd_rs},
    {"plan", "one wheelchair leg by the baseline RRT (JSON)", hrs::cli::cmd_plan},
    {"tour", "one tour of an object sequence from the door (JSON)", hrs::cli::cmd_tour},
    {"design", "optimize a room layout (layout, tours, SVG, report)", hrs::cli::cmd_design},
    {"experiment", "run a study of the paper's experiments (CSV tables)",
     hrs::cli::cmd_experiment},
    {"generate", "random rooms tourable by construction (the room zoo)", hrs::cli::cmd_generate},
    {"view", "the path of a design's interactive page (design.html)", hrs::cli::cmd_view},
};

void usage(std::ostream& out) {
  out << "usage: hrspace <command> [args]   (hrspace <command> --help for details)\n"
         "       hrspace --version\n\n"
         "hrspace designs rooms shared by people and a self-driving wheelchair.\n\ncommands:\n";
  for (const auto& c : kCommands) {
    std::string n = c.name;
    n.resize(12, ' ');
    out << "  " << n << c.summary << "\n";
  }
}

//! Flushes stdout and checks it: a write error (a full device, a closed
//! file) must not pass as success. Returns `status`, or 1 after a message.
int checked_output(const std::string& name, int status) {
  std::cout.flush();
  const bool cout_failed = !std::cout;
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout) || cout_failed) {
    const int err = errno;
    std::cerr << "hrspace " << name << ": cannot write to standard output"
              << (err ? std::string(": ") + std::strerror(err) : std::string()) << "\n";
    return 1;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  if (argc < 2) {
    usage(std::cerr);
    return 2;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    usage(std::cout);
    return checked_output(name, 0);
  }
  if (name == "--version" || name == "version") {
    if (argc > 2) {
      std::cerr << "hrspace --version: takes no arguments, got '" << argv[2] << "'\n";
      return 2;
    }
    std::cout << hrs::version_line() << "\n";
    return checked_output(name, 0);
  }
  const hrs::cli::Argv args(argv + 2, argv + argc);
  for (const auto& c : kCommands) {
    if (name != c.name) continue;
    try {
      return checked_output(name, c.run(args));
    } catch (const hrs::InputError& e) {
      std::cout.flush();
      std::cerr << "hrspace " << name << ": " << e.what() << "\n";
      return 2;
    } catch (const hrs::OutputError& e) {
      std::cout.flush();
      std::cerr << "hrspace " << name << ": " << e.what() << "\n";
      return 1;
    } catch (const std::exception& e) {
      std::cout.flush();
      std::cerr << "hrspace " << name << ": internal error: " << e.what() << "\n";
      return 1;
    }
  }
  std::cerr << "hrspace: unknown command '" << name << "'\n";
  usage(std::cerr);
  return 2;
}
