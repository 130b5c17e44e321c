// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of mesh input: validate_triangle_soup, validate_triangle_mesh and
// read_triangle_mesh. Every rule of the validation is exercised through OFF,
// OBJ and PLY files written into a temporary directory, through the soup
// function, and through a Surface_mesh where a halfedge structure can
// represent the defect.
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/connected_component.h>
#include <Geodesic_ridge/mesh_validation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "support/message_of.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Geodesic_ridge::Invalid_mesh_error;
using Geodesic_ridge::Mesh_file_error;

const double nan_value = std::numeric_limits<double>::quiet_NaN();
const double inf_value = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------
// Helpers

// A unique temporary directory, removed at the end of the test.
class Temp_dir
{
  fs::path m_path;

public:
  Temp_dir()
  {
    static std::atomic<int> counter{0};
    m_path = fs::temp_directory_path() /
             ("geodesic_ridge_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(m_path);
  }
  ~Temp_dir()
  {
    std::error_code ec;
    fs::remove_all(m_path, ec);
  }
  std::string file(const std::string& name) const { return (m_path / name).string(); }
  std::string write(const std::string& name, const std::string& content) const
  {
    std::ofstream out(file(name), std::ios::binary);
    out << content;
    return file(name);
  }
};

// A soup that may be invalid in any way (signed indices, NaN coordinates).
struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<long long>> faces;

  std::vector<Point_3> cgal_points() const
  {
    std::vector<Point_3> result;
    for(const auto& p : points)
      result.emplace_back(p[0], p[1], p[2]);
    return result;
  }
  std::vector<std::vector<std::size_t>> cgal_faces() const
  {
    std::vector<std::vector<std::size_t>> result;
    for(const auto& f : faces)
      result.emplace_back(f.begin(), f.end());
    return result;
  }
};

std::string number(double x)
{
  std::ostringstream out;
  out << std::setprecision(17) << x; // NaN and infinity print as "nan" and "inf"
  return out.str();
}

// The vertex and face lines of OFF, OBJ and ASCII PLY: the formats differ only
// in a tag before each line, whether a face line starts with its size, and the
// first index (1 in OBJ).
void write_vertex_and_face_lines(std::ostream& out, const Soup& s, const char* vertex_tag,
                                 const char* face_tag, bool face_size, long long first_index)
{
  for(const auto& p : s.points)
    out << vertex_tag << number(p[0]) << " " << number(p[1]) << " " << number(p[2]) << "\n";
  for(const auto& f : s.faces)
  {
    out << face_tag;
    if(face_size)
      out << f.size();
    for(long long i : f)
      out << " " << i + first_index;
    out << "\n";
  }
}

std::string to_off(const Soup& s)
{
  std::ostringstream out;
  out << "OFF\n" << s.points.size() << " " << s.faces.size() << " 0\n";
  write_vertex_and_face_lines(out, s, "", "", true, 0);
  return out.str();
}

std::string to_obj(const Soup& s)
{
  std::ostringstream out;
  out << "# written by test_input_validation\n";
  write_vertex_and_face_lines(out, s, "v ", "f", false, 1);
  return out.str();
}

std::string ply_header(const Soup& s, const char* format)
{
  std::ostringstream out;
  out << "ply\nformat " << format << " 1.0\nelement vertex " << s.points.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << s.faces.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  return out.str();
}

std::string to_ply(const Soup& s)
{
  std::ostringstream out;
  out << ply_header(s, "ascii");
  write_vertex_and_face_lines(out, s, "", "", true, 0);
  return out.str();
}

// Binary little-endian PLY: the only format in which a NaN coordinate reaches
// the validation through CGAL's reader (its ASCII parsers reject "nan").
std::string to_binary_ply(const Soup& s)
{
  std::string out = ply_header(s, "binary_little_endian");
  auto append = [&](const void* data, std::size_t n) {
    const char* bytes = static_cast<const char*>(data);
    out.append(bytes, n); // the test machines are little-endian (x86-64)
  };
  for(const auto& p : s.points)
    for(double x : p)
      append(&x, sizeof x);
  for(const auto& f : s.faces)
  {
    const std::uint8_t n = static_cast<std::uint8_t>(f.size());
    append(&n, 1);
    for(long long i : f)
    {
      const std::int32_t i32 = static_cast<std::int32_t>(i);
      append(&i32, 4);
    }
  }
  return out;
}

using Geodesic_ridge::testing::message_of;

bool is_one_line(const std::string& s) { return !s.empty() && s.find('\n') == std::string::npos; }

// Checks that reading `s` from OFF, OBJ and PLY files, and validating it as a
// soup, all throw Invalid_mesh_error with a message containing `needle`.
// `ascii_ply` false writes the PLY file in binary (see rule 5).
void check_invalid_everywhere(const Soup& s, const std::string& needle, bool ascii_ply = true)
{
  Temp_dir dir;
  const std::vector<std::pair<std::string, std::string>> files = {
    {"mesh.off", to_off(s)}, {"mesh.obj", to_obj(s)}, {"mesh.ply", ascii_ply ? to_ply(s) : to_binary_ply(s)}};
  for(const auto& file : files)
  {
    INFO("file " << file.first << ":\n" << file.second);
    const std::string path = dir.write(file.first, file.second);
    Mesh tm;
    const std::string msg = message_of<Invalid_mesh_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(path, tm); });
    CHECK_THAT(msg, Contains(needle));
    CHECK_THAT(msg, Contains(file.first));
    CHECK(is_one_line(msg));
  }
  const std::string msg = message_of<Invalid_mesh_error>(
    [&] { Geodesic_ridge::validate_triangle_soup(s.cgal_points(), s.cgal_faces()); });
  CHECK_THAT(msg, Contains(needle));
  CHECK(is_one_line(msg));
}

// Builds a Surface_mesh face by face; false if a face cannot be added.
bool build_mesh(const Soup& s, Mesh& tm)
{
  tm.clear();
  for(const auto& p : s.points)
    tm.add_vertex(Point_3(p[0], p[1], p[2]));
  for(const auto& f : s.faces)
  {
    std::vector<Mesh::Vertex_index> vs;
    for(long long i : f)
      vs.push_back(Mesh::Vertex_index(static_cast<Mesh::size_type>(i)));
    if(tm.add_face(vs) == Mesh::null_face())
      return false;
  }
  return true;
}

void check_invalid_surface_mesh(const Soup& s, const std::string& needle)
{
  Mesh tm;
  REQUIRE(build_mesh(s, tm));
  const std::string msg = message_of<Invalid_mesh_error>([&] { Geodesic_ridge::validate_triangle_mesh(tm); });
  CHECK_THAT(msg, Contains(needle));
  CHECK(is_one_line(msg));
}

// A closed, consistently oriented tetrahedron.
Soup tetrahedron(double shift = 0)
{
  Soup s;
  s.points = {{shift, 0, 0}, {shift + 1, 0, 0}, {shift, 1, 0}, {shift, 0, 1}};
  s.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return s;
}

// Appends `b` to `a`, renumbering its vertices.
Soup merged(Soup a, const Soup& b)
{
  const long long offset = static_cast<long long>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for(auto f : b.faces)
  {
    for(long long& i : f)
      i += offset;
    a.faces.push_back(f);
  }
  return a;
}

} // namespace

// ---------------------------------------------------------------------------
// A valid mesh, in every format

