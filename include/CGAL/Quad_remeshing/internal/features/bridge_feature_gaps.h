// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hysteresis for feature detection: short chains of almost-sharp edges that continue a feature line
// across a gap, to another feature edge, become features.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_FEATURES_BRIDGE_FEATURE_GAPS_H
#define CGAL_QUAD_REMESHING_INTERNAL_FEATURES_BRIDGE_FEATURE_GAPS_H

#include <CGAL/Quad_remeshing/internal/features/feature_graph.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <functional>
#include <queue>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// A crease whose dihedral angle wavers around the threshold (a coarse fillet, a rim tessellated
// unevenly) comes out of the threshold as short pieces, which erosion then removes. From every free
// end of a feature chain, the cheapest path of at most `max_edges` non-feature edges whose dihedral
// angles all exceed `weak_angle`, each step heading within 45 degrees of the end edge's direction,
// that reaches a vertex already on a feature edge becomes feature. An edge costs its length times
// 1 + (strong_angle - angle) / strong_angle, so straighter, sharper bridges win; ties go to the
// first found (the order of the mesh's halfedges), which keeps the result deterministic.
// `dihedral(e)` is the edge's dihedral angle in degrees (0 where undefined); ends are visited in
// vertex order and the bridges found earlier count as features for the later searches.
// Returns the edges made feature.
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename VPM, typename Dihedral>
std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>
bridge_feature_gaps(const TriangleMesh& tmesh, EdgeIsFeatureMap efm, const VPM& vpm, const Dihedral& dihedral,
                    double weak_angle, double strong_angle, unsigned max_edges)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;

  std::vector<edge_descriptor> added;
  if(max_edges == 0 || !(weak_angle < strong_angle)) return added;
  const double cos_cone = std::cos(45. * CGAL_PI / 180.);

  auto degree = [&](vertex_descriptor v) { return feature_degree(v, tmesh, efm); };
  auto unit = [&](vertex_descriptor a, vertex_descriptor b, double& length) {
    const auto d = get(vpm, b) - get(vpm, a);
    length = std::sqrt(CGAL::to_double(d * d));
    std::array<double, 3> u{{0., 0., 0.}};
    if(length > 0.)
      for(int i = 0; i < 3; ++i) u[std::size_t(i)] = CGAL::to_double(d[i]) / length;
    return u;
  };

  std::vector<vertex_descriptor> ends;
  for(vertex_descriptor v : vertices(tmesh))
    if(degree(v) == 1) ends.push_back(v);

  // search nodes: a vertex reached by a halfedge from its parent node
  struct Node { vertex_descriptor v; halfedge_descriptor in; int parent; unsigned depth; };
  std::vector<Node> nodes;
  typedef std::tuple<double, std::size_t> Entry; // (cost, node): the node index breaks ties
  for(vertex_descriptor v : ends)
  {
    if(degree(v) != 1) continue; // a bridge found earlier reached it
    halfedge_descriptor end_edge = GT::null_halfedge();
    for(halfedge_descriptor h : halfedges_around_target(v, tmesh))
      if(get(efm, edge(h, tmesh))) end_edge = h;
    double l0 = 0.;
    const std::array<double, 3> d0 = unit(source(end_edge, tmesh), v, l0);
    if(!(l0 > 0.)) continue;

    nodes.assign(1, Node{v, GT::null_halfedge(), -1, 0});
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    queue.emplace(0., 0);
    double best_cost = 0.;
    int best = -1;
    auto on_path = [&](int n, vertex_descriptor w) {
      for(; n >= 0; n = nodes[std::size_t(n)].parent)
        if(nodes[std::size_t(n)].v == w) return true;
      return false;
    };
    while(!queue.empty())
    {
      const double cost = std::get<0>(queue.top());
      const std::size_t n = std::get<1>(queue.top());
      queue.pop();
      if(best >= 0 && cost >= best_cost) break;
      if(nodes[n].depth >= max_edges) continue;
      const vertex_descriptor x = nodes[n].v;
      for(halfedge_descriptor h : halfedges_around_source(x, tmesh))
      {
        const edge_descriptor e = edge(h, tmesh);
        if(get(efm, e) || is_border(e, tmesh)) continue;
        const double a = dihedral(e);
        if(!(a > weak_angle)) continue;
        const vertex_descriptor y = target(h, tmesh);
        if(on_path(int(n), y)) continue;
        double l = 0.;
        const std::array<double, 3> d = unit(x, y, l);
        if(!(l > 0.) || d[0] * d0[0] + d[1] * d0[1] + d[2] * d0[2] < cos_cone) continue;
        const double c = cost + l * (1. + (strong_angle - a) / strong_angle);
        nodes.push_back(Node{y, h, int(n), nodes[n].depth + 1});
        if(degree(y) > 0)
        {
          if(best < 0 || c < best_cost) { best = int(nodes.size()) - 1; best_cost = c; }
        }
        else
          queue.emplace(c, nodes.size() - 1);
      }
    }
    for(int n = best; n > 0; n = nodes[std::size_t(n)].parent)
    {
      put(efm, edge(nodes[std::size_t(n)].in, tmesh), true);
      added.push_back(edge(nodes[std::size_t(n)].in, tmesh));
    }
  }
  return added;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_FEATURES_BRIDGE_FEATURE_GAPS_H
