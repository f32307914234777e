// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tables of the experiments harness: rows of named cells, written and read as
// CSV (RFC 4180 quoting), and files replaced atomically so that a killed run
// never leaves a half-written table behind.

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hrs::experiments {

//! One row: cells in insertion order, names unique.
class Row {
 public:
  //! Sets `name` (appended when new, replaced in place otherwise).
  void set(const std::string& name, const std::string& value);
  void set(const std::string& name, double value);
  void set(const std::string& name, long value);
  void set(const std::string& name, int value) { set(name, static_cast<long>(value)); }
  //! Appends every cell of `other` (replacing cells of the same name).
  void merge(const Row& other);
  std::optional<std::string> get(const std::string& name) const;
  //! The cell parsed as a number; nullopt when absent, empty or not a number.
  std::optional<double> number(const std::string& name) const;
  const std::vector<std::pair<std::string, std::string>>& cells() const { return cells_; }
  bool empty() const { return cells_.empty(); }

 private:
  std::vector<std::pair<std::string, std::string>> cells_;
};

using Table = std::vector<Row>;

//! Shortest text that reads back as exactly `v` ("nan"/"inf" spelled out).
std::string format_double(double v);

//! The union of the rows' column names, in order of first appearance.
std::vector<std::string> columns_of(const Table& rows);
//! CSV text with a header line; a cell a row lacks is empty.
std::string to_csv(const Table& rows);
//! Parses CSV text with a header line. Throws hrs::InputError naming `label`
//! and the line for unbalanced quotes or a row with the wrong cell count.
Table parse_csv(const std::string& text, const std::string& label);

//! Reads a whole file; throws hrs::InputError naming the path (and the
//! system's reason) when it cannot, a directory among them.
std::string read_text(const std::filesystem::path& path);
//! Writes `text` to a temporary file beside `path`, flushes it and renames it
//! over `path`: readers see the old file or the new one, never a mix.
//! Throws hrs::OutputError naming the path and the system's reason on any
//! failure (a full disk, an unwritable or missing directory).
void write_text_atomic(const std::filesystem::path& path, const std::string& text);

}  // namespace hrs::experiments
