// Small helpers shared by the test programs: a temporary folder per test, running a
// command line with its output captured, and the bytes of binary values.
#pragma once

#include <gtest/gtest.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <iterator>
#include <string>
#include <vector>

extern char** environ;  // the process environment, passed on to spawned programs

namespace tritri_test {

// A fresh folder for the files one test writes, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("arrangements_test_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() { std::filesystem::remove_all(dir_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path path() const { return dir_; }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
    return path(name);
  }
  // The names of the entries of the folder, sorted.
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir_)) names.insert(e.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path dir_;
};

struct CommandRun {
  int status = -1;  // exit status, -1 if it did not exit normally
  std::string out;  // what it wrote on stdout (and stderr if the command redirects it)
};

// Runs `command` with /bin/sh and captures its stdout.
inline CommandRun run_command(const std::string& command) {
  CommandRun r;
  std::FILE* p = popen(command.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int s = pclose(p);
  r.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  return r;
}

// The bytes of a value, little endian (this machine's order) or reversed to big endian:
// for hand-built binary mesh files.
template <class T>
std::string bytes_of(T value, bool big_endian = false) {
  std::string s(sizeof(T), '\0');
  std::memcpy(s.data(), &value, sizeof(T));
  if (big_endian) std::reverse(s.begin(), s.end());
  return s;
}

// How a spawned program ended.
struct Exit {
  bool exited = false;  // ended by exit(), not by a signal
  int code = -1;        // exit status (exited)
  int signal = 0;       // the signal that ended it (!exited)
  std::string out, err;
};

// Runs `program` with exactly `args` (no shell), stdout and stderr captured through files in
// `dir`; a start failure fails the test.
inline Exit spawn(const std::string& program, const std::vector<std::string>& args,
                  const std::filesystem::path& dir) {
  std::vector<std::string> all{program};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  Exit e;
  pid_t pid = 0;
  const int started = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) {
    ADD_FAILURE() << "cannot start " << program;
    return e;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  e.exited = WIFEXITED(status);
  e.code = e.exited ? WEXITSTATUS(status) : -1;
  e.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  auto slurp = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  e.out = slurp(out);
  e.err = slurp(err);
  return e;
}

}  // namespace tritri_test
