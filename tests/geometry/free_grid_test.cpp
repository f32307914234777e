// SPDX-License-Identifier: GPL-3.0-or-later
// FreeGrid: a blocked cell holds only colliding poses (by the exact CGAL
// reference, which shares nothing with the grid), a certified-free pose never
// lies in a blocked cell, incremental moves equal a rebuild, and analytic
// passages: a gap narrower than the chair separates the room, a wide one
// does not. The column masks and ReachableSet (the fill over whole columns
// of slices, its chamfer distance) against brute force: a plain BFS over the
// cells with blocked() and 26 neighbours, and Dijkstra over the columns.

#include "geometry/free_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "geometry/cspace.h"
#include "tests/support/poses.h"
#include "tests/support/reference.h"
#include "tests/support/scenes.h"

namespace hrs::geometry {
namespace {

using hrs::uniform01;
using hrs::test_support::ExactReference;
using hrs::test_support::split_room;

//! The scenes under test: the L-shaped room and every shipped scene, each
//! also with its movable objects displaced at random (overlaps allowed).
std::vector<Scene> test_scenes(std::mt19937_64& rng) {
  std::vector<Scene> out{hrs::test_support::l_shaped_scene()};
  for (const std::string& f : hrs::test_support::scene_files()) out.push_back(load_scene(f));
  const std::size_t n = out.size();
  for (std::size_t i = 0; i < n; ++i) {
    Scene s = out[i];
    for (Object& o : s.objects) {
      if (o.fixed) continue;
      o.pose.x += 0.6 * (2 * uniform01(rng) - 1);
      o.pose.y += 0.6 * (2 * uniform01(rng) - 1);
      o.pose.theta += 0.8 * (2 * uniform01(rng) - 1);
    }
    out.push_back(std::move(s));
  }
  return out;
}

//! A uniformly random pose in the closed cell.
Pose2 pose_in_cell(const FreeGrid& g, std::size_t cell, std::mt19937_64& rng) {
  const Pose2 c = g.centre(cell);
  return {c.x + g.hx() * (uniform01(rng) - 0.5), c.y + g.hy() * (uniform01(rng) - 0.5),
          c.theta + g.slice_width() * (uniform01(rng) - 0.5)};
}

//! True if a 26-neighbour of the cell is not blocked (the cell is on the
//! border of the blocked region, where the test is tightest).
bool on_border(const FreeGrid& g, std::size_t cell) {
  int ix, iy, k;
  g.coords(cell, ix, iy, k);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      for (int dk = -1; dk <= 1; ++dk) {
        const int x = ix + dx, y = iy + dy, kk = (k + dk + g.slices()) % g.slices();
        if (x < 0 || y < 0 || x >= g.nx() || y >= g.ny()) continue;
        if (!g.blocked(g.index(x, y, kk))) return true;
      }
  return false;
}

TEST(FreeGrid, BlockedBorderCellsHoldOnlyCollidingPosesByExactReference) {
  std::mt19937_64 rng(20261122);
  int checked = 0;
  for (const Scene& scene : test_scenes(rng)) {
    const FreeGrid grid(scene);
    const ExactReference ref(scene);
    ASSERT_GT(grid.blocked_count(), 0u) << scene.name;
    // 400 border cells per scene, one or two random poses each, plus the
    // cell's corners at both heading ends (the extreme poses).
    int found = 0;
    for (int tries = 0; found < 400 && tries < 4'000'000; ++tries) {
      const std::size_t cell = rng() % grid.cell_count();
      if (!grid.blocked(cell) || !on_border(grid, cell)) continue;
      ++found;
      const Pose2 c = grid.centre(cell);
      const double sx[2] = {-0.5, 0.5}, st[2] = {-0.5, 0.5};
      std::vector<Pose2> poses{pose_in_cell(grid, cell, rng)};
      if (found % 4 == 0) {
        for (double a : sx)
          for (double b : sx)
            for (double t : st)
              poses.push_back(
                  {c.x + a * grid.hx(), c.y + b * grid.hy(), c.theta + t * grid.slice_width()});
      }
      for (const Pose2& p : poses) {
        ++checked;
        ASSERT_FALSE(ref.pose_free(p)) << scene.name << ": pose (" << p.x << ", " << p.y << ", "
                                       << p.theta << ") in a blocked cell is free";
      }
    }
    EXPECT_EQ(found, 400) << scene.name;
  }
  EXPECT_GT(checked, 6000);
}

TEST(FreeGrid, CertifiedFreePosesNeverLieInBlockedCells) {
  std::mt19937_64 rng(7);
  for (const Scene& scene : test_scenes(rng)) {
    const FreeGrid grid(scene);
    const CSpace cspace(scene);
    int free_poses = 0;
    for (int i = 0; i < 100'000; ++i) {
      const Pose2 p = hrs::test_support::random_pose(scene, rng);
      if (!cspace.is_free(p)) continue;
      ++free_poses;
      ASSERT_FALSE(grid.blocked(grid.cell_of(p)))
          << scene.name << ": free pose (" << p.x << ", " << p.y << ", " << p.theta << ")";
    }
    EXPECT_GT(free_poses, 300) << scene.name;
  }
}

TEST(FreeGrid, MostCollidingPosesAreInBlockedCells) {
  // Tightness, not soundness: the grid must not be vacuous. A pose that
  // collides by more than the core's margin lies in a blocked cell, so
  // blocked cells hold the large majority of the colliding poses.
  std::mt19937_64 rng(11);
  const Scene scene = load_scene(hrs::test_support::scene_files().front());
  const FreeGrid grid(scene);
  const ExactReference ref(scene);
  int colliding = 0, blocked = 0;
  for (int i = 0; i < 3000; ++i) {
    const Pose2 p = hrs::test_support::random_pose(scene, rng);
    if (ref.pose_free(p)) continue;
    ++colliding;
    blocked += grid.blocked(grid.cell_of(p)) ? 1 : 0;
  }
  ASSERT_GT(colliding, 500);
  EXPECT_GT(static_cast<double>(blocked) / colliding, 0.9) << blocked << " / " << colliding;
  std::printf("colliding poses in blocked cells: %d / %d\n", blocked, colliding);
}

TEST(FreeGrid, IncrementalMovesEqualRebuild) {
  std::mt19937_64 rng(3);
  Scene scene = hrs::test_support::l_shaped_scene();
  FreeGrid grid(scene, {0.05, 72});
  for (int step = 0; step < 60; ++step) {
    const int i = static_cast<int>(rng() % scene.objects.size());
    Pose2& p = scene.objects[i].pose;
    p.x = 0.5 + 5.0 * uniform01(rng), p.y = 0.5 + 5.0 * uniform01(rng);
    if (step % 2 == 0) p.theta = std::numbers::pi * (2 * uniform01(rng) - 1);
    grid.move_object(i, p);
    if (step % 10 != 9) continue;
    const FreeGrid fresh(scene, {0.05, 72});
    ASSERT_EQ(grid.blocked_count(), fresh.blocked_count());
    for (std::size_t c = 0; c < grid.cell_count(); ++c)
      ASSERT_EQ(grid.blocked(c), fresh.blocked(c)) << "cell " << c << " after step " << step;
  }
}

TEST(ReachabilityQuery, GapNarrowerThanTheChairSeparatesTheRoom) {
  // The chair is 0.65 m wide: no pose with its centre at x = 3 fits a
  // 0.55 m gap, so the halves are disconnected; a 1.5 m gap joins them.
  ReachabilityQuery q;
  const Pose2 left{1.0, 1.5, 0.3}, right{5.0, 1.0, -2.0};
  for (double gap : {0.4, 0.55}) {
    const FreeGrid grid(split_room(gap));
    EXPECT_EQ(q.query(grid, left, right), ReachabilityQuery::Answer::kDisconnected) << gap;
    EXPECT_EQ(q.query(grid, right, left), ReachabilityQuery::Answer::kDisconnected) << gap;
    EXPECT_EQ(q.query(grid, left, Pose2{1.5, 2.0, 2.5}), ReachabilityQuery::Answer::kConnected);
  }
  const FreeGrid wide(split_room(1.5));
  EXPECT_EQ(q.query(wide, left, right), ReachabilityQuery::Answer::kConnected);
}

TEST(ReachabilityQuery, BlockedEndIsUnknownAndBudgetIsRespected) {
  const FreeGrid grid(split_room(1.5));
  ReachabilityQuery q;
  // Centre inside the partition: the end cell is blocked.
  EXPECT_EQ(q.query(grid, Pose2{3.0, 0.5, 0.0}, Pose2{1.0, 1.5, 0.0}),
            ReachabilityQuery::Answer::kUnknown);
  EXPECT_EQ(q.query(grid, Pose2{1.0, 1.5, 0.3}, Pose2{5.0, 1.0, -2.0}, 1000),
            ReachabilityQuery::Answer::kUnknown);
  EXPECT_LE(q.visited(), 1000u + 27u);
}


// ---------------------------------------------------------------------------
// Column masks and ReachableSet against brute force.

//! Every cell joined to `start`'s cell by unblocked cells, by a plain BFS
//! over the cells with blocked() and the 26 neighbours (heading wraps).
std::vector<char> brute_reach(const FreeGrid& g, const Pose2& start) {
  std::vector<char> seen(g.cell_count(), 0);
  const std::size_t s = g.cell_of(start);
  if (g.blocked(s)) return seen;
  std::vector<std::size_t> queue{s};
  seen[s] = 1;
  const int n = g.slices();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    int ix, iy, k;
    g.coords(queue[head], ix, iy, k);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        for (int dk = -1; dk <= 1; ++dk) {
          const int x = ix + dx, y = iy + dy, kk = ((k + dk) % n + n) % n;
          if (x < 0 || y < 0 || x >= g.nx() || y >= g.ny()) continue;
          const std::size_t c = g.index(x, y, kk);
          if (seen[c] || g.blocked(c)) continue;
          seen[c] = 1;
          queue.push_back(c);
        }
  }
  return seen;
}

//! Dijkstra over the nx × ny columns (through blocked ones too) with the
//! 8-neighbour weights hx, hy, hypot(hx, hy), from every source column.
std::vector<double> brute_distance(const FreeGrid& g, const std::vector<char>& source) {
  const int nx = g.nx(), ny = g.ny();
  const double hd = std::hypot(g.hx(), g.hy());
  std::vector<double> d(source.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  for (std::size_t c = 0; c < source.size(); ++c)
    if (source[c]) d[c] = 0.0, pq.push({0.0, c});
  while (!pq.empty()) {
    const auto [dc, c] = pq.top();
    pq.pop();
    if (dc > d[c]) continue;
    const int ix = static_cast<int>(c % nx), iy = static_cast<int>(c / nx);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const int x = ix + dx, y = iy + dy;
        if (x < 0 || y < 0 || x >= nx || y >= ny) continue;
        const double w = dx == 0 ? g.hy() : dy == 0 ? g.hx() : hd;
        const std::size_t m = static_cast<std::size_t>(y) * nx + x;
        if (dc + w < d[m]) d[m] = dc + w, pq.push({d[m], m});
      }
  }
  return d;
}

//! Bit k of every column's mask is !blocked(cell (column, k)); no bit at or
//! above slices() is set. Returns the number of cells checked.
std::size_t expect_masks_match(const FreeGrid& g, const std::string& what) {
  EXPECT_TRUE(g.has_column_masks()) << what;
  const std::size_t columns = static_cast<std::size_t>(g.nx()) * g.ny();
  const int n = g.slices();
  for (std::size_t c = 0; c < columns; ++c) {
    const std::uint64_t m = g.free_slices(c);
    if (n < 64) {
      EXPECT_EQ(m >> n, 0u) << what << ": column " << c << " has bits past the ring";
    }
    for (int k = 0; k < n; ++k) {
      const bool free_bit = (m >> k) & 1;
      if (free_bit == g.blocked(c * n + k)) {
        ADD_FAILURE() << what << ": column " << c << " slice " << k << ": mask "
                      << free_bit << ", blocked " << g.blocked(c * n + k);
        return 0;
      }
    }
  }
  return columns * n;
}

//! Scene files plus a 6 × 0.7 m corridor (the chair, 0.65 m wide and 1.1 m
//! long, cannot turn in it: headings near ±π are joined only through the
//! ring's wrap).
std::vector<Scene> reach_scenes() {
  std::vector<Scene> out;
  for (const std::string& f : hrs::test_support::scene_files()) out.push_back(load_scene(f));
  out.push_back(hrs::test_support::l_shaped_scene());
  Scene corridor = hrs::test_support::empty_room(6.0, 0.7);
  corridor.name = "corridor";
  out.push_back(corridor);
  return out;
}

//! Moves 1–3 objects of `scene` (and the grid): anywhere in the room's box
//! with any heading, or a nudge (overlaps allowed; fixed objects too).
void random_moves(Scene& scene, FreeGrid& grid, std::mt19937_64& rng) {
  if (scene.objects.empty()) return;
  const int moves = 1 + static_cast<int>(rng() % 3);
  for (int m = 0; m < moves; ++m) {
    const int i = static_cast<int>(rng() % scene.objects.size());
    Pose2 p = scene.objects[i].pose;
    if (uniform01(rng) < 0.5) {
      p = hrs::test_support::random_pose(scene, rng);
    } else {
      p.x += 0.5 * (2 * uniform01(rng) - 1);
      p.y += 0.5 * (2 * uniform01(rng) - 1);
      p.theta = wrap_angle(p.theta + 0.7 * (2 * uniform01(rng) - 1));
    }
    scene.objects[i].pose = p;
    grid.move_object(i, p);
  }
}

TEST(FreeGridColumns, MasksAreNotBlockedPerCellAfterRandomMovesAndEqualARebuild) {
  std::mt19937_64 rng(424242);
  std::size_t cells = 0;
  for (const FreeGridOptions opt :
       {FreeGridOptions{0.1, 16}, FreeGridOptions{0.1, 37}, FreeGridOptions{0.08, 64}}) {
    for (Scene scene : reach_scenes()) {
      FreeGrid grid(scene, opt);
      const std::string what = scene.name + " slices " + std::to_string(opt.slices);
      cells += expect_masks_match(grid, what + " initial");
      for (int step = 0; step < 12; ++step) {
        random_moves(scene, grid, rng);
        cells += expect_masks_match(grid, what + " step " + std::to_string(step));
        if (step % 4 != 3) continue;
        const FreeGrid fresh(scene, opt);
        const std::size_t columns = static_cast<std::size_t>(grid.nx()) * grid.ny();
        for (std::size_t c = 0; c < columns; ++c)
          ASSERT_EQ(grid.free_slices(c), fresh.free_slices(c)) << what << " column " << c;
      }
    }
  }
  EXPECT_GT(cells, 5'000'000u);
}

TEST(FreeGridColumns, MoreThan64SlicesHaveNoMasksAndCannotBeFilled) {
  const FreeGrid grid(hrs::test_support::l_shaped_scene(), {0.1, 65});
  EXPECT_FALSE(grid.has_column_masks());
  ReachableSet reach;
  EXPECT_THROW(reach.fill(grid, {1.5, 1.5, 0.0}), std::invalid_argument);
  const FreeGrid ok(hrs::test_support::l_shaped_scene(), {0.1, 64});
  EXPECT_TRUE(ok.has_column_masks());
  EXPECT_EQ(ok.column_of({1.53, 2.71, 1.0}), ok.cell_of({1.53, 2.71, 1.0}) / 64);
}

TEST(ReachableSet, EqualsBruteForceBfsAndDijkstraOnRandomLayoutsAndStarts) {
  std::mt19937_64 rng(20261123);
  int fills = 0, empty = 0, partial = 0, wrapped = 0;
  std::size_t cells = 0;
  for (const FreeGridOptions opt :
       {FreeGridOptions{0.1, 16}, FreeGridOptions{0.1, 37}, FreeGridOptions{0.08, 64}}) {
    for (Scene scene : reach_scenes()) {
      FreeGrid grid(scene, opt);
      const int n = grid.slices();
      const std::size_t columns = static_cast<std::size_t>(grid.nx()) * grid.ny();
      for (int layout = 0; layout < 4; ++layout) {
        if (layout > 0) random_moves(scene, grid, rng);
        // Starts: the door's pose, poses inside random unblocked cells, and
        // one uniform pose in the room's box (often in a blocked cell).
        std::vector<Pose2> starts{door_start_pose(scene), hrs::test_support::random_pose(scene, rng)};
        for (int tries = 0; starts.size() < 5 && tries < 100'000; ++tries) {
          const std::size_t c = rng() % grid.cell_count();
          if (!grid.blocked(c)) starts.push_back(pose_in_cell(grid, c, rng));
        }
        for (const Pose2& start : starts) {
          const std::string what = scene.name + " slices " + std::to_string(n) + " layout " +
                                   std::to_string(layout) + " start (" + std::to_string(start.x) +
                                   ", " + std::to_string(start.y) + ", " +
                                   std::to_string(start.theta) + ")";
          ReachableSet reach;
          reach.fill(grid, start);
          ++fills;
          const std::vector<char> want = brute_reach(grid, start);
          std::vector<char> column_want(columns, 0);
          std::size_t reached = 0, unblocked = 0;
          for (std::size_t c = 0; c < grid.cell_count(); ++c) {
            const Pose2 centre = grid.centre(c);
            ASSERT_EQ(grid.cell_of(centre), c) << what;
            ASSERT_EQ(reach.contains(centre), want[c] != 0)
                << what << ": cell " << c << " (centre " << centre.x << ", " << centre.y << ", "
                << centre.theta << ")";
            if (want[c]) column_want[c / n] = 1, ++reached;
            unblocked += grid.blocked(c) ? 0 : 1;
          }
          cells += grid.cell_count();
          // A reached column whose reached slices include both ring ends.
          for (std::size_t col = 0; col < columns && want[grid.cell_of(start)]; ++col)
            if (want[col * n] && want[col * n + n - 1] && !want[col * n + n / 2]) {
              ++wrapped;
              break;
            }
          empty += reached == 0 ? 1 : 0;
          partial += reached > 0 && reached < unblocked ? 1 : 0;
          const std::size_t reached_columns =
              static_cast<std::size_t>(std::count(column_want.begin(), column_want.end(), 1));
          EXPECT_DOUBLE_EQ(reach.column_share(),
                           static_cast<double>(reached_columns) / static_cast<double>(columns))
              << what;
          const std::vector<double> dist = brute_distance(grid, column_want);
          for (std::size_t col = 0; col < columns; ++col) {
            // A pose anywhere in the column (any heading).
            Pose2 p = pose_in_cell(grid, col * n + rng() % n, rng);
            ASSERT_EQ(grid.column_of(p), col) << what;
            ASSERT_EQ(reach.column_reached(p), column_want[col] != 0) << what << " column " << col;
            const double d = reach.distance_to(p);
            if (std::isinf(dist[col])) {
              ASSERT_TRUE(std::isinf(d) && d > 0) << what << " column " << col << ": " << d;
            } else {
              ASSERT_NEAR(d, dist[col], 1e-9) << what << " column " << col;
            }
          }
        }
      }
    }
  }
  std::printf("fills %d: empty %d, partial %d, reaching both ring ends %d; %zu cells compared\n",
              fills, empty, partial, wrapped, cells);
  // The cases the comparison must have covered.
  EXPECT_GT(empty, 10);
  EXPECT_GT(partial, 100);
  EXPECT_GT(wrapped, 15);
}

TEST(ReachableSet, InACorridorTooNarrowToTurnHeadingsJoinOnlyAcrossTheRingsWrap) {
  // The chair (1.1 × 0.65 m) cannot turn round in a 0.7 m corridor: from a
  // heading just below π it reaches headings just above −π (the neighbour
  // slice across the wrap), and never heading 0 or ±π/2.
  const Scene corridor = hrs::test_support::empty_room(6.0, 0.7);
  for (const FreeGridOptions opt :
       {FreeGridOptions{0.1, 16}, FreeGridOptions{0.1, 37}, FreeGridOptions{0.08, 64}}) {
    const FreeGrid grid(corridor, opt);
    const double half = 0.5 * grid.slice_width();
    ReachableSet reach;
    reach.fill(grid, {3.0, 0.35, std::numbers::pi - half});
    EXPECT_TRUE(reach.contains({3.0, 0.35, std::numbers::pi - half})) << opt.slices;
    EXPECT_TRUE(reach.contains({1.5, 0.35, -std::numbers::pi + half})) << opt.slices;
    EXPECT_TRUE(reach.contains({4.5, 0.35, -std::numbers::pi + half})) << opt.slices;
    EXPECT_FALSE(reach.contains({3.0, 0.35, 0.0})) << opt.slices;
    EXPECT_FALSE(reach.contains({3.0, 0.35, std::numbers::pi / 2})) << opt.slices;
    EXPECT_FALSE(reach.contains({3.0, 0.35, -std::numbers::pi / 2})) << opt.slices;
    EXPECT_EQ(reach.distance_to({3.0, 0.35, 0.0}), 0.0) << opt.slices;
    ReachableSet forward;
    forward.fill(grid, {3.0, 0.35, half});
    EXPECT_TRUE(forward.contains({5.0, 0.35, -half})) << opt.slices;
    EXPECT_FALSE(forward.contains({3.0, 0.35, std::numbers::pi - half})) << opt.slices;
  }
}

TEST(ReachableSet, BlockedStartReachesNothingAndEveryDistanceIsInfinite) {
  const Scene scene = hrs::test_support::l_shaped_scene();
  const FreeGrid grid(scene, {0.1, 16});
  ReachableSet reach;
  // Centre in the middle of the table: every heading collides.
  const Pose2 start{1.2, 4.2, 0.3};
  ASSERT_TRUE(grid.blocked(grid.cell_of(start)));
  reach.fill(grid, start);
  EXPECT_FALSE(reach.contains(start));
  EXPECT_EQ(reach.column_share(), 0.0);
  for (std::size_t col = 0; col < static_cast<std::size_t>(grid.nx()) * grid.ny(); col += 7) {
    const Pose2 p = grid.centre(col * grid.slices());
    EXPECT_FALSE(reach.column_reached(p));
    EXPECT_TRUE(std::isinf(reach.distance_to(p)));
  }
  // A default-constructed set holds nothing either.
  const ReachableSet none;
  EXPECT_FALSE(none.contains({1.0, 1.0, 0.0}));
  EXPECT_TRUE(std::isinf(none.distance_to({1.0, 1.0, 0.0})));
}

}  // namespace
}  // namespace hrs::geometry
