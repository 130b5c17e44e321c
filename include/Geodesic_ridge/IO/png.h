// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A picture of a mesh with curves on it, as a PNG: a small z-buffer rasterizer
// (orthographic, two opposite views side by side, so that a ridge on the far
// side shows too); libpng encodes it. Programs that call write_png link libpng
// (CMake: find_package(PNG), PNG::PNG); including the header needs only <png.h>.
#ifndef GEODESIC_RIDGE_IO_PNG_H
#define GEODESIC_RIDGE_IO_PNG_H

#include <Geodesic_ridge/exceptions.h>
#include <Geodesic_ridge/internal/normalization.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>
#include <boost/graph/graph_traits.hpp>

#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace Geodesic_ridge {
namespace IO {

/// \ingroup PkgGeodesicRidgeIO
/// A curve to draw: polylines of points with `x()`, `y()`, `z()`, one colour.
template <class Point_3>
struct Png_curves
{
  std::vector<std::vector<Point_3> > polylines; ///< the polylines
  std::array<unsigned char, 3> rgb = {{220, 30, 30}}; ///< their colour (red, green, blue)
  int width_pixels = 2;                         ///< their width in pixels
};

namespace internal_png {

struct Close_file
{
  void operator()(std::FILE* f) const { std::fclose(f); }
};

// RGB image, rows top to bottom, compressed by libpng (its simplified API
// reports errors by return value, so no longjmp crosses C++ frames).
inline void write_rgb_png(const std::string& filename, int w, int h, const std::vector<unsigned char>& rgb)
{
  std::unique_ptr<std::FILE, Close_file> file(std::fopen(filename.c_str(), "wb"));
  if(!file) throw Error("cannot open '" + filename + "' for writing");
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(w);
  image.height = static_cast<png_uint_32>(h);
  image.format = PNG_FORMAT_RGB;
  const bool written = png_image_write_to_stdio(&image, file.get(), 0, rgb.data(), 3 * w, nullptr) != 0;
  const std::string message = image.message;
  png_image_free(&image);
  if(!written) throw Error("cannot write '" + filename + "': " + message);
  if(std::fclose(file.release()) != 0) throw Error("cannot write '" + filename + "'");
}

// Draws the mesh, coloured by colour(halfedge of the face, w0, w1, w2, shade)
// at each pixel (w: the weights of source(h), target(h), target(next(h))), and
// the curves over it, from two opposite views side by side. Geometry in the
// kernel's types (the mesh's points converted to doubles).
template <class TriangleMesh, class VertexPointMap, class Colour>
class Png_renderer
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef K::Point_3 Point_3;
  typedef K::Vector_3 Vector_3;
  typedef K::Point_2 Point_2;

public:
  Png_renderer(const TriangleMesh& tm, VertexPointMap vpm, int size, const Colour& colour)
    : tm_(tm), vpm_(vpm), size_(size), colour_(colour), rgb_(static_cast<std::size_t>(3 * 2 * size * size), 255),
      depth_(static_cast<std::size_t>(2 * size * size), std::numeric_limits<double>::infinity())
  {
    // drawn on the mesh moved and scaled to a unit size (at 1e-300 a squared
    // length is 0, at 1e300 infinite): the same picture at any scale
    internal::Normalization_of_points all;
    for(auto v : vertices(tm)) all.add(get(vpm, v));
    unit_ = all.normalization();
    CGAL::Bbox_3 box;
    for(auto v : vertices(tm)) box += point(get(vpm, v)).bbox();
    center_ = Point_3((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2, (box.zmin() + box.zmax()) / 2);
    radius_ = std::sqrt(CGAL::squared_distance(Point_3(box.xmin(), box.ymin(), box.zmin()),
                                               Point_3(box.xmax(), box.ymax(), box.zmax()))) / 2;
  }

  // view `side` (0 left, 1 right) looking along `direction`
  template <class Curve_point>
  void draw(int side, const Vector_3& direction, const std::vector<Png_curves<Curve_point> >& curves)
  {
    look_ = direction / std::sqrt(direction.squared_length());
    const Vector_3 up0 = std::abs(look_.y()) < 0.9 ? Vector_3(0, 1, 0) : Vector_3(0, 0, 1);
    right_ = CGAL::cross_product(look_, up0);
    right_ = right_ / std::sqrt(right_.squared_length());
    up_ = CGAL::cross_product(right_, look_);
    x0_ = side * size_;
    for(auto f : faces(tm_)) draw_face(halfedge(f, tm_));
    for(const auto& c : curves)
      for(const auto& pl : c.polylines)
        for(std::size_t i = 0; i + 1 < pl.size(); ++i) draw_segment(point(pl[i]), point(pl[i + 1]), c);
  }

  void write(const std::string& filename) const { write_rgb_png(filename, 2 * size_, size_, rgb_); }

private:
  template <class P>
  Point_3 point(const P& p) const
  {
    return unit_.to_unit(Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }

  // screen position and depth
  std::pair<Point_2, double> project(const Point_3& p) const
  {
    const Vector_3 q = p - center_;
    const double scale = 0.47 * size_ / radius_;
    return {Point_2(x0_ + size_ / 2.0 + (q * right_) * scale, size_ / 2.0 - (q * up_) * scale), q * look_};
  }

  void draw_face(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
  {
    const Point_3 p[3] = {point(get(vpm_, source(h, tm_))), point(get(vpm_, target(h, tm_))),
                          point(get(vpm_, target(next(h, tm_), tm_)))};
    const Vector_3 n = CGAL::normal(p[0], p[1], p[2]);
    if(n == CGAL::NULL_VECTOR) return;
    const double shade = 0.35 + 0.6 * std::abs(n * look_) / std::sqrt(n.squared_length());
    std::array<std::pair<Point_2, double>, 3> s = {{project(p[0]), project(p[1]), project(p[2])}};
    const double area = CGAL::area(s[0].first, s[1].first, s[2].first);
    if(area == 0) return;
    const CGAL::Bbox_2 box = s[0].first.bbox() + s[1].first.bbox() + s[2].first.bbox();
    const int xmin = (std::max)(x0_, static_cast<int>(std::floor(box.xmin())));
    const int xmax = (std::min)(x0_ + size_ - 1, static_cast<int>(std::ceil(box.xmax())));
    const int ymin = (std::max)(0, static_cast<int>(std::floor(box.ymin())));
    const int ymax = (std::min)(size_ - 1, static_cast<int>(std::ceil(box.ymax())));
    for(int y = ymin; y <= ymax; ++y)
      for(int x = xmin; x <= xmax; ++x)
      {
        const Point_2 px(x + 0.5, y + 0.5);
        const double w0 = CGAL::area(px, s[1].first, s[2].first) / area;
        const double w1 = CGAL::area(s[0].first, px, s[2].first) / area;
        const double w2 = 1 - w0 - w1;
        if(w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double z = w0 * s[0].second + w1 * s[1].second + w2 * s[2].second;
        const std::size_t i = pixel(x, y);
        if(z >= depth_[i]) continue;
        depth_[i] = z;
        set(i, colour_(h, w0, w1, w2, shade));
      }
  }

  // a curve segment, drawn where the surface does not hide it (a small depth
  // offset keeps curves on the surface visible)
  template <class Curves>
  void draw_segment(const Point_3& a, const Point_3& b, const Curves& c)
  {
    const auto [pa, za] = project(a);
    const auto [pb, zb] = project(b);
    const double offset = 0.01 * radius_;
    const int steps = 1 + static_cast<int>((std::max)(std::abs(pb.x() - pa.x()), std::abs(pb.y() - pa.y())));
    for(int k = 0; k <= steps; ++k)
    {
      const double t = double(k) / steps;
      const Point_2 q = pa + t * (pb - pa);
      const double z = za + t * (zb - za);
      for(int dy = -c.width_pixels / 2; dy <= c.width_pixels / 2; ++dy)
        for(int dx = -c.width_pixels / 2; dx <= c.width_pixels / 2; ++dx)
        {
          const int X = static_cast<int>(q.x()) + dx, Y = static_cast<int>(q.y()) + dy;
          if(X < x0_ || X >= x0_ + size_ || Y < 0 || Y >= size_) continue;
          const std::size_t i = pixel(X, Y);
          if(z - offset <= depth_[i]) set(i, c.rgb);
        }
    }
  }

  std::size_t pixel(int x, int y) const { return static_cast<std::size_t>(y * 2 * size_ + x); }
  void set(std::size_t i, const std::array<unsigned char, 3>& c)
  {
    rgb_[3 * i] = c[0];
    rgb_[3 * i + 1] = c[1];
    rgb_[3 * i + 2] = c[2];
  }

  const TriangleMesh& tm_;
  const VertexPointMap vpm_;
  const int size_;
  const Colour& colour_;
  std::vector<unsigned char> rgb_;
  std::vector<double> depth_;
  internal::Normalization unit_;
  Point_3 center_;
  double radius_ = 1;
  Vector_3 look_, right_, up_;
  int x0_ = 0;
};

template <class TriangleMesh, class VertexPointMap, class Point_3, class Colour>
void render(const std::string& filename, const TriangleMesh& tm, VertexPointMap vpm,
            const std::vector<Png_curves<Point_3> >& curves, int size, std::array<double, 3> view,
            const Colour& colour)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3 Vector_3;
  Png_renderer<TriangleMesh, VertexPointMap, Colour> renderer(tm, vpm, size, colour);
  const Vector_3 direction(view[0], view[1], view[2]);
  renderer.draw(0, direction, curves);
  renderer.draw(1, -direction, curves);
  renderer.write(filename);
}

// The plain surface's colour, Lambert-shaded.
inline std::array<unsigned char, 3> grey(double shade)
{
  const unsigned char g = static_cast<unsigned char>(255 * std::min(1.0, shade));
  return std::array<unsigned char, 3>{{g, g, static_cast<unsigned char>(std::min(255, g + 12))}};
}

} // namespace internal_png

/// \ingroup PkgGeodesicRidgeIO
/// Renders the triangle mesh (grey, Lambert-shaded) and the curves on it from
/// two opposite directions (left: looking along -view, right: along +view), and
/// writes a PNG of `2*size` × `size` pixels. Curves are drawn where they are
/// not hidden by the surface (a small depth offset keeps curves on it visible).
template <class TriangleMesh, class VertexPointMap, class Point_3>
void write_png(const std::string& filename, const TriangleMesh& tm, VertexPointMap vpm,
               const std::vector<Png_curves<Point_3> >& curves, int size = 600,
               std::array<double, 3> view = {{0.3, -0.4, -1.0}})
{
  auto grey = [](typename boost::graph_traits<TriangleMesh>::halfedge_descriptor, double, double, double,
                 double shade) { return internal_png::grey(shade); };
  internal_png::render(filename, tm, vpm, curves, size, view, grey);
}

/// \ingroup PkgGeodesicRidgeIO
/// The viridis colour map (a perceptual one) at t in [0, 1], as a polynomial fit.
inline std::array<double, 3> viridis(double t)
{
  t = std::max(0.0, std::min(1.0, t));
  static const double c[7][3] = {{0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
                                 {0.1050930431085774, 1.404613529898575, 1.384590162594685},
                                 {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
                                 {-4.634230498983486, -5.799100973351585, -19.33244095627987},
                                 {6.228269936347081, 14.17993336680509, 56.69055260068105},
                                 {4.776384997670288, -13.74514537774601, -65.35303263337234},
                                 {-5.435455855934631, 4.645852612178535, 26.3124352495832}};
  std::array<double, 3> rgb = {{0, 0, 0}};
  for(int k = 0; k < 3; ++k)
  {
    double v = 0;
    for(int i = 6; i >= 0; --i) v = v * t + c[i][k];
    rgb[k] = std::max(0.0, std::min(1.0, v));
  }
  return rgb;
}

/// \ingroup PkgGeodesicRidgeIO
/// Same as above, with the surface coloured by the field that interpolates
/// `values` (a vertex property map of doubles) linearly on each face: viridis
/// from 0 to `largest`, darkened in thin bands at `bands` equally spaced
/// levels, so that iso-lines show. A face with a vertex whose value is not
/// finite (a part of the mesh the source cannot reach: infinite distance) is
/// drawn grey, as by the function above.
template <class TriangleMesh, class VertexPointMap, class VertexValueMap, class Point_3>
void write_png(const std::string& filename, const TriangleMesh& tm, VertexPointMap vpm, VertexValueMap values,
               double largest, int bands, const std::vector<Png_curves<Point_3> >& curves, int size = 600,
               std::array<double, 3> view = {{0.3, -0.4, -1.0}})
{
  auto coloured = [&](typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, double w0, double w1,
                      double w2, double shade) {
    const double d = w0 * get(values, source(h, tm)) + w1 * get(values, target(h, tm)) +
                     w2 * get(values, target(next(h, tm), tm));
    if(!std::isfinite(d))
      return internal_png::grey(shade);
    const double t = largest > 0 ? d / largest : 0;
    const double phase = t * bands - std::floor(t * bands);
    const double band = (bands > 0 && (phase < 0.06 || phase > 0.94)) ? 0.45 : 1.0;
    const auto c = viridis(t);
    std::array<unsigned char, 3> rgb;
    for(int k = 0; k < 3; ++k)
      rgb[k] = static_cast<unsigned char>(255 * std::min(1.0, c[k] * band * (0.55 + 0.45 * shade)));
    return rgb;
  };
  internal_png::render(filename, tm, vpm, curves, size, view, coloured);
}

} // namespace IO
} // namespace Geodesic_ridge

#endif
