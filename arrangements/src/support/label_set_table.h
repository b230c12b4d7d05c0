// LabelSetTable: the label sets of a mesh (output_mesh.h: label_sets, indexed per triangle)
// stored once each, new sets appended. Shared by preprocessing (stages/1_preprocess.cpp),
// triangulation (stages/5_triangulate.cpp) and the rounding's clean-up
// (rounding/mesh_on_positions.cpp).
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "arrangements/triangle_soup.h"

namespace arrangements {

class LabelSetTable {
 public:
  // Indexes the sets already in `sets` (distinct), which must outlive the table.
  explicit LabelSetTable(std::vector<LabelSet>& sets) : sets_(sets) {
    for (std::size_t i = 0; i < sets_.size(); ++i) index_.emplace(sets_[i], static_cast<int>(i));
  }
  // The index of `labels` (sorted, unique) in the sets, appended when new. O(log n) compares.
  int index_of(LabelSet labels) {
    const auto [it, inserted] = index_.try_emplace(std::move(labels), static_cast<int>(sets_.size()));
    if (inserted) sets_.push_back(it->first);
    return it->second;
  }

 private:
  std::vector<LabelSet>& sets_;
  std::map<LabelSet, int> index_;
};

}  // namespace arrangements
