// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/args.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "api/operations.h"
#include "geometry/error.h"
#include "geometry/scene.h"

namespace hrs::cli {

Args::Args(const std::vector<std::string>& argv, std::set<std::string> options,
           std::set<std::string> flags) {
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a == "--help" || a == "-h") {
      help_ = true;
    } else if (a.size() > 2 && a.rfind("--", 0) == 0) {
      std::string name = a.substr(2);
      std::string value;
      bool has_value = false;
      if (auto eq = name.find('='); eq != std::string::npos) {
        value = name.substr(eq + 1);
        name = name.substr(0, eq);
        has_value = true;
      }
      if (options.count(name)) {
        if (!has_value) {
          if (i + 1 >= argv.size()) throw InputError("option --" + name + " needs a value");
          value = argv[++i];
        }
        if (values_.count(name))
          throw InputError("option --" + name + " given twice ('" + values_[name] + "' and '" +
                           value + "'): give it once");
        values_[name] = value;
      } else if (flags.count(name) && !has_value) {
        if (!flags_set_.insert(name).second)
          throw InputError("option --" + name + " given twice: give it once");
      } else {
        throw InputError("unknown option --" + name + " (see --help)");
      }
    } else {
      positional_.push_back(a);
    }
  }
}

std::optional<std::string> Args::get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::string Args::get_or(const std::string& name, const std::string& fallback) const {
  return get(name).value_or(fallback);
}

static bool to_double(const std::string& s, double& out) {
  const char* b = s.data();
  const char* e = s.data() + s.size();
  while (b < e && (*b == ' ' || *b == '\t')) ++b;
  while (e > b && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r')) --e;
  if (b < e && *b == '+') ++b;
  auto [p, ec] = std::from_chars(b, e, out);
  return ec == std::errc() && p == e && std::isfinite(out);
}

double Args::number(const std::string& name, double fallback) const {
  auto v = get(name);
  if (!v) return fallback;
  double d;
  if (!to_double(*v, d)) throw InputError("--" + name + ": not a finite number: '" + *v + "'");
  return d;
}

long Args::integer(const std::string& name, long fallback, long min, long max) const {
  auto v = get(name);
  if (!v) return fallback;
  long n = 0;
  auto [p, ec] = std::from_chars(v->data(), v->data() + v->size(), n);
  if (ec != std::errc() || p != v->data() + v->size())
    throw InputError("--" + name + ": not an integer: '" + *v + "'");
  if (n < min || n > max)
    throw InputError("--" + name + ": " + *v + " is outside [" + std::to_string(min) + ", " +
                     std::to_string(max) + "]");
  return n;
}

void Args::expect_positional(std::size_t n, const std::string& usage) const {
  if (positional_.size() != n) throw InputError("usage: " + usage);
}

std::vector<double> parse_numbers(const std::string& text, std::size_t count,
                                  const std::string& what) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string field;
  while (std::getline(ss, field, ',')) {
    double d;
    if (!to_double(field, d))
      throw InputError(what + ": not a finite number: '" + field + "' in '" + text + "'");
    out.push_back(d);
  }
  if (out.size() != count)
    throw InputError(what + ": expected " + std::to_string(count) +
                     " comma-separated numbers, got '" + text + "'");
  return out;
}

std::string format_number(double v) {
  char buf[64];
  auto [p, ec] = std::to_chars(buf, buf + sizeof(buf), v);
  return ec == std::errc() ? std::string(buf, p) : std::string("nan");
}

std::string read_input(const std::string& path) {
  // Bounded (geometry::limits::kInputBytes): /dev/zero, a FIFO or a huge
  // file is one message naming the input, never unbounded memory.
  if (path == "-") return geometry::read_input_stream(std::cin, "stdin");
  return geometry::read_input_file(path);
}

namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

std::vector<std::vector<double>> read_numeric_csv(const std::string& text,
                                                  const std::vector<CsvColumn>& columns,
                                                  const std::string& label) {
  std::vector<std::vector<double>> rows;
  std::stringstream ss(text);
  std::string line;
  std::size_t line_no = 0;
  bool first = true;
  while (std::getline(ss, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    std::vector<std::string> fields;
    std::stringstream ls(line);
    std::string f;
    while (std::getline(ls, f, ',')) fields.push_back(f);
    if (!line.empty() && line.back() == ',') fields.push_back("");
    const std::string at = label + ": line " + std::to_string(line_no);
    if (first) {
      first = false;
      bool header = fields.size() == columns.size();
      for (std::size_t i = 0; header && i < columns.size(); ++i)
        header = trimmed(fields[i]) == columns[i].name;
      if (header) continue;
    }
    if (fields.size() != columns.size()) {
      std::string names;
      for (const auto& c : columns) names += (names.empty() ? "" : ",") + c.name;
      throw InputError(at + ": expected " + std::to_string(columns.size()) +
                       " comma-separated numbers (" + names + "), got " +
                       std::to_string(fields.size()) + " field(s)");
    }
    std::vector<double> row(columns.size());
    for (std::size_t i = 0; i < columns.size(); ++i) {
      const std::string where =
          at + ", field " + std::to_string(i + 1) + " (" + columns[i].name + ")";
      if (!to_double(fields[i], row[i]))
        throw InputError(where + ": not a finite number: '" + fields[i] + "'");
      if (std::abs(row[i]) > columns[i].max_abs)
        throw InputError(where + ": " + format_number(row[i]) + " is outside [-" +
                         format_number(columns[i].max_abs) + ", " +
                         format_number(columns[i].max_abs) + "]");
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::optional<planning::ReuseOptions> planner_option(const Args& args, const std::string& allowed,
                                                     const std::string& fallback) {
  return api::choose_planner(args.get_or("planner", "baseline"), args.get("reuse"),
                             {allowed.c_str(), fallback.c_str()});
}

}  // namespace hrs::cli
