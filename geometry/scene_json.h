// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Internal to geometry/scene_*.cpp, not part of the API: the names of the
// scene format, its message and JSON-pointer helpers, and FieldReader.

#include <array>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>

#include "geometry/polygon_ops.h"
#include "geometry/scene.h"

namespace hrs::geometry::scene_io {

using Json = nlohmann::json;

inline constexpr std::string_view kFormat = "hrspace-scene/1";
inline constexpr std::string_view kComment = "comment";
inline constexpr std::array<std::string_view, 4> kSideNames{"front", "back", "left", "right"};
//! Door centre on the boundary, door width on its edge: the contact
//! tolerance of furniture (geometry/polygon_ops.h).
inline constexpr double kBoundaryTolerance = kContactTolerance;

//! Replaces control characters so that a message stays on one line.
std::string one_line(std::string_view text);
//! A string as a JSON literal (quoted, escaped), for messages.
std::string literal(std::string_view s);
//! A short rendering of a JSON value for messages ("got ...").
std::string shown(const Json& j);
//! Shortest text for a double that reads back to the same value.
std::string num(double v);
//! The JSON pointer of a member or an element of the value at `ptr`.
std::string child(const std::string& ptr, std::string_view key);
std::string child(const std::string& ptr, std::size_t index);

//! The room edge holding the door: index i (edge i -> i+1) or -1. Among edges
//! within tolerance of the centre, prefers one on which the opening fits.
int door_edge(const Polygon& room, const Door& door, bool require_fit);

//! Typed, limit-checked access to the fields of one JSON document; every
//! failure is an InputError "LABEL: /pointer: what is wrong".
class FieldReader {
 public:
  explicit FieldReader(std::string label) : label_(std::move(label)) {}

  [[noreturn]] void fail(const std::string& ptr, const std::string& what) const;

 protected:
  void expect_object(const Json& j, const std::string& ptr) const;
  void expect_array(const Json& j, const std::string& ptr) const;
  //! Rejects fields outside `allowed` (and "comment").
  void check_keys(const Json& j, const std::string& ptr,
                  std::initializer_list<std::string_view> allowed) const;
  const Json& require(const Json& j, const std::string& ptr, std::string_view key) const;
  static const Json* optional(const Json& j, std::string_view key);

  std::string string(const Json& j, const std::string& ptr) const;
  bool boolean(const Json& j, const std::string& ptr) const;
  double number(const Json& j, const std::string& ptr) const;
  //! A finite number in [lo, hi]; `what` names the limit in the message.
  double bounded(const Json& j, const std::string& ptr, double lo, double hi,
                 const char* what) const;
  //! A length > 0: a size, width, depth or radius (limits::kMinLength..kLength).
  double positive(const Json& j, const std::string& ptr) const;
  //! A distance >= 0 (at most limits::kLength).
  double non_negative(const Json& j, const std::string& ptr) const;
  //! A weight >= 0 (at most limits::kWeight).
  double weight(const Json& j, const std::string& ptr) const;
  double coordinate(const Json& j, const std::string& ptr) const;
  double angle(const Json& j, const std::string& ptr) const;
  int integer_in(const Json& j, const std::string& ptr, int min, int max) const;

  //! An array of exactly n elements; calls each(element, pointer, index).
  void fixed_array(
      const Json& j, const std::string& ptr, std::size_t n, const char* what,
      const std::function<void(const Json&, const std::string&, std::size_t)>& each) const;
  Vec2 point(const Json& j, const std::string& ptr) const;
  Pose2 pose(const Json& j, const std::string& ptr) const;
  std::array<double, 2> size2(const Json& j, const std::string& ptr, const char* what) const;
  //! Vertices of a simple counter-clockwise polygon.
  Polygon polygon(const Json& j, const std::string& ptr) const;

 private:
  std::string label_;
};

//! Parses scene text into JSON, rejecting (through `errors`) empty text,
//! nesting deeper than limits::kDepth, duplicate keys and invalid JSON.
Json parse_json(std::string_view text, const FieldReader& errors);

}  // namespace hrs::geometry::scene_io
