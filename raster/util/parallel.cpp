// ThreadPool on oneTBB: a task_arena capped at the requested concurrency.
#include "raster/util/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace raster {

struct ThreadPool::Arena {
  tbb::task_arena arena;
  explicit Arena(int threads) : arena(threads) {}
};

ThreadPool::ThreadPool(int threads)
    : threads_(threads > 0 ? threads : tbb::info::default_concurrency()), arena_(std::make_unique<Arena>(threads_)) {}

ThreadPool::~ThreadPool() = default;

void ThreadPool::parallelFor(int count, const std::function<void(int)>& fn) {
  if (threads_ == 1 || count <= 1) {
    for (int i = 0; i < count; ++i) fn(i);
    return;
  }
  arena_->arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, count, 1), [&](const tbb::blocked_range<int>& r) {
      for (int i = r.begin(); i < r.end(); ++i) fn(i);
    });
  });
}

}  // namespace raster
