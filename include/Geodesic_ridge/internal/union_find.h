// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef GEODESIC_RIDGE_INTERNAL_UNION_FIND_H
#define GEODESIC_RIDGE_INTERNAL_UNION_FIND_H

#include <cstddef>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// The one union-find of the package (union by size, path compression) over
/// the elements 0, 1, ..., with the answers the algorithms ask for. Every set
/// has a label, an element of it: `find` returns it. A new set is labelled by
/// its element; a union keeps one of the two labels, or the one the caller
/// names (the extended surface keeps the data of a merged vertex copy under
/// one of its ids).
///
/// Flat arrays instead of `CGAL::Union_find`, which allocates every element on
/// its own (one heap block per face or vertex on large meshes); the links are
/// CGAL's (the smaller set under the larger, on a tie the first under the
/// second), so every label is the one `CGAL::Union_find` gave.
class Union_find
{
public:
  explicit Union_find(std::size_t n = 0)
  {
    parent_.reserve(n);
    size_.reserve(n);
    label_.reserve(n);
    for(std::size_t i = 0; i < n; ++i) add();
  }
  /// a new element, alone in its set; returns it
  std::size_t add()
  {
    const std::size_t i = parent_.size();
    parent_.push_back(i);
    size_.push_back(1);
    label_.push_back(i);
    ++sets_;
    return i;
  }
  std::size_t size() const { return parent_.size(); }
  /// the label of the set of `i`
  std::size_t find(std::size_t i) const { return label_[root(i)]; }
  /// Unites the sets of `a` and `b`; returns false if they were one set already.
  bool unite(std::size_t a, std::size_t b)
  {
    std::size_t ra = root(a), rb = root(b);
    if(ra == rb) return false;
    if(size_[ra] > size_[rb]) std::swap(ra, rb);
    parent_[ra] = rb;
    size_[rb] += size_[ra];
    --sets_;
    return true;
  }
  /// Unites the sets of `a` and `b`, labelled as the set of `b` was.
  void unite_into(std::size_t a, std::size_t b)
  {
    const std::size_t label = find(b);
    unite(a, b);
    label_[root(b)] = label;
  }
  std::size_t number_of_sets() const { return sets_; }

private:
  std::size_t root(std::size_t i) const
  {
    std::size_t r = i;
    while(parent_[r] != r) r = parent_[r];
    while(parent_[i] != r) { const std::size_t up = parent_[i]; parent_[i] = r; i = up; }
    return r;
  }

  // mutable: path compression in the const `find`, as CGAL's does
  mutable std::vector<std::size_t> parent_;
  std::vector<std::size_t> size_, label_;
  std::size_t sets_ = 0;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif
