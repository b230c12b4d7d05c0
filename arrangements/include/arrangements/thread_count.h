// arrangements/thread_count.h
//
// The worker-thread policy shared by the command-line tools (arrange, tritri-compare) and
// the Python module (tritri.arrange, tritri.MAX_THREADS), and the strict parsing of the
// tools' numeric option values.
//
// Policy: a thread count is an integer from 0 to kMaxThreads (1024); 0 means all cores
// (tbb::info::default_concurrency()). Anything else is a usage error: exit status 2 in the
// tools, ValueError in Python. Why a fixed cap: oneTBB 2021 does not refuse large values
// itself. A task_arena of more than 65535 slots (candidate pairs use one per run) crashes
// with SIGSEGV, 2^31 - 1 fails with bad_alloc, and a global_control limit above the number
// of cores makes oneTBB create that many OS threads (4096 on a 2-core machine: about 3500
// threads and a second of start-up, for no speed-up). When the system refuses a thread
// (ulimit -u or -v, a container's pids limit), oneTBB calls std::terminate (SIGABRT) from
// its thread-creating code, where no caller can catch it; 1024 stays far from the crash and
// well inside common process limits, while allowing more threads than any current machine's
// cores. The tools start their workers up front instead (src/support/worker_threads.h): a
// refused thread is then "cannot start N worker threads: ..." and an error exit status.
//
//   parse_count(text, lo, hi): a command-line integer, strictly: one or more ASCII digits and
//   nothing else (no sign, space, "0x" prefix or suffix), with a value in [lo, hi]
//   (overflow-safe); std::nullopt otherwise.
#pragma once

#include <optional>
#include <string_view>

// The cap as a preprocessor number too, so that usage texts can spell it in literals.
#define ARRANGEMENTS_MAX_THREADS 1024
#define ARRANGEMENTS_STRINGIFY_IMPL(x) #x
#define ARRANGEMENTS_STRINGIFY(x) ARRANGEMENTS_STRINGIFY_IMPL(x)
#define ARRANGEMENTS_MAX_THREADS_STR ARRANGEMENTS_STRINGIFY(ARRANGEMENTS_MAX_THREADS)

namespace arrangements {

inline constexpr int kMaxThreads = ARRANGEMENTS_MAX_THREADS;

constexpr bool valid_thread_count(long long n) { return n >= 0 && n <= kMaxThreads; }

constexpr std::optional<long long> parse_count(std::string_view text, long long lo, long long hi) {
  if (text.empty() || lo > hi || hi < 0) return std::nullopt;
  long long n = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    const int d = c - '0';
    if (n > hi / 10 || n * 10 > hi - d) return std::nullopt;  // n * 10 + d > hi, without overflow
    n = n * 10 + d;
  }
  if (n < lo) return std::nullopt;
  return n;
}

}  // namespace arrangements