TEST_CASE("a closed tetrahedron reads and validates in OFF, OBJ and PLY", "[input]")
{
  const Soup s = tetrahedron();
  Temp_dir dir;
  for(const std::string& path : {dir.write("t.off", to_off(s)), dir.write("t.obj", to_obj(s)),
                                 dir.write("t.ply", to_ply(s)), dir.write("t.bin.ply", to_binary_ply(s)),
                                 dir.write("T.OFF", to_off(s))})
  {
    INFO(path);
    Mesh tm;
    REQUIRE_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(path, tm));
    CHECK(tm.number_of_vertices() == 4);
    CHECK(tm.number_of_faces() == 4);
    CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(tm));
  }
  CHECK_NOTHROW(Geodesic_ridge::validate_triangle_soup(s.cgal_points(), s.cgal_faces()));
}

// ---------------------------------------------------------------------------
// One test case per rule, in the order the rules are checked

TEST_CASE("rule 1: an empty mesh is rejected", "[input][validation]")
{
  Soup no_face = tetrahedron();
  no_face.faces.clear();
  check_invalid_everywhere(no_face, "mesh is empty");
  check_invalid_everywhere(Soup{}, "mesh is empty");

  Mesh tm;
  CHECK_THAT(message_of<Invalid_mesh_error>([&] { Geodesic_ridge::validate_triangle_mesh(tm); }),
             Contains("mesh is empty (0 vertices, 0 faces)"));
}

TEST_CASE("rule 2: a face that is not a triangle is rejected by the validation, triangulated by the reader",
          "[input][validation]")
{
  // A square pyramid: a closed mesh whose base (face 0) is a quad.
  Soup s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  s.faces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  CHECK_THAT(message_of<Geodesic_ridge::Repairable_mesh_error>(
               [&] { Geodesic_ridge::validate_triangle_soup(s.cgal_points(), s.cgal_faces()); }),
             Contains("face 0 has 4 vertices; only triangle meshes are supported"));
  check_invalid_surface_mesh(s, "face 0 has 4 vertices; only triangle meshes are supported");
  // The reader triangulates it (test_repair.cpp tests how): the quad's two
  // triangles are faces 0 and 5, the other faces keep their index.
  Temp_dir dir;
  for(const std::string& path : {dir.write("p.off", to_off(s)), dir.write("p.obj", to_obj(s)),
                                 dir.write("p.ply", to_ply(s)), dir.write("p.bin.ply", to_binary_ply(s))})
  {
    INFO(path);
    Mesh tm;
    const auto map = Geodesic_ridge::IO::read_triangle_mesh(path, tm);
    CHECK(tm.number_of_faces() == 6);
    CHECK(map.statistics().triangulated_polygons == 1);
    for(std::size_t j = 0; j < 6; ++j)
      CHECK(map.file_face(Mesh::Face_index(static_cast<Mesh::size_type>(j)), tm) == (j == 5 ? 0 : j));
  }
}

TEST_CASE("rule 3: a face index out of range is rejected", "[input][validation]")
{
  Soup s = tetrahedron();
  s.faces[3] = {1, 2, 7};
  check_invalid_everywhere(s, "face 3 refers to vertex 7, out of range (the mesh has 4 vertices");

  SECTION("one past the end (CGAL's OBJ reader lets it through)")
  {
    s.faces[3] = {1, 2, 4};
    check_invalid_everywhere(s, "face 3 refers to vertex 4");
  }
  SECTION("a negative index in a soup of signed integers")
  {
    std::vector<std::vector<int>> faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, -1}};
    CHECK_THAT(message_of<Invalid_mesh_error>(
                 [&] { Geodesic_ridge::validate_triangle_soup(s.cgal_points(), faces); }),
               Contains("face 3 refers to vertex -1"));
  }
}

TEST_CASE("rule 4: a face repeating a vertex is rejected", "[input][validation]")
{
  Soup s = tetrahedron();
  s.faces[3] = {1, 2, 2};
  check_invalid_everywhere(s, "face 3 repeats vertex 2");
}

TEST_CASE("rule 5: a non-finite coordinate is rejected", "[input][validation]")
{
  for(double bad : {nan_value, inf_value, -inf_value})
  {
    INFO("bad coordinate " << bad);
    Soup s = tetrahedron();
    s.points[2][1] = bad;
    // OFF and OBJ: CGAL's readers reject the token as malformed; the re-read
    // names the vertex. PLY: only binary PLY can carry the value through
    // CGAL's reader (its ASCII parser rejects "nan" and "inf": see the PLY
    // file errors), and the validation rejects it.
    check_invalid_everywhere(s, "vertex 2 has a non-finite coordinate", false);
    check_invalid_surface_mesh(s, "vertex 2 has a non-finite coordinate");
  }
  SECTION("an overflowing coordinate in a text file is infinite")
  {
    Temp_dir dir;
    std::string off = to_off(tetrahedron());
    off.replace(off.find("\n0 1 0\n"), 7, "\n0 1e400 0\n");
    const std::string path = dir.write("huge.off", off);
    Mesh tm;
    CHECK_THAT(message_of<Invalid_mesh_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(path, tm); }),
               Contains("vertex 2 has a non-finite coordinate"));
  }
  SECTION("the vertex_point_map named parameter is the one checked")
  {
    Mesh tm;
    REQUIRE(build_mesh(tetrahedron(), tm));
    auto alt = tm.add_property_map<Mesh::Vertex_index, Point_3>("v:alternative").first;
    for(auto v : tm.vertices())
      alt[v] = tm.point(v);
    alt[Mesh::Vertex_index(3)] = Point_3(0, nan_value, 1);
    CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(tm));
    CHECK_THAT(message_of<Invalid_mesh_error>([&] {
                 Geodesic_ridge::validate_triangle_mesh(tm, CGAL::parameters::vertex_point_map(alt));
               }),
               Contains("vertex 3 has a non-finite coordinate"));
  }
}

TEST_CASE("rule 6: an isolated vertex is rejected", "[input][validation]")
{
  Soup s = tetrahedron();
  s.points.push_back({5, 5, 5});
  check_invalid_everywhere(s, "vertex 4 is isolated (used by no face)");
  check_invalid_surface_mesh(s, "vertex 4 is isolated (used by no face)");

  SECTION("a removed (garbage) vertex of a Surface_mesh is not isolated")
  {
    Mesh tm;
    REQUIRE(build_mesh(s, tm));
    tm.remove_vertex(Mesh::Vertex_index(4));
    CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(tm));
  }
}

TEST_CASE("rule 7: two faces on the same three vertices are rejected", "[input][validation]")
{
  Soup s = tetrahedron();
  s.faces.push_back({0, 1, 2}); // face 0 with the other orientation
  check_invalid_everywhere(s, "faces 0 and 4 are duplicates (both on vertices 0, 1, 2)");

  // A halfedge structure can glue two opposite triangles into a closed "pillow".
  Soup pillow;
  pillow.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  pillow.faces = {{0, 1, 2}, {0, 2, 1}};
  check_invalid_surface_mesh(pillow, "faces 0 and 1 are duplicates");
}

TEST_CASE("rule 8: an edge shared by three faces is rejected", "[input][validation]")
{
  Soup s = tetrahedron();
  s.points.push_back({0.5, -1, 0.5});
  s.faces.push_back({0, 1, 4}); // a fin on edge 0-1
  check_invalid_everywhere(s, "edge 0-1 is non-manifold: it is shared by 3 faces");
}

