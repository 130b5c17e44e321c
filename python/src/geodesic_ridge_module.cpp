// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module `geodesic_ridge._geodesic_ridge`: the package's functions
// on NumPy arrays (python/geodesic_ridge/__init__.py adds the Python side).
// A mesh is V (n, 3) float64 and F (m, 3) integers, 0-based; vertex i is V[i]
// and face j is F[j] in the results too. Every computation releases the GIL;
// every error of the package is one of the module's exceptions, with the C++
// message.
#include "../../examples/cli/statistics_json.h"

#include <Geodesic_ridge/IO/read_triangle_mesh.h>
#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/compute_geodesic_ridges.h>
#include <Geodesic_ridge/distance_field.h>
#include <Geodesic_ridge/isolines.h>
#include <Geodesic_ridge/mesh_validation.h>
#include <Geodesic_ridge/refined_mesh.h>
#include <Geodesic_ridge/solvers/Dijkstra_solver.h>
#include <Geodesic_ridge/solvers/Exact_solver.h>
#include <Geodesic_ridge/solvers/Fast_marching_solver.h>
#include <Geodesic_ridge/solvers/Heat_method_solver.h>
#include <Geodesic_ridge/solvers/Window_propagation_solver.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace GR = Geodesic_ridge;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;
typedef CGAL::Polygon_mesh_processing::Face_location<Mesh, double> Location;
typedef GR::Ridge_curve<Mesh, Point_3> Ridge_curve;
typedef decltype(GR::make_distance_field(std::declval<const Mesh&>(), std::declval<const Ridge_curve&>())) Field_type;

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Doubles;

// ---------------------------------------------------------------------------
// Exceptions: geodesic_ridge.Error and its subclasses, made here so that the
// four input errors also derive from ValueError and AlgorithmError from
// RuntimeError (pybind11's register_exception takes a single base).

struct Python_exceptions
{
  PyObject* error = nullptr;
  PyObject* mesh_file = nullptr;
  PyObject* invalid_mesh = nullptr;
  PyObject* invalid_source = nullptr;
  PyObject* invalid_parameter = nullptr;
  PyObject* algorithm = nullptr;
};
Python_exceptions exceptions;

PyObject* new_exception(py::module_& m, const char* name, PyObject* base, PyObject* builtin, const char* doc)
{
  py::tuple bases = builtin ? py::make_tuple(py::handle(base), py::handle(builtin)) : py::make_tuple(py::handle(base));
  const std::string qualified = std::string("geodesic_ridge.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if(!type) throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return type;
}

void register_exceptions(py::module_& m)
{
  exceptions.error = new_exception(m, "Error", PyExc_Exception, nullptr, "Base class of every error of geodesic_ridge.");
  exceptions.mesh_file = new_exception(m, "MeshFileError", exceptions.error, PyExc_ValueError,
                                       "A mesh file cannot be opened, has an unknown extension or is malformed.");
  exceptions.invalid_mesh = new_exception(m, "InvalidMeshError", exceptions.error, PyExc_ValueError,
                                          "The mesh breaks a rule of the package (the message names it and the "
                                          "first offending vertex or face).");
  exceptions.invalid_source = new_exception(m, "InvalidSourceError", exceptions.error, PyExc_ValueError,
                                            "A source (or a query point) is not on the mesh.");
  exceptions.invalid_parameter = new_exception(m, "InvalidParameterError", exceptions.error, PyExc_ValueError,
                                               "A named parameter is unknown or out of its range.");
  exceptions.algorithm = new_exception(m, "AlgorithmError", exceptions.error, PyExc_RuntimeError,
                                       "A postcondition of the algorithm failed (please report it with the mesh).");
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p) std::rethrow_exception(p);
    }
    catch(const GR::Mesh_file_error& e) { PyErr_SetString(exceptions.mesh_file, e.what()); }
    catch(const GR::Invalid_mesh_error& e) { PyErr_SetString(exceptions.invalid_mesh, e.what()); }
    catch(const GR::Invalid_source_error& e) { PyErr_SetString(exceptions.invalid_source, e.what()); }
    catch(const GR::Invalid_parameter_error& e) { PyErr_SetString(exceptions.invalid_parameter, e.what()); }
    catch(const GR::Algorithm_error& e) { PyErr_SetString(exceptions.algorithm, e.what()); }
    catch(const GR::Error& e) { PyErr_SetString(exceptions.error, e.what()); }
  });
}

// ---------------------------------------------------------------------------
// The mesh from NumPy, validated once.

// The mesh and, per face, where CGAL's corner order starts in F's row: CGAL's
// corner k (source(halfedge(f)), its target, the next target) is F[f][(k +
// rotation[f]) % 3]. Barycentric coordinates in and out are in F's order.
struct Mesh_data
{
  Mesh mesh;
  std::vector<unsigned char> rotation;

