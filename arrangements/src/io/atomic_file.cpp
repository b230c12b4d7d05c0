// AtomicFile (see atomic_file.h): a temporary file beside the final path, renamed into place.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace arrangements::detail {
namespace {

std::string system_reason(int err) { return std::generic_category().message(err); }

}  // namespace

AtomicFile::AtomicFile(std::string final_path) : final_(std::move(final_path)) {
  static std::atomic<unsigned> counter{0};
  // O_EXCL: never reuse a file that someone else (another thread, process) is writing.
  for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
    tmp_ = final_ + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno != EEXIST) break;
  }
  if (fd_ < 0) {
    const int err = errno;
    throw std::runtime_error(final_ + ": cannot create a temporary file beside it (" + system_reason(err) + ")");
  }
  buffer_.reserve(kBufferSize);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) ::unlink(tmp_.c_str());
}

void AtomicFile::finish() {
  flush();
  if (::fsync(fd_) != 0 && errno != EINVAL) fail("cannot flush to disk");  // EINVAL: no fsync (pipes, ...)
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("cannot close");
}

void AtomicFile::commit() {
  if (fd_ >= 0) throw std::logic_error(final_ + ": AtomicFile::commit() before finish()");
  if (std::rename(tmp_.c_str(), final_.c_str()) != 0) fail("cannot rename the temporary file into place");
  committed_ = true;
}

void AtomicFile::flush() {
  const char* p = buffer_.data();
  std::size_t left = buffer_.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write failed");
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  buffer_.clear();
}

void AtomicFile::fail(const char* what) const {
  const int err = errno;  // before the message's allocations can change it
  throw std::runtime_error(final_ + ": " + what + " (" + system_reason(err) + ")");
}

}  // namespace arrangements::detail
