// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of the triangulation of polygons on reading, of the repair
// (repair.h), of the map back to the file's indices (file_index_map.h), and of
// the PLY face layouts CGAL's reader does not take. Every repair kind is tried
// on a small crafted mesh, and the indices the map gives are checked against
// the file: positions of vertices, corners of faces, points of locations.
#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/file_index_map.h>
#include <Geodesic_ridge/repair.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include "support/message_of.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
namespace PMP = CGAL::Polygon_mesh_processing;
using Catch::Matchers::Contains;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Map = Geodesic_ridge::File_index_map<Mesh>;
using Polygons = std::vector<std::vector<std::size_t>>;
using Geodesic_ridge::Invalid_mesh_error;
using Geodesic_ridge::Mesh_file_error;
using Geodesic_ridge::Repairable_mesh_error;
namespace gp = Geodesic_ridge::parameters;

struct Soup
{
  std::vector<Point_3> points;
  Polygons faces;
};

// A file in a directory of its own, removed at the end of the test.
class Temp_file
{
  fs::path dir_;
  std::string path_;

public:
  Temp_file(const std::string& name, const std::string& content)
  {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() /
           ("geodesic_ridge_repair_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(dir_);
    path_ = (dir_ / name).string();
    std::ofstream(path_, std::ios::binary) << content;
  }
  ~Temp_file()
  {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  const std::string& path() const { return path_; }
};

std::string to_off(const Soup& s)
{
  std::ostringstream out;
  out.precision(17);
  out << "OFF\n" << s.points.size() << " " << s.faces.size() << " 0\n";
  for(const Point_3& p : s.points)
    out << p << "\n";
  for(const auto& f : s.faces)
  {
    out << f.size();
    for(std::size_t i : f)
      out << " " << i;
    out << "\n";
  }
  return out.str();
}

using Geodesic_ridge::testing::message_of;

// A unit cube of 6 outward quads; vertex 4x + 2y + z is at (x, y, z).
Soup cube_of_quads()
{
  Soup s;
  for(int x : {0, 1})
    for(int y : {0, 1})
      for(int z : {0, 1})
        s.points.emplace_back(x, y, z);
  s.faces = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
  return s;
}

// A pentagonal prism: bottom and top pentagons (faces 0 and 1), 5 side quads.
Soup pentagonal_prism()
{
  Soup s;
  for(double z : {0., 1.})
    for(int k = 0; k < 5; ++k)
      s.points.emplace_back(std::cos(2 * CGAL_PI * k / 5), std::sin(2 * CGAL_PI * k / 5), z);
  s.faces = {{4, 3, 2, 1, 0}, {5, 6, 7, 8, 9}};
  for(std::size_t k = 0; k < 5; ++k)
    s.faces.push_back({k, (k + 1) % 5, 5 + (k + 1) % 5, 5 + k});
  return s;
}

// An octahedron, outward.
Soup octahedron()
{
  Soup s;
  s.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for(std::size_t x : {0, 1})
    for(std::size_t y : {2, 3})
      for(std::size_t z : {4, 5})
        s.faces.push_back((x + y + z) % 2 == 0 ? std::vector<std::size_t>{x, y, z} : std::vector<std::size_t>{x, z, y});
  return s;
}

// A tube between two rings of n vertices, each closed by a cone to the same
// apex, vertex 0: a sphere pinched at vertex 0. Cone A (faces 0..n-1) has
// radius 1, cone B (the last n faces) radius 1.5.
Soup pinched_sphere(std::size_t n = 6)
{
  Soup s;
  s.points.emplace_back(0, 0, 0);
  for(double y : {1., -1.})
    for(std::size_t k = 0; k < n; ++k)
    {
      const double r = y > 0 ? 1 : 1.5, t = 2 * CGAL_PI * double(k) / double(n);
      s.points.emplace_back(r * std::cos(t), y, 2 + r * std::sin(t));
    }
  auto a = [&](std::size_t k) { return 1 + k % n; };
  auto b = [&](std::size_t k) { return 1 + n + k % n; };
  for(std::size_t k = 0; k < n; ++k)
    s.faces.push_back({0, a(k + 1), a(k)});
  for(std::size_t k = 0; k < n; ++k)
  {
    s.faces.push_back({a(k), a(k + 1), b(k + 1)});
    s.faces.push_back({a(k), b(k + 1), b(k)});
  }
  for(std::size_t k = 0; k < n; ++k)
    s.faces.push_back({0, b(k), b(k + 1)});
  return s;
}

Mesh::Vertex_index vertex(std::size_t i) { return Mesh::Vertex_index(static_cast<Mesh::size_type>(i)); }
Mesh::Face_index face(std::size_t j) { return Mesh::Face_index(static_cast<Mesh::size_type>(j)); }

// The point of a file location: its coordinates times the file face's vertices.
Point_3 point_of(const Geodesic_ridge::File_face_location& l, const Soup& s)
{
  double x = 0, y = 0, z = 0;
  REQUIRE(l.coordinates.size() == s.faces[l.face].size());
  for(std::size_t k = 0; k < l.coordinates.size(); ++k)
  {
    const Point_3& p = s.points[s.faces[l.face][k]];
    x += l.coordinates[k] * p.x();
    y += l.coordinates[k] * p.y();
    z += l.coordinates[k] * p.z();
  }
  return Point_3(x, y, z);
}

// Checks every map of `map` against the file `s`: each mesh vertex is at the
// position of its file vertex, and is one of that file vertex's mesh
// vertices; each mesh face is one of its file face's faces; and a point of
// each mesh face, converted to the file's terms and back, stays where it is.
void check_against_file(const Mesh& tm, const Map& map, const Soup& s)
{
  REQUIRE(map.number_of_file_vertices() == s.points.size());
  REQUIRE(map.number_of_file_faces() == s.faces.size());
  for(Mesh::Vertex_index v : tm.vertices())
  {
    const std::size_t fv = map.file_vertex(v, tm);
    CHECK(tm.point(v) == s.points[fv]);
    const auto vs = map.vertices(fv);
    CHECK(std::find(vs.begin(), vs.end(), v) != vs.end());
  }
  for(Mesh::Face_index f : tm.faces())
  {
    const std::size_t ff = map.file_face(f, tm);
    const auto fs = map.faces(ff);
    CHECK(std::find(fs.begin(), fs.end(), f) != fs.end());
    const std::pair<Mesh::Face_index, std::array<double, 3>> loc(f, {{0.2, 0.3, 0.5}});
    const Point_3 p = PMP::construct_point(loc, tm);
    const Geodesic_ridge::File_face_location l = map.file_location(loc, tm);
    CHECK(l.face == ff);
    CHECK(std::sqrt(CGAL::squared_distance(point_of(l, s), p)) < 1e-12);
    for(const auto& back : {map.locate(l.face, p, tm), map.location(l.face, l.coordinates, tm)})
    {
      REQUIRE(back);
      CHECK(std::sqrt(CGAL::squared_distance(PMP::construct_point(*back, tm), p)) < 1e-12);
      CHECK((std::min)({back->second[0], back->second[1], back->second[2]}) > -1e-12);
    }
  }
}

// The faces of tm as cyclic triples of file vertices, starting at the smallest.
std::multiset<std::array<std::size_t, 3>> file_triangles(const Mesh& tm, const Map& map)
{
  std::multiset<std::array<std::size_t, 3>> result;
  for(Mesh::Face_index f : tm.faces())
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(tm.halfedge(f), tm))
      t[k++] = map.file_vertex(v, tm);
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    result.insert(t);
  }
  return result;
}

