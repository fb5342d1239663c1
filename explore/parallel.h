// Runs n independent tasks on worker threads. Each task writes only its own
// result slot, so the results do not depend on the number of threads or on
// which thread ran what: the same bits with 1 thread or 64.
#pragma once

#include <cstddef>
#include <functional>

namespace afford {

// Calls task(i) for every i in [0, n) on `threads` threads (at least one;
// the calling thread only waits and reports). `progress(done, n)` is called
// on the calling thread about every `every_s` seconds and once at the end.
// The first exception a task throws stops the others from starting new
// tasks and is rethrown here.
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& task,
                  const std::function<void(std::size_t, std::size_t)>& progress = {}, double every_s = 0.2);

// The number of threads to use when none is asked for: every core.
int default_threads();

}  // namespace afford
