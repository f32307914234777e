// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Minimal command-line parsing for the hrspace subcommands: positional
// arguments, `--name value` options and `--flag` switches, each declared up
// front so that a typo is an error (exit 2), never silently ignored.
//
// Why not CLI11 (Debian's libcli11-dev): the option parsing proper is the
// Args constructor below, about 30 lines. CLI11 would replace only that; the
// rest of this file (numbers with ranges, pose triples, numeric CSV with
// line and field in the message, --planner/--reuse) is ours either way. Its
// error texts ("The following argument was not expected: ...") and exit
// codes (105, 106, ...) differ from the one-line, exit-2 messages the tests
// and scripts rely on, and its generated help would replace the hand-written
// pages of each subcommand: keeping both means a custom formatter and a
// catch that rewrites every CLI::ParseError, more code than the parser.

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "planning/reuse.h"

namespace hrs::cli {

class Args {
 public:
  //! `options` take a value, `flags` do not; anything else starting with
  //! "--" is an InputError, and so is an option or flag given twice (no
  //! option is repeatable: the second value would silently win).
  //! `--help`/`-h` is always accepted.
  Args(const std::vector<std::string>& argv, std::set<std::string> options,
       std::set<std::string> flags = {});

  bool help() const { return help_; }
  const std::vector<std::string>& positional() const { return positional_; }
  bool flag(const std::string& name) const { return flags_set_.count(name) > 0; }
  std::optional<std::string> get(const std::string& name) const;
  std::string get_or(const std::string& name, const std::string& fallback) const;
  //! Parses an option as a number; InputError naming the option when malformed.
  double number(const std::string& name, double fallback) const;
  long integer(const std::string& name, long fallback, long min, long max) const;
  //! Requires exactly `n` positional arguments; `usage` is printed otherwise.
  void expect_positional(std::size_t n, const std::string& usage) const;

 private:
  bool help_ = false;
  std::vector<std::string> positional_;
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_set_;
};

//! Parses "x,y,theta" into three numbers; InputError naming `what` otherwise.
std::vector<double> parse_numbers(const std::string& text, std::size_t count,
                                  const std::string& what);

//! Shortest decimal text that reads back as exactly `v` (std::to_chars).
std::string format_number(double v);

//! Reads a whole file, or stdin when path is "-"; InputError when unreadable
//! (missing, a directory, a read error).
std::string read_input(const std::string& path);

//! One column of a numeric CSV file: its header name and the largest
//! magnitude accepted.
struct CsvColumn {
  std::string name;
  double max_abs;
};

//! Splits CSV text (comma-separated, blank lines ignored) into rows of
//! numbers, one per column. The first non-blank line is a header exactly when
//! its fields are the column names in order (spaces around them ignored); any
//! other line must hold as many finite numbers as there are columns, each
//! within its column's magnitude. InputError "LABEL: line N[, field K]: what".
std::vector<std::vector<double>> read_numeric_csv(const std::string& text,
                                                  const std::vector<CsvColumn>& columns,
                                                  const std::string& label);

//! --planner baseline|proposed and --reuse LIST of design, plan and tour:
//! nullopt for the baseline, else the proposed planner's techniques
//! (`fallback` without --reuse; a technique outside `allowed` is refused: it
//! would do nothing in this command). hrs::InputError on a bad value.
std::optional<planning::ReuseOptions> planner_option(const Args& args, const std::string& allowed,
                                                     const std::string& fallback);

}  // namespace hrs::cli
