// tests/support/run_program.h
//
// Running the project's programs from a test: run_command (a shell command line, stdout
// captured), spawn (a program with exact arguments, no shell, stdout and stderr captured,
// with how it ended: exit code or signal) and spawn_limited (the same under an
// address-space limit, with its wall time and peak resident memory).
#pragma once

#include <gtest/gtest.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern char** environ;  // the process environment, passed on to spawned programs

namespace tritri_test {

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

// How a spawned program ended.
struct Exit {
  bool exited = false;  // ended by exit(), not by a signal
  int code = -1;        // exit status (exited)
  int signal = 0;       // the signal that ended it (!exited)
  std::string out, err;
};

// Runs `program` with exactly `args` (no shell), stdout and stderr captured through files in
// `dir`; a start failure fails the test.
inline Exit spawn(const std::string& program, const std::vector<std::string>& args, const std::filesystem::path& dir) {
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

// How a program run by spawn_limited ended, and what it cost.
struct LimitedExit {
  Exit exit;
  double seconds = 0;      // wall time from start to end
  long peak_rss_kb = 0;    // its peak resident memory (wait4's ru_maxrss)
};

// spawn, with the program's address space (RLIMIT_AS) limited to address_space_bytes (a
// memory allocation beyond it fails, as a thread stack does), measured on its own
// (wait4). fork + exec: between them only async-signal-safe calls. The peak memory
// includes what the calling process holds when it forks (the child starts as its copy):
// free large buffers before measuring.
inline LimitedExit spawn_limited(const std::string& program, const std::vector<std::string>& args,
                                 const std::filesystem::path& dir, rlim_t address_space_bytes) {
  std::vector<std::string> all{program};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string out = (dir / "stdout.txt").string(), err = (dir / "stderr.txt").string();
  LimitedExit r;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    const rlimit limit{address_space_bytes, address_space_bytes};
    const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (setrlimit(RLIMIT_AS, &limit) != 0 || o < 0 || e < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0) _exit(127);
    execve(program.c_str(), argv.data(), environ);
    _exit(127);
  }
  if (pid < 0) {
    ADD_FAILURE() << "cannot start " << program;
    return r;
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peak_rss_kb = usage.ru_maxrss;
  r.exit.exited = WIFEXITED(status);
  r.exit.code = r.exit.exited ? WEXITSTATUS(status) : -1;
  r.exit.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  auto slurp = [](const std::string& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  };
  r.exit.out = slurp(out);
  r.exit.err = slurp(err);
  return r;
}

// Values no integer option of the tools takes: empty, signs, spaces, prefixes, suffixes,
// fractions, NaN, numbers beyond every range (2^31 - 1, 2^63, 2^64, 10^30); then `option`
// (an option where a value belongs).
inline std::vector<std::string> bad_integer_values(const std::string& option) {
  return {"",
          "-1",
          "-0",
          "+5",
          " 5",
          "5 ",
          "5x",
          "0x10",
          "1e3",
          "1.5",
          "nan",
          "NaN",
          "inf",
          "two",
          "2147483647",
          "2147483648",
          "9223372036854775807",
          "9223372036854775808",
          "18446744073709551616",
          "1000000000000000000000000000000",
          option};
}

}  // namespace tritri_test