  std::array<double, 3> to_cgal(std::size_t f, const std::array<double, 3>& b) const
  {
    const int r = rotation[f];
    return {{b[r], b[(1 + r) % 3], b[(2 + r) % 3]}};
  }
  std::array<double, 3> from_cgal(std::size_t f, const std::array<double, 3>& b) const
  {
    std::array<double, 3> out;
    for(int k = 0; k < 3; ++k) out[(k + rotation[f]) % 3] = b[k];
    return out;
  }
};

std::shared_ptr<const Mesh_data> mesh_from_arrays(const py::array& V_in, const py::array& F_in)
{
  const Doubles V = Doubles::ensure(V_in);
  if(!V || V.ndim() != 2 || V.shape(1) != 3)
    throw GR::Invalid_mesh_error("V must be an array of shape (n, 3) of numbers");
  if(F_in.ndim() != 2 || F_in.shape(1) != 3)
    throw GR::Invalid_mesh_error("F must be an array of shape (m, 3) of integers (triangles)");
  const char kind = F_in.dtype().kind(); // 'i' signed, 'u' unsigned integers
  if(F_in.size() > 0 && kind != 'i' && kind != 'u')
    throw GR::Invalid_mesh_error("F must hold integers (int32 or int64), not " + std::string(py::str(F_in.dtype())));
  const auto F = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(F_in);
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  {
    auto v = V.unchecked<2>();
    auto f = F.unchecked<2>();
    points.reserve(v.shape(0));
    for(py::ssize_t i = 0; i < v.shape(0); ++i) points.emplace_back(v(i, 0), v(i, 1), v(i, 2));
    triangles.reserve(f.shape(0));
    for(py::ssize_t j = 0; j < f.shape(0); ++j)
    {
      std::array<std::size_t, 3> t;
      for(int k = 0; k < 3; ++k)
      {
        if(f(j, k) < 0)
          throw GR::Invalid_mesh_error("face " + std::to_string(j) + " has a negative vertex index (" +
                                       std::to_string(f(j, k)) + ")");
        t[k] = static_cast<std::size_t>(f(j, k));
      }
      triangles.push_back(t);
    }
  }
  auto data = std::make_shared<Mesh_data>();
  {
    py::gil_scoped_release release;
    GR::validate_triangle_soup(points, triangles);
    Mesh& mesh = data->mesh;
    for(const Point_3& p : points) mesh.add_vertex(p);
    for(const auto& t : triangles)
    {
      const face_descriptor f = mesh.add_face(vertex_descriptor(static_cast<Mesh::size_type>(t[0])),
                                              vertex_descriptor(static_cast<Mesh::size_type>(t[1])),
                                              vertex_descriptor(static_cast<Mesh::size_type>(t[2])));
      if(f == Mesh::null_face())
        throw GR::Algorithm_error("a validated face could not be added to the mesh"); // (the validation's rules forbid it)
      const std::size_t first = mesh.source(mesh.halfedge(f));
      data->rotation.push_back(static_cast<unsigned char>(first == t[0] ? 0 : first == t[1] ? 1 : 2));
    }
  }
  return data;
}

// ---------------------------------------------------------------------------
// The named parameters, from keyword arguments. Every one is passed to the
// pipeline, the defaults being the package's (`cone_ridge`: with the cone
// field or a solver with cones), so that one chain type serves every call.

struct Options
{
  std::string solver = "exact";
  double tolerance = GR::default_tolerance;
  double leaf_curvature = GR::default_leaf_curvature;
  double branch_curvature = GR::default_branch_curvature;
  int initial_rings = GR::default_initial_rings;
  int extension_step = GR::default_extension_step;
  int maximum_rings = GR::default_maximum_rings;
  int maximum_solves = GR::default_maximum_solves;
  bool tree_from_solver = false;
  bool predicted_extension = true;
  int fast_marching_margin = GR::default_fast_marching_margin;
  double minimum_spur_angle = GR::default_minimum_spur_angle;
  double kink_angle = GR::default_kink_angle;
  bool corner_fallback = true;
  GR::Field field = GR::Field::linear;
  std::optional<bool> cone_ridge;
  double cone_ridge_tolerance = GR::default_cone_ridge_tolerance;
};

const char* const solver_names = "exact, vtp, fmm, heat, heat-idt, dijkstra";

GR::Field field_of(const py::handle& value)
{
  if(!py::isinstance<py::str>(value)) throw GR::Invalid_parameter_error("field must be 'linear' or 'cone'");
  const std::string s = value.cast<std::string>();
  if(s == "linear") return GR::Field::linear;
  if(s == "cone") return GR::Field::cone;
  throw GR::Invalid_parameter_error("field must be 'linear' or 'cone', not '" + s + "'");
}

