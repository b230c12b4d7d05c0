// arrangements/src/support/worker_threads.h (internal: the arrange tool; usable by any
// caller that sets a oneTBB thread limit)
//
// Starting oneTBB's worker threads where a refusal can be reported. oneTBB creates its
// workers lazily, at the first parallel loop, and they start each other: when the system
// refuses a thread (ulimit -u, ulimit -v, a container's pids limit), oneTBB throws from the
// worker that was creating it, which ends in std::terminate (SIGABRT) where no caller can
// catch anything.
//
// void start_worker_threads(n)
//   n   the threads a run uses (the caller's tbb::global_control max_allowed_parallelism),
//       1 to kMaxThreads (thread_count.h); 1 starts nothing
//   First probes that the system gives n - 1 more threads at once, each with oneTBB's
//   stack size and each allocating as a oneTBB worker does (so that the allocator's
//   per-thread arenas are counted too); then, while that still holds, makes oneTBB start
//   its n - 1 workers (a task_arena of n slots whose tasks wait, at most a second, until n
//   threads have joined). oneTBB keeps its workers for the rest of the process, so later
//   parallel loops (of the same limit) create no thread.
//   Throws WorkerThreadsError, "cannot start N worker threads: REASON" (REASON: the
//   system's, e.g. "Resource temporarily unavailable"), when the probe is refused; nothing
//   is left running then.
//   Cost: n - 1 thread creations twice (about 50 microseconds each).
//
// void exit_on_worker_failure(tool, n, status)
//   Installs a std::terminate handler for what no probe can rule out (the system refusing
//   a thread later): an uncaught std::runtime_error (what oneTBB throws when a thread cannot
//   be created) prints "TOOL: cannot start N worker threads: WHAT" on stderr and ends the
//   process with exit status `status` (_exit: no cleanup runs; nothing has been written by
//   then in the tools, whose output files are written after the parallel stages,
//   atomically). Any other termination aborts as before (a programming error keeps its
//   core dump). tool must outlive the process (a string literal).
#pragma once

#include <stdexcept>
#include <string>

namespace arrangements::detail {

struct WorkerThreadsError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void start_worker_threads(int n);

void exit_on_worker_failure(const char* tool, int n, int status);

}  // namespace arrangements::detail
