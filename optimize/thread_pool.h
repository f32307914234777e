// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A small fixed pool of worker threads for the M tours of one annealing
// iteration (paper §III-E plans M = 10 tours per layout; docs/design-notes.md wants them
// in parallel). run(n, fn) calls fn(0) … fn(n−1) once each, spread over the
// workers and the calling thread, and returns when all are done. Work items
// must write only their own outputs; then results do not depend on the
// number of threads.

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace hrs::optimize {

class ThreadPool {
 public:
  //! `threads` in total, the caller included (<= 0: all hardware threads).
  explicit ThreadPool(int threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  //! Threads used by run(), the caller included.
  int size() const { return static_cast<int>(workers_.size()) + 1; }
  //! Runs fn(i) for i in [0, n); rethrows the first exception of an item.
  void run(int n, const std::function<void(int)>& fn);

 private:
  void work_loop();
  void drain(std::unique_lock<std::mutex>& lock);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int)>* job_ = nullptr;
  int count_ = 0;
  int next_ = 0;
  int running_ = 0;  //!< items started and not finished
  unsigned generation_ = 0;
  bool quit_ = false;
  std::exception_ptr error_;
};

}  // namespace hrs::optimize