template <class T>
T number_of(const std::string& name, const py::handle& value)
{
  const bool is_bool = py::isinstance<py::bool_>(value);
  if constexpr(std::is_same<T, bool>::value)
  {
    if(!is_bool && !(py::hasattr(value, "dtype") && std::string(py::str(value.attr("dtype"))) == "bool"))
      throw GR::Invalid_parameter_error(name + " must be True or False");
    return value.cast<bool>();
  }
  else
  {
    if(is_bool || !(py::isinstance<py::int_>(value) || py::hasattr(value, "__index__") ||
                    (std::is_floating_point<T>::value && py::isinstance<py::float_>(value)) ||
                    (std::is_floating_point<T>::value && py::hasattr(value, "__float__"))))
      throw GR::Invalid_parameter_error(name + (std::is_integral<T>::value ? " must be an integer" : " must be a number"));
    if constexpr(std::is_integral<T>::value)
    {
      const long long x = py::int_(py::reinterpret_borrow<py::object>(value)).cast<long long>();
      if(x < std::numeric_limits<T>::min() || x > std::numeric_limits<T>::max())
        throw GR::Invalid_parameter_error(name + " is out of range");
      return static_cast<T>(x);
    }
    else
      return py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
  }
}

// Every named parameter once: how a keyword sets it and how the statistics
// report it.
struct Parameter
{
  std::string name;
  std::function<void(Options&, const py::handle&)> set;
  std::function<nlohmann::ordered_json(const Options&)> get;
};

template <class T>
Parameter member(const std::string& name, T Options::*m)
{
  return {name, [name, m](Options& o, const py::handle& value) { o.*m = number_of<T>(name, value); },
          [m](const Options& o) { return nlohmann::ordered_json(o.*m); }};
}

const std::vector<Parameter>& parameters()
{
  static const std::vector<Parameter> all = {
      member("tolerance", &Options::tolerance),
      member("leaf_curvature", &Options::leaf_curvature),
      member("branch_curvature", &Options::branch_curvature),
      member("initial_rings", &Options::initial_rings),
      member("extension_step", &Options::extension_step),
      member("maximum_rings", &Options::maximum_rings),
      member("maximum_solves", &Options::maximum_solves),
      member("tree_from_solver", &Options::tree_from_solver),
      member("predicted_extension", &Options::predicted_extension),
      member("fast_marching_margin", &Options::fast_marching_margin),
      member("minimum_spur_angle", &Options::minimum_spur_angle),
      member("kink_angle", &Options::kink_angle),
      member("corner_fallback", &Options::corner_fallback),
      {"field", [](Options& o, const py::handle& value) { o.field = field_of(value); },
       [](const Options& o) { return nlohmann::ordered_json(o.field == GR::Field::cone ? "cone" : "linear"); }},
      // None: the package's default (with the cone field or a solver with cones)
      {"cone_ridge",
       [](Options& o, const py::handle& value) {
         if(value.is_none()) o.cone_ridge.reset();
         else o.cone_ridge = number_of<bool>("cone_ridge", value);
       },
       [](const Options& o) { return o.cone_ridge ? nlohmann::ordered_json(*o.cone_ridge) : nlohmann::ordered_json(); }},
      member("cone_ridge_tolerance", &Options::cone_ridge_tolerance)};
  return all;
}

Options options_from(const std::string& solver, const py::dict& kwargs)
{
  Options o;
  o.solver = solver;
  if(solver != "exact" && solver != "vtp" && solver != "fmm" && solver != "heat" && solver != "heat-idt" &&
     solver != "dijkstra")
    throw GR::Invalid_parameter_error("unknown solver '" + solver + "': one of " + solver_names);
  for(const auto& [key, value] : kwargs)
  {
    const std::string k = py::str(key);
    const auto& all = parameters();
    const auto p = std::find_if(all.begin(), all.end(), [&](const Parameter& q) { return q.name == k; });
    if(p == all.end())
    {
      std::string names;
      for(const Parameter& q : all) names += (names.empty() ? "" : ", ") + q.name;
      throw GR::Invalid_parameter_error("unknown named parameter '" + k + "'; the named parameters are " + names);
    }
    p->set(o, value);
  }
  return o;
}

