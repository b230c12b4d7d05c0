// Starting oneTBB's worker threads where a refusal can be reported (worker_threads.h).
#include "support/worker_threads.h"

#include <pthread.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <string>
#include <vector>

namespace arrangements::detail {
namespace {

// Probe threads wait here until every one has been created (so they all exist at once).
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool open = false;
};

void* wait_at_gate(void* arg) {
  Gate& gate = *static_cast<Gate*>(arg);
  void* volatile block = std::malloc(64);  // as a oneTBB worker allocates: its malloc arena too
  std::free(block);
  std::unique_lock lock(gate.m);
  gate.cv.wait(lock, [&] { return gate.open; });
  return nullptr;
}

// 0 when count threads with oneTBB's stack size could exist at once; else the error of
// the first refused pthread_create.
int probe_threads(int count) {
  pthread_attr_t attr;
  if (int e = pthread_attr_init(&attr)) return e;
  int error = pthread_attr_setstacksize(&attr, tbb::global_control::active_value(tbb::global_control::thread_stack_size));
  Gate gate;
  std::vector<pthread_t> started;
  for (int i = 0; i < count && error == 0; ++i) {
    pthread_t t;
    error = pthread_create(&t, &attr, wait_at_gate, &gate);
    if (error == 0) started.push_back(t);
  }
  pthread_attr_destroy(&attr);
  {
    std::lock_guard lock(gate.m);
    gate.open = true;
  }
  gate.cv.notify_all();
  for (pthread_t t : started) pthread_join(t, nullptr);
  return error;
}

// Makes oneTBB create its n - 1 workers now: n tasks that each wait until n threads run
// one (or a second has passed: oneTBB owes no thread to a loop).
void gather_workers(int n) {
  std::mutex m;
  std::condition_variable cv;
  int joined = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  tbb::task_arena arena(n);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<int>(0, n, 1),
        [&](const tbb::blocked_range<int>&) {
          std::unique_lock lock(m);
          if (++joined == n) cv.notify_all();
          cv.wait_until(lock, deadline, [&] { return joined >= n; });
        },
        tbb::simple_partitioner());
  });
}

const char* g_tool = "arrangements";
int g_threads = 0;
int g_status = 1;

[[noreturn]] void on_terminate() {
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::runtime_error& error) {
      std::fprintf(stderr, "%s: cannot start %d worker threads: %s\n", g_tool, g_threads, error.what());
      std::fflush(stderr);
      _exit(g_status);
    } catch (...) {
    }
  }
  std::abort();
}

}  // namespace

void start_worker_threads(int n) {
  if (n <= 1) return;
  const std::string what = "cannot start " + std::to_string(n) + " worker threads: ";
  if (const int error = probe_threads(n - 1)) throw WorkerThreadsError(what + std::strerror(error));
  try {
    gather_workers(n);
  } catch (const std::runtime_error& e) {  // oneTBB refused a thread in this one
    throw WorkerThreadsError(what + e.what());
  }
}

void exit_on_worker_failure(const char* tool, int n, int status) {
  g_tool = tool;
  g_threads = n;
  g_status = status;
  std::set_terminate(on_terminate);
}

}  // namespace arrangements::detail
