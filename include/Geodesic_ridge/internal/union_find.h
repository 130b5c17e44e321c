// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef GEODESIC_RIDGE_INTERNAL_UNION_FIND_H
#define GEODESIC_RIDGE_INTERNAL_UNION_FIND_H

#include <cstddef>
#include <numeric>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// Union-find over 0..n-1 with path halving and union by size.
class Union_find
{
public:
  explicit Union_find(std::size_t n) : parent_(n), size_(n, 1), sets_(n)
  {
    std::iota(parent_.begin(), parent_.end(), std::size_t(0));
  }
  std::size_t find(std::size_t i)
  {
    while(parent_[i] != i) { parent_[i] = parent_[parent_[i]]; i = parent_[i]; }
    return i;
  }
  /// Returns false if `a` and `b` were already in one set.
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a); b = find(b);
    if(a == b) return false;
    if(size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    --sets_;
    return true;
  }
  std::size_t number_of_sets() const { return sets_; }

private:
  std::vector<std::size_t> parent_, size_;
  std::size_t sets_;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif
