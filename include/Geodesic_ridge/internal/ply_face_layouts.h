// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The PLY face layouts that CGAL's PLY reader does not take: triangle strips
// (element "tristrips"), and face lists whose indices are 8- or 16-bit
// integers. They are read with CGAL's own PLY parser (its header reader and
// its list reader); any other element that holds vertex-index lists is
// refused with a message that names it, rather than silently dropped.
#ifndef GEODESIC_RIDGE_INTERNAL_PLY_FACE_LAYOUTS_H
#define GEODESIC_RIDGE_INTERNAL_PLY_FACE_LAYOUTS_H

#include <Geodesic_ridge/exceptions.h>

#include <CGAL/IO/Color.h>
#include <CGAL/IO/PLY/PLY_reader.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace Geodesic_ridge {
namespace internal {
namespace ply {

using CGAL::IO::internal::PLY_element;

[[noreturn]] inline void error(const std::string& filename, const std::string& what)
{
  throw Mesh_file_error(filename + ": " + what);
}

// The name of `element`'s property that lists vertex indices
// ("vertex_indices" or "vertex_index"), or an empty string.
inline std::string index_list_name(PLY_element& element)
{
  for(const char* name : {"vertex_indices", "vertex_index"})
    for(std::size_t k = 0; k < element.number_of_properties(); ++k)
      if(element.property(k)->name() == name)
        return name;
  return std::string();
}

// The size in bits of the integers of the list `tag` of `element`; 0 if it
// is not a list of integers. Negative sizes stand for signed types.
inline int integer_list_bits(PLY_element& element, const char* tag)
{
  if(element.has_property<std::vector<std::int8_t>>(tag)) return -8;
  if(element.has_property<std::vector<std::uint8_t>>(tag)) return 8;
  if(element.has_property<std::vector<std::int16_t>>(tag)) return -16;
  if(element.has_property<std::vector<std::uint16_t>>(tag)) return 16;
  if(element.has_property<std::vector<std::int32_t>>(tag)) return -32;
  if(element.has_property<std::vector<std::uint32_t>>(tag)) return 32;
  return 0;
}

inline bool is_vertex_element(const std::string& name) { return name == "vertex" || name == "vertices"; }
inline bool is_face_element(const std::string& name) { return name == "face" || name == "faces"; }

// The layout of one element that holds faces; throws if we cannot read it.
// Returns true if CGAL's reader cannot read it either.
inline bool needs_own_reader(const std::string& filename, PLY_element& element)
{
  const std::string& name = element.name();
  const std::string tag = index_list_name(element);
  const bool faces = is_face_element(name), strips = name == "tristrips";
  if(tag.empty())
  {
    if(faces || strips)
      error(filename, "element '" + name + "' has no 'vertex_indices' list: its faces cannot be read");
    return false; // not a face element: ignored, as CGAL does
  }
  if(!faces && !strips)
    error(filename, "element '" + name + "' holds vertex-index lists in a layout this reader does not take "
                    "(it reads 'face' lists and 'tristrips'); its faces would be lost");
  const int bits = integer_list_bits(element, tag.c_str());
  if(bits == 0)
    error(filename, "element '" + name + "': property '" + tag + "' is a list of non-integer numbers, not of "
                    "vertex indices");
  return strips || (bits != 32 && bits != -32);
}

// True if the file holds faces that CGAL's PLY reader drops (triangle strips)
// or cannot read (8- or 16-bit index lists); throws for a face layout that
// neither reads. A header CGAL cannot parse is left to CGAL's reader.
inline bool needs_own_reader(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  CGAL::IO::internal::PLY_reader reader(false);
  if(!reader.init(in))
    return false;
  bool own = false;
  for(std::size_t i = 0; i < reader.number_of_elements(); ++i)
    if(!is_vertex_element(reader.element(i).name()))
      own = needs_own_reader(filename, reader.element(i)) || own;
  return own;
}

// The index lists of every item of `element` (CGAL's face reader). A
// negative index of a signed type becomes SIZE_MAX.
inline bool read_index_lists(std::istream& in, PLY_element& element, std::vector<std::vector<std::size_t>>& lists)
{
  namespace cip = CGAL::IO::internal;
  const std::string tag = index_list_name(element);
  std::vector<CGAL::IO::Color> no_colors;
  switch(integer_list_bits(element, tag.c_str()))
  {
    case -8: return cip::read_PLY_faces<std::int8_t>(in, element, lists, no_colors, tag.c_str());
    case 8: return cip::read_PLY_faces<std::uint8_t>(in, element, lists, no_colors, tag.c_str());
    case -16: return cip::read_PLY_faces<std::int16_t>(in, element, lists, no_colors, tag.c_str());
    case 16: return cip::read_PLY_faces<std::uint16_t>(in, element, lists, no_colors, tag.c_str());
    case -32: return cip::read_PLY_faces<std::int32_t>(in, element, lists, no_colors, tag.c_str());
    default: return cip::read_PLY_faces<std::uint32_t>(in, element, lists, no_colors, tag.c_str());
  }
}

inline bool is_restart(std::size_t index) { return index == std::size_t(-1) || index == 0xFFFFFFFFu; }

// Triangle strips to triangles, in order: in a strip v0 v1 v2 v3 ..., the
// k-th triangle (k from 0) is (v_k, v_k+1, v_k+2), its first two corners
// swapped when k is odd, so that all have the strip's orientation; -1 (or the
// largest unsigned index) restarts the strip. A triangle that repeats a
// vertex only joins strips and is no face: it is skipped.
inline void strips_to_triangles(const std::vector<std::vector<std::size_t>>& strips,
                                std::vector<std::vector<std::size_t>>& triangles)
{
  for(const std::vector<std::size_t>& strip : strips)
  {
    std::size_t run = 0; // vertices since the last restart
    for(std::size_t i = 0; i < strip.size(); ++i)
    {
      if(is_restart(strip[i]))
      {
        run = 0;
        continue;
      }
      if(++run < 3)
        continue;
      std::size_t a = strip[i - 2], b = strip[i - 1];
      const std::size_t c = strip[i];
      if((run - 3) % 2 == 1)
        std::swap(a, b);
      if(a != b && b != c && a != c)
        triangles.push_back({a, b, c});
    }
  }
}

// Reads the properties of the element's next item; false on a read error.
inline bool read_item(std::istream& in, PLY_element& element)
{
  for(std::size_t k = 0; k < element.number_of_properties(); ++k)
  {
    element.property(k)->get(in);
    if(in.fail())
      return false;
  }
  return true;
}

// Skips the items of an element nobody reads.
inline bool skip(std::istream& in, PLY_element& element)
{
  for(std::size_t j = 0; j < element.number_of_items(); ++j)
    if(!read_item(in, element))
      return false;
  return true;
}

template <class Point>
bool read_points(std::istream& in, PLY_element& element, std::vector<Point>& points)
{
  for(std::size_t j = 0; j < element.number_of_items(); ++j)
  {
    if(!read_item(in, element))
      return false;
    Point p;
    CGAL::IO::internal::process_properties(element, p,
                                           CGAL::IO::make_ply_point_reader(CGAL::Identity_property_map<Point>()));
    points.push_back(p);
  }
  return true;
}

// Reads a PLY file whose faces `needs_own_reader()` found: the vertices, then
// the faces of every face element and the triangles of every strip element,
// in the order of the elements in the file: file face j is the j-th of them.
template <class Point>
void read(const std::string& filename, std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons)
{
  std::ifstream in(filename, std::ios::binary);
  CGAL::IO::internal::PLY_reader reader(false);
  if(!reader.init(in))
    error(filename, "malformed PLY header");
  for(std::size_t i = 0; i < reader.number_of_elements(); ++i)
  {
    PLY_element& element = reader.element(i);
    bool ok = true;
    if(is_vertex_element(element.name()))
      ok = read_points(in, element, points);
    else if(is_face_element(element.name()))
      ok = read_index_lists(in, element, polygons);
    else if(element.name() == "tristrips")
    {
      std::vector<std::vector<std::size_t>> strips;
      ok = read_index_lists(in, element, strips);
      strips_to_triangles(strips, polygons);
    }
    else
      ok = skip(in, element);
    if(!ok || in.fail())
      error(filename, "malformed or truncated PLY content in element '" + element.name() + "'");
  }
}

} // namespace ply
} // namespace internal
} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_INTERNAL_PLY_FACE_LAYOUTS_H
