// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Helpers of remesh_for_quadrangulation(): triangle figures, radius ratio, final face splitting.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_REMESHING_REMESHING_HELPERS_H
#define CGAL_QUAD_REMESHING_INTERNAL_REMESHING_REMESHING_HELPERS_H

#include <CGAL/AABB_traits.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// Smallest and mean inner angle (degrees) over the faces; degenerate corners count as 0.
template <typename TriangleMesh, typename VPM>
std::pair<double, double> triangle_angles(const TriangleMesh& tmesh, const VPM& vpm)
{
  double mn = 180., sum = 0.;
  std::size_t n = 0;
  for(auto f : faces(tmesh))
  {
    auto h = halfedge(f, tmesh);
    for(int i = 0; i < 3; ++i, h = next(h, tmesh))
    {
      const auto& p = get(vpm, source(h, tmesh));
      const auto& q = get(vpm, target(h, tmesh));
      const auto& r = get(vpm, target(next(h, tmesh), tmesh));
      const auto u = p - q, v = r - q;
      const double l = std::sqrt(CGAL::to_double(u * u) * CGAL::to_double(v * v));
      const double a = l > 0. ? std::acos(std::max(-1., std::min(1., CGAL::to_double(u * v) / l))) * 180. / CGAL_PI : 0.;
      mn = (std::min)(mn, a);
      sum += a;
      ++n;
    }
  }
  return {n ? mn : 0., n ? sum / double(n) : 0.};
}

// 2 * inradius / circumradius: 1 for an equilateral triangle, 0 for a degenerate one.
template <typename Point>
double radius_ratio(const Point& p, const Point& q, const Point& r)
{
  const double a = std::sqrt(CGAL::to_double(CGAL::squared_distance(q, r)));
  const double b = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, r)));
  const double c = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
  const double s = a + b + c;
  const double den = s * a * b * c;
  if(!(den > 0.)) return 0.;
  // 16 A^2 = s (-a+b+c)(a-b+c)(a+b-c)
  const double v = (-a + b + c) * (a - b + c) * (a + b - c) / (a * b * c);
  return std::max(0., std::min(1., v));
}

// Final refinement (paper, Figure 5): a face whose three edges are features gets a centre vertex; then
// every non-feature edge joining two feature vertices is split at its midpoint (projected on `tree`),
// which also splits every face with two feature edges (their third edge is such an edge).
// Returns the number of vertices inserted, and appends them to `*inserted_vertices` if given.
template <typename TriangleMesh, typename VPM, typename EdgeIsFeatureMap, typename Tree>
std::size_t split_feature_faces(TriangleMesh& tmesh, const VPM& vpm, EdgeIsFeatureMap efm, const Tree& tree,
                                std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>*
                                  inserted_vertices = nullptr)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VPM>::value_type Point;
  std::size_t inserted = 0;

  std::vector<face_descriptor> triple;
  for(face_descriptor f : faces(tmesh))
  {
    int n = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tmesh), tmesh))
      if(get(efm, edge(h, tmesh))) ++n;
    if(n == 3) triple.push_back(f);
  }
  for(face_descriptor f : triple)
  {
    const halfedge_descriptor h = halfedge(f, tmesh);
    const Point c = CGAL::centroid(get(vpm, source(h, tmesh)), get(vpm, target(h, tmesh)),
                                   get(vpm, target(next(h, tmesh), tmesh)));
    const halfedge_descriptor hc = CGAL::Euler::add_center_vertex(h, tmesh);
    put(vpm, target(hc, tmesh), c);
    if(inserted_vertices) inserted_vertices->push_back(target(hc, tmesh));
    for(halfedge_descriptor g : halfedges_around_target(hc, tmesh)) put(efm, edge(g, tmesh), false);
    ++inserted;
  }

  auto is_feature_vertex = [&](typename boost::graph_traits<TriangleMesh>::vertex_descriptor v) {
    for(halfedge_descriptor g : halfedges_around_target(v, tmesh))
      if(get(efm, edge(g, tmesh))) return true;
    return false;
  };
  std::vector<edge_descriptor> to_split;
  for(edge_descriptor e : edges(tmesh))
    if(!get(efm, e) && !is_border(e, tmesh) && is_feature_vertex(source(halfedge(e, tmesh), tmesh)) &&
       is_feature_vertex(target(halfedge(e, tmesh), tmesh)))
      to_split.push_back(e);
  for(edge_descriptor e : to_split)
  {
    const halfedge_descriptor h = halfedge(e, tmesh);
    const Point m = tree.closest_point(CGAL::midpoint(get(vpm, source(h, tmesh)), get(vpm, target(h, tmesh))));
    const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, tmesh); // a -> m, followed by h: m -> b
    put(vpm, target(hnew, tmesh), m);
    if(inserted_vertices) inserted_vertices->push_back(target(hnew, tmesh));
    put(efm, edge(hnew, tmesh), false);
    put(efm, edge(h, tmesh), false);
    const halfedge_descriptor oh = opposite(h, tmesh); // b -> m, followed by m -> a
    const halfedge_descriptor n1 = CGAL::Euler::split_face(hnew, next(h, tmesh), tmesh);
    put(efm, edge(n1, tmesh), false);
    const halfedge_descriptor n2 = CGAL::Euler::split_face(oh, next(next(oh, tmesh), tmesh), tmesh);
    put(efm, edge(n2, tmesh), false);
    ++inserted;
  }
  return inserted;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
