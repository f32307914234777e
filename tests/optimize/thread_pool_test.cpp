// SPDX-License-Identifier: GPL-3.0-or-later
// The tour thread pool: every item runs exactly once, on several threads,
// and an item's exception reaches the caller.
#include "optimize/thread_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>

namespace hrs::optimize {
namespace {

TEST(ThreadPool, EveryItemRunsExactlyOnceForAnyThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.size(), threads);
    for (int round = 0; round < 200; ++round) {
      const int n = round % 13;
      std::vector<std::atomic<int>> hits(n);
      pool.run(n, [&](int i) { hits[i].fetch_add(1); });
      for (int i = 0; i < n; ++i) ASSERT_EQ(hits[i].load(), 1) << threads << " threads";
    }
  }
}

TEST(ThreadPool, UsesMoreThanOneThread) {
  ThreadPool pool(2);
  std::mutex m;
  std::set<std::thread::id> ids;
  for (int round = 0; round < 50 && ids.size() < 2; ++round) {
    pool.run(8, [&](int) {
      volatile double s = 0;
      for (int k = 0; k < 200000; ++k) s = s + k;
      std::lock_guard lock(m);
      ids.insert(std::this_thread::get_id());
    });
  }
  EXPECT_EQ(ids.size(), 2u);
}

TEST(ThreadPool, ExceptionsReachTheCaller) {
  ThreadPool pool(3);
  EXPECT_THROW(pool.run(10,
                        [](int i) {
                          if (i == 7) throw std::runtime_error("item 7");
                        }),
               std::runtime_error);
  int count = 0;
  std::mutex m;
  pool.run(5, [&](int) {
    std::lock_guard lock(m);
    ++count;
  });
  EXPECT_EQ(count, 5);  // still usable
}

}  // namespace
}  // namespace hrs::optimize
