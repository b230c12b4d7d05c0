// arrangements/src/io/standard_output.h (internal to the command-line tools)
//
// Output to stdout that cannot be written is an error, never lost in silence (a full
// device, a closed stdout, a pipe that failed):
//   keep_standard_streams_open()   first thing in main: a standard stream (0, 1, 2) that
//                                  is closed gets /dev/null in its place, opened so that
//                                  writes to stdout still fail (read-only: EBADF, as on a
//                                  closed descriptor), so no file the program opens takes
//                                  descriptor 1 and receives what is meant for stdout
//   finish_standard_output(tool, status)
//                                  last thing in main: flushes stdout; if that or any
//                                  earlier write to it failed, prints "TOOL: cannot write
//                                  to standard output (REASON)" on stderr and returns
//                                  failure_status, the tool's status for an error (the
//                                  output is lost, whatever else happened); else status
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace arrangements::detail {

inline void keep_standard_streams_open() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    // The lowest free descriptor is fd (the ones below are open by now).
    const int opened = ::open("/dev/null", fd == 2 ? O_WRONLY : O_RDONLY);
    if (opened >= 0 && opened != fd) ::close(opened);
  }
}

// failure_status: arrange 1, tritri-compare 2 (its 1 means the classifiers disagree).
inline int finish_standard_output(const char* tool, int status, int failure_status) {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int err = errno;
  if (flushed && !std::ferror(stdout)) return status;
  if (err != 0)
    std::fprintf(stderr, "%s: cannot write to standard output (%s)\n", tool, std::strerror(err));
  else
    std::fprintf(stderr, "%s: cannot write to standard output\n", tool);
  return failure_status;
}

}  // namespace arrangements::detail