TEST_CASE("rule 9: a surface with a border is accepted, a bowtie at a border vertex is not", "[input][validation]")
{
  Soup s = tetrahedron();
  s.faces.pop_back(); // remove face 3 = (1, 2, 3): three border edges
  CHECK_NOTHROW(Geodesic_ridge::validate_triangle_soup(s.cgal_points(), s.cgal_faces()));
  Mesh tm;
  REQUIRE(build_mesh(s, tm));
  CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(tm));
  // two triangles sharing only vertex 0: its faces form two fans (paths)
  Soup bowtie;
  bowtie.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  bowtie.faces = {{0, 1, 2}, {0, 3, 4}};
  check_invalid_everywhere(bowtie, "vertex 0 is non-manifold (its faces form 2 separate fans)");
}

TEST_CASE("rule 10: an inconsistent orientation is rejected", "[input][validation]")
{
  Soup s = tetrahedron();
  s.faces[3] = {1, 3, 2}; // flipped
  check_invalid_everywhere(s, "faces 0 and 3 are inconsistently oriented (both traverse edge 2->1");
}

TEST_CASE("rule 11: a non-manifold vertex is rejected", "[input][validation]")
{
  // Two tetrahedra touching at vertex 0: closed, oriented, edge-manifold, one
  // component, but the faces around vertex 0 form two fans.
  Soup s = tetrahedron();
  Soup other;
  other.points = {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  other.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for(auto& f : other.faces)
    for(long long& i : f)
      i = (i == 0) ? 0 : i + 3;
  s.points.insert(s.points.end(), other.points.begin(), other.points.end());
  s.faces.insert(s.faces.end(), other.faces.begin(), other.faces.end());
  check_invalid_everywhere(s, "vertex 0 is non-manifold (its faces form 2 separate fans)");

  // Not through a Surface_mesh: Surface_mesh::add_face refuses to close a
  // second fan at a vertex (checked), so a pinched vertex cannot be built.
}

TEST_CASE("rule 12: several connected components: the validation refuses them, the reader keeps them",
          "[input][validation][components]")
{
  const Soup s = merged(merged(tetrahedron(), tetrahedron(5)), tetrahedron(10));
  const std::string needle = "mesh has 3 connected components; the algorithm takes one "
                             "(extract_connected_component() copies the source's)";
  CHECK_THAT(message_of<Invalid_mesh_error>(
               [&] { Geodesic_ridge::validate_triangle_soup(s.cgal_points(), s.cgal_faces()); }),
             Contains(needle));
  check_invalid_surface_mesh(s, needle);
  Temp_dir dir;
  for(const std::string& path : {dir.write("m.off", to_off(s)), dir.write("m.obj", to_obj(s)),
                                 dir.write("m.ply", to_ply(s))})
  {
    INFO(path);
    Mesh tm;
    Geodesic_ridge::IO::read_triangle_mesh(path, tm);
    CHECK(tm.number_of_vertices() == 12);
    CHECK(tm.number_of_faces() == 12);
  }
}

TEST_CASE("extract_connected_component: the source's part, and every index and point mapped both ways",
          "[input][components]")
{
  // three tetrahedra, the middle one's vertices and faces listed in reverse
  Soup middle = tetrahedron(5);
  std::reverse(middle.points.begin(), middle.points.end());
  for(auto& f : middle.faces)
    for(long long& i : f)
      i = 3 - i;
  std::reverse(middle.faces.begin(), middle.faces.end());
  const Soup s = merged(merged(tetrahedron(), middle), tetrahedron(10));
  Temp_dir dir;
  Mesh tm;
  const auto file_map = Geodesic_ridge::IO::read_triangle_mesh(dir.write("m.off", to_off(s)), tm);
  Mesh part;
  const auto cc = Geodesic_ridge::extract_connected_component(tm, Mesh::Face_index(6), part);
  CHECK_THROWS_AS(Geodesic_ridge::extract_connected_component(tm, Mesh::Face_index(0), part),
                  Geodesic_ridge::Invalid_parameter_error); // not empty
  CHECK(cc.number_of_components() == 3);
  CHECK(cc.number_of_other_faces() == 8);
  CHECK(cc.number_of_other_vertices() == 8);
  CHECK(part.number_of_faces() == 4);
  CHECK(part.number_of_vertices() == 4);
  CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(part));
  for(Mesh::Vertex_index v : tm.vertices())
  {
    const auto c = cc.component_vertex(v);
    CHECK(bool(c) == (v >= Mesh::Vertex_index(4) && v < Mesh::Vertex_index(8)));
    if(c)
    {
      CHECK(cc.mesh_vertex(*c) == v);
      CHECK(part.point(*c) == tm.point(v));
    }
  }
  for(Mesh::Face_index f : tm.faces())
  {
    const auto c = cc.component_face(f);
    REQUIRE(bool(c) == (f >= Mesh::Face_index(4) && f < Mesh::Face_index(8)));
    if(!c)
      continue;
    CHECK(cc.mesh_face(*c) == f);
    // a point of the face: the same point in the part, and back
    const std::pair<Mesh::Face_index, std::array<double, 3>> loc(f, {{0.5, 0.3, 0.2}});
    const auto in_part = cc.component_location(loc);
    REQUIRE(in_part);
    CHECK(in_part->first == *c);
    const Point_3 p = CGAL::Polygon_mesh_processing::construct_point(loc, tm);
    const Point_3 q = CGAL::Polygon_mesh_processing::construct_point(*in_part, part);
    CHECK(CGAL::squared_distance(p, q) < 1e-28);
    const auto back = cc.mesh_location(*in_part);
    CHECK(back.first == f);
    CHECK(back.second == loc.second); // only reordered, twice
  }
  CHECK_FALSE(cc.component_location({Mesh::Face_index(0), {{1, 0, 0}}}));

  // the file's indices, through the part: faces 4-7 and vertices 4-7 are in
  // it, the others in other components
  const auto map = file_map.restricted_to_component(cc, tm, part);
  for(std::size_t j = 0; j < 12; ++j)
  {
    const bool inside = j >= 4 && j < 8;
    CHECK(map.faces(j).size() == (inside ? 1u : 0u));
    CHECK(map.in_other_component(j) == !inside);
    CHECK(map.vertices(j).size() == (inside ? 1u : 0u));
    CHECK(map.vertex_in_other_component(j) == !inside);
    CHECK_FALSE(file_map.in_other_component(j));
  }
  for(Mesh::Face_index f : part.faces())
  {
    const std::pair<Mesh::Face_index, std::array<double, 3>> loc(f, {{0.2, 0.3, 0.5}});
    const auto a = map.file_location(loc, part);
    const auto b = file_map.file_location(cc.mesh_location(loc), tm);
    CHECK(a.face == b.face);
    CHECK(a.coordinates == b.coordinates);
    CHECK(map.file_face(f, part) == file_map.file_face(cc.mesh_face(f), tm));
  }
  for(Mesh::Vertex_index v : part.vertices())
    CHECK(map.file_vertex(v, part) == file_map.file_vertex(cc.mesh_vertex(v), tm));
}

