// arrangements/src/io/atomic_file.h (internal to the mesh writers)
//
// AtomicFile: the one way this project writes a file that others may read: the bytes go
// to a new temporary file beside the final path and are renamed into place once complete.
//
//   AtomicFile f(path);   creates ".tritri-XXXXXX" (6 random letters and digits) in the
//                         folder of path (O_EXCL: never a file that another thread or
//                         process is writing): a short name of its own, so that any path
//                         the system takes (a name of up to NAME_MAX bytes) can be written
//   f.append(bytes)       buffered (1 MiB) writes; pieces of 64 KiB or more are written
//                         directly, after what is buffered
//   f.finish()            writes what is buffered; gives the file the permission bits of
//                         the file at path when there is one (else it has 0666 minus the
//                         umask, as any new file); closes it
//   f.commit()            renames the temporary file to path (after finish())
//   ~AtomicFile()         removes the temporary file unless commit() succeeded
//
// Guarantees (towards other readers, and if this process fails): path holds either what it
// held before or every byte appended, never a part of them; an old file at path is replaced
// only by a successful commit(); after a failure (an exception from any call, or no
// commit()) the temporary file is removed once the AtomicFile is destroyed. Not synced to
// disk (no fsync, as cp and the peers' tools: 1.8 ms per file, a third of a small Boolean's
// output stage): after a crash of the whole system, some file systems may show the new file
// empty or partial (ext4 and btrfs write the data before a rename over an old file).
//
// Errors: std::runtime_error naming the final path, what failed and the system's reason:
//   "PATH: cannot create a temporary file beside it (REASON)"
//   "PATH: write failed (REASON)",
//   "PATH: cannot close (REASON)", "PATH: cannot rename the temporary file into place (REASON)",
//   "PATH: cannot give the temporary file the mode of the file it replaces (REASON)"
// (REASON: std::generic_category().message(errno), e.g. "No such file or directory").
// commit() before finish() is a programming error: std::logic_error.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace arrangements::detail {

class AtomicFile {
 public:
  explicit AtomicFile(std::string final_path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  void append(std::string_view bytes) {
    if (bytes.size() >= kDirectSize) {  // a chunk formatted apart: written as it is, not copied
      flush();
      write_all(bytes);
      return;
    }
    buffer_.append(bytes);
    if (buffer_.size() >= kBufferSize) flush();
  }
  void append(char c) {
    buffer_.push_back(c);
    if (buffer_.size() >= kBufferSize) flush();
  }
  void finish();
  void commit();
  const std::string& final_path() const { return final_; }

 private:
  static constexpr std::size_t kBufferSize = std::size_t{1} << 20;
  static constexpr std::size_t kDirectSize = std::size_t{1} << 16;

  void flush();
  void write_all(std::string_view bytes);
  [[noreturn]] void fail(const char* what) const;

  std::string final_, tmp_;
  int fd_ = -1;
  std::string buffer_;
  bool committed_ = false;
};

}  // namespace arrangements::detail