// Calls f with the named parameters of `o`: one instantiation per solver.
template <class F>
auto with_parameters(const Options& o, const F& f)
{
  namespace p = GR::parameters;
  auto with = [&](const auto& solver) {
    typedef std::decay_t<decltype(solver)> Solver;
    const bool cone_ridge =
        o.cone_ridge ? *o.cone_ridge : (o.field == GR::Field::cone || GR::Geodesic_solver_traits<Solver>::has_cones);
    return f(p::solver(solver)
                 .tolerance(o.tolerance)
                 .leaf_curvature(o.leaf_curvature)
                 .branch_curvature(o.branch_curvature)
                 .initial_rings(o.initial_rings)
                 .extension_step(o.extension_step)
                 .maximum_rings(o.maximum_rings)
                 .maximum_solves(o.maximum_solves)
                 .tree_from_solver(o.tree_from_solver)
                 .predicted_extension(o.predicted_extension)
                 .fast_marching_margin(o.fast_marching_margin)
                 .minimum_spur_angle(o.minimum_spur_angle)
                 .kink_angle(o.kink_angle)
                 .corner_fallback(o.corner_fallback)
                 .field(o.field)
                 .cone_ridge(cone_ridge)
                 .cone_ridge_tolerance(o.cone_ridge_tolerance));
  };
  if(o.solver == "vtp") return with(GR::Window_propagation_solver());
  if(o.solver == "fmm") return with(GR::Fast_marching_solver());
  if(o.solver == "heat") return with(GR::Heat_method_solver<>());
  if(o.solver == "heat-idt") return with(GR::Heat_method_idt_solver());
  if(o.solver == "dijkstra") return with(GR::Dijkstra_solver());
  return with(GR::Exact_solver());
}

// ---------------------------------------------------------------------------
// Sources: a vertex index, or a surface point (face, barycentric): an object
// with `face` and `barycentric` (geodesic_ridge.SurfacePoint) or a pair.

struct Source
{
  std::optional<vertex_descriptor> vertex;
  Location point;
};

Source source_from(const Mesh_data& data, const py::handle& s)
{
  const Mesh& mesh = data.mesh;
  if(!py::isinstance<py::bool_>(s) && (py::isinstance<py::int_>(s) || (py::hasattr(s, "__index__") && !py::hasattr(s, "__len__"))))
  {
    const long long v = py::int_(py::reinterpret_borrow<py::object>(s)).cast<long long>();
    if(v < 0 || v >= static_cast<long long>(mesh.number_of_vertices()))
      throw GR::Invalid_source_error("source vertex " + std::to_string(v) + " is not a vertex of the mesh (it has " +
                                     std::to_string(mesh.number_of_vertices()) + " vertices)");
    return {vertex_descriptor(static_cast<Mesh::size_type>(v)), Location()};
  }
  py::object face, barycentric;
  if(py::hasattr(s, "face") && py::hasattr(s, "barycentric"))
  {
    face = s.attr("face");
    barycentric = s.attr("barycentric");
  }
  else if(py::isinstance<py::sequence>(s) && !py::isinstance<py::str>(s) && py::len(s) == 2)
  {
    face = s[py::int_(0)];
    barycentric = s[py::int_(1)];
  }
  else
    throw GR::Invalid_source_error("a source is a vertex index or a SurfacePoint(face, barycentric)");
  if(py::isinstance<py::bool_>(face) || !(py::isinstance<py::int_>(face) || py::hasattr(face, "__index__")))
    throw GR::Invalid_source_error("a source's face must be an integer");
  const long long f = py::int_(face).cast<long long>();
  if(f < 0 || f >= static_cast<long long>(mesh.number_of_faces()))
    throw GR::Invalid_source_error("source face " + std::to_string(f) + " is not a face of the mesh (it has " +
                                   std::to_string(mesh.number_of_faces()) + " faces)");
  const Doubles b = Doubles::ensure(barycentric);
  if(!b || b.size() != 3) throw GR::Invalid_source_error("a source's barycentric coordinates are 3 numbers");
  // (the package checks that they are finite, non-negative and sum to 1)
  return {std::nullopt, Location(face_descriptor(static_cast<Mesh::size_type>(f)),
                                 data.to_cgal(static_cast<std::size_t>(f), {{b.at(0), b.at(1), b.at(2)}}))};
}

Ridge_curve compute(const Mesh& mesh, const Source& source, const Options& o)
{
  return with_parameters(o, [&](const auto& np) {
    return source.vertex ? GR::compute_ridge_curve(mesh, *source.vertex, np)
                         : GR::compute_ridge_curve(mesh, source.point, np);
  });
}

// ---------------------------------------------------------------------------
// Results as NumPy arrays.

template <class T>
py::array_t<T> array_of(const std::vector<T>& values)
{
  py::array_t<T> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

py::array_t<double> points_array(const std::vector<Point_3>& points)
{
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t(3)});
  auto m = a.mutable_unchecked<2>();
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int k = 0; k < 3; ++k) m(static_cast<py::ssize_t>(i), k) = CGAL::to_double(points[i][k]);
  return a;
}

