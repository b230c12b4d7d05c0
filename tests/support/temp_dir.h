// tests/support/temp_dir.h
//
// The files a test writes: TempDir, a fresh folder per test (named after the test and the
// process, removed afterwards), and bytes_of, the bytes of a binary value for hand-built
// binary mesh files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace tritri_test {

// A fresh folder for the files one test writes, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() / ("arrangements_test_" + std::string(info->test_suite_name()) + "_" +
                                                     info->name() + "_" + std::to_string(::getpid()));
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

// The bytes of a value, little endian (this machine's order) or reversed to big endian:
// for hand-built binary mesh files.
template <class T>
std::string bytes_of(T value, bool big_endian = false) {
  std::string s(sizeof(T), '\0');
  std::memcpy(s.data(), &value, sizeof(T));
  if (big_endian) std::reverse(s.begin(), s.end());
  return s;
}

}  // namespace tritri_test