TEST_CASE("rule 13: a face with exactly collinear corners is rejected, with no epsilon", "[input][validation]")
{
  Soup s = tetrahedron();
  s.points[3] = {2, 0, 0}; // on the line of vertices 0 and 1: face 1 = (0, 1, 3) is flat
  check_invalid_everywhere(s, "face 1 is degenerate (its corners are collinear)");
  check_invalid_surface_mesh(s, "face 1 is degenerate (its corners are collinear)");

  // Nearly collinear is not collinear: the predicate is exact.
  s.points[3] = {2, 1e-200, 0};
  CHECK_NOTHROW(Geodesic_ridge::validate_triangle_soup(s.cgal_points(), s.cgal_faces()));
  Temp_dir dir;
  Mesh tm;
  CHECK_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(dir.write("thin.off", to_off(s)), tm));
}

// ---------------------------------------------------------------------------
// File errors

TEST_CASE("file errors: missing file, unsupported extension, directory", "[input][file]")
{
  Temp_dir dir;
  Mesh tm;
  CHECK_THAT(message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(dir.file("none.off"), tm); }),
             Contains("none.off: cannot open the file (No such file or directory)"));
  const std::string stl = dir.write("mesh.stl", "solid x\nendsolid x\n");
  CHECK_THAT(message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(stl, tm); }),
             Contains("unsupported extension '.stl'; expected .off, .obj or .ply"));
  const std::string noext = dir.write("mesh", to_off(tetrahedron()));
  CHECK_THAT(message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(noext, tm); }),
             Contains("no extension"));
  fs::create_directory(dir.file("folder.off"));
  CHECK_THAT(message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(dir.file("folder.off"), tm); }),
             Contains("is a directory"));
}

TEST_CASE("file errors: a failed read leaves the mesh untouched", "[input][file]")
{
  Temp_dir dir;
  Mesh tm;
  REQUIRE(build_mesh(tetrahedron(), tm));
  Soup isolated = tetrahedron();
  isolated.points.push_back({2, 2, 2}); // a vertex no face uses
  CHECK_THROWS_AS(Geodesic_ridge::IO::read_triangle_mesh(dir.write("isolated.off", to_off(isolated)), tm),
                  Invalid_mesh_error);
  CHECK_THROWS_AS(Geodesic_ridge::IO::read_triangle_mesh(dir.write("bad.off", "OFF\n4 4 0\n0 0\n"), tm), Mesh_file_error);
  CHECK(tm.number_of_faces() == 4);
}

TEST_CASE("file errors: malformed or truncated OFF", "[input][file][off]")
{
  const std::string good = to_off(tetrahedron());
  const std::string verts = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  struct Case
  {
    const char* name;
    std::string content;
    const char* needle;
  };
  const std::vector<Case> cases = {
    {"fewer faces than the header says", "OFF\n4 4 0\n" + verts + "3 0 2 1\n3 0 1 3\n",
     "file is truncated: the header announces 4 vertices and 4 faces, but it ends after 2 faces"},
    {"cut in the middle of a face", good.substr(0, good.size() - 3),
     "line 10: face 3 announces 3 vertices but lists 2"},
    {"fewer vertices than the header says", "OFF\n4 4 0\n0 0 0\n1 0 0\n",
     "ends after 2 vertices"},
    {"a vertex with two coordinates", "OFF\n4 4 0\n0 0 0\n1 0\n0 1 0\n0 0 1\n",
     "line 4: vertex 1 has 2 coordinate(s), expected 3"},
    {"a garbage coordinate", "OFF\n4 4 0\n0 0 0\n1 0 foo\n0 1 0\n0 0 1\n",
     "line 4: vertex 1: 'foo' is not a number"},
    {"a garbage face index", "OFF\n4 4 0\n" + verts + "3 0 2 x\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
     "line 7: face 0: 'x' is not a vertex index"},
    {"a negative face index", "OFF\n4 4 0\n" + verts + "3 0 2 -1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
     "line 7: face 0: '-1' is not a vertex index"},
    {"a bad header keyword", "PFF\n4 4 0\n" + verts, "line 1: expected the OFF header, found 'PFF'"},
    {"counts without E", "OFF\n4 4\n" + verts, "line 2: expected the OFF counts 'V F E'"},
    {"an empty file", "", "file is empty (no OFF header)"},
    {"only the keyword", "OFF\n", "file ends after the OFF keyword"},
  };
  Temp_dir dir;
  for(const Case& c : cases)
  {
    INFO(c.name);
    const std::string path = dir.write("bad.off", c.content);
    Mesh tm;
    const std::string msg = message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(path, tm); });
    CHECK_THAT(msg, Contains(c.needle));
    CHECK_THAT(msg, Contains("bad.off"));
    CHECK(is_one_line(msg));
  }
}

TEST_CASE("plain OFF files are read by the fast path exactly as CGAL's reader reads them", "[input][file][off]")
{
  namespace mio = Geodesic_ridge::internal::mesh_io;
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  // plain files, in the forms the fast path takes
  std::vector<std::string> plain = {
    to_off(tetrahedron()),
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces,
    "OFF 4 4 6\n0 0 0  \n\n1 0 0\n\t0 1 0\n0 0 1" + std::string("\n") + faces + "trailing text, never read\n",
    "OFF\r\n4 4 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3",
    "OFF\n5 3 0\n+1.5e-3 -.25 5.\n1E2 0.1 -0\n0.3 1e+1 7\n2.5e-320 1e-400 -4.9e-324\n.5 5 0005\n4 0 1 2 3\n3 0 2 4\n3 1 3 4\n",
  };
  { // many numbers in the forms writers use (the fast path parses with std::from_chars)
    std::mt19937 random(20261205);
    std::cout << "[input] plain OFF numbers: std::mt19937 seed 20261205" << std::endl;
    std::uniform_real_distribution<double> mantissa(-1, 1);
    std::uniform_int_distribution<int> exponent(-30, 30), form(0, 4);
    const int n = 3000;
    std::string file = "OFF\n" + std::to_string(n) + " " + std::to_string(n - 2) + " 0\n";
    char buffer[64];
    for(int i = 0; i < 3 * n; ++i)
    {
      const double x = std::ldexp(mantissa(random), exponent(random));
      const char* const formats[] = {"%.17g", "%.6f", "%e", "%.9g", "%+.3E"};
      std::snprintf(buffer, sizeof buffer, formats[form(random)], x);
      file += buffer;
      file += (i % 3 == 2) ? "\n" : " ";
    }
    for(int i = 0; i + 2 < n; ++i)
      file += "3 " + std::to_string(i) + " " + std::to_string(i + 1) + " " + std::to_string(i + 2) + "\n";
    plain.push_back(file);
  }
  // anything else: CGAL's reader reads it (or explains why not)
  const std::vector<std::string> other = {
    "# a comment\nOFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces,
    "OFF\n4 4 0\n0 0 0 # here\n1 0 0\n0 1 0\n0 0 1\n" + faces,
    "OFF\n4 4 0\n0 0 0 1\n1 0 0\n0 1 0\n0 0 1\n" + faces,
    "COFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces,
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 255 0 0\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 4\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n",
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n2 0 2\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
    "OFF\n4 4 0\n0x1 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces,
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1e400 0\n0 0 1\n" + faces,
    "OFF\n4 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces,
  };
  Temp_dir dir;
  auto same_as_cgal = [&](const std::string& path) {
    std::vector<Point_3> points, cgal_points;
    std::vector<std::vector<std::size_t>> polygons, cgal_polygons;
    const bool plain_read = mio::read_plain_OFF(path, points, polygons);
    if(plain_read)
    {
      REQUIRE(CGAL::IO::read_polygon_soup(path, cgal_points, cgal_polygons, CGAL::parameters::verbose(false)));
      REQUIRE(points.size() == cgal_points.size());
      for(std::size_t i = 0; i < points.size(); ++i)
        for(int k = 0; k < 3; ++k)
        {
          const double a = points[i][k], b = cgal_points[i][k];
          CHECK(std::memcmp(&a, &b, sizeof a) == 0);
        }
      CHECK(polygons == cgal_polygons);
    }
    else
      CHECK((points.empty() && polygons.empty()));
    return plain_read;
  };
  for(const std::string& content : plain)
  {
    INFO(content);
    CHECK(same_as_cgal(dir.write("plain.off", content)));
  }
  for(const std::string& content : other)
  {
    INFO(content);
    CHECK_FALSE(same_as_cgal(dir.write("other.off", content)));
  }
  for(const fs::path& data_dir : {fs::path(GEODESIC_RIDGE_DATA_DIR), fs::path(GEODESIC_RIDGE_DATA_DIR) / "boundary",
                                  fs::path(GEODESIC_RIDGE_SHARED_DATA_DIR)})
  {
    if(!fs::is_directory(data_dir))
      continue;
    for(const auto& entry : fs::directory_iterator(data_dir))
      if(entry.path().extension() == ".off" && fs::file_size(entry.path()) < 2000000)
      {
        INFO(entry.path().string());
        same_as_cgal(entry.path().string());
      }
  }
}

