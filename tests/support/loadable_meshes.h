// tests/support/loadable_meshes.h
//
// for_each_loadable_mesh(dir, f): calls f(path, soup) for every mesh file under dir
// (mesh_files order) that load_triangle_soup reads; files it refuses (the collection's bad
// files: test_load_triangle_soup's business) are skipped.
#pragma once

#include <filesystem>

#include "arrangements/input_error.h"
#include "arrangements/load_triangle_soup.h"
#include "shared_meshes.h"

namespace tritri_test {

template <class F>
void for_each_loadable_mesh(const std::filesystem::path& dir, F&& f) {
  for (const std::filesystem::path& path : mesh_files(dir)) {
    arrangements::TriangleSoup soup;
    try {
      soup = arrangements::load_triangle_soup(path.string());
    } catch (const arrangements::InputError&) {
      continue;
    }
    f(path, soup);
  }
}

}  // namespace tritri_test