// The triangles of CGAL's triangulate_faces on the polygon mesh of `s`, as
// cyclic triples of its vertices, starting at the smallest.
std::multiset<std::array<std::size_t, 3>> cgal_triangles(const Soup& s)
{
  Mesh polygons;
  for(const Point_3& p : s.points)
    polygons.add_vertex(p);
  for(const auto& f : s.faces)
  {
    std::vector<Mesh::Vertex_index> vs;
    for(std::size_t i : f)
      vs.push_back(vertex(i));
    REQUIRE(polygons.add_face(vs) != Mesh::null_face());
  }
  REQUIRE(PMP::triangulate_faces(polygons));
  std::multiset<std::array<std::size_t, 3>> cgal;
  for(Mesh::Face_index f : polygons.faces())
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(polygons.halfedge(f), polygons))
      t[k++] = v.idx();
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    cgal.insert(t);
  }
  return cgal;
}

Map read(const Soup& s, Mesh& tm, bool repair = false)
{
  const Temp_file file("mesh.off", to_off(s));
  return Geodesic_ridge::IO::read_triangle_mesh(file.path(), tm, gp::repair(repair));
}

// An octahedron whose face (1,0,x) below edge 0-2 is split at the edge's
// midpoint m (vertex 6), the gap closed by the cap (0, m, 2), face 9: exactly
// collinear.
Soup octahedron_with_cap()
{
  Soup s = octahedron();
  std::size_t below = 0, above = 0;
  for(std::size_t j = 0; j < s.faces.size(); ++j)
  {
    const auto& f = s.faces[j];
    for(std::size_t k = 0; k < 3; ++k)
    {
      if(f[k] == 2 && f[(k + 1) % 3] == 0) below = j;
      if(f[k] == 0 && f[(k + 1) % 3] == 2) above = j;
    }
  }
  REQUIRE(below != above); // the octahedron is closed: edge 0-2 has a face on each side
  const std::size_t x = s.faces[below][0] + s.faces[below][1] + s.faces[below][2] - 2; // its third vertex
  s.points.emplace_back(0.5, 0.5, 0); // vertex 6: the midpoint of 0-2
  s.faces[below] = {2, 6, x};
  s.faces.push_back({6, 0, x});
  s.faces.push_back({0, 6, 2}); // face 9: the cap
  return s;
}

// A closed tetrahedron away from the origin (faces 0 to 3) and, as face 4, a
// polygon of the given corners, each a vertex of its own (vertices 4 on).
Soup tetrahedron_and_polygon(const std::vector<Point_3>& corners)
{
  Soup s;
  s.points = {{0, 0, 50}, {1, 0, 50}, {0, 1, 50}, {0, 0, 51}};
  s.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  s.faces.emplace_back();
  for(const Point_3& p : corners)
  {
    s.faces.back().push_back(s.points.size());
    s.points.push_back(p);
  }
  return s;
}

// Polygon 4 of `s` (tetrahedron_and_polygon()) is refused without the
// repair, for the reason `why`, and removed by it: the tetrahedron is left.
void check_untriangulable(const Soup& s, const std::string& why)
{
  Mesh tm;
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }),
             Contains("face 4 (" + std::to_string(s.faces[4].size()) + " vertices) cannot be triangulated: " + why));
  const Map map = read(s, tm, true);
  CHECK(map.statistics().removed_degenerate_faces == 1);
  CHECK(map.faces(4).empty());
  CHECK(tm.number_of_faces() == 4);
  CHECK(tm.number_of_vertices() == 4);
  CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(tm));
  check_against_file(tm, map, s);
}

} // namespace

// ---------------------------------------------------------------------------
// Polygons, triangulated on reading

TEST_CASE("polygons are triangulated on reading by CGAL's rule, face j staying in file face j", "[repair][polygons]")
{
  const Soup s = pentagonal_prism();
  Mesh tm;
  const Map map = read(s, tm);
  const auto& st = map.statistics();
  CHECK(st.triangulated_polygons == 7);
  CHECK(st.triangles_from_polygons == 16);
  CHECK(st.non_planar_polygons == 0);
  CHECK_FALSE(st.repaired);
  CHECK(st.repair_report().empty());
  CHECK_THAT(st.triangulation_note(), Contains("7 polygons triangulated into 16 triangles; 0 not planar"));
  REQUIRE(tm.number_of_faces() == 16);
  REQUIRE(tm.number_of_vertices() == 10);
  for(std::size_t j = 0; j < 7; ++j)
  {
    CHECK(map.file_face(face(j), tm) == j);
    CHECK(map.faces(j).size() == (j < 2 ? 3u : 2u));
  }
  for(std::size_t i = 0; i < 10; ++i)
    CHECK(map.file_vertex(vertex(i), tm) == i);
  check_against_file(tm, map, s);

  // the same triangles as CGAL's triangulate_faces on the polygon mesh
  CHECK(file_triangles(tm, map) == cgal_triangles(s));

  SECTION("a vertex out of the plane of its polygons makes them non-planar")
  {
    Soup bent = s;
    // out of the top pentagon's plane and of its two side quads' planes
    bent.points[7] = Point_3(1.25 * bent.points[7].x(), 1.25 * bent.points[7].y(), 1.25);
    Mesh tm2;
    CHECK(read(bent, tm2).statistics().non_planar_polygons == 3);
  }
}

TEST_CASE("the refusals name file indices, and the ones the repair fixes are Repairable_mesh_error", "[repair][messages]")
{
  // a tetrahedron without its face (1, 2, 3), an isolated vertex in front:
  // with --repair the mesh's vertices are the file's shifted by one
  Soup open;
  open.points = {{9, 9, 9}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  open.faces = {{1, 3, 2}, {1, 2, 4}, {1, 4, 3}};
  Mesh tm;
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(open, tm); }), Contains("vertex 0 is isolated"));
  // repaired, it is an open surface (a border is supported): its vertices are the file's shifted by one
  const auto map = read(open, tm, true);
  CHECK(tm.number_of_vertices() == 4);
  CHECK(map.file_vertex(*tm.vertices().begin(), tm) == 1);

  // a quad with a repeated vertex, a 2-gon: refused, the repair removes them
  Soup s = cube_of_quads();
  s.faces.push_back({0, 1, 0, 2});
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }), Contains("face 6 repeats vertex 0"));
  s.faces.back() = {3, 5};
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }),
             Contains("face 6 has 2 vertices; a face needs at least 3"));
  CHECK(read(s, tm, true).statistics().removed_invalid_faces == 1);
}

// ---------------------------------------------------------------------------
// One test per kind of repair, the maps checked against the file

TEST_CASE("repair: an isolated vertex is removed and the other indices are translated", "[repair][isolated]")
{
  Soup s = cube_of_quads();
  s.points.insert(s.points.begin() + 2, Point_3(5, 5, 5));
  for(auto& f : s.faces)
    for(std::size_t& i : f)
      i += i >= 2 ? 1 : 0;
  Mesh tm;
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }), Contains("vertex 2 is isolated"));
  const Map map = read(s, tm, true);
  const auto& st = map.statistics();
  CHECK(st.repaired);
  CHECK(st.removed_isolated_vertices == 1);
  CHECK(st.triangulated_polygons == 6);
  CHECK(st.merged_vertices + st.removed_invalid_faces + st.removed_duplicate_faces + st.split_non_manifold_edges +
          st.split_non_manifold_vertices + st.removed_degenerate_faces + st.reoriented_faces == 0);
  CHECK(tm.number_of_vertices() == 8);
  CHECK(map.vertices(2).empty());
  CHECK_FALSE(map.vertex(2, tm));
  for(std::size_t v = 0; v < 9; ++v)
    if(v != 2)
    {
      REQUIRE(map.vertex(v, tm));
      CHECK(tm.point(*map.vertex(v, tm)) == s.points[v]);
      CHECK(map.file_vertex(vertex(v < 2 ? v : v - 1), tm) == v); // the file's order, kept
    }
  for(std::size_t j = 0; j < 6; ++j)
    CHECK(map.faces(j).size() == 2);
  check_against_file(tm, map, s);
  const auto lines = st.repair_report();
  CHECK(lines.size() == 8);
  CHECK(std::find(lines.begin(), lines.end(), "repair: 1 isolated vertices removed") != lines.end());
}

TEST_CASE("repair: a pinched vertex is split, and stands for the copy with the largest incident area",
          "[repair][non-manifold]")
{
  const Soup s = pinched_sphere();
  Mesh tm;
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }),
             Contains("vertex 0 is non-manifold (its faces form 2 separate fans)"));
  const Map map = read(s, tm, true); // one closed sphere once split
  CHECK(map.statistics().split_non_manifold_vertices == 1);
  CHECK(map.statistics().added_vertex_copies == 1);
  CHECK(tm.number_of_vertices() == s.points.size() + 1);
  const auto copies = map.vertices(0);
  REQUIRE(copies.size() == 2);
  CHECK(copies[0] == vertex(0));
  CHECK(copies[1] == vertex(1)); // right after the vertex it copies
  REQUIRE(map.vertex(0, tm));
  const Mesh::Vertex_index source = *map.vertex(0, tm);
  for(Mesh::Face_index f : CGAL::faces_around_target(tm.halfedge(source), tm))
    CHECK(map.file_face(f, tm) >= 18); // cone B, the larger
  check_against_file(tm, map, s);
}

