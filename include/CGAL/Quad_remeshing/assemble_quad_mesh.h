// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Places the quadrangulation of every patch on the surface and merges them into one conforming quad mesh.

#ifndef CGAL_QUAD_REMESHING_ASSEMBLE_QUAD_MESH_H
#define CGAL_QUAD_REMESHING_ASSEMBLE_QUAD_MESH_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/assembly/parameterize_patch.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  What the assembly needs to know of a patch layout on a triangle mesh: the arcs (pieces of patch
  sides between corners and T-junctions, as chains of mesh vertices) and, per patch, its triangles and
  its sides in counterclockwise order (the patch on the left), each side a sequence of arcs.

  @tparam TriangleMesh a model of `FaceListGraph`
*/
template <typename TriangleMesh>
struct Patch_layout_description
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor; ///< mesh vertex
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;     ///< mesh face

  /// a chain of mesh vertices, at least two
  struct Arc
  {
    std::vector<vertex_descriptor> vertices; ///< the chain, in the arc's own direction
    bool on_feature = false;                 ///< the arc lies on a feature line (or the mesh boundary)
  };
  /// an arc as seen from a patch
  struct Side_arc
  {
    std::size_t arc = 0;    ///< index in `arcs`
    bool reversed = false;  ///< the patch walks the arc against its direction
  };
  /// a patch: a topological disk bounded by its sides
  struct Patch
  {
    std::vector<face_descriptor> faces;           ///< its triangles
    std::vector<std::vector<Side_arc>> sides;     ///< counterclockwise; side i runs from corner i to corner i+1
  };

  std::vector<Arc> arcs;       ///< every arc once
  std::vector<Patch> patches;  ///< every patch
};

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `assemble_quad_mesh()`.
*/
struct Quad_assembly_statistics
{
  std::size_t patches = 0;         ///< patches placed
  std::size_t vertices = 0;        ///< vertices of the quad mesh
  std::size_t faces = 0;           ///< faces of the quad mesh
  std::size_t feature_edges = 0;   ///< quad edges on feature arcs
  double seconds = 0.;             ///< time spent

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["patches"] = patches;
    r["V"] = vertices;
    r["F"] = faces;
    r["feature_edges"] = feature_edges;
    r["seconds"] = seconds;
    return r;
  }
};