TEST_CASE("file errors: malformed OBJ, including what CGAL's reader silently accepts", "[input][file][obj]")
{
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  struct Case
  {
    const char* name;
    std::string content;
    const char* needle;
  };
  const std::vector<Case> cases = {
    // CGAL reads "f 1 3 x" as the 2-gon (1, 3).
    {"a garbage face token", verts + "f 1 3 x\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
     "line 5: face 0: 'x' is not a vertex reference"},
    // CGAL maps 0 to the vertex count so far, i.e. to a vertex defined later.
    {"the invalid index 0", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 3 0\nv 0 0 1\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
     "line 4: face 0: '0' is not a vertex reference"},
    {"a relative index before the first vertex", verts + "f 1 3 -9\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
     "relative reference -9 points before the first vertex"},
    {"an unknown statement", verts + "foo bar\n", "line 5: unknown OBJ statement 'foo'"},
    {"a vertex with two coordinates", "v 0 0 0\nv 1 0\n", "line 2: vertex 1 has 2 coordinate(s), expected 3"},
    {"a garbage coordinate", "v 0 0 0\nv 1 zero 0\n", "line 2: vertex 1: 'zero' is not a number"},
  };
  Temp_dir dir;
  for(const Case& c : cases)
  {
    INFO(c.name);
    const std::string path = dir.write("bad.obj", c.content);
    Mesh tm;
    const std::string msg = message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(path, tm); });
    CHECK_THAT(msg, Contains(c.needle));
    CHECK_THAT(msg, Contains("bad.obj"));
  }
  SECTION("a truncated OBJ has no header to compare with: it is read as an open mesh")
  {
    const std::string path = dir.write("cut.obj", verts + "f 1 3 2\nf 1 2 4\n");
    Mesh tm;
    CHECK_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(path, tm));
    CHECK(tm.number_of_faces() == 2);
  }
  SECTION("texture and normal references are accepted")
  {
    const std::string path =
      dir.write("tex.obj", verts + "vt 0 0\nvn 0 0 1\nf -4 -2 -3\nf 1/1/1 2/1/1 4/1/1\nf 1//1 4//1 3//1\nf 2 3 4\n");
    Mesh tm;
    CHECK_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(path, tm));
    CHECK(tm.number_of_faces() == 4);
  }
}

TEST_CASE("file errors: malformed or truncated PLY", "[input][file][ply]")
{
  const Soup s = tetrahedron();
  const std::string ascii = to_ply(s);
  const std::string binary = to_binary_ply(s);
  Soup with_nan = s;
  with_nan.points[1][2] = nan_value;
  struct Case
  {
    const char* name;
    std::string content;
    const char* needle;
  };
  const std::vector<Case> cases = {
    {"ASCII, fewer faces than the header says", ascii.substr(0, ascii.rfind("3 0 3 2")), "malformed or truncated PLY"},
    {"binary, truncated", binary.substr(0, binary.size() - 5), "malformed or truncated PLY"},
    {"garbage index", ascii.substr(0, ascii.rfind("3 1 2 3")) + "3 1 x 3\n", "malformed or truncated PLY"},
    // CGAL's ASCII PLY parser rejects "nan" before the validation can see it.
    {"ASCII nan", to_ply(with_nan), "malformed or truncated PLY"},
    {"a header cut short", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n", "malformed or truncated PLY"},
    {"not a PLY file", to_off(s), "does not start with 'ply'"},
  };
  Temp_dir dir;
  for(const Case& c : cases)
  {
    INFO(c.name);
    const std::string path = dir.write("bad.ply", c.content);
    Mesh tm;
    const std::string msg = message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(path, tm); });
    CHECK_THAT(msg, Contains(c.needle));
    CHECK_THAT(msg, Contains("bad.ply"));
  }
}

// ---------------------------------------------------------------------------
// Sizes the file cannot hold (issue 41: the allocation bounded by the input)

namespace {

// Appends the bytes of x in the file's byte order (the test machines are
// little-endian, x86-64).
template <class T>
void append_bytes(std::string& out, T x, bool big_endian)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &x, sizeof(T));
  if(big_endian)
    std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

// The tetrahedron in binary PLY, its face lists counted by `Count` (of PLY
// type `count_type`): face j announces counts[j] indices (and lists its 3).
template <class Count>
std::string binary_ply_counts(bool big_endian, const char* count_type, const std::array<Count, 4>& counts)
{
  const Soup s = tetrahedron();
  std::string out = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 4\nproperty list " + count_type + " int vertex_indices\nend_header\n";
  for(const auto& p : s.points)
    for(double x : p)
      append_bytes(out, static_cast<float>(x), big_endian);
  for(std::size_t j = 0; j < 4; ++j)
  {
    append_bytes(out, counts[j], big_endian);
    for(long long i : s.faces[j])
      append_bytes(out, static_cast<std::int32_t>(i), big_endian);
  }
  return out;
}

// The tetrahedron in ASCII PLY, with `count_type` counts, the faces as given.
std::string ascii_ply_faces(const char* count_type, const std::string& faces)
{
  return std::string("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 4\nproperty list ") + count_type + " int vertex_indices\nend_header\n" +
         "0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + faces;
}

// A binary OFF file (big-endian, as CGAL reads it: no color count after a
// face): the counts, then the tetrahedron's vertices and `faces` (each its
// size, then its indices).
std::string binary_off(std::int32_t nv, std::int32_t nf, const std::vector<std::vector<std::int32_t>>& faces)
{
  std::string out = "OFF BINARY\n";
  for(std::int32_t count : {nv, nf, 0})
    append_bytes(out, count, true);
  for(const auto& p : tetrahedron().points)
    for(double x : p)
      append_bytes(out, static_cast<float>(x), true);
  for(const auto& f : faces)
    for(std::int32_t i : f)
      append_bytes(out, i, true);
  return out;
}