TEST_CASE("repair: a non-manifold edge is split where the faces allow it", "[repair][non-manifold]")
{
  // two tetrahedra glued along edge 0-1: four faces on it
  Soup s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0.5, 1}, {0.5, -1, 0}, {0.5, -0.5, -1}};
  s.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {1, 0, 4}, {0, 5, 4}, {1, 4, 5}, {0, 1, 5}};
  Mesh tm;
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }),
             Contains("edge 0-1 is non-manifold: it is shared by 4 faces"));
  const Geodesic_ridge::Repaired_soup<Point_3> r = Geodesic_ridge::repair_mesh(s.points, s.faces);
  CHECK(r.statistics.split_non_manifold_edges == 1);
  CHECK(r.statistics.split_non_manifold_vertices == 2);
  CHECK(r.statistics.added_vertex_copies == 2);
  CHECK(r.points.size() == 8);
  CHECK(r.vertex_to_file == std::vector<std::size_t>{0, 0, 1, 1, 2, 3, 4, 5});
  CHECK(r.face_to_file == std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7});
  // two closed tetrahedra now: read in two parts (the algorithm takes one of them)
  read(s, tm, true);
  CHECK(tm.number_of_faces() == 8);
  CHECK(tm.number_of_vertices() == 8);
  CHECK_THAT(message_of<Invalid_mesh_error>([&] { Geodesic_ridge::validate_triangle_soup(r.points, r.triangles); }),
             Contains("2 connected components"));
}

TEST_CASE("repair: degenerate faces are removed, and the faces around them keep a file face that holds them",
          "[repair][degenerate]")
{
  const Soup s = octahedron_with_cap();
  Mesh tm;
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }), Contains("face 9 is degenerate"));
  const Map map = read(s, tm, true);
  CHECK(map.statistics().removed_degenerate_faces == 1);
  CHECK(map.faces(9).empty());
  CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(tm));
  check_against_file(tm, map, s);
  // every face lies in its file face: its corners are in the file face's plane, inside it
  for(Mesh::Face_index f : tm.faces())
  {
    const auto& ff = s.faces[map.file_face(f, tm)];
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(tm.halfedge(f), tm))
    {
      CHECK(CGAL::coplanar(s.points[ff[0]], s.points[ff[1]], s.points[ff[2]], tm.point(v)));
      const auto b = PMP::barycentric_coordinates(s.points[ff[0]], s.points[ff[1]], s.points[ff[2]], tm.point(v));
      CHECK((std::min)({b[0], b[1], b[2]}) > -1e-12);
    }
  }
}

TEST_CASE("repair: an inconsistent orientation is fixed by reversing the fewer faces", "[repair][orientation]")
{
  for(bool most : {false, true})
  {
    INFO((most ? "all faces but face 0 reversed" : "face 0 reversed"));
    Soup s = octahedron();
    for(std::size_t j = 0; j < s.faces.size(); ++j)
      if((j == 0) != most)
        std::reverse(s.faces[j].begin(), s.faces[j].end());
    Mesh tm;
    CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }), Contains("inconsistently oriented"));
    const Map map = read(s, tm, true);
    CHECK(map.statistics().reoriented_faces == 1);
    check_against_file(tm, map, s);
    // face 0 is the one reversed: its corners run against the file's order
    REQUIRE(map.faces(0).size() == 1);
    std::vector<std::size_t> around;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(tm.halfedge(map.faces(0)[0]), tm))
      around.push_back(map.file_vertex(v, tm));
    std::vector<std::size_t> reversed(s.faces[0].rbegin(), s.faces[0].rend());
    std::rotate(reversed.begin(), std::find(reversed.begin(), reversed.end(), around[0]), reversed.end());
    CHECK(around == reversed);
  }
}

