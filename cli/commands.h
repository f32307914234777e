// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The hrspace subcommands. Each takes the arguments after its name, writes to
// stdout/stderr and returns the exit status; InputError escapes to main(),
// which prints it as one line and exits 2.

#include <string>
#include <vector>

namespace hrs::cli {

using Argv = std::vector<std::string>;

int cmd_validate(const Argv& args);  //!< cli/cmd_geometry.cpp
int cmd_collide(const Argv& args);   //!< cli/cmd_geometry.cpp
int cmd_rs(const Argv& args);        //!< cli/cmd_rs.cpp
int cmd_plan(const Argv& args);      //!< cli/cmd_planning.cpp
int cmd_tour(const Argv& args);      //!< cli/cmd_planning.cpp
int cmd_design(const Argv& args);    //!< cli/cmd_optimize.cpp
int cmd_experiment(const Argv& args);  //!< cli/cmd_experiment.cpp
int cmd_generate(const Argv& args);    //!< cli/cmd_generate.cpp
int cmd_view(const Argv& args);        //!< cli/cmd_view.cpp

}  // namespace hrs::cli
