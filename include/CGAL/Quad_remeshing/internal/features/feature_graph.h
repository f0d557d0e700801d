// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Corners and lines of the graph formed by the feature edges of a mesh.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_FEATURES_FEATURE_GRAPH_H
#define CGAL_QUAD_REMESHING_INTERNAL_FEATURES_FEATURE_GRAPH_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <set>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

struct Feature_graph_figures
{
  std::size_t feature_edges = 0;
  std::size_t feature_lines = 0;
};

template <typename TriangleMesh, typename EdgeIsFeatureMap>
std::size_t feature_degree(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                           const TriangleMesh& tmesh, const EdgeIsFeatureMap& efm)
{
  std::size_t d = 0;
  for(auto h : halfedges_around_target(v, tmesh))
    if(get(efm, edge(h, tmesh))) ++d;
  return d;
}

// Corners: feature degree 1 or > 2, or degree 2 with a turn sharper than `corner_angle` degrees.
// Lines: chains of feature edges between corners; a closed loop without corner counts once.
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename VPM, typename Vertex>
Feature_graph_figures feature_corners_and_lines(const TriangleMesh& tmesh, const EdgeIsFeatureMap& efm,
                                                const VPM& vpm, double corner_angle,
                                                std::vector<Vertex>& corners)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  Feature_graph_figures fig;
  const double cos_turn = std::cos(corner_angle * CGAL_PI / 180.);
  std::set<Vertex> corner_set;
  for(Vertex v : vertices(tmesh))
  {
    std::vector<halfedge_descriptor> in;
    for(halfedge_descriptor h : halfedges_around_target(v, tmesh))
      if(get(efm, edge(h, tmesh))) in.push_back(h);
    bool corner = !in.empty() && in.size() != 2;
    if(in.size() == 2)
    {
      // turning angle between (a -> v) and (v -> b)
      const auto& p = get(vpm, v);
      const auto d1 = p - get(vpm, source(in[0], tmesh));
      const auto d2 = get(vpm, source(in[1], tmesh)) - p;
      const double l = std::sqrt(CGAL::to_double(d1 * d1) * CGAL::to_double(d2 * d2));
      corner = l > 0. && CGAL::to_double(d1 * d2) / l < cos_turn;
    }
    if(corner) { corners.push_back(v); corner_set.insert(v); }
  }

  std::set<edge_descriptor> visited;
  for(edge_descriptor e : edges(tmesh))
    if(get(efm, e)) ++fig.feature_edges;

  // walks from `h` (whose source is where we come from) until a corner is reached
  auto walk = [&](halfedge_descriptor h) {
    for(;;)
    {
      visited.insert(edge(h, tmesh));
      const Vertex v = target(h, tmesh);
      if(corner_set.count(v)) return;
      halfedge_descriptor nxt = h;
      bool found = false;
      for(halfedge_descriptor g : halfedges_around_source(v, tmesh))
        if(get(efm, edge(g, tmesh)) && edge(g, tmesh) != edge(h, tmesh)) { nxt = g; found = true; break; }
      if(!found || visited.count(edge(nxt, tmesh))) return;
      h = nxt;
    }
  };
  for(Vertex c : corners)
    for(halfedge_descriptor h : halfedges_around_source(c, tmesh))
      if(get(efm, edge(h, tmesh)) && !visited.count(edge(h, tmesh)))
      {
        ++fig.feature_lines;
        walk(h);
      }
  for(edge_descriptor e : edges(tmesh))
    if(get(efm, e) && !visited.count(e))
    {
      ++fig.feature_lines; // a closed loop without corner
      walk(halfedge(e, tmesh));
    }
  return fig;
}

template <typename TriangleMesh, typename Vertex>
void write_corner_map(const TriangleMesh&, const std::vector<Vertex>&, CGAL::internal_np::Param_not_found) {}

template <typename TriangleMesh, typename Vertex, typename VertexCornerMap>
void write_corner_map(const TriangleMesh& tmesh, const std::vector<Vertex>& corners, VertexCornerMap vcm)
{
  for(Vertex v : vertices(tmesh)) put(vcm, v, false);
  for(Vertex v : corners) put(vcm, v, true);
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
