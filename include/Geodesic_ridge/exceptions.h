// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Typed exceptions thrown by every stage of the package.
#ifndef GEODESIC_RIDGE_EXCEPTIONS_H
#define GEODESIC_RIDGE_EXCEPTIONS_H

#include <stdexcept>
#include <string>

namespace Geodesic_ridge {

/// \ingroup PkgGeodesicRidgeRef
/// Base class of every exception the package throws. `what()` is a one-line
/// message that names the problem (a CLI prints it as is).
class Error : public std::runtime_error
{
public:
  /// makes the exception with its one-line message
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// \ingroup PkgGeodesicRidgeRef
/// The user's input is wrong; nothing was computed.
class Input_error : public Error
{
public:
  /// makes the exception with its one-line message
  using Error::Error;
};

/// \ingroup PkgGeodesicRidgeRef
/// A mesh file cannot be opened, is truncated, or is not in a format we read.
class Mesh_file_error : public Input_error
{
public:
  /// makes the exception with its one-line message
  using Input_error::Input_error;
};

/// \ingroup PkgGeodesicRidgeRef
/// The mesh is not one the algorithm supports (non-triangle, non-manifold,
/// open, several components, degenerate faces, non-finite coordinates, ...).
class Invalid_mesh_error : public Input_error
{
public:
  /// makes the exception with its one-line message
  using Input_error::Input_error;
};

/// \ingroup PkgGeodesicRidgeRef
/// The mesh breaks a rule that the repair (`repair_mesh()`, or
/// `IO::read_triangle_mesh()` with `parameters::repair(true)`; the command
/// line's `--repair`) fixes: a face with fewer than three distinct vertices, an
/// isolated vertex, duplicate faces, a non-manifold edge or vertex, an
/// inconsistent orientation, a degenerate face.
class Repairable_mesh_error : public Invalid_mesh_error
{
public:
  /// makes the exception with its one-line message
  using Invalid_mesh_error::Invalid_mesh_error;
};

/// \ingroup PkgGeodesicRidgeRef
/// The source (vertex index, face index, barycentric coordinates) is invalid.
class Invalid_source_error : public Input_error
{
public:
  /// makes the exception with its one-line message
  using Input_error::Input_error;
};

/// \ingroup PkgGeodesicRidgeRef
/// A parameter (tolerance, ...) is out of its range or not a number.
class Invalid_parameter_error : public Input_error
{
public:
  /// makes the exception with its one-line message
  using Input_error::Input_error;
};

/// \ingroup PkgGeodesicRidgeRef
/// An invariant of the algorithm failed (for example the cut is not a disk).
/// This is a bug in the package, never a consequence of the input: report it.
class Algorithm_error : public Error
{
public:
  /// makes the exception with its one-line message
  using Error::Error;
};

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_EXCEPTIONS_H