/*!
  \ingroup PkgQuadRemeshingRef

  places the quadrangulation of every patch on the triangle mesh and merges them into one conforming
  quad mesh.

  Vertices on arcs are shared by the patches on both sides: the k-th of the `s` edges of an arc ends
  at arclength fraction k/s along the arc's chain, and arc end points are the chain's end vertices.
  Interior vertices of a patch are placed through a map of the patch's triangles onto the patch's
  polygon (the convex polygon of its quadrangulation, the boundary fixed by arclength along each arc)
  with positive mean-value weights, which makes the map one-to-one; each pattern vertex is located in
  that map and lifted to the surface by barycentric interpolation.

  @tparam TriangleMesh a model of `FaceListGraph` (triangles)
  @tparam PatchQuadrangulation a class with the members `positions` (a random-access range of
          `std::array<double,2>`: the 2D embedding of every vertex), `quads` (a range of
          `std::array<std::size_t,4>`, counterclockwise) and `boundary` (the boundary vertices,
          counterclockwise, starting at corner 0, side i having as many edges as the sum of its arcs'
          counts); for example `Polygon_quadrangulation`
  @tparam QuadMesh a model of `MutableFaceGraph`
  @tparam EdgeFeatureMap a model of `WritablePropertyMap` with `QuadMesh`'s `edge_descriptor` as key
          type and `bool` as value type

  @param tmesh the triangle mesh
  @param layout the arcs and patches on `tmesh`
  @param arc_edge_counts the number of quad edges on each arc (at least 1)
  @param quadrangulations the quadrangulation of each patch, in the order of `layout.patches`
  @param qmesh the output, empty on entry (it is not cleared, so that property maps created on it stay valid)
  @param qmesh_edge_is_feature receives `true` for the quad edges on feature arcs and `false` for the others
  @param verbose whether to print progress to `std::cerr`

  @throws std::invalid_argument if the counts do not match the quadrangulations, and
          std::runtime_error if a patch is not a disk or the quads do not form a manifold mesh
*/
template <typename TriangleMesh, typename PatchQuadrangulation, typename QuadMesh, typename EdgeFeatureMap>
Quad_assembly_statistics assemble_quad_mesh(const TriangleMesh& tmesh,
                                            const Patch_layout_description<TriangleMesh>& layout,
                                            const std::vector<int>& arc_edge_counts,
                                            const std::vector<PatchQuadrangulation>& quadrangulations,
                                            QuadMesh& qmesh,
                                            EdgeFeatureMap qmesh_edge_is_feature,
                                            bool verbose = false)
{
  typedef boost::graph_traits<TriangleMesh> TGT;
  typedef typename TGT::vertex_descriptor t_vertex;
  typedef typename TGT::halfedge_descriptor t_halfedge;
  typedef typename boost::graph_traits<QuadMesh>::vertex_descriptor q_vertex;
  typedef typename boost::property_traits<typename boost::property_map<QuadMesh, CGAL::vertex_point_t>::type>::value_type
    Q_point;
  typedef typename Patch_layout_description<TriangleMesh>::Side_arc Side_arc;

  CGAL::Real_timer timer;
  timer.start();
  Quad_assembly_statistics stats;
  if(arc_edge_counts.size() != layout.arcs.size())
    throw std::invalid_argument("assemble_quad_mesh: one edge count per arc is needed");
  if(quadrangulations.size() != layout.patches.size())
    throw std::invalid_argument("assemble_quad_mesh: one quadrangulation per patch is needed");
  if(num_vertices(qmesh) != 0 || num_faces(qmesh) != 0)
    throw std::invalid_argument("assemble_quad_mesh: the output mesh must be empty");
  auto tvpm = get(CGAL::vertex_point, tmesh);
  auto point_of = [&](t_vertex v) {
    const auto p = get(tvpm, v);
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  auto add_point = [&](const std::array<double, 3>& p) { return add_vertex(Q_point(p[0], p[1], p[2]), qmesh); };

  // Shared vertices: arc end points (keyed by mesh vertex) and the inner subdivision points of every arc.
  std::map<t_vertex, q_vertex> end_vertex;
  std::vector<std::vector<q_vertex>> arc_points(layout.arcs.size());
  std::vector<std::vector<double>> arc_fraction(layout.arcs.size()); // arclength fraction of each chain vertex
  for(std::size_t a = 0; a < layout.arcs.size(); ++a)
  {
    const auto& chain = layout.arcs[a].vertices;
    const int s = arc_edge_counts[a];
    if(chain.size() < 2) throw std::invalid_argument("assemble_quad_mesh: an arc needs two vertices");
    if(s < 1) throw std::invalid_argument("assemble_quad_mesh: an arc needs at least one edge");
    std::vector<double> cumulative(chain.size(), 0.);
    for(std::size_t i = 1; i < chain.size(); ++i)
    {
      const auto p = point_of(chain[i - 1]), q = point_of(chain[i]);
      cumulative[i] = cumulative[i - 1]
                      + std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    }
    const double total = cumulative.back();
    arc_fraction[a].resize(chain.size());
    for(std::size_t i = 0; i < chain.size(); ++i)
      arc_fraction[a][i] = total > 0 ? cumulative[i] / total : double(i) / double(chain.size() - 1);
    for(t_vertex v : {chain.front(), chain.back()})
      if(end_vertex.find(v) == end_vertex.end()) end_vertex[v] = add_point(point_of(v));
    arc_points[a].resize(std::size_t(s) + 1);
    arc_points[a][0] = end_vertex[chain.front()];
    arc_points[a][std::size_t(s)] = end_vertex[chain.back()];
    std::size_t seg = 1;
    for(int k = 1; k < s; ++k)
    {
      const double f = double(k) / double(s);
      while(seg + 1 < chain.size() && arc_fraction[a][seg] < f) ++seg;
      const double f0 = arc_fraction[a][seg - 1], f1 = arc_fraction[a][seg];
      const double t = f1 > f0 ? (f - f0) / (f1 - f0) : 0.;
      const auto p = point_of(chain[seg - 1]), q = point_of(chain[seg]);
      arc_points[a][std::size_t(k)] = add_point({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])});
    }
  }

  std::vector<std::array<q_vertex, 4>> quads;
  for(std::size_t pi = 0; pi < layout.patches.size(); ++pi)
  {
    const auto& patch = layout.patches[pi];
    const auto& pattern = quadrangulations[pi];
    const std::size_t n = patch.sides.size();
    std::vector<int> side_count(n, 0);
    for(std::size_t i = 0; i < n; ++i)
      for(const Side_arc& sa : patch.sides[i]) side_count[i] += arc_edge_counts[sa.arc];
    std::size_t perimeter = 0;
    for(int c : side_count) perimeter += std::size_t(c);
    if(perimeter != pattern.boundary.size())
      throw std::invalid_argument("assemble_quad_mesh: patch " + std::to_string(pi)
                                  + ": its quadrangulation does not have the sides' edge counts");

    // pattern vertex -> quad-mesh vertex, first on the boundary (shared), with the uv of each corner
    std::vector<q_vertex> vmap(pattern.positions.size(), boost::graph_traits<QuadMesh>::null_vertex());
    std::vector<std::size_t> corner_index(n + 1, 0);
    {
      std::size_t k = 0;
      for(std::size_t i = 0; i < n; ++i)
      {
        corner_index[i] = k;
        for(const Side_arc& sa : patch.sides[i])
        {
          const int s = arc_edge_counts[sa.arc];
          for(int j = 0; j < s; ++j, ++k)
            vmap[pattern.boundary[k]] = arc_points[sa.arc][std::size_t(sa.reversed ? s - j : j)];
        }
      }
      corner_index[n] = k;
    }

    // the patch's triangles as a local indexed mesh
    internal::Patch_map map;
    std::unordered_map<std::size_t, std::size_t> local;
    std::vector<t_vertex> local_to_mesh;
    auto local_id = [&](t_vertex v) {
      const std::size_t key = std::size_t(v);
      auto it = local.find(key);
      if(it != local.end()) return it->second;
      const std::size_t id = map.points.size();
      local.emplace(key, id);
      map.points.push_back(point_of(v));
      local_to_mesh.push_back(v);
      return id;
    };
    for(auto f : patch.faces)
    {
      std::array<std::size_t, 3> t;
      int c = 0;
      for(t_halfedge h : halfedges_around_face(halfedge(f, tmesh), tmesh))
      {
        if(c == 3) throw std::invalid_argument("assemble_quad_mesh: the mesh must be triangulated");
        t[c++] = local_id(target(h, tmesh));
      }
      map.triangles.push_back(t);
    }
    map.uv.assign(map.points.size(), {{0., 0.}});
    map.fixed.assign(map.points.size(), false);

    // boundary of the map: every chain vertex of every arc, at its place along its side of the polygon
    auto corner_uv = [&](std::size_t i) { return pattern.positions[pattern.boundary[corner_index[i % n] % perimeter]]; };
    std::size_t fixed_count = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const auto c0 = corner_uv(i), c1 = corner_uv(i + 1);
      double offset = 0.;
      for(const Side_arc& sa : patch.sides[i])
      {
        const auto& chain = layout.arcs[sa.arc].vertices;
        const double s = double(arc_edge_counts[sa.arc]);
        for(std::size_t q = 0; q < chain.size(); ++q)
        {
          const std::size_t idx = sa.reversed ? chain.size() - 1 - q : q;
          const double along = sa.reversed ? 1. - arc_fraction[sa.arc][idx] : arc_fraction[sa.arc][idx];
          const double t = (offset + along * s) / double(side_count[i]);
          auto it = local.find(std::size_t(chain[idx]));
          if(it == local.end())
            throw std::runtime_error("assemble_quad_mesh: patch " + std::to_string(pi) + ": an arc vertex is not in the patch");
          if(!map.fixed[it->second]) ++fixed_count;
          map.fixed[it->second] = true;
          map.uv[it->second] = {{c0[0] + t * (c1[0] - c0[0]), c0[1] + t * (c1[1] - c0[1])}};
        }
        offset += s;
      }
    }
    if(fixed_count + 0 == 0) throw std::runtime_error("assemble_quad_mesh: patch without boundary");
    internal::solve_mean_value_map(map);
    internal::build_location_grid(map);

    for(std::size_t v = 0; v < pattern.positions.size(); ++v)
      if(vmap[v] == boost::graph_traits<QuadMesh>::null_vertex())
        vmap[v] = add_point(internal::lift(map, {{pattern.positions[v][0], pattern.positions[v][1]}}));
    for(const auto& q : pattern.quads)
      quads.push_back({{vmap[q[0]], vmap[q[1]], vmap[q[2]], vmap[q[3]]}});
    ++stats.patches;
  }

  for(const auto& q : quads)
  {
    std::vector<q_vertex> face(q.begin(), q.end());
    if(CGAL::Euler::add_face(face, qmesh) == boost::graph_traits<QuadMesh>::null_face())
      throw std::runtime_error("assemble_quad_mesh: the patch quadrangulations do not form a manifold mesh");
  }
  for(auto e : edges(qmesh)) put(qmesh_edge_is_feature, e, false);
  for(std::size_t a = 0; a < layout.arcs.size(); ++a)
    if(layout.arcs[a].on_feature)
      for(std::size_t k = 0; k + 1 < arc_points[a].size(); ++k)
      {
        const auto h = halfedge(arc_points[a][k], arc_points[a][k + 1], qmesh);
        if(h.second)
        {
          put(qmesh_edge_is_feature, edge(h.first, qmesh), true);
          ++stats.feature_edges;
        }
      }
  stats.vertices = num_vertices(qmesh);
  stats.faces = num_faces(qmesh);
  stats.seconds = timer.time();
  if(verbose)
    std::cerr << "[assemble] " << stats.patches << " patches -> " << stats.vertices << " vertices, " << stats.faces
              << " quads, " << stats.feature_edges << " feature edges (" << stats.seconds << " s)\n";
  return stats;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_ASSEMBLE_QUAD_MESH_H
