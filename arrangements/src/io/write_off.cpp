#include "io/write_off.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace arrangements {

void write_off(const std::string& path, const std::vector<Vec3>& V, const std::vector<Tri>& F) {
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot open for writing");
  bool ok = std::fprintf(f, "OFF\n%zu %zu 0\n", V.size(), F.size()) > 0;
  for (const Vec3& v : V) ok &= std::fprintf(f, "%.17g %.17g %.17g\n", v[0], v[1], v[2]) > 0;
  for (const Tri& t : F) ok &= std::fprintf(f, "3 %d %d %d\n", t[0], t[1], t[2]) > 0;
  ok &= std::fflush(f) == 0;
  ok &= std::fclose(f) == 0;
  std::error_code ec;
  if (ok) std::filesystem::rename(tmp, path, ec);
  if (!ok || ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error(path + ": write failed");
  }
}

}  // namespace arrangements
