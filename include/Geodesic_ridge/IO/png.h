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
// the curves over it.
template <class TriangleMesh, class VertexPointMap, class Point_3, class Colour>
void render(const std::string& filename, const TriangleMesh& tm, VertexPointMap vpm,
            const std::vector<Png_curves<Point_3> >& curves, int size, std::array<double, 3> view,
            const Colour& colour)
{
  typedef std::array<double, 3> V3;
  auto sub = [](const V3& a, const V3& b) { return V3{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; };
  auto cross = [](const V3& a, const V3& b) {
    return V3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  };
  auto dot = [](const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto unit = [&](V3 a) { const double l = std::sqrt(dot(a, a)); for(double& x : a) x /= l; return a; };
  auto to3 = [](const auto& p) { return V3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}}; };

  V3 lo = {{1e300, 1e300, 1e300}}, hi = {{-1e300, -1e300, -1e300}};
  for(auto v : vertices(tm))
  {
    const V3 p = to3(get(vpm, v));
    for(int k = 0; k < 3; ++k) { lo[k] = std::min(lo[k], p[k]); hi[k] = std::max(hi[k], p[k]); }
  }
  const V3 center = {{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}};
  const double radius = std::sqrt(dot(sub(hi, lo), sub(hi, lo))) / 2;
  const int W = 2 * size, H = size;
  std::vector<unsigned char> rgb(static_cast<std::size_t>(3 * W * H), 255);
  std::vector<double> depth(static_cast<std::size_t>(W * H), std::numeric_limits<double>::infinity());

  for(int side = 0; side < 2; ++side)
  {
    const V3 d = unit(side == 0 ? view : V3{{-view[0], -view[1], -view[2]}}); // looking direction
    const V3 up0 = std::abs(d[1]) < 0.9 ? V3{{0, 1, 0}} : V3{{0, 0, 1}};
    const V3 right = unit(cross(d, up0)), up = cross(right, d);
    const int x0 = side * size;
    auto project = [&](const V3& p, double& sx, double& sy, double& sz) {
      const V3 q = sub(p, center);
      sx = x0 + size / 2.0 + dot(q, right) / radius * size * 0.47;
      sy = size / 2.0 - dot(q, up) / radius * size * 0.47;
      sz = dot(q, d);
    };
    for(auto f : faces(tm))
    {
      const auto h = halfedge(f, tm);
      const V3 p[3] = {to3(get(vpm, source(h, tm))), to3(get(vpm, target(h, tm))),
                       to3(get(vpm, target(next(h, tm), tm)))};
      V3 n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
      const double nl = std::sqrt(dot(n, n));
      if(nl == 0) continue;
      for(double& x : n) x /= nl;
      const double shade = 0.35 + 0.6 * std::abs(dot(n, d));
      double sx[3], sy[3], sz[3];
      for(int k = 0; k < 3; ++k) project(p[k], sx[k], sy[k], sz[k]);
      const int xmin = std::max(x0, static_cast<int>(std::floor(std::min({sx[0], sx[1], sx[2]}))));
      const int xmax = std::min(x0 + size - 1, static_cast<int>(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
      const int ymin = std::max(0, static_cast<int>(std::floor(std::min({sy[0], sy[1], sy[2]}))));
      const int ymax = std::min(H - 1, static_cast<int>(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
      const double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
      if(area == 0) continue;
      for(int y = ymin; y <= ymax; ++y)
        for(int x = xmin; x <= xmax; ++x)
        {
          const double px = x + 0.5, py = y + 0.5;
          const double w0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
          const double w1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
          const double w2 = 1 - w0 - w1;
          if(w0 < 0 || w1 < 0 || w2 < 0) continue;
          const double z = w0 * sz[0] + w1 * sz[1] + w2 * sz[2];
          const std::size_t i = static_cast<std::size_t>(y * W + x);
          if(z >= depth[i]) continue;
          depth[i] = z;
          const auto c = colour(h, w0, w1, w2, shade);
          rgb[3 * i] = c[0]; rgb[3 * i + 1] = c[1]; rgb[3 * i + 2] = c[2];
        }
    }
    const double offset = 0.01 * radius;
    for(const auto& c : curves)
      for(const auto& pl : c.polylines)
        for(std::size_t i = 0; i + 1 < pl.size(); ++i)
        {
          double ax, ay, az, bx, by, bz;
          project(to3(pl[i]), ax, ay, az);
          project(to3(pl[i + 1]), bx, by, bz);
          const int steps = 1 + static_cast<int>(std::max(std::abs(bx - ax), std::abs(by - ay)));
          for(int s = 0; s <= steps; ++s)
          {
            const double t = double(s) / steps;
            const double x = ax + t * (bx - ax), y = ay + t * (by - ay), z = az + t * (bz - az);
            for(int dy = -c.width_pixels / 2; dy <= c.width_pixels / 2; ++dy)
              for(int dx = -c.width_pixels / 2; dx <= c.width_pixels / 2; ++dx)
              {
                const int X = static_cast<int>(x) + dx, Y = static_cast<int>(y) + dy;
                if(X < x0 || X >= x0 + size || Y < 0 || Y >= H) continue;
                const std::size_t i2 = static_cast<std::size_t>(Y * W + X);
                if(z - offset > depth[i2]) continue;
                rgb[3 * i2] = c.rgb[0]; rgb[3 * i2 + 1] = c.rgb[1]; rgb[3 * i2 + 2] = c.rgb[2];
              }
          }
        }
  }
  write_rgb_png(filename, W, H, rgb);
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
                 double shade) {
    const unsigned char g = static_cast<unsigned char>(255 * std::min(1.0, shade));
    return std::array<unsigned char, 3>{{g, g, static_cast<unsigned char>(std::min(255, g + 12))}};
  };
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
/// levels, so that iso-lines show.
template <class TriangleMesh, class VertexPointMap, class VertexValueMap, class Point_3>
void write_png(const std::string& filename, const TriangleMesh& tm, VertexPointMap vpm, VertexValueMap values,
               double largest, int bands, const std::vector<Png_curves<Point_3> >& curves, int size = 600,
               std::array<double, 3> view = {{0.3, -0.4, -1.0}})
{
  auto coloured = [&](typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, double w0, double w1,
                      double w2, double shade) {
    const double d = w0 * get(values, source(h, tm)) + w1 * get(values, target(h, tm)) +
                     w2 * get(values, target(next(h, tm), tm));
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
