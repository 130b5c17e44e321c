// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef GEODESIC_RIDGE_INTERNAL_UNION_FIND_H
#define GEODESIC_RIDGE_INTERNAL_UNION_FIND_H

#include <CGAL/Union_find.h>

#include <cstddef>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

/// The one union-find of the package: CGAL's `Union_find` (union by size, path
/// compression) over the elements 0, 1, ..., with the answers the algorithms
/// ask for. Every set has a label, an element of it: `find` returns it. A new
/// set is labelled by its element; a union keeps one of the two labels, or
/// the one the caller names (the extended surface keeps the data of a merged
/// vertex copy under one of its ids).
class Union_find
{
public:
  explicit Union_find(std::size_t n = 0)
  {
    handles_.reserve(n);
    for(std::size_t i = 0; i < n; ++i) add();
  }
  /// a new element, alone in its set; returns it
  std::size_t add()
  {
    handles_.push_back(sets_.push_back(handles_.size()));
    return handles_.size() - 1;
  }
  std::size_t size() const { return handles_.size(); }
  /// the label of the set of `i`
  std::size_t find(std::size_t i) const { return *sets_.find(handles_[i]); }
  /// Unites the sets of `a` and `b`; returns false if they were one set already.
  bool unite(std::size_t a, std::size_t b)
  {
    if(sets_.same_set(handles_[a], handles_[b])) return false;
    sets_.unify_sets(handles_[a], handles_[b]);
    return true;
  }
  /// Unites the sets of `a` and `b`, labelled as the set of `b` was.
  void unite_into(std::size_t a, std::size_t b)
  {
    const std::size_t label = find(b);
    unite(a, b);
    *sets_.find(handles_[b]) = label;
  }
  std::size_t number_of_sets() const { return sets_.number_of_sets(); }

private:
  CGAL::Union_find<std::size_t> sets_;
  std::vector<CGAL::Union_find<std::size_t>::handle> handles_;
};

} // namespace internal
} // namespace Geodesic_ridge

#endif
