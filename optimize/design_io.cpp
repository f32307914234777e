// SPDX-License-Identifier: GPL-3.0-or-later
// The output files of `hrspace design` (optimize/design_io.h): their texts,
// and writing them so that no failure leaves a truncated file behind.

#include "optimize/design_io.h"
#include "optimize/preferences_json.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "geometry/error.h"
#include "geometry/version.h"
#include "planning/tour_json.h"

namespace hrs::optimize {

namespace {

using geometry::Vec2;
using nlohmann::json;

json terms_json(const CostTerms& t) {
  return {{"path_length", t.path_length},
          {"path_rotation", t.path_rotation},
          {"path_clearance", t.path_clearance},
          {"unfound_penalty", t.unfound_penalty},
          {"interior_distance", t.interior_distance},
          {"interior_rotation", t.interior_rotation},
          {"path", t.path()},
          {"interior", t.interior()},
          {"total", t.total()},
          {"tours_found", t.tours_found},
          {"tours_total", t.tours_total}};
}

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

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

//! A temporary name beside `path`, unique to this process.
std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  return path.parent_path() / name;
}

//! Writes `text` to a new file at `path` and flushes it to disk; false with
//! errno set on failure.
bool write_synced(const std::filesystem::path& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int saved = n < 0 ? errno : EIO;
      ::close(fd);
      errno = saved;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
    const int saved = errno;
    ::close(fd);
    errno = saved;
    return false;
  }
  return ::close(fd) == 0;
}

}  // namespace

void write_files_atomic(const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
  std::vector<std::filesystem::path> temporaries;
  auto discard = [&] {
    std::error_code ignored;
    for (const auto& t : temporaries) std::filesystem::remove(t, ignored);
  };
  for (const auto& [path, text] : files) {
    temporaries.push_back(temporary_beside(path));
    if (!write_synced(temporaries.back(), text)) {
      const std::string reason = std::strerror(errno);
      discard();
      throw OutputError(path.string() + ": cannot write file: " + reason);
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (::rename(temporaries[i].c_str(), files[i].first.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      discard();
      throw OutputError(files[i].first.string() + ": cannot replace file: " + reason);
    }
  }
}

void require_writable_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create directory: " + ec.message());
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(dir.string() + ": exists and is not a directory");
  }
  const std::filesystem::path probe = temporary_beside(dir / "write-check");
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw InputError(dir.string() + ": directory is not writable: " + std::strerror(errno));
  }
  ::close(fd);
  std::filesystem::remove(probe, ec);
}

const std::vector<std::string>& design_file_names() {
  static const std::vector<std::string> names{"layout.json", "tours.json", "design.svg",
                                              "report.json"};
  return names;
}

std::string tours_document(const DesignResult& result) {
  std::vector<double> likelihoods;
  for (const Sequence& s : result.sequences) likelihoods.push_back(s.likelihood);
  return planning::tours_json(result.tours, likelihoods, /*timings=*/false, /*indent=*/1) + "\n";
}

