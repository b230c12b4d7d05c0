// arrangements/src/support/process_usage.h
//
// The two measurements the pipeline's statistics report: seconds since a steady-clock
// time point, and the process's peak resident memory in MB (getrusage; Linux reports
// kilobytes). Cost: one system call each.
#pragma once

#include <sys/resource.h>

#include <chrono>

namespace arrangements {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

inline double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

}  // namespace arrangements
