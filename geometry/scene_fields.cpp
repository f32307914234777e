// SPDX-License-Identifier: GPL-3.0-or-later
// Typed, limit-checked reading of the scene format's fields
// (FieldReader, geometry/scene_json.h): numbers against the limits of the
// format, points, poses, sizes and simple counter-clockwise polygons.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/error.h"
#include "geometry/polygon_ops.h"
#include "geometry/scene_json.h"

namespace hrs::geometry::scene_io {

void FieldReader::fail(const std::string& ptr, const std::string& what) const {
  // The whole document has the empty pointer: then the message names only the file.
  throw InputError(one_line(label_ + ": " + (ptr.empty() ? "" : ptr + ": ") + what));
}

void FieldReader::expect_object(const Json& j, const std::string& ptr) const {
  if (!j.is_object()) fail(ptr, "must be a JSON object, got " + shown(j));
}

void FieldReader::expect_array(const Json& j, const std::string& ptr) const {
  if (!j.is_array()) fail(ptr, "must be an array, got " + shown(j));
}

void FieldReader::check_keys(const Json& j, const std::string& ptr,
                             std::initializer_list<std::string_view> allowed) const {
  for (const auto& [key, value] : j.items()) {
    if (key == kComment) continue;
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail(child(ptr, key), "unknown field (allowed: " + list + ", comment)");
  }
}

const Json& FieldReader::require(const Json& j, const std::string& ptr,
                                 std::string_view key) const {
  const auto it = j.find(std::string(key));
  if (it == j.end()) fail(child(ptr, key), "missing required field");
  return *it;
}

const Json* FieldReader::optional(const Json& j, std::string_view key) {
  const auto it = j.find(std::string(key));
  return it == j.end() ? nullptr : &*it;
}

std::string FieldReader::string(const Json& j, const std::string& ptr) const {
  if (!j.is_string()) fail(ptr, "must be a string, got " + shown(j));
  return j.get<std::string>();
}

bool FieldReader::boolean(const Json& j, const std::string& ptr) const {
  if (!j.is_boolean()) fail(ptr, "must be true or false, got " + shown(j));
  return j.get<bool>();
}

double FieldReader::number(const Json& j, const std::string& ptr) const {
  if (!j.is_number()) fail(ptr, "must be a number, got " + shown(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(ptr, "must be a finite number, got " + num(v));
  return v;
}

double FieldReader::bounded(const Json& j, const std::string& ptr, double lo, double hi,
                            const char* what) const {
  const double v = number(j, ptr);
  if (!(v >= lo && v <= hi)) {
    fail(ptr, "must be within [" + num(lo) + ", " + num(hi) + "] (" + what + "), got " + num(v));
  }
  return v;
}

double FieldReader::positive(const Json& j, const std::string& ptr) const {
  const double v = number(j, ptr);
  if (!(v > 0.0)) fail(ptr, "must be > 0, got " + num(v));
  return bounded(j, ptr, limits::kMinLength, limits::kLength, "length limits of the format");
}

double FieldReader::non_negative(const Json& j, const std::string& ptr) const {
  const double v = number(j, ptr);
  if (!(v >= 0.0)) fail(ptr, "must be >= 0, got " + num(v));
  return bounded(j, ptr, 0.0, limits::kLength, "length limits of the format");
}

double FieldReader::weight(const Json& j, const std::string& ptr) const {
  const double v = number(j, ptr);
  if (!(v >= 0.0)) fail(ptr, "must be >= 0, got " + num(v));
  return bounded(j, ptr, 0.0, limits::kWeight, "weight limit of the format");
}

double FieldReader::coordinate(const Json& j, const std::string& ptr) const {
  return bounded(j, ptr, -limits::kCoordinate, limits::kCoordinate,
                 "coordinate limit of the format");
}

double FieldReader::angle(const Json& j, const std::string& ptr) const {
  return bounded(j, ptr, -limits::kAngle, limits::kAngle, "angle limit of the format");
}

int FieldReader::integer_in(const Json& j, const std::string& ptr, int min, int max) const {
  if (!j.is_number_integer()) fail(ptr, "must be an integer, got " + shown(j));
  const bool too_big = j.is_number_unsigned() ? j.get<std::uint64_t>() > std::uint64_t(max)
                                              : j.get<std::int64_t>() > std::int64_t{max};
  if (too_big)
    fail(ptr, "must be <= " + std::to_string(max) + " (limit of the format), got " + j.dump());
  const auto v = j.get<std::int64_t>();
  if (v < min) fail(ptr, "must be >= " + std::to_string(min) + ", got " + std::to_string(v));
  return static_cast<int>(v);
}

void FieldReader::fixed_array(
    const Json& j, const std::string& ptr, std::size_t n, const char* what,
    const std::function<void(const Json&, const std::string&, std::size_t)>& each) const {
  if (!j.is_array() || j.size() != n) {
    fail(ptr, "must be " + std::string(what) + " (an array of " + std::to_string(n) +
                  " numbers), got " + shown(j));
  }
  for (std::size_t i = 0; i < n; ++i) each(j[i], child(ptr, i), i);
}

Vec2 FieldReader::point(const Json& j, const std::string& ptr) const {
  Vec2 p;
  fixed_array(j, ptr, 2, "a point [x, y]",
              [&](const Json& e, const std::string& p2, std::size_t i) {
                (i == 0 ? p.x : p.y) = coordinate(e, p2);
              });
  return p;
}

Pose2 FieldReader::pose(const Json& j, const std::string& ptr) const {
  Pose2 p;
  fixed_array(j, ptr, 3, "a pose [x, y, theta]",
              [&](const Json& e, const std::string& p2, std::size_t i) {
                const double v = i < 2 ? coordinate(e, p2) : angle(e, p2);
                (i == 0 ? p.x : i == 1 ? p.y : p.theta) = v;
              });
  return p;
}

std::array<double, 2> FieldReader::size2(const Json& j, const std::string& ptr,
                                         const char* what) const {
  std::array<double, 2> s{};
  fixed_array(j, ptr, 2, what,
              [&](const Json& e, const std::string& p2, std::size_t i) { s[i] = positive(e, p2); });
  return s;
}

Polygon FieldReader::polygon(const Json& j, const std::string& ptr) const {
  expect_array(j, ptr);
  if (j.size() < 3) fail(ptr, "needs at least 3 vertices, got " + std::to_string(j.size()));
  if (j.size() > limits::kVertices) {
    fail(ptr, "has " + std::to_string(j.size()) + " vertices, more than the format's limit of " +
                  std::to_string(limits::kVertices));
  }
  Polygon poly;
  for (std::size_t i = 0; i < j.size(); ++i) poly.push_back(point(j[i], child(ptr, i)));
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const double edge = norm(poly[(i + 1) % poly.size()] - poly[i]);
    if (!(edge >= limits::kMinLength)) {
      fail(child(ptr, (i + 1) % poly.size()),
           "edge from vertex " + std::to_string(i) + " is " + num(edge) +
               " m long, shorter than the format's limit of " + num(limits::kMinLength) + " m");
    }
  }
  if (!is_simple(poly)) {
    fail(ptr, "is not a simple polygon (edges cross, touch or repeat a vertex)");
  }
  if (!is_counterclockwise(poly)) {
    fail(ptr, "is clockwise; vertices must be counter-clockwise");
  }
  return poly;
}

}  // namespace hrs::geometry::scene_io
