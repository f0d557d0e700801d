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

// Splits every edge longer than 4/3 of `length` into ceil(l / length) equal pieces (the pieces of a
// feature edge are features; the new vertices are not constrained), then triangulates every face that
// got new vertices by cutting ears, the shortest diagonal first, at its corners (the triangle's corners
// and the ends of the diagonals cut so far; a vertex inside a side has a flat angle). A long, thin
// triangle becomes a ladder of about as many triangles as its sides have pieces, where the split pass
// of isotropic_remeshing(), which cuts the longest edge at its midpoint and joins it to the opposite
// corner, makes about (l / length)^2 of them. The surface does not change. Returns the number of
// vertices inserted.
template <typename TriangleMesh, typename VPM, typename EdgeIsFeatureMap, typename VertexIsConstrainedMap>
std::size_t split_long_edges_evenly(TriangleMesh& tmesh, const VPM& vpm, EdgeIsFeatureMap efm,
                                    VertexIsConstrainedMap vcm, double length)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VPM>::value_type Point;
  std::vector<edge_descriptor> long_edges;
  for(edge_descriptor e : edges(tmesh))
  {
    const double l2 = CGAL::to_double(CGAL::squared_distance(get(vpm, source(e, tmesh)), get(vpm, target(e, tmesh))));
    if(l2 > CGAL::square(4. / 3. * length)) long_edges.push_back(e);
  }
  auto is_new = get(CGAL::dynamic_vertex_property_t<bool>(), tmesh);
  for(vertex_descriptor v : vertices(tmesh)) put(is_new, v, false);
  std::vector<face_descriptor> touched;
  std::size_t inserted = 0;
  for(edge_descriptor e : long_edges)
  {
    const halfedge_descriptor h = halfedge(e, tmesh);
    const Point p = get(vpm, source(h, tmesh)), q = get(vpm, target(h, tmesh));
    const bool feature = get(efm, e);
    const int pieces = int(std::ceil(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q))) / length));
    for(halfedge_descriptor g : {h, opposite(h, tmesh)})
      if(!is_border(g, tmesh)) touched.push_back(face(g, tmesh));
    // split_edge(h) inserts a vertex between source(h) and target(h) and returns the halfedge that ends
    // at it; h keeps ending at target(h), so the next split cuts the remaining part
    for(int i = 1; i < pieces; ++i)
    {
      const halfedge_descriptor n = CGAL::Euler::split_edge(h, tmesh);
      const vertex_descriptor v = target(n, tmesh);
      put(vpm, v, CGAL::barycenter(p, double(pieces - i), q, double(i)));
      put(is_new, v, true);
      put(vcm, v, false);
      put(efm, edge(n, tmesh), feature);
      ++inserted;
    }
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for(face_descriptor f : touched)
  {
    // the cycle as a linked list of positions; hedge[i] is the face's halfedge that ends at vertex i
    std::vector<halfedge_descriptor> hedge;
    for(halfedge_descriptor g : halfedges_around_face(halfedge(f, tmesh), tmesh)) hedge.push_back(g);
    std::size_t n = hedge.size();
    if(n <= 3) continue;
    std::vector<std::size_t> prv(n), nxt(n);
    std::vector<std::size_t> corners;
    for(std::size_t i = 0; i < n; ++i)
    {
      prv[i] = (i + n - 1) % n;
      nxt[i] = (i + 1) % n;
      if(!get(is_new, target(hedge[i], tmesh))) corners.push_back(i);
    }
    while(n > 3)
    {
      std::size_t best = std::size_t(-1);
      double best_d = 0.;
      for(std::size_t i : corners)
      {
        const vertex_descriptor u = target(hedge[prv[i]], tmesh), w = target(hedge[nxt[i]], tmesh);
        if(halfedge(u, w, tmesh).second) continue; // the diagonal would be a second u-w edge
        const double d = CGAL::to_double(CGAL::squared_distance(get(vpm, u), get(vpm, w)));
        if(best == std::size_t(-1) || d < best_d) { best = i; best_d = d; }
      }
      if(best == std::size_t(-1))
      {
        // no ear can be cut: a centre vertex joined to every vertex of the rest
        const halfedge_descriptor c = CGAL::Euler::add_center_vertex(hedge[corners.front()], tmesh);
        const vertex_descriptor v = target(c, tmesh);
        put(vpm, v, CGAL::centroid(get(vpm, target(hedge[prv[corners.front()]], tmesh)),
                                   get(vpm, target(hedge[corners.front()], tmesh)),
                                   get(vpm, target(hedge[nxt[corners.front()]], tmesh))));
        put(vcm, v, false);
        for(halfedge_descriptor g : halfedges_around_target(c, tmesh)) put(efm, edge(g, tmesh), false);
        ++inserted;
        break;
      }
      const std::size_t u = prv[best], w = nxt[best];
      // the new halfedge w -> u follows hedge[w]: the ear (u, best, w) is cut off; its opposite u -> w
      // now ends at w in the remaining face
      const halfedge_descriptor wu = CGAL::Euler::split_face(hedge[w], hedge[u], tmesh);
      put(efm, edge(wu, tmesh), false);
      hedge[w] = opposite(wu, tmesh);
      nxt[u] = w;
      prv[w] = u;
      corners.erase(std::find(corners.begin(), corners.end(), best));
      for(std::size_t k : {u, w})
        if(std::find(corners.begin(), corners.end(), k) == corners.end()) corners.push_back(k);
      --n;
    }
  }
  return inserted;
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
