// The one place threads appear: a parallel loop over independent work items, on oneTBB.
//
// Stage code never sees a thread. Work items must be independent (each pixel of a pass is
// owned by exactly one item: a screen tile, or a band of one), so results do not depend on
// the thread count: ThreadPool(1) runs items serially in order and is bit-identical to any
// other count.
#pragma once

#include <functional>
#include <memory>

namespace raster {

class ThreadPool {
 public:
  // threads = 0: every core of the machine.
  explicit ThreadPool(int threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return threads_; }
  // Calls fn(i) for every i in [0, count), in parallel, and returns when all are done.
  void parallelFor(int count, const std::function<void(int)>& fn);
  // Wakes the pool's sleeping helpers now, without waiting for them, so that the next
  // parallelFor finds them running: a helper that slept through a long pause (another
  // renderer's frame, the application's own work) takes tens of microseconds to wake,
  // which a pass's serial start (vertex shading, setup, binning) can hide.
  void wake();

 private:
  int threads_;
  struct Arena;
  std::unique_ptr<Arena> arena_;
};

}  // namespace raster
