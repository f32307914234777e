// SPDX-License-Identifier: GPL-3.0-or-later
// One planning round of a design run; see tour_round.h.

#include "optimize/tour_round.h"

#include <algorithm>

#include "planning/lattice.h"
#include "planning/recheck.h"

namespace hrs::optimize {

TourRound::TourRound(const geometry::Scene& scene, const DesignOptions& options,
                     const std::vector<Sequence>& sequences, const std::atomic<bool>* stop)
    : work_(scene),
      cspace_(work_, options.cspace),
      gate_(work_, cspace_, options.gate),
      options_(options),
      sequences_(&sequences),
      pool_(options.threads),
      tours_(sequences.size()),
      invalidated_(sequences.size(), 0),
      blockage_(sequences.size()),
      finished_(sequences.size(), 0) {
  // The planner configuration decides whether RRTs skip tried goal nodes.
  planning::TourOptions tour = options.tour;
  tour.planner.skip_tried_goal_nodes = options.planner.goalskip;
  if (options.planner.proposed) {
    reuse_ = std::make_unique<planning::ReusePlanner>(work_, cspace_, tour, options.planner.reuse,
                                                      options.seed);
    if (options.planner.refuse) reuse_->set_gate(&gate_);
  }
  planning::TourHooks hooks = reuse_ ? reuse_->hooks() : planning::TourHooks{};
  if (!reuse_ && options.planner.refuse) hooks.gate = &gate_;
  hooks.cancel = &cancel_;
  hooks.stop = stop;
  // The objects' goal poses in their own frames, once for all M planners.
  auto local_goals = std::make_shared<std::vector<std::vector<planning::GoalPose>>>();
  for (const geometry::Object& o : work_.objects)
    local_goals->push_back(planning::local_goal_poses(work_, o, tour.goals, stop));
  hooks.local_goals = local_goals;
  local_goals_ = std::move(local_goals);
  tour_options_ = tour;
  stop_ = stop;
  for (std::size_t k = 0; k < sequences.size(); ++k) {
    hooks.tour = static_cast<int>(k);
    planners_.push_back(std::make_unique<planning::TourPlanner>(
        work_, cspace_, tour, tour_seed(options.seed, 0, static_cast<int>(k)), hooks));
  }
}

std::vector<int> TourRound::walled_stops() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < grades_.size(); ++i)
    if (grades_[i] > 0.0) out.push_back(static_cast<int>(i));
  return out;
}

std::vector<int> TourRound::failing_stops() {
  std::vector<int> out;
  for (std::size_t k = 0; k < tours_.size(); ++k) {
    if (tours_[k].found) continue;
    const auto& nodes = (*sequences_)[k].nodes;
    const std::size_t at = static_cast<std::size_t>(std::max(0, tours_[k].stats.depth)) + 1;
    if (at >= nodes.size()) continue;
    const int object = work_.find_object(nodes[at]);
    if (object >= 0 && std::find(out.begin(), out.end(), object) == out.end())
      out.push_back(object);
  }
  std::sort(out.begin(), out.end());
  return out;
}

bool TourRound::fails_leaving_the_door() const {
  bool unfound = false;
  for (const planning::Tour& t : tours_) {
    if (t.found) continue;
    if (t.stats.depth > 0) return false;
    unfound = true;
  }
  return unfound;
}

std::vector<planning::GoalPose> TourRound::goals_of(int index) const {
  return planners_.front()->goals_for(work_.objects[index].id);
}

TourRound::Outcome TourRound::plan(int iteration, std::optional<planning::ReuseCounters>& legs,
                                   const Bound* bound) {
  const int m = static_cast<int>(tours_.size());
  follow_layout();
  cancel_.store(false);
  std::fill(finished_.begin(), finished_.end(), 0);
  Outcome out;
  out.kept = m;
  out.bound = bound ? bound->base : 0.0;
  if (bound && bound->floors)
    for (double f : *bound->floors) out.bound += f;
  int prefix = 0;
  // The proposed planner's legs derive from (seed, iteration), not the tour.
  if (reuse_) reuse_->begin_iteration(tour_seed(options_.seed, iteration, m));
  pool_.run(m, [&](int k) {
    if (cancel_.load()) return;  // the layout is rejected: not started
    planners_[k]->set_seed(tour_seed(options_.seed, iteration, k));
    tours_[k] = planners_[k]->plan((*sequences_)[k].nodes);
    invalidated_[k] = planning::recheck_tour(cspace_, work_.wheelchair.turning_radius, tours_[k],
                                             reuse_ ? reuse_->measures() : nullptr)
                          ? 0
                          : 1;
    grade(k);
    if (!bound) return;
    std::lock_guard lock(mutex_);
    finished_[k] = 1;
    while (!out.rejected && prefix < m && finished_[prefix]) {
      out.bound += bound->model->tour_total(prefix, tours_[prefix], blockage_[prefix]);
      if (bound->floors) out.bound -= (*bound->floors)[prefix];
      ++prefix;
      if (bound->acceptance->rejects(out.bound)) {
        out.rejected = true;
        out.kept = prefix;
        cancel_.store(true);
      }
    }
  });
  if (reuse_) legs = reuse_->end_iteration(out.kept);
  for (int k = 0; k < out.kept; ++k) out.dropped += invalidated_[k];
  return out;
}

