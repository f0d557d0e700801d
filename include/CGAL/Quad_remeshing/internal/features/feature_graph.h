// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Corners and lines of the graph formed by the feature edges of a mesh.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_FEATURES_FEATURE_GRAPH_H
#define CGAL_QUAD_REMESHING_INTERNAL_FEATURES_FEATURE_GRAPH_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>
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

// The chains of feature edges between the vertices of `stops` (a set) walked from `starts` (its vertices, in
// the order the chains are wanted), then the closed chains through none of them, each from one of its
// vertices; each chain as its vertices in order (a closed one ends where it starts). A chain also ends at
// a vertex of feature degree other than 2.
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename Vertex>
std::vector<std::vector<Vertex>> feature_chains(const TriangleMesh& tmesh, const EdgeIsFeatureMap& efm,
                                                const std::vector<Vertex>& starts, const std::set<Vertex>& stops)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  std::set<edge_descriptor> visited;
  std::vector<std::vector<Vertex>> chains;
  // walks from `h` (whose source is where we come from) until a stop is reached
  auto walk = [&](halfedge_descriptor h) {
    std::vector<Vertex> chain(1, source(h, tmesh));
    for(;;)
    {
      visited.insert(edge(h, tmesh));
      const Vertex v = target(h, tmesh);
      chain.push_back(v);
      if(stops.count(v)) break;
      halfedge_descriptor nxt = h;
      bool found = false;
      for(halfedge_descriptor g : halfedges_around_source(v, tmesh))
        if(get(efm, edge(g, tmesh)) && edge(g, tmesh) != edge(h, tmesh)) { nxt = g; found = true; break; }
      if(!found || visited.count(edge(nxt, tmesh))) break;
      h = nxt;
    }
    chains.push_back(chain);
  };
  for(Vertex c : starts)
    for(halfedge_descriptor h : halfedges_around_source(c, tmesh))
      if(get(efm, edge(h, tmesh)) && !visited.count(edge(h, tmesh))) walk(h);
  for(edge_descriptor e : edges(tmesh))
    if(get(efm, e) && !visited.count(e)) walk(halfedge(e, tmesh));
  return chains;
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

  for(edge_descriptor e : edges(tmesh))
    if(get(efm, e)) ++fig.feature_edges;
  fig.feature_lines = feature_chains(tmesh, efm, corners, corner_set).size();
  return fig;
}

// The vertices where a feature chain between the vertices of `stops` bends away by more than `tolerance`
// from the straight segment between its neighbours in a Douglas-Peucker simplification of the chain
// (a closed chain through no stop is first split at two of its vertices far apart, both returned);
// `stops` themselves are not returned. Held in place by the remeshing, they keep a line that turns a lot
// over a few edges shorter than the target length (a hairpin bend, the end of a slot) from being cut
// short by the collapses along it, which keep only some of its vertices: between two held vertices,
// every input vertex stays within about `tolerance` of the remeshed line.
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename VPM, typename Vertex>
std::vector<Vertex> feature_bend_vertices(const TriangleMesh& tmesh, const EdgeIsFeatureMap& efm, const VPM& vpm,
                                          const std::vector<Vertex>& stops, double tolerance)
{
  const std::set<Vertex> stop_set(stops.begin(), stops.end());
  std::vector<Vertex> bends;
  auto point = [&](Vertex v) {
    const auto& p = get(vpm, v);
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  // squared distance from p to the segment [a, b]
  auto sq_distance = [](const std::array<double, 3>& p, const std::array<double, 3>& a, const std::array<double, 3>& b) {
    double ab[3], ap[3], ab2 = 0., t = 0.;
    for(int i = 0; i < 3; ++i) { ab[i] = b[i] - a[i]; ap[i] = p[i] - a[i]; ab2 += ab[i] * ab[i]; t += ab[i] * ap[i]; }
    t = ab2 > 0. ? (std::min)(1., (std::max)(0., t / ab2)) : 0.;
    double d = 0.;
    for(int i = 0; i < 3; ++i) d += (ap[i] - t * ab[i]) * (ap[i] - t * ab[i]);
    return d;
  };
  const double tol2 = tolerance * tolerance;
  for(std::vector<Vertex>& chain : feature_chains(tmesh, efm, stops, stop_set))
  {
    std::vector<std::array<double, 3>> p;
    for(Vertex v : chain) p.push_back(point(v));
    std::vector<std::pair<std::size_t, std::size_t>> ranges(1, std::make_pair(std::size_t(0), p.size() - 1));
    if(chain.size() > 3 && chain.front() == chain.back() && !stop_set.count(chain.front()))
    {
      // A closed chain through no stop starts at an arbitrary vertex, which the simplification would
      // never hold (it is an end), though the loop may bend most there (the tip of a narrow oval, cut
      // short by the collapses: teapot's spout). The loop is split instead at two vertices far apart:
      // the one farthest from the start and the one farthest from that, both held if they are farther
      // apart than `tolerance` (a smaller loop is left to the remeshing).
      auto farthest_from = [&](std::size_t a) {
        std::size_t far = a;
        double far_d = -1.;
        for(std::size_t k = 0; k + 1 < p.size(); ++k)
        {
          const double d = sq_distance(p[k], p[a], p[a]);
          if(d > far_d) { far = k; far_d = d; }
        }
        return far;
      };
      const std::size_t a = farthest_from(0), b = farthest_from(a);
      if(sq_distance(p[a], p[b], p[b]) <= tol2) continue;
      bends.push_back(chain[a]);
      bends.push_back(chain[b]);
      // the loop from `hi` around through its start to `lo` (its first arc), then on to `hi` again
      const std::size_t lo = (std::min)(a, b), hi = (std::max)(a, b);
      std::vector<Vertex> rotated(chain.begin() + std::ptrdiff_t(hi), chain.end() - 1);
      rotated.insert(rotated.end(), chain.begin(), chain.begin() + std::ptrdiff_t(hi) + 1);
      chain.swap(rotated);
      p.clear();
      for(Vertex v : chain) p.push_back(point(v));
      const std::size_t split = p.size() - 1 - (hi - lo); // where the first arc ends, at `lo`
      ranges.assign(1, std::make_pair(std::size_t(0), split));
      ranges.emplace_back(split, p.size() - 1);
    }
    while(!ranges.empty())
    {
      const std::size_t i = ranges.back().first, j = ranges.back().second;
      ranges.pop_back();
      std::size_t far = i;
      double far_d = tol2;
      for(std::size_t k = i + 1; k < j; ++k)
      {
        const double d = sq_distance(p[k], p[i], p[j]);
        if(d > far_d) { far = k; far_d = d; }
      }
      if(far == i) continue;
      if(!stop_set.count(chain[far])) bends.push_back(chain[far]);
      ranges.emplace_back(i, far);
      ranges.emplace_back(far, j);
    }
  }
  return bends;
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
