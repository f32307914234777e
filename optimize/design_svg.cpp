// SPDX-License-Identifier: GPL-3.0-or-later
// design.svg and the contact sheet (optimize/design_io.h): the room, the door
// and its clear zone, the objects with their fronts, the tours, the chair at
// its start, the unmet preferences, and a legend.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "geometry/polygon_ops.h"
#include "optimize/design_io.h"

namespace hrs::optimize {

namespace {

using geometry::Vec2;

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

//! Maps scene metres to SVG pixels (y up → y down).
struct Frame {
  double xmin, ymax, scale, left, top;
  double x(double wx) const { return left + (wx - xmin) * scale; }
  double y(double wy) const { return top + (ymax - wy) * scale; }
  std::string pt(Vec2 p) const { return num(x(p.x)) + "," + num(y(p.y)); }
  std::string points(const geometry::Polygon& poly) const {
    std::string s;
    for (const auto& p : poly) {
      if (!s.empty()) s += ' ';
      s += pt(p);
    }
    return s;
  }
};


// ---- design.svg layers ----------------------------------------------------

constexpr double kPixelsPerMetre = 100.0;

//! The drawing's size and its map from scene metres: the room's bounding box
//! with margins for the title above and the legend below.
struct Canvas {
  Frame frame;
  double width, height;
};

Canvas room_canvas(const geometry::Scene& scene) {
  const auto [xmin, ymin, xmax, ymax] = geometry::bounding_box(scene.room.polygon);
  const double scale = kPixelsPerMetre;
  return {Frame{xmin, ymax, scale, 20.0, 40.0}, (xmax - xmin) * scale + 40.0,
          (ymax - ymin) * scale + 105.0};
}

//! The <svg> element, a white background and the title.
void svg_open(std::ostringstream& s, const Canvas& canvas, const std::string& title) {
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(canvas.width) << "\" height=\""
    << num(canvas.height) << "\" viewBox=\"0 0 " << num(canvas.width) << " " << num(canvas.height)
    << "\" font-family=\"sans-serif\">\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"20\" y=\"25\" font-size=\"15\">" << escape(title) << "</text>\n";
}

void room_layer(std::ostringstream& s, const Frame& f, const geometry::Scene& scene) {
  s << "<polygon points=\"" << f.points(scene.room.polygon)
    << "\" fill=\"#f7f7f2\" stroke=\"#222\" stroke-width=\"4\"/>\n";
}

//! The door: its clear zone, then the opening drawn over the wall, labelled.
void door_layer(std::ostringstream& s, const Frame& f, const geometry::Scene& scene) {
  s << "<polygon points=\"" << f.points(geometry::door_clear_zone(scene))
    << "\" fill=\"#ffe9c7\" stroke=\"#e0a040\" stroke-dasharray=\"5,4\"/>\n";
  const Vec2 n = geometry::door_inward_normal(scene);
  const Vec2 along{n.y, -n.x};
  const Vec2 c = scene.door.center;
  s << "<line x1=\"" << num(f.x((c - 0.5 * scene.door.width * along).x)) << "\" y1=\""
    << num(f.y((c - 0.5 * scene.door.width * along).y)) << "\" x2=\""
    << num(f.x((c + 0.5 * scene.door.width * along).x)) << "\" y2=\""
    << num(f.y((c + 0.5 * scene.door.width * along).y))
    << "\" stroke=\"#f7f7f2\" stroke-width=\"6\"/>\n";
  s << "<text x=\"" << num(f.x(c.x + 0.25 * n.x)) << "\" y=\"" << num(f.y(c.y + 0.25 * n.y))
    << "\" font-size=\"11\" fill=\"#a06010\" text-anchor=\"middle\">door</text>\n";
}

//! Objects, fixed ones grey, each with a mark on its front (local +x) and its id.
void objects_layer(std::ostringstream& s, const Frame& f, const geometry::Scene& scene) {
  for (const auto& o : scene.objects) {
    s << "<polygon points=\"" << f.points(geometry::world_footprint(o)) << "\" fill=\""
      << (o.fixed ? "#d8d8d8" : "#cfe0f5") << "\" stroke=\"#345\" stroke-width=\"1.5\"/>\n";
    double front = 0.0;
    for (const auto& p : o.footprint) front = std::max(front, p.x);
    const Vec2 a = geometry::to_world(o.pose, {front, -0.12}),
               b = geometry::to_world(o.pose, {front, 0.12});
    s << "<line x1=\"" << num(f.x(a.x)) << "\" y1=\"" << num(f.y(a.y)) << "\" x2=\""
      << num(f.x(b.x)) << "\" y2=\"" << num(f.y(b.y))
      << "\" stroke=\"#c02020\" stroke-width=\"5\"/>\n";
    s << "<text x=\"" << num(f.x(o.pose.x)) << "\" y=\"" << num(f.y(o.pose.y) + 4)
      << "\" font-size=\"12\" text-anchor=\"middle\">" << escape(o.id) << "</text>\n";
  }
}

//! Unmet preferences: the object outlined in orange, dashed, and under its
//! id what is off and by how much (e.g. "wall angle 88°", "→ bed 0.4 m").
void preferences_layer(std::ostringstream& s, const Frame& f, const geometry::Scene& scene,
                       const PreferenceReport& report) {
  for (const auto& o : scene.objects) {
    std::vector<std::string> notes;
    for (const PreferenceCheck& c : report.checks) {
      if (c.met || c.object != o.id) continue;
      const bool angle = c.angular();
      char value[48];
      std::snprintf(value, sizeof value, angle ? "%.0f\u00b0" : "%.2f m",
                    angle ? c.residual * 180.0 / std::numbers::pi : c.residual);
      const std::string what = c.kind.starts_with("wall")
                                   ? (angle ? "wall angle" : "wall")
                                   : "\u2192 " + c.other +
                                         (c.kind == "relation_faces" ? " facing" : angle ? " angle" : "");
      notes.push_back(what + " " + value);
    }
    if (notes.empty()) continue;
    s << "<polygon points=\"" << f.points(geometry::world_footprint(o))
      << "\" fill=\"none\" stroke=\"#e07010\" stroke-width=\"3\" stroke-dasharray=\"6,3\"/>\n";
    for (std::size_t k = 0; k < notes.size(); ++k)
      s << "<text x=\"" << num(f.x(o.pose.x)) << "\" y=\"" << num(f.y(o.pose.y) + 17 + 11 * k)
        << "\" font-size=\"10\" fill=\"#b05000\" text-anchor=\"middle\">" << escape(notes[k])
        << "</text>\n";
  }
}

//! One polyline per leg of a tour, bold (the most likely tour) or faint.
void tour_polylines(std::ostringstream& s, const Frame& f, const planning::Tour& tour, bool bold) {
  for (const auto& leg : tour.legs) {
    s << "<polyline fill=\"none\" points=\"";
    bool first = true;
    for (const auto& w : leg.waypoints) {
      s << (first ? "" : " ") << f.pt(w.position());
      first = false;
    }
    s << "\" stroke=\"" << (bold ? "#d62728" : "#5070a0") << "\" stroke-width=\""
      << (bold ? "3" : "1") << "\" stroke-opacity=\"" << (bold ? "0.95" : "0.35") << "\"/>\n";
  }
}

//! Tours: the others faintly first, then the most likely one (tours[0]) boldly.
void tours_layer(std::ostringstream& s, const Frame& f, const std::vector<planning::Tour>& tours) {
  for (std::size_t k = 1; k < tours.size(); ++k) tour_polylines(s, f, tours[k], false);
  if (!tours.empty()) tour_polylines(s, f, tours[0], true);
}

//! The chair's outline at its start pose, dashed.
void start_chair_layer(std::ostringstream& s, const Frame& f, const geometry::Scene& scene) {
  const auto start = geometry::door_start_pose(scene);
  const double l = scene.wheelchair.length / 2, w = scene.wheelchair.width / 2;
  const geometry::Polygon chair{
      geometry::to_world(start, {-l, -w}), geometry::to_world(start, {l, -w}),
      geometry::to_world(start, {l, w}), geometry::to_world(start, {-l, w})};
  s << "<polygon points=\"" << f.points(chair)
    << "\" fill=\"none\" stroke=\"#2a7\" stroke-width=\"1.5\" stroke-dasharray=\"3,2\"/>\n";
}

//! Below the room: a 1 m scale bar, the final cost and tours found, and the
//! most likely sequence with its likelihood.
void legend(std::ostringstream& s, const Canvas& canvas, const DesignResult& result) {
  const double scale = canvas.frame.scale, by = canvas.height - 40.0;
  s << "<line x1=\"20\" y1=\"" << num(by) << "\" x2=\"" << num(20 + scale) << "\" y2=\"" << num(by)
    << "\" stroke=\"black\" stroke-width=\"3\"/>\n";
  s << "<text x=\"" << num(20 + scale + 8) << "\" y=\"" << num(by + 4)
    << "\" font-size=\"12\">1 m</text>\n";
  const int found = result.final.tours_found, total = result.final.tours_total;
  s << "<text x=\"" << num(20 + scale + 50) << "\" y=\"" << num(by + 4) << "\" font-size=\"12\">"
    << "cost " << num(result.final.total()) << ", tours found " << found << "/" << total
    << ", preferences met " << result.preferences.met << "/" << result.preferences.total
    << "</text>\n";
  if (result.sequences.empty()) return;
  std::string seq;
  for (const auto& id : result.sequences[0].nodes) {
    if (!seq.empty()) seq += " \u2192 ";
    seq += id;
  }
  const bool shown = !result.tours.empty() && result.tours[0].found;
  char lik[32];
  std::snprintf(lik, sizeof lik, "%.3f", result.sequences[0].likelihood);
  s << "<text x=\"20\" y=\"" << num(by + 20) << "\" font-size=\"11\" fill=\""
    << (shown ? "#d62728" : "#777") << "\">most likely tour" << (shown ? " (bold)" : "") << ": "
    << escape(seq) << ", L = " << lik << (shown ? "" : " \u2014 not found") << "</text>\n";
}

}  // namespace

std::string design_svg(const DesignResult& result, const std::string& title,
                       const std::string& overlay) {
  return design_picture(result, title, overlay).svg;
}

Picture design_picture(const DesignResult& result, const std::string& title,
                       const std::string& overlay) {
  const auto& scene = result.layout;
  const Canvas canvas = room_canvas(scene);
  const Frame& f = canvas.frame;
  std::ostringstream s;
  svg_open(s, canvas, title);
  room_layer(s, f, scene);
  door_layer(s, f, scene);
  objects_layer(s, f, scene);
  preferences_layer(s, f, scene, result.preferences);
  tours_layer(s, f, result.tours);
  if (!overlay.empty()) {
    // Room coordinates (metres, y up) mapped like every other layer.
    s << "<g class=\"overlay\" transform=\"matrix(" << num(f.scale) << " 0 0 " << num(-f.scale)
      << " " << num(f.left - f.xmin * f.scale) << " " << num(f.top + f.ymax * f.scale) << ")\">\n"
      << overlay << "</g>\n";
  }
  start_chair_layer(s, f, scene);
  legend(s, canvas, result);
  s << "</svg>\n";
  return {s.str(), canvas.width, canvas.height};
}

std::string contact_sheet_svg(const std::vector<Picture>& pictures, int columns) {
  double cell_w = 0.0, cell_h = 0.0;
  for (const Picture& p : pictures) cell_w = std::max(cell_w, p.width), cell_h = std::max(cell_h, p.height);
  columns = std::max(1, std::min(columns, static_cast<int>(pictures.size())));
  const int rows = (static_cast<int>(pictures.size()) + columns - 1) / columns;
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(columns * cell_w)
      << "\" height=\"" << num(rows * cell_h) << "\">\n";
  for (std::size_t i = 0; i < pictures.size(); ++i) {
    std::string s = pictures[i].svg;
    const auto pos = s.find("<svg ");
    if (pos == std::string::npos) continue;
    s.replace(pos, 5,
              "<svg x=\"" + num((i % columns) * cell_w) + "\" y=\"" +
                  num(static_cast<double>(i / columns) * cell_h) + "\" ");
    out << s;
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace hrs::optimize
