// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Many sources on one mesh: what does not depend on the source (the mesh's
// validation, its index maps, its corner angles and curvature) is done once,
// and the sources run in parallel with TBB when CGAL is linked with it.
#ifndef GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGES_H
#define GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGES_H

#include <Geodesic_ridge/compute_geodesic_ridge.h>
#include <Geodesic_ridge/internal/corner_angles.h>

#include <CGAL/tags.h>

#include <boost/iterator/function_output_iterator.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <iterator>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace Geodesic_ridge {
namespace internal {

// The sources of a batch, validated and made in input order (a bad one is
// reported before any work, as with one source).
template <class TriangleMesh, class SourceRange, class NamedParameters>
std::vector<Geodesic_source<TriangleMesh> > make_sources(const TriangleMesh& tm, const SourceRange& sources,
                                                         const NamedParameters& np)
{
  std::vector<Geodesic_source<TriangleMesh> > made;
  for(const auto& s : sources) made.push_back(make_source(tm, s, np));
  return made;
}

// Computes `compute(i)` for i in [0, n) and hands the results to `write` in
// order of i: serially, or with TBB in a pipeline whose middle stage runs in
// parallel and whose last stage writes in order as soon as a result's
// predecessors are written, a few results per thread in flight (a result
// holds the extended surface's data: keeping many at once costs more in the
// allocator than it saves). The first exception, in order of i, is rethrown
// after the results before it are written.
template <class ConcurrencyTag, class Compute, class Write>
void compute_in_order(std::size_t n, const Compute& compute, const Write& write)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value)
  {
    typedef std::decay_t<decltype(compute(std::size_t(0)))> Result;
    struct Item
    {
      std::size_t index = 0;
      std::optional<Result> result;
      std::exception_ptr error;
    };
    typedef std::shared_ptr<Item> Item_ptr;
    std::size_t next = 0;
    std::exception_ptr first_error; // read by the first and written by the last stage, both serial
    std::atomic<bool> failed(false);
    const std::size_t in_flight = 2 * static_cast<std::size_t>(std::max(1, tbb::this_task_arena::max_concurrency()));
    auto take = [&](tbb::flow_control& control) -> Item_ptr {
      if(next == n || failed.load()) { control.stop(); return nullptr; }
      auto item = std::make_shared<Item>();
      item->index = next++;
      return item;
    };
    auto run = [&](Item_ptr item) -> Item_ptr {
      if(failed.load()) return item; // no result: it will not be written
      try
      {
        item->result.emplace(compute(item->index));
      }
      catch(...)
      {
        item->error = std::current_exception();
      }
      return item;
    };
    auto put = [&](Item_ptr item) {
      if(first_error || (!item->result && !item->error)) return; // after a failure: not written
      if(item->error)
      {
        first_error = item->error;
        failed.store(true);
        return;
      }
      write(std::move(*item->result));
      item->result.reset();
    };
    tbb::parallel_pipeline(in_flight,
                           tbb::make_filter<void, Item_ptr>(tbb::filter_mode::serial_in_order, take) &
                               tbb::make_filter<Item_ptr, Item_ptr>(tbb::filter_mode::parallel, run) &
                               tbb::make_filter<Item_ptr, void>(tbb::filter_mode::serial_in_order, put));
    if(first_error) std::rethrow_exception(first_error);
    return;
  }
#else
  static_assert(!std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag needs TBB (CGAL_LINKED_WITH_TBB); use CGAL::Parallel_if_available_tag");
#endif
  for(std::size_t i = 0; i < n; ++i) write(compute(i));
}

} // namespace internal