TEST_CASE("repair: vertices at one position are merged; faces with repeated vertices and duplicates removed",
          "[repair][merge]")
{
  // a tetrahedron whose vertex 3 is also vertex 4 (same position) in one face,
  // with a duplicate of face 0 and a face repeating a vertex
  Soup s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}};
  s.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 4}, {0, 1, 2}, {2, 2, 3}};
  Mesh tm;
  // without the repair: the first rule broken, and the hint that vertices coincide
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }), Contains("face 5 repeats vertex 2"));
  s.faces.pop_back();
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }), Contains("faces 0 and 4 are duplicates"));
  s.faces.pop_back();
  // (without the repair, the two copies of vertex 3 leave an open surface: a
  // border is supported, so it is read as such, the copies counted)
  Map open_map;
  CHECK_NOTHROW(open_map = read(s, tm));
  CHECK(tm.number_of_vertices() == 5);
  CHECK(open_map.statistics().repeated_positions == 1);
  s.faces.push_back({0, 1, 2});
  s.faces.push_back({2, 2, 3});
  const Map map = read(s, tm, true);
  const auto& st = map.statistics();
  CHECK(st.merged_vertices == 1);
  CHECK(st.removed_duplicate_faces == 1);
  CHECK(st.removed_invalid_faces == 1);
  CHECK(st.removed_isolated_vertices == 0);
  CHECK(tm.number_of_vertices() == 4);
  CHECK(tm.number_of_faces() == 4);
  CHECK(map.vertices(4) == map.vertices(3));
  CHECK(map.file_vertex(map.vertices(4)[0], tm) == 3);
  CHECK(map.faces(5).empty());
  CHECK(map.faces(0).size() + map.faces(4).size() == 1);
  check_against_file(tm, map, s);
}

TEST_CASE("repair: degenerate faces are removed when the file has an isolated vertex too", "[repair][degenerate]")
{
  // CGAL's remove_degenerate_faces() asserts that its mesh is valid, which a
  // vertex of no face is not (fuzzed OBJ and OFF files): such vertices are
  // removed before it
  Soup s = octahedron_with_cap();
  s.points.emplace_back(7, 7, 7);
  Mesh tm;
  const Map map = read(s, tm, true);
  CHECK(map.statistics().removed_degenerate_faces == 1);
  CHECK(map.statistics().removed_isolated_vertices == 1);
  CHECK(map.faces(9).empty());
  CHECK(map.vertices(7).empty());
  CHECK_NOTHROW(Geodesic_ridge::validate_triangle_mesh(tm));
  check_against_file(tm, map, s);
}

TEST_CASE("repair: a vertex CGAL adds while removing degenerate faces is given the file vertex at its position",
          "[repair][degenerate]")
{
  // (found by fuzzing) four corners on the line x = y = 1: removing the flat
  // faces, CGAL splits an edge at (1, 1, 1), vertex 6, with a vertex of its
  // own, which had no file vertex (an index out of range in the map back)
  Soup s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 4}, {1, 1, 0}, {0, 0, 2}, {1, 1, 5}, {1, 1, 1}, {0, 1, 1}};
  s.faces = {{1}, {0, 3, 2, 1}, {1, 5, 6, 7}, {0, 1, 4, 4}, {0, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  Mesh tm;
  const Map map = read(s, tm, true);
  CHECK(map.statistics().removed_degenerate_faces == 2);
  for(Mesh::Vertex_index v : tm.vertices())
    CHECK(tm.point(v) == s.points[map.file_vertex(v, tm)]);
  REQUIRE(map.vertices(6).size() == 1);
  CHECK(tm.point(map.vertices(6)[0]) == s.points[6]);
  // (the faces CGAL flipped across the quads, not planar, lie in no file
  // face: their locations are not checked)
  for(Mesh::Face_index f : tm.faces())
    CHECK(map.file_face(f, tm) < s.faces.size());
}

// ---------------------------------------------------------------------------
// Polygons CGAL's triangulation cannot take (issue 41: fuzzed files crashed in it)

TEST_CASE("a polygon through a position twice is refused, and removed by the repair, not given to CGAL",
          "[repair][polygons][untriangulable]")
{
  // The polygons of the fuzzed OBJ files on which CGAL's triangulate_face()
  // failed its assertions (the repair's merge had made each repeated position
  // one vertex): h0, h1 and h2 != halfedge_descriptor(), a Surface_mesh
  // property index in range, and its constrained triangulation's vaa != vbb
  // and "insert ok". Here each corner is a vertex of its own.
  const std::vector<std::pair<std::vector<Point_3>, std::string>> polygons = {
    {{{0, 15, 6}, {-1, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, -1}}, "5 and 7"},
    {{{1, 1, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 1}, {1, 11, 0}, {1, 1, 1}, {0, 1, 1}}, "4 and 7"},
    {{{0, 4, 0}, {6, 1, 10}, {0, 4, 0}, {0, 0, 1}, {0, 0, 2}, {2, 6, 5}}, "4 and 6"},
    {{{0, 0, 0}, {8, 1, 0}, {1, 1, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}, "6 and 8"},
    {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0, 0, 1}}, "4 and 7"},
    {{{6, 1, 1}, {0, 5, 0}, {0, 10, 1}, {0, 0, 2}, {0, 10, 1}}, "6 and 8"}};
  for(const auto& p : polygons)
  {
    INFO("vertices " << p.second);
    check_untriangulable(tetrahedron_and_polygon(p.first), "its vertices " + p.second + " are at the same position");
  }
  // with the vertex itself repeated, the soup's rules refuse it first
  Soup s = tetrahedron_and_polygon(polygons[0].first);
  s.faces[4][3] = s.faces[4][1];
  Mesh tm;
  CHECK_THAT(message_of<Repairable_mesh_error>([&] { read(s, tm); }), Contains("face 4 repeats vertex 5"));
  CHECK(read(s, tm, true).statistics().removed_degenerate_faces == 1);
  CHECK(tm.number_of_faces() == 4);
}