void TourRound::grade(int k) {
  blockage_[k].clear();
  if (tours_[k].found || !options_.planner.escape) return;
  blockage_[k] = stop_grades(k);
}

std::vector<double> TourRound::stop_grades(int k) {
  std::vector<double> out;
  const auto& nodes = (*sequences_)[k].nodes;
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const int object = work_.find_object(nodes[i]);
    if (object < 0) {
      out.push_back(1.0);
      continue;
    }
    double b;
    {
      std::lock_guard lock(mutex_);
      b = grades_[object];
    }
    if (b < 0.0) {
      b = gate_.blockage(planners_[k]->goals_for(nodes[i]));
      std::lock_guard lock(mutex_);
      grades_[object] = b;
    }
    out.push_back(b);
  }
  return out;
}

std::vector<double> TourRound::certain_floors(const CostModel& model) {
  follow_layout();
  std::vector<double> floors(tours_.size(), 0.0);
  for (std::size_t k = 0; k < tours_.size(); ++k) {
    const auto& nodes = (*sequences_)[k].nodes;
    for (std::size_t i = 1; i < nodes.size(); ++i) {
      const int object = work_.find_object(nodes[i]);
      if (object < 0 || !gate_.walls_off(planners_[k]->goals_for(nodes[i]))) continue;
      planning::Tour unfound;
      unfound.found = false;
      unfound.stats.depth = static_cast<int>(i) - 1;
      const std::vector<double> grades =
          options_.planner.escape ? stop_grades(static_cast<int>(k)) : std::vector<double>{};
      floors[k] = model.tour_total(static_cast<int>(k), unfound, grades);
      break;
    }
  }
  return floors;
}

void TourRound::follow_gate() {
  if (gate_version_ == version_) return;
  gate_.invalidate();
  gate_version_ = version_;
}

void TourRound::follow_layout() {
  follow_gate();
  if (graded_version_ == version_) return;
  grades_.assign(work_.objects.size(), -1.0);
  graded_version_ = version_;
}

void TourRound::move(int o, const Pose2& to) {
  work_.objects[static_cast<std::size_t>(o)].pose = to;
  cspace_.move_object(o, to);
  ++version_;
}

void TourRound::place(const std::vector<Pose2>& poses) {
  for (std::size_t i = 0; i < poses.size(); ++i)
    if (cspace_.object_pose(static_cast<int>(i)) != poses[i]) move(static_cast<int>(i), poses[i]);
}

bool TourRound::fits(const std::vector<Pose2>& p, int moved) {
  std::vector<std::pair<std::size_t, Pose2>> saved;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (work_.objects[i].pose != p[i]) {
      saved.emplace_back(i, work_.objects[i].pose);
      work_.objects[i].pose = p[i];
    }
  const bool ok = object_fits(work_, moved);
  for (const auto& [i, pose] : saved) work_.objects[i].pose = pose;
  return ok;
}

void TourRound::trial(int moved, const Pose2& to, const std::function<void()>& f) {
  const Pose2 from = cspace_.object_pose(moved);
  cspace_.move_object(moved, to);
  f();
  cspace_.move_object(moved, from);
}

int TourRound::rescue(const std::vector<Pose2>& poses, const std::vector<planning::Tour>& tours,
                      int iteration) {
  place(poses);
  ++version_;  // the grades are recomputed for the rescued tours
  follow_layout();
  tours_ = tours;
  std::vector<int> unfound;
  for (std::size_t k = 0; k < tours_.size(); ++k)
    if (!tours_[k].found && unfound.size() < static_cast<std::size_t>(kRescueTours))
      unfound.push_back(static_cast<int>(k));
  std::vector<char> now_found(tours_.size(), 0);
  pool_.run(static_cast<int>(unfound.size()), [&](int u) {
    const int k = unfound[static_cast<std::size_t>(u)];
    planning::LatticePlanner lattice(work_, cspace_, work_.wheelchair.turning_radius);
    int searches = 0;
    planning::TourHooks hooks;
    if (options_.planner.refuse) hooks.gate = &gate_;
    hooks.stop = stop_;
    hooks.tour = k;
    hooks.local_goals = local_goals_;
    hooks.fallback = [&](const Pose2& from, const Pose2& to) -> std::optional<rs::Path> {
      if (searches++ >= kRescueLegs || (stop_ && stop_->load())) return std::nullopt;
      planning::LatticeResult r = lattice.plan(from, to);
      if (!r.found()) return std::nullopt;
      return std::move(r.path);
    };
    planning::TourPlanner planner(work_, cspace_, tour_options_,
                                  tour_seed(options_.seed, iteration, k), hooks);
    planning::Tour tour = planner.plan((*sequences_)[k].nodes);
    if (tour.found && planning::recheck_tour(cspace_, work_.wheelchair.turning_radius, tour,
                                             nullptr)) {
      tours_[k] = std::move(tour);
      now_found[k] = 1;
    }
  });
  for (std::size_t k = 0; k < tours_.size(); ++k) grade(static_cast<int>(k));
  return static_cast<int>(std::count(now_found.begin(), now_found.end(), 1));
}

}  // namespace hrs::optimize