struct File_case
{
  const char* name;
  std::string content;
  const char* needle;
};

// Each file is refused with Mesh_file_error, a one-line message that holds
// the needle and the file's name.
void check_refused(const std::vector<File_case>& cases, const std::string& filename)
{
  Temp_dir dir;
  for(const File_case& c : cases)
  {
    INFO(c.name);
    const std::string path = dir.write(filename, c.content);
    Mesh tm;
    const std::string msg = message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(path, tm); });
    CHECK_THAT(msg, Contains(c.needle));
    CHECK_THAT(msg, Contains(filename));
    CHECK(is_one_line(msg));
  }
}

} // namespace

TEST_CASE("file errors: a PLY list longer than the rest of the file is refused before it is allocated",
          "[input][file][ply]")
{
  const std::string faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string tail = faces.substr(faces.find('\n') + 1); // faces 1 to 3
  std::string binary_cut = binary_ply_counts<std::int32_t>(false, "int", {3, 3, 3, 3});
  binary_cut.resize(binary_cut.size() - 14); // in the last face's count
  const std::vector<File_case> cases = {
    // CGAL's reader resized the list to 1.9e9 ints (7.6 GB) before reading one
    {"ASCII, a huge count", ascii_ply_faces("int", "1900000000 0 2 1\n" + tail),
     "element 'face' item 0: list 'vertex_indices' announces 1900000000 values, which the file cannot hold "
     "(31 bytes left, at least 2 per value)"},
    {"ASCII, a count over the range of int, which CGAL's reader saturates",
     ascii_ply_faces("int", "3 0 2 1\n99999999999 0 1 3\n3 0 3 2\n3 1 2 3\n"),
     "element 'face' item 1: list 'vertex_indices' announces 2147483647 values"},
    {"ASCII, an unsigned count of -1, which CGAL's reader reads as 2^32 - 1",
     ascii_ply_faces("uint", "-1 0 2 1\n" + tail), "announces 4294967295 values, which the file cannot hold"},
    {"ASCII, a negative count", ascii_ply_faces("int", "-1 0 2 1\n" + tail),
     "element 'face' item 0: list 'vertex_indices' announces -1 values, which the file cannot hold (a negative count)"},
    // (CGAL's reader reads numbers, not words: "1-3" is 1 then -3, the count)
    {"ASCII, a negative count glued to a coordinate",
     "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
     "element face 4\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1-3 0 2 1\n" + tail,
     "element 'face' item 0: list 'vertex_indices' announces -3 values, which the file cannot hold (a negative count)"},
    {"ASCII, fewer values than the last count", ascii_ply_faces("int", "3 0 2 1\n3 0 1 3\n3 0 3 2\n5 1 2 3\n"),
     "element 'face' item 3: list 'vertex_indices' announces 5 values, which the file cannot hold"},
    // CGAL's reader took the count from uninitialized memory there
    {"ASCII, the file ends before a count", ascii_ply_faces("int", "3 0 2 1\n3 0 1 3\n3 0 3 2\n"),
     "element 'face' item 3: the file ends before the count of list 'vertex_indices'"},
    {"binary little-endian, a huge unsigned count",
     binary_ply_counts<std::uint32_t>(false, "uint", {3, 4000000000u, 3, 3}),
     "element 'face' item 1: list 'vertex_indices' announces 4000000000 values, which the file cannot hold "
     "(44 bytes left, 4 per value)"},
    {"binary big-endian, a huge count", binary_ply_counts<std::int32_t>(true, "int", {1900000000, 3, 3, 3}),
     "element 'face' item 0: list 'vertex_indices' announces 1900000000 values, which the file cannot hold "
     "(60 bytes left, 4 per value)"},
    {"binary big-endian, a negative 16-bit count", binary_ply_counts<std::int16_t>(true, "short", {3, 3, -3, 3}),
     "element 'face' item 2: list 'vertex_indices' announces -3 values, which the file cannot hold (a negative count)"},
    {"binary, the file ends in a count", binary_cut,
     "element 'face' item 3: the file ends before the count of list 'vertex_indices'"},
    // (CGAL's reader takes the body as part of the header, and reads the
    // items from the failed stream)
    // (CGAL's reader takes the second line for the format line, whatever it
    // says, and adds the property to an element it does not have)
    {"an element on the format line", "ply\nelement ascii 1.0\nproperty list uchar int vertex_indices\n"
                                      "element vertex 0\nend_header\n",
     "PLY header: a property before any element (line 3)"},
    // (CGAL's point reader asserts on it, and without assertions dereferences null)
    {"a vertex coordinate that is a list", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                           "property float y\nproperty list uchar float z\nend_header\n",
     "PLY header: vertex coordinate 'z' is a list, not float or double (line 6)"},
    // (CGAL's reader adds a point for each vertex item, of no property it knows)
    {"a huge count of items of no property", "ply\nformat ascii 1.0\nelement vertex 3000000000\n"
                                             "property int64 w\nend_header\n",
     "the header announces 3000000000 'vertex', more items than the file has bytes (75)"},
    {"no end_header", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nelement tristrips 1\n"
                      "property list int int vertex_indices\n3 0 1 2\n",
     "malformed or truncated PLY header: no 'end_header' line"},
  };
  check_refused(cases, "bad.ply");
}

