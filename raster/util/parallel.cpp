// ThreadPool: on oneTBB (a task_arena capped at the requested concurrency), or, in the
// ThreadSanitizer build (RASTER_STD_THREADS), on plain std::threads that the sanitizer sees
// whole: oneTBB from Debian is not instrumented, so its own synchronisation would be
// invisible to ThreadSanitizer and every hand-off through it a false report. Both run each
// item once on some thread; items are independent, so the output is the same.
#include "raster/util/parallel.h"

#if RASTER_STD_THREADS
#include <atomic>
#include <thread>
#include <vector>
#else
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace raster {

#if RASTER_STD_THREADS

struct ThreadPool::Arena {};

ThreadPool::ThreadPool(int threads)
    : threads_(threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()))) {}

ThreadPool::~ThreadPool() = default;

void ThreadPool::wake() {}   // each parallelFor starts its own threads

// Fork-join per call: the workers take items from a shared counter until none are left.
void ThreadPool::parallelFor(int count, const std::function<void(int)>& fn) {
  if (threads_ == 1 || count <= 1) {
    for (int i = 0; i < count; ++i) fn(i);
    return;
  }
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i = next++; i < count; i = next++) fn(i);
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < std::min(threads_, count); ++t) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
}

#else

// oneTBB admits as many workers as the machine has cores unless told otherwise: an arena
// asked for more (--threads 16 on 2 cores, as llvmpipe's LP_NUM_THREADS=16 runs 16) would run
// on fewer and print a warning on stderr. The limit is process-wide, so it is raised to the
// largest pool made so far and never lowered: an arena is still capped at its own count.
static void admitWorkersFor(int threads) {
  static std::mutex mutex;
  static std::unique_ptr<tbb::global_control> limit;
  const std::lock_guard<std::mutex> lock(mutex);
  if (size_t(threads) <= tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)) return;
  limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(threads));
}

struct ThreadPool::Arena {
  tbb::task_arena arena;
  explicit Arena(int threads) : arena(threads) { admitWorkersFor(threads); }
};

ThreadPool::ThreadPool(int threads)
    : threads_(threads > 0 ? threads : tbb::info::default_concurrency()), arena_(std::make_unique<Arena>(threads_)) {}

ThreadPool::~ThreadPool() = default;

// An empty task enqueued into the arena: a helper wakes to run it, then looks for more
// work for a while before it sleeps again.
void ThreadPool::wake() {
  if (threads_ > 1) arena_->arena.enqueue([] {});
}

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

#endif

}  // namespace raster
