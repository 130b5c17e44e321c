// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What stage 2 leaves for stage 3 of each face of M: its copies in E that no
// other copy dominates, with their corner distances.
#ifndef GEODESIC_RIDGE_INTERNAL_FACE_COPIES_H
#define GEODESIC_RIDGE_INTERNAL_FACE_COPIES_H

#include <array>
#include <cstddef>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// What stage 3 needs of one original face.
struct Face_copies
{
  std::vector<std::size_t> copies;              // faces of E
  std::vector<std::array<double, 3> > fields;   // their corner distances
  std::vector<char> split;                      // empty, or per copy: one front of a copy split at a kink
};

// Keeps the entries j of fc for which keep(j) is true, in order.
template <class Keep>
void keep_face_copies_if(Face_copies& fc, const Keep& keep)
{
  std::size_t kept = 0;
  for(std::size_t j = 0; j < fc.copies.size(); ++j)
    if(keep(j))
    {
      fc.copies[kept] = fc.copies[j];
      fc.fields[kept] = fc.fields[j];
      if(!fc.split.empty()) fc.split[kept] = fc.split[j];
      ++kept;
    }
  fc.copies.resize(kept);
  fc.fields.resize(kept);
  if(!fc.split.empty()) fc.split.resize(kept);
}

} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_FACE_COPIES_H
