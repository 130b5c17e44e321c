// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Polylines in CGAL's text format: one polyline per line, `n x1 y1 z1 ... xn yn zn`.
#ifndef GEODESIC_RIDGE_IO_POLYLINES_H
#define GEODESIC_RIDGE_IO_POLYLINES_H

#include <Geodesic_ridge/exceptions.h>

#include <fstream>
#include <limits>
#include <ostream>
#include <string>

namespace Geodesic_ridge {
namespace IO {

/// \ingroup PkgGeodesicRidgeIO
/// Writes a range of polylines (each a range of points with `x()`, `y()`,
/// `z()`) with 17 significant digits, so that the coordinates read back are
/// the very doubles of the mesh's vertices.
template <class PolylineRange>
void write_polylines(std::ostream& os, const PolylineRange& polylines)
{
  os.precision(std::numeric_limits<double>::max_digits10);
  for(const auto& polyline : polylines)
  {
    os << polyline.size();
    for(const auto& p : polyline) os << ' ' << p.x() << ' ' << p.y() << ' ' << p.z();
    os << '\n';
  }
}

/// Same, to a file. Throws `Error` if the file cannot be written.
template <class PolylineRange>
void write_polylines(const std::string& filename, const PolylineRange& polylines)
{
  std::ofstream os(filename);
  if(!os) throw Error("cannot open '" + filename + "' for writing");
  write_polylines(os, polylines);
  os.flush();
  if(!os) throw Error("cannot write '" + filename + "'");
}

} // namespace IO
} // namespace Geodesic_ridge

#endif
