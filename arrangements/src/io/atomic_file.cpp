// AtomicFile (see atomic_file.h): a temporary file beside the final path, renamed into place.
#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace arrangements::detail {
namespace {

std::string system_reason(int err) { return std::generic_category().message(err); }

// splitmix64: scrambles a counter into well-spread bits.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// ".tritri-" and 6 letters and digits: differs between threads (counter), processes
// (pid) and runs (clock); O_EXCL settles any collision that is left.
std::string temporary_name() {
  static std::atomic<std::uint64_t> counter{0};
  static constexpr char kChars[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  const auto now = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  std::uint64_t bits = mix(mix(counter++) ^ mix(static_cast<std::uint64_t>(::getpid())) ^ now);
  std::string name = ".tritri-";
  for (int i = 0; i < 6; ++i, bits /= 62) name += kChars[bits % 62];
  return name;
}

}  // namespace

AtomicFile::AtomicFile(std::string final_path) : final_(std::move(final_path)) {
  // In the folder of the final path (rename works within one file system).
  const std::size_t slash = final_.rfind('/');
  const std::string folder = slash == std::string::npos ? std::string() : final_.substr(0, slash + 1);
  // O_EXCL: never reuse a file that someone else (another thread, process) is writing.
  for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
    tmp_ = folder + temporary_name();
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
  // Replacing a file keeps its permission bits (not set-user-ID and the like).
  struct stat old {};
  if (::stat(final_.c_str(), &old) == 0 && S_ISREG(old.st_mode) && ::fchmod(fd_, old.st_mode & 0777) != 0)
    fail("cannot give the temporary file the mode of the file it replaces");
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
  write_all(buffer_);
  buffer_.clear();
}

void AtomicFile::write_all(std::string_view bytes) {
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write failed");
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

void AtomicFile::fail(const char* what) const {
  const int err = errno;  // before the message's allocations can change it
  throw std::runtime_error(final_ + ": " + what + " (" + system_reason(err) + ")");
}

}  // namespace arrangements::detail
