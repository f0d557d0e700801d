// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Local quad edge length on the remeshed triangle mesh: the global length, shortened where the
// surface bends so much that a quad of that size would stray from it.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_QUAD_SIZING_H
#define CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_QUAD_SIZING_H

#include <CGAL/Quad_remeshing/internal/bbox_diagonal.h>
#include <CGAL/Quad_remeshing/internal/component_lengths.h>
#include <CGAL/Quad_remeshing/internal/cross_field/face_geometry.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Bbox_3.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/*
  Per vertex (indexed by `get(vertex_index, v)`, dense indices), the quad edge length h that keeps the
  sagitta of a quad diagonal, about h^2 k / 4 on a surface of normal curvature k, under `tolerance`
  (absolute): h = sqrt(4 tolerance / k), clamped to [min_ratio * U, U] for U the vertex's upper bound
  (`upper`, by vertex index: the length of its component; empty: the global length L everywhere). A
  tolerance that is not positive gives the upper bounds.

  The curvature of a vertex is the largest, over its non-feature edges, of the angle between the two
  face normals divided by the distance between the two face centroids (feature edges are creases the
  quads follow, not bends they cut across), and, on a feature line, of the line's turning angle there
  (below the 45 degrees of a corner) divided by the mean length of its two edges. The result is then graded, h(v) <= h(w) + grading |vw|
  (a Dijkstra sweep from the smallest sizes), so that neighbouring quads differ little in size.
*/
template <typename TriangleMesh, typename EdgeIsFeature>
std::vector<double> curvature_quad_sizing(const TriangleMesh& tm, EdgeIsFeature is_feature, double L, double tolerance,
                                          const std::vector<double>& upper = {}, double min_ratio = 0.25,
                                          double grading = 0.5)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  const auto vpm = get(CGAL::vertex_point, tm);
  const auto vim = get(CGAL::vertex_index, tm);
  const std::size_t nv = num_vertices(tm);
  std::vector<double> h = upper.size() == nv ? upper : std::vector<double>(nv, L);
  const std::vector<double> bound = h;
  if(!(tolerance > 0.) || !(L > 0.)) return h;

  auto point = [&](typename GT::vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return Vec3d{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  auto face_data = [&](face_descriptor f, Vec3d& n, Vec3d& c) {
    const halfedge_descriptor h0 = halfedge(f, tm);
    const Vec3d a = point(source(h0, tm)), b = point(target(h0, tm)), d = point(target(next(h0, tm), tm));
    n = v_cross(v_sub(b, a), v_sub(d, a));
    const double l = v_norm(n);
    if(!(l > 0.)) return false;
    for(int i = 0; i < 3; ++i) { n[i] /= l; c[i] = (a[i] + b[i] + d[i]) / 3.; }
    return true;
  };

  std::vector<double> curvature(nv, 0.);
  for(auto e : edges(tm))
  {
    if(is_border(e, tm) || get(is_feature, e)) continue;
    const halfedge_descriptor he = halfedge(e, tm);
    Vec3d n0, n1, c0, c1;
    if(!face_data(face(he, tm), n0, c0) || !face_data(face(opposite(he, tm), tm), n1, c1)) continue;
    const double d = v_norm(v_sub(c1, c0));
    if(!(d > 0.)) continue;
    const double cosine = (std::max)(-1., (std::min)(1., v_dot(n0, n1)));
    const double k = std::acos(cosine) / d;
    for(auto v : {source(he, tm), target(he, tm)})
    {
      double& kv = curvature[std::size_t(get(vim, v))];
      kv = (std::max)(kv, k);
    }
  }
  // a feature line bending at a vertex (by less than a corner's 45 degrees: corners are quad vertices
  // anyway) is a curve the quad edges follow as chords
  for(auto v : vertices(tm))
  {
    std::vector<typename GT::vertex_descriptor> ends;
    if(halfedge(v, tm) == GT::null_halfedge()) continue;
    for(halfedge_descriptor g : halfedges_around_target(v, tm))
      if(get(is_feature, edge(g, tm))) ends.push_back(source(g, tm));
    if(ends.size() != 2) continue;
    const Vec3d a = v_sub(point(ends[0]), point(v)), b = v_sub(point(ends[1]), point(v));
    const double la = v_norm(a), lb = v_norm(b);
    if(!(la > 0.) || !(lb > 0.)) continue;
    const double cosine = (std::max)(-1., (std::min)(1., v_dot(a, b) / (la * lb)));
    const double turn = CGAL_PI - std::acos(cosine);
    if(turn >= CGAL_PI / 4.) continue;
    double& kv = curvature[std::size_t(get(vim, v))];
    kv = (std::max)(kv, turn / (0.5 * (la + lb)));
  }
  for(std::size_t i = 0; i < nv; ++i)
    if(curvature[i] > 0.)
      h[i] = (std::max)(min_ratio * bound[i], (std::min)(bound[i], std::sqrt(4. * tolerance / curvature[i])));

  // grading: h(v) <= h(w) + grading |vw|, smallest sizes first
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  std::vector<typename GT::vertex_descriptor> vertex_at(nv);
  for(auto v : vertices(tm))
  {
    const std::size_t i = std::size_t(get(vim, v));
    vertex_at[i] = v;
    if(h[i] < L) queue.emplace(h[i], i); // (a small component's vertices too: no edge leaves a component)
  }
  while(!queue.empty())
  {
    const Item top = queue.top();
    queue.pop();
    if(top.first > h[top.second]) continue;
    const auto v = vertex_at[top.second];
    if(halfedge(v, tm) == GT::null_halfedge()) continue;
    for(halfedge_descriptor g : halfedges_around_target(v, tm))
    {
      const std::size_t j = std::size_t(get(vim, source(g, tm)));
      const double candidate = top.first + grading * v_norm(v_sub(point(source(g, tm)), point(v)));
      if(candidate < h[j])
      {
        h[j] = candidate;
        queue.emplace(candidate, j);
      }
    }
  }
  return h;
}

// `curvature_quad_sizing()` with the tolerance a fraction of the bounding-box diagonal, under the length of
// each vertex's component (vertex_component_quad_edge_lengths(), `component_resolution`); no sizing (an empty
// vector: the uniform length) when that fraction is not positive and every component has the length L.
template <typename TriangleMesh, typename EdgeIsFeature>
std::vector<double> quad_sizing(const TriangleMesh& tm, EdgeIsFeature is_feature, double L, double relative_tolerance,
                                double component_resolution = default_component_resolution)
{
  if(num_vertices(tm) == 0) return {};
  const std::vector<double> upper = vertex_component_quad_edge_lengths(tm, L, component_resolution);
  if(!(relative_tolerance > 0.))
    return std::all_of(upper.begin(), upper.end(), [L](double u) { return !(u < L); }) ? std::vector<double>() : upper;
  return curvature_quad_sizing(tm, is_feature, L, relative_tolerance * mesh_bbox_diagonal(tm), upper);
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_QUAD_SIZING_H