// The vertices (n, 3) and triangles (m, 3) of a mesh without removed
// elements, in index order, each face from CGAL's first corner.
std::pair<py::array_t<double>, py::array_t<std::int64_t> > mesh_arrays(const Mesh& mesh)
{
  std::vector<Point_3> points(mesh.points().begin(), mesh.points().end());
  py::array_t<std::int64_t> F({static_cast<py::ssize_t>(mesh.number_of_faces()), py::ssize_t(3)});
  auto m = F.mutable_unchecked<2>();
  py::ssize_t i = 0;
  for(auto f : mesh.faces())
  {
    int k = 0;
    for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) m(i, k++) = static_cast<std::int64_t>(v.idx());
    ++i;
  }
  return {points_array(points), F};
}

py::object json_to_python(const nlohmann::ordered_json& j)
{
  return py::module_::import("json").attr("loads")(j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

/// The ridge of one source, as arrays (the polylines reported and their
/// points' locations); the C++ result stays for the distance field.
struct Ridge
{
  std::shared_ptr<const Mesh_data> mesh;
  std::shared_ptr<const Ridge_curve> curve;
  Options options; // the parameters it was computed with

  py::list polylines() const { return polylines_of(curve->ridge_polylines()); }
  py::list linear_polylines() const { return polylines_of(curve->polylines); }
  static py::list polylines_of(const Ridge_curve::Polylines& lines)
  {
    py::list out;
    for(const auto& line : lines)
    {
      std::vector<Point_3> points;
      for(const auto& p : line) points.push_back(p.point);
      out.append(points_array(points));
    }
    return out;
  }
  std::size_t size() const
  {
    std::size_t n = 0;
    for(const auto& line : curve->ridge_polylines()) n += line.size();
    return n;
  }
  py::array_t<std::int64_t> faces() const
  {
    std::vector<std::int64_t> f;
    for(const auto& line : curve->ridge_polylines())
      for(const auto& p : line) f.push_back(static_cast<std::int64_t>(p.face));
    return array_of(f);
  }
  py::array_t<double> barycentric() const
  {
    py::array_t<double> a({static_cast<py::ssize_t>(size()), py::ssize_t(3)});
    auto m = a.mutable_unchecked<2>();
    py::ssize_t i = 0;
    for(const auto& line : curve->ridge_polylines())
      for(const auto& p : line)
      {
        const auto b = mesh->from_cgal(p.face, p.barycentric);
        for(int k = 0; k < 3; ++k) m(i, k) = b[k];
        ++i;
      }
    return a;
  }
  py::array_t<double> angles() const
  {
    std::vector<double> a;
    for(const auto& line : curve->ridge_polylines())
      for(const auto& p : line) a.push_back(p.angle);
    return array_of(a);
  }
  py::array_t<double> vertex_distances() const { return array_of(curve->vertex_distances); }
  py::object statistics() const
  {
    nlohmann::ordered_json parameters = {{"solver", options.solver}};
    for(const Parameter& p : ::parameters()) parameters[p.name] = p.get(options);
    parameters["cone_ridge"] = curve->statistics.cone_ridge_traced; // (the default resolved)
    nlohmann::ordered_json j = {{"parameters", parameters}};
    j.update(geodesic_ridge_cli::ridge_json(*curve));
    j["timings_seconds"] = geodesic_ridge_cli::timings_json(*curve, 0);
    return json_to_python(j);
  }
};

/// The region-wise distance field of one source.
struct Distance_field
{
  std::shared_ptr<const Mesh_data> mesh;
  std::shared_ptr<const Ridge_curve> curve;
  std::shared_ptr<const Field_type> field;
  Options options;

  py::array_t<double> distance(const py::array& faces_in, const py::array& barycentric_in) const
  {
    const auto faces = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(faces_in);
    const Doubles b = Doubles::ensure(barycentric_in);
    if(!faces || faces.ndim() != 1) throw GR::Invalid_parameter_error("faces must be an array of shape (k,) of integers");
    if(!b || b.ndim() != 2 || b.shape(1) != 3 || b.shape(0) != faces.shape(0))
      throw GR::Invalid_parameter_error("barycentric must be an array of shape (k, 3), k = len(faces)");
    const py::ssize_t k = faces.shape(0);
    std::vector<Location> where(static_cast<std::size_t>(k));
    auto f = faces.unchecked<1>();
    auto c = b.unchecked<2>();
    const std::int64_t n = static_cast<std::int64_t>(mesh->mesh.number_of_faces());
    for(py::ssize_t i = 0; i < k; ++i)
    {
      if(f(i) < 0 || f(i) >= n)
        throw GR::Invalid_source_error("query " + std::to_string(i) + ": face " + std::to_string(f(i)) +
                                       " is not a face of the mesh (it has " + std::to_string(n) + " faces)");
      const std::array<double, 3> l = {{c(i, 0), c(i, 1), c(i, 2)}};
      for(double x : l)
        if(!std::isfinite(x) || x < -1e-12)
          throw GR::Invalid_source_error("query " + std::to_string(i) +
                                         ": barycentric coordinates must be finite and non-negative");
      if(std::abs(l[0] + l[1] + l[2] - 1) > 1e-9)
        throw GR::Invalid_source_error("query " + std::to_string(i) + ": barycentric coordinates must sum to 1");
      where[static_cast<std::size_t>(i)] =
          Location(face_descriptor(static_cast<Mesh::size_type>(f(i))), mesh->to_cgal(static_cast<std::size_t>(f(i)), l));
    }
    std::vector<double> d(where.size());
    {
      py::gil_scoped_release release;
      for(std::size_t i = 0; i < where.size(); ++i) d[i] = field->distance(where[i]);
    }
    return array_of(d);
  }
};

class Ridge_solver
{
public:
  Ridge_solver(const py::array& V, const py::array& F, const std::string& solver, const py::dict& kwargs)
    : options_(options_from(solver, kwargs)), mesh_(mesh_from_arrays(V, F))
  {
    // the parameters checked as every entry point checks them: a bad one is
    // reported here, before any work
    with_parameters(options_, [](const auto& np) {
      using CGAL::parameters::choose_parameter;
      using CGAL::parameters::get_parameter;
      GR::internal::get_tolerance(np);
      GR::internal::get_leaf_curvature(np);
      GR::internal::get_branch_curvature(np);
      GR::internal::pipeline_options(np, choose_parameter(get_parameter(np, GR::internal_np::solver_t()), GR::Exact_solver()));
      return 0;
    });
  }

  Ridge ridge(const py::handle& source) const { return {mesh_, run(source, options_), options_}; }

  Distance_field distance_field(const py::handle& source, const std::string& field) const
  {
    Options o = options_;
    o.field = field_of(py::str(field));
    auto curve = run(source, o);
    py::gil_scoped_release release;
    auto f = std::make_shared<const Field_type>(GR::make_distance_field(mesh(), *curve, GR::parameters::field(o.field)));
    return {mesh_, curve, f, o};
  }

  // (V2, F2, distance, original face of each face of the refined mesh)
  py::tuple refine(const py::handle& source) const
  {
    auto curve = run(source, options_);
    Mesh refined;
    std::vector<std::int64_t> original;
    {
      py::gil_scoped_release release;
      refine_into(*curve, refined, original);
    }
    return refined_arrays(refined, original);
  }

  py::list isolines(const py::handle& source, const py::object& values) const
  {
    auto curve = run(source, options_);
    std::vector<double> levels;
    const bool count = !py::isinstance<py::bool_>(values) && (py::isinstance<py::int_>(values) ||
                                                               (py::hasattr(values, "__index__") && !py::hasattr(values, "__len__")));
    if(count)
    {
      const long long n = py::int_(values).cast<long long>();
      if(n < 0 || n > 100000) throw GR::Invalid_parameter_error("the number of iso-lines must be in [0, 100000]");
      levels.resize(static_cast<std::size_t>(n));
    }
    else
    {
      const Doubles v = Doubles::ensure(values);
      if(!v || v.ndim() != 1) throw GR::Invalid_parameter_error("values must be an integer or a sequence of distances");
      for(py::ssize_t i = 0; i < v.shape(0); ++i)
      {
        if(!std::isfinite(v.at(i))) throw GR::Invalid_parameter_error("iso-line levels must be finite");
        levels.push_back(v.at(i));
      }
    }
    std::vector<GR::Isoline<Point_3> > lines;
    {
      py::gil_scoped_release release;
      Mesh refined;
      std::vector<std::int64_t> original;
      const auto distance = refine_into(*curve, refined, original);
      if(count)
      {
        double largest = 0;
        for(double d : curve->vertex_distances) largest = (std::max)(largest, d);
        for(auto v : refined.vertices()) largest = (std::max)(largest, distance[v]);
        levels = GR::equally_spaced_levels(levels.size(), largest);
      }
      GR::isolines(refined, distance, levels, std::back_inserter(lines));
    }
    py::module_ m = py::module_::import("geodesic_ridge");
    py::list out;
    for(const auto& l : lines) out.append(m.attr("Isoline")(l.level, points_array(l.points), l.closed));
    return out;
  }

  std::vector<Ridge> ridges(const py::iterable& sources, const std::optional<int>& threads) const
  {
    if(threads && *threads < 1) throw GR::Invalid_parameter_error("threads must be at least 1");
    std::vector<Source> parsed;
    bool all_vertices = true;
    for(const py::handle& s : sources)
    {
      parsed.push_back(source_from(*mesh_, s));
      all_vertices = all_vertices && parsed.back().vertex.has_value();
    }
    std::vector<std::shared_ptr<const Ridge_curve> > curves;
    {
      py::gil_scoped_release release;
      auto collect = boost::make_function_output_iterator(
          [&](auto&& rc) { curves.push_back(std::make_shared<const Ridge_curve>(std::forward<decltype(rc)>(rc))); });
      auto run_all = [&] {
        with_parameters(options_, [&](const auto& np) {
          if(all_vertices)
          {
            std::vector<vertex_descriptor> v;
            for(const Source& s : parsed) v.push_back(*s.vertex);
            GR::compute_ridge_curves<CGAL::Parallel_if_available_tag>(mesh(), v, collect, np);
          }
          else
          {
            std::vector<Location> l;
            for(const Source& s : parsed) l.push_back(s.vertex ? location_of(*s.vertex) : s.point);
            GR::compute_ridge_curves<CGAL::Parallel_if_available_tag>(mesh(), l, collect, np);
          }
          return 0;
        });
      };
#ifdef CGAL_LINKED_WITH_TBB
      if(threads)
        tbb::task_arena(*threads).execute(run_all);
      else
        run_all();
#else
      run_all();
#endif
    }
    std::vector<Ridge> out;
    for(auto& c : curves) out.push_back({mesh_, c, options_});
    return out;
  }

  std::size_t number_of_vertices() const { return mesh().number_of_vertices(); }
  std::size_t number_of_faces() const { return mesh().number_of_faces(); }
  const std::string& solver() const { return options_.solver; }

private:
  const Mesh& mesh() const { return mesh_->mesh; }

  std::shared_ptr<const Ridge_curve> run(const py::handle& source, const Options& o) const
  {
    const Source s = source_from(*mesh_, source);
    py::gil_scoped_release release;
    return std::make_shared<const Ridge_curve>(compute(mesh(), s, o));
  }

  // a vertex as a point of one of its faces
  Location location_of(vertex_descriptor v) const
  {
    const auto h = mesh().halfedge(v); // (validated: every vertex has a face)
    for(auto g : CGAL::halfedges_around_target(h, mesh()))
      if(!mesh().is_border(g))
      {
        const face_descriptor f = mesh().face(g);
        std::array<double, 3> b = {{0, 0, 0}};
        const auto h0 = mesh().halfedge(f);
        b[mesh().source(h0) == v ? 0 : mesh().target(h0) == v ? 1 : 2] = 1;
        return Location(f, b);
      }
    return Location(); // (unreachable)
  }

  Mesh::Property_map<vertex_descriptor, double> refine_into(const Ridge_curve& curve, Mesh& refined,
                                                           std::vector<std::int64_t>& original) const
  {
    auto distance = refined.add_property_map<vertex_descriptor, double>("v:distance", 0).first;
    struct Visitor
    {
      std::vector<std::int64_t>* original;
      void face_created(face_descriptor from, face_descriptor created)
      {
        if(original->size() <= static_cast<std::size_t>(created)) original->resize(static_cast<std::size_t>(created) + 1, -1);
        (*original)[static_cast<std::size_t>(created)] = static_cast<std::int64_t>(static_cast<std::size_t>(from));
      }
    };
    GR::refine_mesh_along_ridge(mesh(), curve, refined, CGAL::parameters::default_values(),
                                GR::parameters::vertex_distance_map(distance).visitor(Visitor{&original}));
    original.resize(refined.number_of_faces(), -1);
    return distance;
  }

  static py::tuple refined_arrays(const Mesh& refined, const std::vector<std::int64_t>& original)
  {
    auto distance = refined.property_map<vertex_descriptor, double>("v:distance").first;
    std::vector<double> d;
    for(auto v : refined.vertices()) d.push_back(distance[v]);
    const auto [V, F] = mesh_arrays(refined);
    return py::make_tuple(V, F, array_of(d), array_of(original));
  }

  Options options_;
  std::shared_ptr<const Mesh_data> mesh_;
};

py::tuple read_mesh(const std::string& path, bool repair)
{
  Mesh mesh;
  std::optional<GR::File_index_map<Mesh> > map;
  {
    py::gil_scoped_release release;
    map.emplace(GR::IO::read_triangle_mesh(path, mesh, GR::parameters::repair(repair)));
  }
  const auto [V, F] = mesh_arrays(mesh);
  // the map back to the file's indices, where the numbering changed
  bool same = mesh.number_of_vertices() == map->number_of_file_vertices() &&
              mesh.number_of_faces() == map->number_of_file_faces();
  std::vector<std::int64_t> file_vertex, file_face;
  for(auto v : mesh.vertices())
  {
    file_vertex.push_back(static_cast<std::int64_t>(map->file_vertex(v, mesh)));
    same = same && file_vertex.back() == static_cast<std::int64_t>(v.idx());
  }
  for(auto f : mesh.faces())
  {
    file_face.push_back(static_cast<std::int64_t>(map->file_face(f, mesh)));
    same = same && file_face.back() == static_cast<std::int64_t>(f.idx());
  }
  if(same) return py::make_tuple(V, F);
  py::module_ gr = py::module_::import("geodesic_ridge");
  return py::make_tuple(V, F, gr.attr("FileIndexMap")(array_of(file_vertex), array_of(file_face)));
}

} // namespace

PYBIND11_MODULE(_geodesic_ridge, m)
{
  m.doc() = "The geodesic ridge (cut locus) of a source on a triangle mesh, and its region-wise distance field.";
  register_exceptions(m);

  py::class_<Ridge>(m, "Ridge", "The ridge of one source: polylines and their points' surface locations.")
      .def_property_readonly("polylines", &Ridge::polylines,
                             "list of (k, 3) float64 arrays: the ridge reported (the cone ridge with exact and vtp), "
                             "polylines between junctions and free ends; a closed one repeats its first point")
      .def_property_readonly("linear_polylines", &Ridge::linear_polylines,
                             "list of (k, 3) arrays: the ridge of the region-wise linear field")
      .def_property_readonly("faces", &Ridge::faces, "(p,) int64: the face of each point of `polylines`, in order")
      .def_property_readonly("barycentric", &Ridge::barycentric,
                             "(p, 3) float64: each point's barycentric coordinates in its face (in F's corner order)")
      .def_property_readonly("angles", &Ridge::angles,
                             "(p,) float64: degrees between the arrival directions of the fronts meeting there")
      .def_property_readonly("vertex_distances", &Ridge::vertex_distances,
                             "(n,) float64: the solver's geodesic distance at each vertex")
      .def_property_readonly("statistics", &Ridge::statistics,
                             "dict: the mesh, the ridge's size, every stage's counts and timings (as the command "
                             "line's --stats JSON)")
      .def("__len__", [](const Ridge& r) { return r.curve->ridge_polylines().size(); })
      .def("__repr__", [](const Ridge& r) {
        const auto& s = r.curve->statistics.ridge;
        return "<Ridge: " + std::to_string(r.curve->ridge_polylines().size()) + " polylines, " +
               std::to_string(s.junctions) + " junctions, " + std::to_string(s.cycles) + " cycles>";
      });

  py::class_<Distance_field>(m, "DistanceField", "The region-wise geodesic distance field of one source.")
      .def("distance", &Distance_field::distance, py::arg("faces"), py::arg("barycentric"),
           "distances at k surface points: faces (k,) integers, barycentric (k, 3); returns (k,) float64")
      .def_property_readonly("kind", [](const Distance_field& d) {
        return d.field->field() == GR::Field::cone ? "cone" : "linear";
      })
      .def_property_readonly("maximum_distance", [](const Distance_field& d) { return d.field->maximum_distance(); })
      .def_property_readonly("vertex_distances", [](const Distance_field& d) { return array_of(d.curve->vertex_distances); })
      .def_property_readonly("ridge", [](const Distance_field& d) { return Ridge{d.mesh, d.curve, d.options}; });

  py::class_<Ridge_solver>(m, "RidgeSolver",
                           "A mesh validated once and the named parameters; computes ridges, distance fields, "
                           "refined meshes and iso-lines of sources on it.")
      .def(py::init([](const py::array& V, const py::array& F, const std::string& solver, const py::kwargs& kwargs) {
             return Ridge_solver(V, F, solver, kwargs);
           }),
           py::arg("V"), py::arg("F"), py::arg("solver") = "exact")
      .def("ridge", &Ridge_solver::ridge, py::arg("source"))
      .def("distance_field", &Ridge_solver::distance_field, py::arg("source"), py::arg("field") = "linear")
      .def("refine", &Ridge_solver::refine, py::arg("source"))
      .def("isolines", &Ridge_solver::isolines, py::arg("source"), py::arg("values"))
      .def("ridges", &Ridge_solver::ridges, py::arg("sources"), py::arg("threads") = py::none())
      .def_property_readonly("number_of_vertices", &Ridge_solver::number_of_vertices)
      .def_property_readonly("number_of_faces", &Ridge_solver::number_of_faces)
      .def_property_readonly("solver", &Ridge_solver::solver);

  m.def("read_mesh", &read_mesh, py::arg("path"), py::arg("repair") = false);
#ifdef CGAL_LINKED_WITH_TBB
  m.attr("parallel") = true;
#else
  m.attr("parallel") = false;
#endif
}