TEST_CASE("a polygon whose outline touches or crosses itself is refused, and removed by the repair",
          "[repair][polygons][untriangulable]")
{
  std::vector<Point_3> pentagram;
  for(int k = 0; k < 5; ++k)
    pentagram.emplace_back(std::cos(4 * CGAL_PI * k / 5), std::sin(4 * CGAL_PI * k / 5), 0);
  // a corner on another edge (CGAL's constrained triangulation looped
  // forever), an edge folding back over the one before (a corner was lost),
  // a pentagram (CGAL's triangulation computes the crossings, in a projection
  // whose rounded predicates may contradict them: its "insert ok" assertion),
  // and a polygon far from planar whose outline crosses itself only seen
  // along its normal, as CGAL projects it (along x, its normal's largest
  // coordinate, the outline is simple)
  const std::vector<std::vector<Point_3>> polygons = {{{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {2, 0, 0}, {0, 2, 0}},
                                                      {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                                      pentagram,
                                                      {{-2, 1, 3}, {3, 3, -3}, {-1, -3, 0}, {3, 0, 0}, {2, 0, 3}}};
  for(std::size_t i = 0; i < polygons.size(); ++i)
  {
    INFO("polygon " << i);
    check_untriangulable(tetrahedron_and_polygon(polygons[i]), "its outline touches or crosses itself");
  }
  // collinear corners and a null normal (an outline enclosing no area), quads too
  check_untriangulable(tetrahedron_and_polygon({{0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {2, 2, 2}, {-1, -1, -1}}),
                       "its vertices are collinear");
  check_untriangulable(tetrahedron_and_polygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}),
                       "its normal is null (its outline encloses no area)");
}

TEST_CASE("simple polygons are still triangulated as CGAL does: non-convex, with straight corners, not planar",
          "[repair][polygons]")
{
  // an L of 7 corners, one of them straight, in a tilted plane; bent out of
  // it; with a corner a hair (not exactly) off another edge; far from planar,
  // its outline crossing itself along x (its normal's largest coordinate)
  // but not along its normal, as CGAL projects it
  std::vector<Point_3> l_shape;
  for(const auto& xy : std::vector<std::array<double, 2>>{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})
    l_shape.emplace_back(xy[0], xy[1], 0.3 * xy[0] + 0.7 * xy[1]);
  std::vector<Point_3> bent = l_shape;
  bent[4] = Point_3(1, 1, 3);
  const std::vector<Point_3> hair = {{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {2, 1e-9, 0}, {0, 2, 0}};
  const std::vector<Point_3> wild = {{2, 2, 1}, {0, 1, 3}, {2, -2, -1}, {-1, 1, 0}, {3, 1, 0}};
  for(const auto& corners : {l_shape, bent, hair, wild})
  {
    Soup s;
    s.points = corners;
    s.faces.emplace_back(corners.size());
    std::iota(s.faces[0].begin(), s.faces[0].end(), std::size_t(0));
    INFO(to_off(s));
    for(bool repair : {false, true})
    {
      Mesh tm;
      const Map map = read(s, tm, repair);
      CHECK(map.statistics().triangles_from_polygons == corners.size() - 2);
      CHECK(map.statistics().removed_degenerate_faces == 0);
      CHECK(file_triangles(tm, map) == cgal_triangles(s));
    }
  }
}

// ---------------------------------------------------------------------------
// PLY face layouts

namespace {

std::string tetrahedron_ply(const std::string& face_element)
{
  return "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n" +
         face_element.substr(0, face_element.find("DATA")) + "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" +
         face_element.substr(face_element.find("DATA") + 5);
}

} // namespace

TEST_CASE("PLY: triangle strips and 8- and 16-bit index lists are read; other face layouts refused by name",
          "[repair][ply]")
{
  // the faces a strip stands for, in strip order; -1 restarts a strip, and a
  // triangle that repeats a vertex (joining strips) is no face
  const std::vector<std::array<std::size_t, 3>> expected = {{0, 1, 2}, {2, 1, 3}, {2, 3, 0}, {0, 3, 1}};
  for(const std::string strips : {"9 0 1 2 3 -1 2 3 0 1\n", "10 0 1 2 3 3 2 2 3 0 1\n", "4 0 1 2 3\n4 2 3 0 1\n"})
  {
    INFO(strips);
    const std::size_t n = std::count(strips.begin(), strips.end(), '\n');
    const Temp_file file("strips.ply", tetrahedron_ply("element tristrips " + std::to_string(n) +
                                                       "\nproperty list int int vertex_indices\nDATA\n" + strips));
    Mesh tm;
    const Map map = Geodesic_ridge::IO::read_triangle_mesh(file.path(), tm);
    REQUIRE(tm.number_of_faces() == 4);
    REQUIRE(map.number_of_file_faces() == 4);
    for(std::size_t j = 0; j < 4; ++j)
    {
      std::vector<std::size_t> around, want(expected[j].begin(), expected[j].end());
      for(Mesh::Vertex_index v : CGAL::vertices_around_face(tm.halfedge(face(j)), tm))
        around.push_back(v.idx());
      std::rotate(around.begin(), std::find(around.begin(), around.end(), want[0]), around.end());
      CHECK(around == want);
      CHECK(map.file_face_vertices(j) == want);
    }
  }
  for(const std::string type : {"uchar", "char", "ushort", "short"})
  {
    INFO(type);
    const Temp_file file("small.ply", tetrahedron_ply("element face 4\nproperty list uchar " + type +
                                                      " vertex_indices\nDATA\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"));
    Mesh tm;
    CHECK_NOTHROW(Geodesic_ridge::IO::read_triangle_mesh(file.path(), tm));
    CHECK(tm.number_of_faces() == 4);
  }
  const std::vector<std::pair<std::string, std::string>> refused = {
    {"element range_grid 4\nproperty list uchar int vertex_indices\nDATA\n1 0\n1 1\n1 2\n1 3\n",
     "element 'range_grid' holds vertex-index lists in a layout this reader does not take"},
    {"element tristrips 1\nproperty list int float vertex_indices\nDATA\n4 0 1 2 3\n",
     "element 'tristrips': property 'vertex_indices' is a list of non-integer numbers"},
    {"element face 1\nproperty list uchar int corners\nDATA\n3 0 1 2\n",
     "element 'face' has no 'vertex_indices' list"}};
  for(const auto& r : refused)
  {
    INFO(r.first);
    const Temp_file file("refused.ply", tetrahedron_ply(r.first));
    Mesh tm;
    const std::string msg =
      message_of<Mesh_file_error>([&] { Geodesic_ridge::IO::read_triangle_mesh(file.path(), tm); });
    CHECK_THAT(msg, Contains(r.second));
    CHECK_THAT(msg, Contains("refused.ply"));
  }
}
