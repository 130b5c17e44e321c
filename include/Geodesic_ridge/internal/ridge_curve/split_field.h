// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 3: the field of one front of a copy split in several (the copy
// splitters' common step).
#ifndef GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SPLIT_FIELD_H
#define GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SPLIT_FIELD_H

#include <algorithm>
#include <array>
#include <cstddef>

namespace Geodesic_ridge {
namespace internal {

// One field of a split copy with distances d: that of the front `front` (the
// owner of the corners k with owner[k] == front): d at its corners, its own
// value there (`value_at(k)`, never below d) at the others. The split fields'
// envelope keeps the copy's corner distances.
template <class ValueAt>
std::array<double, 3> split_field(const std::array<double, 3>& d, const std::array<std::size_t, 3>& owner,
                                  std::size_t front, const ValueAt& value_at)
{
  std::array<double, 3> field;
  for(int k = 0; k < 3; ++k) field[k] = owner[k] == front ? d[k] : std::max(d[k], value_at(k));
  return field;
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_RIDGE_CURVE_SPLIT_FIELD_H
