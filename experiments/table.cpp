// SPDX-License-Identifier: GPL-3.0-or-later
#include "experiments/table.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include "geometry/error.h"
#include "geometry/scene.h"
#include "io/files.h"
#include "optimize/design_io.h"

namespace hrs::experiments {

void Row::set(const std::string& name, const std::string& value) {
  for (auto& [n, v] : cells_) {
    if (n == name) {
      v = value;
      return;
    }
  }
  cells_.emplace_back(name, value);
}

void Row::set(const std::string& name, double value) { set(name, format_double(value)); }
void Row::set(const std::string& name, long value) { set(name, std::to_string(value)); }

void Row::merge(const Row& other) {
  for (const auto& [n, v] : other.cells_) set(n, v);
}

std::optional<std::string> Row::get(const std::string& name) const {
  for (const auto& [n, v] : cells_)
    if (n == name) return v;
  return std::nullopt;
}

std::optional<double> Row::number(const std::string& name) const {
  const auto text = get(name);
  if (!text || text->empty()) return std::nullopt;
  double v = 0.0;
  const char* b = text->data();
  const char* e = b + text->size();
  const auto [p, ec] = std::from_chars(b, e, v);
  if (ec != std::errc() || p != e) return std::nullopt;
  return v;
}

std::string format_double(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, p) : std::string("nan");
}

std::vector<std::string> columns_of(const Table& rows) {
  std::vector<std::string> columns;
  std::set<std::string> seen;
  for (const Row& r : rows)
    for (const auto& [n, v] : r.cells())
      if (seen.insert(n).second) columns.push_back(n);
  return columns;
}

namespace {

std::string quote(const std::string& cell) {
  if (cell.find_first_of(",\"\n\r") == std::string::npos) return cell;
  std::string out = "\"";
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string to_csv(const Table& rows) {
  const std::vector<std::string> columns = columns_of(rows);
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i) out += ',';
    out += quote(columns[i]);
  }
  out += '\n';
  for (const Row& r : rows) {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (i) out += ',';
      const std::string cell = r.get(columns[i]).value_or("");
      // A lone empty cell would read back as a blank line: quote it.
      out += columns.size() == 1 && cell.empty() ? std::string("\"\"") : quote(cell);
    }
    out += '\n';
  }
  return out;
}

namespace {

//! One CSV record and whether it was an empty line.
struct Record {
  std::vector<std::string> cells;
  bool blank = false;
};

//! Splits CSV text into records (RFC 4180 quoting; LF or CRLF line ends).
std::vector<Record> split_records(const std::string& text, const std::string& label) {
  std::vector<Record> records;
  Record record;
  std::string cell;
  bool quoted = false, in_record = false, chars = false;
  long line = 1, record_line = 1;
  auto end_record = [&] {
    record.cells.push_back(std::move(cell));
    cell.clear();
    record.blank = !chars;
    records.push_back(std::move(record));
    record = {};
    in_record = false;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        if (c == '\n') ++line;
        cell += c;
      }
      continue;
    }
    if (!in_record) {
      in_record = true;
      chars = false;
      record_line = line;
    }
    if (c != '\n' && c != '\r') chars = true;
    if (c == '"' && cell.empty()) {
      quoted = true;
    } else if (c == ',') {
      record.cells.push_back(std::move(cell));
      cell.clear();
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      end_record();
      ++line;
    } else {
      cell += c;
    }
  }
  if (quoted)
    throw InputError(label + ": line " + std::to_string(record_line) + ": unbalanced quote");
  if (in_record) end_record();
  return records;
}

}  // namespace

Table parse_csv(const std::string& text, const std::string& label) {
  const std::vector<Record> records = split_records(text, label);
  Table rows;
  if (records.empty()) return rows;
  const std::vector<std::string>& header = records.front().cells;
  for (std::size_t k = 1; k < records.size(); ++k) {
    if (records[k].blank) continue;
    const auto& cells = records[k].cells;
    if (cells.size() != header.size())
      throw InputError(label + ": record " + std::to_string(k + 1) + " has " +
                       std::to_string(cells.size()) + " cells, the header " +
                       std::to_string(header.size()));
    Row r;
    for (std::size_t i = 0; i < header.size(); ++i) r.set(header[i], cells[i]);
    rows.push_back(std::move(r));
  }
  return rows;
}

std::string read_text(const std::filesystem::path& path) {
  // Bounded like every input (geometry::limits::kInputBytes), with the path
  // in the message.
  return geometry::read_input_file(path.string());
}

void write_text_atomic(const std::filesystem::path& path, const std::string& text) {
  io::write_files_atomic({{path, text}});
}

}  // namespace hrs::experiments