TEST_CASE("a valid PLY file reads as before: ASCII, binary of either byte order, with extra properties",
          "[input][file][ply]")
{
  // the shuffled octahedron of the index order test, with properties around
  // the coordinates and the index lists, and elements before and after
  const std::array<std::array<double, 3>, 6> corners = {
    {{0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Soup s;
  s.points.assign(corners.begin(), corners.end());
  s.faces = {{1, 4, 5}, {4, 3, 5}, {3, 2, 5}, {2, 1, 5}, {4, 1, 0}, {3, 4, 0}, {2, 3, 0}, {1, 2, 0}};
  REQUIRE_NOTHROW(Geodesic_ridge::validate_triangle_soup(s.cgal_points(), s.cgal_faces()));
  const std::string header_start = "ply\nformat ";
  const std::string header_rest =
    " 1.0\ncomment extra properties\nelement camera 2\nproperty float view_x\nproperty list uchar short path\n"
    "element vertex 6\nproperty float nx\nproperty double x\nproperty double y\nproperty double z\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty list uint float weights\n"
    "element face 8\nproperty uchar flags\nproperty list uchar int vertex_indices\n"
    "property list ushort float texcoord\nproperty int material\n"
    "element material 1\nproperty list uchar char name\nend_header\n";
  auto write = [&](int format) {
    const bool big = format == 2;
    std::string out = header_start + (format == 0 ? "ascii" : big ? "binary_big_endian" : "binary_little_endian") +
                      header_rest;
    std::ostringstream text;
    for(int c = 0; c < 2; ++c) // camera: view_x, path (3 shorts)
      if(format == 0)
        text << "0.5 3 -1 0 700\n";
      else
      {
        append_bytes(out, 0.5f, big);
        append_bytes(out, std::uint8_t(3), big);
        for(std::int16_t v : {-1, 0, 700})
          append_bytes(out, v, big);
      }
    for(std::size_t i = 0; i < 6; ++i) // vertex: nx, x, y, z, rgb, i + 1 weights
      if(format == 0)
      {
        text << "-0.25 " << number(s.points[i][0]) << " " << number(s.points[i][1]) << " " << number(s.points[i][2])
             << " 255 128 0 " << i + 1;
        for(std::size_t k = 0; k <= i; ++k)
          text << " 0.125";
        text << "\n";
      }
      else
      {
        append_bytes(out, -0.25f, big);
        for(double x : s.points[i])
          append_bytes(out, x, big);
        for(std::uint8_t c : {255, 128, 0})
          append_bytes(out, c, big);
        append_bytes(out, static_cast<std::uint32_t>(i + 1), big);
        for(std::size_t k = 0; k <= i; ++k)
          append_bytes(out, 0.125f, big);
      }
    for(const auto& f : s.faces) // face: flags, the indices, 6 texture coordinates, material
      if(format == 0)
        text << "7 3 " << f[0] << " " << f[1] << " " << f[2] << " 6 0 0 1 0 0 1 -2\n";
      else
      {
        append_bytes(out, std::uint8_t(7), big);
        append_bytes(out, std::uint8_t(3), big);
        for(long long i : f)
          append_bytes(out, static_cast<std::int32_t>(i), big);
        append_bytes(out, std::uint16_t(6), big);
        for(float t : {0.f, 0.f, 1.f, 0.f, 0.f, 1.f})
          append_bytes(out, t, big);
        append_bytes(out, std::int32_t(-2), big);
      }
    if(format == 0) // material: a name of 4 chars
      text << "4 103 111 108 100\n";
    else
    {
      append_bytes(out, std::uint8_t(4), big);
      out += "gold";
    }
    return out + text.str();
  };
  Temp_dir dir;
  for(int format : {0, 1, 2})
  {
    INFO("format " << format);
    const std::string path = dir.write("extra.ply", write(format));
    std::vector<Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    REQUIRE(CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)));
    CHECK(points == s.cgal_points());
    CHECK(polygons == s.cgal_faces());
    Mesh tm;
    REQUIRE_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(path, tm));
    REQUIRE(tm.number_of_vertices() == 6);
    REQUIRE(tm.number_of_faces() == 8);
    for(std::size_t i = 0; i < 6; ++i)
      CHECK(tm.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(i))) == points[i]);
    for(std::size_t j = 0; j < 8; ++j)
    {
      std::vector<std::size_t> around;
      for(auto v : CGAL::vertices_around_face(tm.halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(j))), tm))
        around.push_back(v.idx());
      std::rotate(around.begin(), std::find(around.begin(), around.end(), polygons[j][0]), around.end());
      CHECK(around == polygons[j]);
    }
  }
  SECTION("the check reads a large binary file in chunks: a list across a chunk's end, a file without a last newline")
  {
    // a strip of 2n triangles whose lists cross the 1 MB chunks of the walk
    const int n = 60000;
    std::string out = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(2 * n + 2) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                      std::to_string(2 * n) + "\nproperty list uchar int vertex_indices\n"
                      "property list uchar uchar pad\nend_header\n";
    for(int i = 0; i <= n; ++i)
      for(int k = 0; k < 2; ++k)
        for(float x : {float(i), float(k), 0.f})
          append_bytes(out, x, false);
    for(int i = 0; i < n; ++i)
      for(const std::array<int, 3>& t : {std::array<int, 3>{2 * i, 2 * i + 2, 2 * i + 1},
                                          std::array<int, 3>{2 * i + 1, 2 * i + 2, 2 * i + 3}})
      {
        append_bytes(out, std::uint8_t(3), false);
        for(int v : t)
          append_bytes(out, std::int32_t(v), false);
        append_bytes(out, std::uint8_t(i % 7), false);
        out.append(static_cast<std::size_t>(i % 7), 'p');
      }
    REQUIRE(out.size() > 2000000);
    Mesh tm;
    REQUIRE_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(dir.write("strip.ply", out), tm));
    CHECK(tm.number_of_faces() == static_cast<Mesh::size_type>(2 * n));
    // the same with its last list cut: refused, named
    const std::string cut = out.substr(0, out.size() - 2);
    const std::string msg = message_of<Mesh_file_error>(
      [&] { Geodesic_ridge::IO::read_triangle_mesh(dir.write("cut.ply", cut), tm); });
    CHECK_THAT(msg, Contains("element 'face' item " + std::to_string(2 * n - 1) + ": list 'pad' announces"));
  }
}