/// \ingroup PkgGeodesicRidgeRef
/// \brief computes the ridge curve of every source of `sources` on `tm` and
/// writes the `Ridge_curve`s to `out`, in the order of `sources`; each is
/// the one `compute_ridge_curve()` returns for that source, bit for bit.
///
/// What does not depend on the source is done once: the mesh's validation,
/// its index maps, its corner angles and Gaussian curvature. With
/// `ConcurrencyTag` = `CGAL::Parallel_tag` (or the default
/// `CGAL::Parallel_if_available_tag` when \cgal is linked with TBB,
/// `CGAL_LINKED_WITH_TBB`) the sources run in parallel (a TBB pipeline), and
/// each result is written, in order, as soon as those before it are: memory
/// holds about two results per thread.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`
/// \tparam SourceRange a range of sources: vertex descriptors of `tm`, or
///         `Face_location`s (`std::pair<face_descriptor, std::array<FT, 3>>`)
/// \tparam OutputIterator an output iterator accepting the `Ridge_curve` that
///         `compute_ridge_curve()` returns
///
/// \param tm the mesh
/// \param sources the sources
/// \param out the output iterator
/// \param np the named parameters of `compute_ridge_curve()`, the same for every source
/// \returns `out` past the last ridge curve
///
/// \pre The preconditions of `compute_ridge_curve()`, for every source: the
///      mesh, every source and the parameters are checked before any ridge is
///      computed (`Input_error` naming the problem; for a bad source,
///      `Invalid_source_error`).
///
/// If the computation of a source throws (`Algorithm_error`), the ridges of
/// the sources before it are written and its exception is rethrown; the
/// sources after it may have been computed, but are not written.
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class TriangleMesh, class SourceRange,
          class OutputIterator, class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator compute_ridge_curves(const TriangleMesh& tm, const SourceRange& sources, OutputIterator out,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  internal::get_tolerance(np);
  internal::pipeline_options(np, choose_parameter(get_parameter(np, internal_np::solver_t()), Exact_solver()));
  // on the unit mesh, as compute_ridge_curve() (internal/normalization.h)
  internal::Normalization n;
  const auto unit_np = internal::unit_parameters(tm, np, n);
  validate_triangle_mesh(tm, unit_np);
  // the index maps are initialized here, before any thread reads them
  const auto maps = internal::mesh_maps(tm, unit_np);
  const auto made = internal::make_sources(tm, sources, unit_np);
  const internal::Corner_angles angles = internal::corner_angles(tm, maps.vpm, maps.vim, maps.fim);
  internal::compute_in_order<ConcurrencyTag>(
      made.size(),
      [&](std::size_t i) {
        auto rc = internal::ridge_curve_impl(tm, made[i], unit_np, &angles);
        internal::map_from_unit(rc, n);
        return rc;
      },
      [&](auto&& result) { *out++ = std::move(result); });
  return out;
}

/// \ingroup PkgGeodesicRidgeRef
/// \brief computes the geodesic ridge of every source of `sources` on `tm`
/// and writes, per source and in their order, its polylines
/// (`std::vector<std::vector<Point_3>>`) to `out`: the batch version of
/// `compute_geodesic_ridge()`, through `compute_ridge_curves()` (whose
/// parameters, preconditions and concurrency it shares).
template <class ConcurrencyTag = CGAL::Parallel_if_available_tag, class TriangleMesh, class SourceRange,
          class OutputIterator, class NamedParameters = CGAL::parameters::Default_named_parameters>
OutputIterator compute_geodesic_ridges(const TriangleMesh& tm, const SourceRange& sources, OutputIterator out,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  auto polylines_of = [&out](const auto& rc) {
    typedef std::decay_t<decltype(rc.polylines[0][0].point)> Point_3;
    std::vector<std::vector<Point_3> > polylines;
    ridge_polyline_points(rc.ridge_polylines(), std::back_inserter(polylines));
    *out++ = std::move(polylines);
  };
  compute_ridge_curves<ConcurrencyTag>(tm, sources, boost::make_function_output_iterator(polylines_of), np);
  return out;
}

} // namespace Geodesic_ridge

#endif // GEODESIC_RIDGE_COMPUTE_GEODESIC_RIDGES_H