namespace {

// ---- report.json sections -------------------------------------------------

//! "cost"/"terms": every cost term of the input and of the best layout.
json terms_comparison_json(const DesignResult& result) {
  json terms = json::object();
  const json initial = terms_json(result.initial), final = terms_json(result.final);
  for (const auto& [name, value] : initial.items())
    terms[name] = {{"initial", value}, {"final", final[name]}};
  return terms;
}

//! One entry of "trace": the annealer's step, then its planning when planned.
json trace_step_json(const DesignStep& s, const geometry::Scene& layout) {
  const auto& e = s.anneal;
  json step = {{"iteration", e.iteration + 1},
               {"temperature", e.temperature},
               {"object", e.object >= 0 ? json(layout.objects[e.object].id) : json(nullptr)},
               {"move", e.rotation ? "rotate" : (e.jump ? "jump" : "translate")},
               {"valid", e.valid},
               {"accepted", e.accepted},
               {"proposed", finite_or_null(e.proposed_cost)},
               {"current", e.current_cost},
               {"best", finite_or_null(e.best_cost)}};
  if (s.planned) {
    step["tours_found"] = s.proposed.tours_found;
    if (s.rejected_early) {
      step["rejected_early"] = true;
      step["tours_planned"] = s.proposed.tours_total;
    }
    step["planning_ms"] = s.planning_ms;
    if (s.legs) {
      const auto& c = *s.legs;
      step["legs"] = {{"database", c.legs_database}, {"repaired", c.legs_repaired},
                      {"planned", c.legs_planned},   {"failed", c.legs_failed},
                      {"failed_ms", c.failed_ms},    {"planned_ms", c.planned_ms}};
    }
  }
  return step;
}

//! "trace": one entry per iteration.
json trace_json(const DesignResult& result) {
  json trace = json::array();
  for (const auto& s : result.trace) trace.push_back(trace_step_json(s, result.layout));
  return trace;
}

//! "sequences": the M sequences with their likelihoods, most likely first.
json sequences_json(const DesignResult& result) {
  json seqs = json::array();
  for (const auto& s : result.sequences)
    seqs.push_back({{"sequence", s.nodes}, {"likelihood", s.likelihood}});
  return seqs;
}

//! The report's sections about how the run went: what was asked, how the
//! proposals fared, what was planned or skipped, costs, time and trace.
json run_report_json(const DesignResult& result, const RunInfo& info) {
  return {{"scene", result.layout.name},
          {"version", hrs::version()},
          {"commit", hrs::commit()},
          {"seed", info.seed},
          {"planner", info.planner},
          {"iterations", info.iterations},
          {"iterations_run", result.proposals},
          {"stopped", result.stopped},
          {"valid", result.valid},
          {"threads", result.threads},
          {"planned_every_iteration", result.planned_every_iteration},
          {"tours_invalidated", result.tours_invalidated},
          {"tours_planned", result.tours_planned},
          {"early_rejection",
           {{"proposals", result.early.proposals},
            {"tours_skipped", result.early.tours_skipped},
            {"legs_skipped", result.early.legs_skipped},
            {"planning_saved_estimate_s", result.early.saved_s_estimate}}},
          {"unblock",
           {{"walled_before", result.unblock.walled_before},
            {"walled_after", result.unblock.walled_after},
            {"proposals", result.unblock.proposals},
            {"accepted", result.unblock.accepted}}},
          {"covering_moves", result.covering_moves},
          {"polish", {{"tried", result.polish.tried}, {"kept", result.polish.kept}}},
          {"refused_legs",
           {{"legs", result.legs_refused},
            {"reachability_fills", result.gate_fills},
            {"reachability_ms", result.gate_ms}}},
          {"preferences", preferences_json(result.preferences)},
          {"preferences_initial",
           {{"met", result.preferences_initial.met}, {"total", result.preferences_initial.total}}},
          {"cost",
           {{"initial", result.initial.total()},
            {"final", result.final.total()},
            {"terms", terms_comparison_json(result)}}},
          {"time_s",
           {{"total", result.time_total_s},
            {"planning", result.time_planning_s},
            {"planning_share",
             result.time_total_s > 0 ? result.time_planning_s / result.time_total_s : 0.0}}},
          {"acceptance_rate",
           result.proposals > 0 ? static_cast<double>(result.accepted) / result.proposals : 0.0},
          {"accepted", result.accepted},
          {"valid_proposals", result.valid_proposals},
          {"temperature", {{"start", result.t_start}, {"end", result.t_end}}},
          {"sequences", sequences_json(result)},
          {"trace", trace_json(result)}};
}

//! "reuse" of the proposed planner (paper §V): where the legs came from (each
//! key counted once per iteration) and the RRT iterations of the fresh plans
//! (Fig. "rrt-it").
json reuse_json(const DesignResult& result) {
  const auto& c = result.counters;
  json histogram = json::array();
  for (const auto& [iterations, count] : c.rrt_iterations)
    histogram.push_back({{"iterations", iterations}, {"legs", count}});
  return {{"techniques", result.reuse},
          {"legs_database", c.legs_database},
          {"legs_repaired", c.legs_repaired},
          {"legs_planned", c.legs_planned},
          {"legs_failed", c.legs_failed},
          {"legs_rejected", c.legs_rejected},
          {"checks_skipped", c.checks_skipped},
          {"trees_reused", c.trees_reused},
          {"failures_reused", c.failures_reused},
          {"legs_proven", c.legs_proven},
          {"leg_requests", c.leg_requests},
          {"rrt_iterations_histogram", histogram},
          {"time_ms",
           {{"database", c.database_ms},
            {"repaired", c.repaired_ms},
            {"planned", c.planned_ms},
            {"failed", c.failed_ms},
            {"proofs", c.proof_ms}}}};
}

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

std::string report_document(const DesignResult& result, const RunInfo& info) {
  json r = run_report_json(result, info);
  if (result.proposed) r["reuse"] = reuse_json(result);
  return r.dump(1) + "\n";
}

std::string design_svg(const DesignResult& result, const std::string& title) {
  const auto& scene = result.layout;
  const Canvas canvas = room_canvas(scene);
  const Frame& f = canvas.frame;
  std::ostringstream s;
  svg_open(s, canvas, title);
  room_layer(s, f, scene);
  door_layer(s, f, scene);
  objects_layer(s, f, scene);
  tours_layer(s, f, result.tours);
  start_chair_layer(s, f, scene);
  legend(s, canvas, result);
  s << "</svg>\n";
  return s.str();
}

std::string contact_sheet_svg(const std::vector<std::string>& svgs, int columns) {
  auto attr = [](const std::string& svg, const std::string& name) {
    const auto p = svg.find(name + "=\"");
    if (p == std::string::npos) return 0.0;
    return std::stod(svg.substr(p + name.size() + 2));
  };
  double cell_w = 0.0, cell_h = 0.0;
  for (const auto& s : svgs)
    cell_w = std::max(cell_w, attr(s, "width")), cell_h = std::max(cell_h, attr(s, "height"));
  columns = std::max(1, std::min(columns, static_cast<int>(svgs.size())));
  const int rows = (static_cast<int>(svgs.size()) + columns - 1) / columns;
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(columns * cell_w)
      << "\" height=\"" << num(rows * cell_h) << "\">\n";
  for (std::size_t i = 0; i < svgs.size(); ++i) {
    std::string s = svgs[i];
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

void write_design(const DesignResult& result, const RunInfo& info,
                  const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create directory: " + ec.message());
  const std::string title = result.layout.name + " — seed " + std::to_string(info.seed) +
                            (result.valid ? "" : " (NOT VALID)");
  write_files_atomic({{dir / "layout.json", geometry::write_scene(result.layout)},
                      {dir / "tours.json", tours_document(result)},
                      {dir / "design.svg", design_svg(result, title)},
                      {dir / "report.json", report_document(result, info)}});
}

}  // namespace hrs::optimize