TEST_CASE("file errors: an OFF face or vertex count larger than the file is refused before it is allocated",
          "[input][file][off]")
{
  const std::string verts = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::string tail = "3 0 1 3\n3 0 3 2\n3 1 2 3\n"; // faces 1 to 3
  const std::vector<std::vector<std::int32_t>> faces = {{3, 0, 2, 1}, {3, 0, 1, 3}, {3, 0, 3, 2}, {3, 1, 2, 3}};
  std::string binary_cut = binary_off(4, 4, faces);
  binary_cut.resize(binary_cut.size() - 16); // before the last face's size
  const std::vector<File_case> cases = {
    // (COFF: not a plain OFF file, CGAL's reader reads it; it converted the
    // size, a double, to size_t and resized the face to it)
    {"COFF, a face size of 1e121", "COFF\n4 4 0\n" + verts + "1e121 0 2 1\n" + tail,
     "line 7: face 0 announces 1e121 vertices, which the file cannot hold (31 bytes left, at least 2 per index)"},
    {"COFF, a negative face size", "COFF\n4 4 0\n" + verts + "-8 0 2 1\n" + tail,
     "line 7: face 0 announces -8 vertices, a negative count"},
    {"COFF, comments and blank lines before a face size of 3e9",
     "COFF\n4 4 0\n# the vertices\n" + verts +
       "\n3 0 2 1 # the first face\n  # a comment\n\n+3e9 0 1 3\n3 0 3 2\n3 1 2 3\n",
     "line 12: face 1 announces +3e9 vertices, which the file cannot hold"},
    // (CGAL's scanner reads colors at indices it derives from the numbers of
    // a line and of the lines before: out of bounds there; found by fuzz/)
    {"COFF, a vertex of one number", "COFF\n4 4 0\n0 0 0\n1 0 0\n0gggg 1 0\n0 0 1\n3 0 2 1\n" + tail,
     "line 5: vertex 2 has 1 number(s), expected 3 at least"},
    {"COFF, a vertex without a color after one with",
     "COFF\n4 4 0\n0 0 0 255 0 0\n1 0 0\n0 1 0 0 0 255\n0 0 1 9 9 9\n3 0 2 1\n" + tail,
     "line 4: vertex 1 has 0 color value(s) after one with colors"},
    {"COFF, a negative color index", "COFF\n4 4 0\n0 0 0 3\n1 0 0 -5\n0 1 0 7\n0 0 1 9\n3 0 2 1\n" + tail,
     "line 4: vertex 1 has 1 color value(s) after one with colors"},
    {"COFF, a face without a color after one with",
     "COFF\n4 4 0\n" + verts + "3 0 2 1 0.5 0.5 0.5\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
     "line 8: face 1 has 0 color value(s) after one with colors"},
    {"COFF, fewer vertex lines than the header announces", "COFF\n4 4 0\n0 0 0 1 1 1\n1 0 0 1 1 1\n",
     "file is truncated: the header announces 4 vertices, but it ends after 2"},
    {"STOFF, texture coordinates without colors", "STOFF\n4 4 0\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n0 0 1 1 1\n"
     "3 0 2 1\n" + tail, "texture coordinates without colors"},
    // (an assertion of CGAL's reader, an exception in a build with assertions)
    {"4OFF, a vertex of w = 0", "4OFF\n4 4 0\n0 0 0 1\n1 0 0 1\n0 1 0 0\n0 0 1 1\n3 0 2 1\n" + tail,
     "line 5: vertex 2 has the homogeneous coordinate w = 0"},
    // (an "OFF" file: the line-by-line diagnosis names the line, as for the
    // files CGAL's reader refuses)
    {"OFF, a face size of 1e121 (not a plain file either)", "OFF\n4 4 0\n" + verts + "1e121 0 2 1\n" + tail,
     "line 7: face 0: '1e121' is not a vertex count"},
    {"OFF, a face size of 1e9 on a short line", "OFF\n4 4 0\n" + verts + "1000000000 0 2 1\n" + tail,
     "line 7: face 0 announces 1000000000 vertices but lists 3"},
    // counts that the plain parse of the header does not read
    {"counts over several lines", "OFF\n2000000000\n4 0\n" + verts + "3 0 2 1\n" + tail,
     "the header announces 2000000000 vertices and 4 faces, which take at least"},
    {"nOFF, a huge vertex count (found by fuzz/)", "nOFF\n3\n400000000 4 0\n" + verts,
     "the header announces 400000000 vertices and 4 faces, which take at least"},
    {"binary, a huge vertex count", binary_off(2000000000, 4, faces),
     "the header announces 2000000000 vertices and 4 faces, which take at least"},
    {"binary, a huge face size", binary_off(4, 4, {{2000000000, 0, 2, 1}, {3, 0, 1, 3}, {3, 0, 3, 2}, {3, 1, 2, 3}}),
     "binary OFF, byte 71: face 0 announces 2000000000 vertices, which the file cannot hold (60 bytes left, 4 per "
     "index)"},
    {"binary, a negative face size", binary_off(4, 4, {{3, 0, 2, 1}, {-5, 0, 1, 3}, {3, 0, 3, 2}, {3, 1, 2, 3}}),
     "binary OFF, byte 87: face 1 announces -5 vertices, a negative count"},
    // (CGAL's reader took the size from uninitialized memory there)
    {"binary, the file ends before a face size", binary_cut, "face 3: the file ends before its vertex count"},
  };
  check_refused(cases, "bad.off");

  SECTION("the same files with sizes the file holds read as before")
  {
    Temp_dir dir;
    const std::vector<std::string> good = {
      "COFF\n4 4 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n0 0 1 9 9 9\n3 0 2 1\n" + tail,
      "COFF\n4 4 0\n# the vertices\n" + verts + "\n3 0 2 1 # the first face\n  # a comment\n\n+3 0 1 3\n3 0 3 2\n"
      "3.7 1 2 3\n",
      "COFF\n4 4 0\n0 0 0 3\n1 0 0 0\n0 1 0 7\n0 0 1 200\n3 0 2 1 1\n3 0 1 3 0.5 0.5 0.5\n3 0 3 2 9 9 9 9\n"
      "3 1 2 3 0\n",
      "STCOFF\n4 4 0\n0 0 0 255 0 0 0 0\n1 0 0 255 0 0 1 0\n0 1 0 0 255 0 0 1\n0 0 1 0 0 255 1 1\n3 0 2 1\n" +
        tail,
      "OFF\n4\n4\n0\n" + verts + "3 0 2 1\n" + tail,
      "4OFF\n4 4 0\n0 0 0 1\n2 0 0 2\n0 1 0 1\n0 0 -3 -3\n3 0 2 1\n" + tail,
      "nOFF\n3\n4 4 0\n" + verts + "3 0 2 1\n" + tail,
      binary_off(4, 4, faces),
    };
    for(const std::string& content : good)
    {
      INFO(content);
      Mesh tm;
      REQUIRE_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(dir.write("good.off", content), tm));
      CHECK(tm.number_of_faces() == 4);
    }
  }
}

// ---------------------------------------------------------------------------
// Index order and the repository's meshes

TEST_CASE("vertex i and face j of the file are vertex i and face j of the mesh", "[input][order]")
{
  // An octahedron, outward oriented, with shuffled vertices and faces.
  const std::array<std::array<double, 3>, 6> corners = {
    {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  const std::array<int, 6> file_position = {3, 0, 5, 1, 4, 2}; // corner c is vertex file_position[c]
  Soup s;
  s.points.resize(6);
  for(int c = 0; c < 6; ++c)
    s.points[file_position[c]] = corners[c];
  for(int sx : {0, 1})
    for(int sy : {0, 1})
      for(int sz : {0, 1})
      {
        long long x = file_position[sx], y = file_position[2 + sy], z = file_position[4 + sz];
        s.faces.push_back((sx + sy + sz) % 2 == 0 ? std::vector<long long>{x, y, z} : std::vector<long long>{x, z, y});
      }
  std::swap(s.faces[0], s.faces[5]);
  std::swap(s.faces[2], s.faces[7]);
  std::rotate(s.faces[1].begin(), s.faces[1].begin() + 1, s.faces[1].end());
  REQUIRE_NOTHROW(Geodesic_ridge::validate_triangle_soup(s.cgal_points(), s.cgal_faces()));

  Temp_dir dir;
  for(const std::string& path : {dir.write("o.off", to_off(s)), dir.write("o.obj", to_obj(s)),
                                 dir.write("o.ply", to_ply(s)), dir.write("o.bin.ply", to_binary_ply(s))})
  {
    INFO(path);
    Mesh tm;
    REQUIRE_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(path, tm));
    REQUIRE(tm.number_of_vertices() == 6);
    REQUIRE(tm.number_of_faces() == 8);
    for(std::size_t i = 0; i < 6; ++i)
      CHECK(tm.point(Mesh::Vertex_index(static_cast<Mesh::size_type>(i))) ==
            Point_3(s.points[i][0], s.points[i][1], s.points[i][2]));
    for(std::size_t j = 0; j < 8; ++j)
    {
      // The same cyclic triple, starting anywhere (orientation is preserved).
      std::vector<long long> around;
      for(auto v : CGAL::vertices_around_face(tm.halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(j))), tm))
        around.push_back(static_cast<long long>(v.idx()));
      REQUIRE(around.size() == 3);
      const auto& f = s.faces[j];
      const bool same = (around == f) ||
                        (around == std::vector<long long>{f[1], f[2], f[0]}) ||
                        (around == std::vector<long long>{f[2], f[0], f[1]});
      CHECK(same);
    }
  }
}

TEST_CASE("every mesh of the repository's data directory reads and validates", "[input][data]")
{
  const fs::path data_dir(GEODESIC_RIDGE_DATA_DIR);
  REQUIRE(fs::is_directory(data_dir));
  std::size_t count = 0;
  for(const auto& entry : fs::directory_iterator(data_dir))
  {
    std::string ext = entry.path().extension().string();
    if(ext != ".off" && ext != ".obj" && ext != ".ply")
      continue;
    INFO(entry.path().string());
    Mesh tm;
    REQUIRE_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(entry.path().string(), tm));
    CHECK(tm.number_of_faces() > 0);
    CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(tm));
    ++count;
  }
  CHECK(count > 0);
}
