// CommandLine: the command-line conventions of the tools (arrange, tritri-compare,
// make_test_meshes), written once. A bad command line is a usage error: the message
// "TOOL: ... (see --help)" on stderr and exit status 2. An option with a value is given
// at most once, and its value is the next argument, which must not look like an option
// (`--threads --stats` is refused; write ./--x for a file named --x). Counts are parsed
// strictly (parse_count, thread_count.h), and so are positive numbers (the whole value a
// finite decimal number above 0: "0.25", "1e-3"). Any other argument starting with '-' (but not
// "-" alone) is an unknown option; the rest are operands (input files), never empty.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>
#include <system_error>

#include "arrangements/thread_count.h"

namespace arrangements::detail {

class CommandLine {
 public:
  CommandLine(const char* tool, int argc, char** argv) : tool_(tool), argc_(argc), argv_(argv) {}

  // Steps to the next argument; false after the last one.
  bool next() { return ++i_ < argc_ && (current_ = argv_[i_], true); }
  const std::string& current() const { return current_; }

  [[noreturn]] void usage_error(const std::string& message) const {
    std::fprintf(stderr, "%s: %s (see --help)\n", tool_, message.c_str());
    std::exit(2);
  }

  // The value of the option `name` (the current argument), which takes the next one.
  std::string value(const std::string& name) {
    if (!given_.insert(name).second) usage_error(name + " given twice");
    if (i_ + 1 >= argc_) usage_error(name + " needs a value");
    if (std::string_view(argv_[i_ + 1]).starts_with("--"))
      usage_error(name + " needs a value, got the option '" + argv_[i_ + 1] + "'");
    return argv_[++i_];
  }

  // The value of the option `name` as an integer from lo to hi.
  long long count(const std::string& name, long long lo, long long hi) {
    const std::string v = value(name);
    const auto n = parse_count(v, lo, hi);
    if (!n)
      usage_error(name + " needs an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got '" + v +
                  "'");
    return *n;
  }

  // The value of the option `name` as a finite number above 0.
  double positive_number(const std::string& name) {
    const std::string v = value(name);
    double x = 0;
    const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), x);
    if (v.empty() || error != std::errc{} || end != v.data() + v.size() || !std::isfinite(x) || !(x > 0))
      usage_error(name + " needs a finite number above 0, got '" + v + "'");
    return x;
  }

  // The current argument as an operand named `what` (refused: an unknown option, empty).
  const std::string& operand(const std::string& what) const {
    if (current_.size() > 1 && current_[0] == '-') usage_error("unknown option '" + current_ + "'");
    if (current_.empty()) usage_error(what + " is empty");
    return current_;
  }

  bool given(const std::string& name) const { return given_.count(name) > 0; }

 private:
  const char* tool_;
  int argc_;
  char** argv_;
  int i_ = 0;
  std::string current_;
  std::set<std::string> given_;  // options with a value seen so far
};

}  // namespace arrangements::detail
