// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The quad edge length of each connected component: the global length, shortened on a component too
// small for it (a steering wheel inside a truck), so that every part keeps its shape.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_COMPONENT_LENGTHS_H
#define CGAL_QUAD_REMESHING_INTERNAL_COMPONENT_LENGTHS_H

#include <CGAL/Quad_remeshing/internal/bbox_diagonal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// A component's bounding-box diagonal spans at least this many quad edges (remesh_for_quadrangulation()'s
// and quad_remesh()'s `component_resolution`). With the global length only, the spokes of truck's
// steering wheel (a part 0.2 across, spokes 0.03 wide, quads 0.08) were one quad wide and its quads
// crossed the holes between them: 1.1% of the diagonal from the input.
constexpr double default_component_resolution = 8.;

/*
  Fills `component` (a face property map, written) with the connected components of `tm` and returns,
  per component, `min(L, d / resolution)` for `d` the diagonal of its bounding box, rounded down to `L`
  over a power of sqrt(2), never under `L / 4`, except for the
  largest components (a diagonal within 1% of the largest: the remeshing moves the boxes a little, and
  equal parts stay equal), which keep `L`: the global length is the user's choice (`quad_edge_length`, a
  number of faces) for the main part, whatever its size. `L` everywhere when `resolution` is not positive.
*/
template <typename TriangleMesh, typename VPM, typename FaceComponentMap>
std::vector<double> component_quad_edge_lengths(const TriangleMesh& tm, VPM vpm, FaceComponentMap component,
                                                double L, double resolution)
{
  const std::size_t n = CGAL::Polygon_mesh_processing::connected_components(tm, component);
  std::vector<double> lengths(n, L);
  if(!(resolution > 0.)) return lengths;
  std::vector<CGAL::Bbox_3> boxes(n);
  for(auto f : faces(tm))
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
      boxes[std::size_t(get(component, f))] += get(vpm, v).bbox();
  std::vector<double> diagonals(n);
  for(std::size_t c = 0; c < n; ++c) diagonals[c] = bbox_diagonal(boxes[c]);
  const double largest = n ? *std::max_element(diagonals.begin(), diagonals.end()) : 0.;
  for(std::size_t c = 0; c < n; ++c)
    if(diagonals[c] < 0.99 * largest && diagonals[c] / resolution < L)
    {
      // down to a power of sqrt(2) of L (components of about the same size are remeshed in one call), at
      // least L / 4 (as the curvature sizing: a speck does not need more)
      double l = L;
      while(l > diagonals[c] / resolution && l > 0.26 * L) l /= std::sqrt(2.);
      lengths[c] = (std::max)(l, 0.25 * L);
    }
  return lengths;
}

// Per vertex (by `get(vertex_index, v)`, dense indices), the length of its component as above; an
// isolated vertex gets `L`.
template <typename TriangleMesh>
std::vector<double> vertex_component_quad_edge_lengths(const TriangleMesh& tm, double L, double resolution)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  const std::vector<double> lengths =
    component_quad_edge_lengths(tm, get(CGAL::vertex_point, tm), component, L, resolution);
  std::vector<double> result(num_vertices(tm), L);
  for(auto v : vertices(tm))
  {
    const auto h = halfedge(v, tm);
    if(h == GT::null_halfedge()) continue;
    auto f = face(h, tm);
    if(f == GT::null_face()) f = face(opposite(h, tm), tm);
    if(f != GT::null_face()) result[std::size_t(get(CGAL::vertex_index, tm, v))] = lengths[std::size_t(get(component, f))];
  }
  return result;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_COMPONENT_LENGTHS_H
