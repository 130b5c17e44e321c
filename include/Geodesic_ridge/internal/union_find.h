// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef GEODESIC_RIDGE_INTERNAL_UNION_FIND_H
#define GEODESIC_RIDGE_INTERNAL_UNION_FIND_H

#include <boost/pending/disjoint_sets.hpp>

#include <cstddef>

namespace Geodesic_ridge {
namespace internal {

/// Union-find over 0..n-1: Boost's disjoint sets (union by rank, path
/// compression), with the two answers the algorithms ask for: whether a union
/// joined two sets (Kruskal) and how many sets are left (components).
class Union_find
{
public:
  explicit Union_find(std::size_t n) : sets_(n), number_of_sets_(n) {}
  std::size_t find(std::size_t i) { return sets_.find_set(i); }
  /// Returns false if `a` and `b` were already in one set.
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b) return false;
    sets_.link(a, b);
    --number_of_sets_;
    return true;
  }
  std::size_t number_of_sets() const { return number_of_sets_; }

private:
  boost::disjoint_sets_with_storage<> sets_;
  std::size_t number_of_sets_;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif
