// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Places the quadrangulation of every patch on the surface and merges them into one conforming quad mesh.

#ifndef CGAL_QUAD_REMESHING_ASSEMBLE_QUAD_MESH_H
#define CGAL_QUAD_REMESHING_ASSEMBLE_QUAD_MESH_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/assembly/cut_open_patch.h>
#include <CGAL/Quad_remeshing/internal/assembly/parameterize_patch.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
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
  std::size_t folded_quads = 0;    ///< quads of the patterns left out because they fold onto themselves at the tip of a slit
  std::size_t merged_quads = 0;    ///< pairs of quads merged into one around an inner vertex with two edges
  std::size_t closed_quads = 0;    ///< quads left out in pairs on the same four vertices, facing each other (a slit folded shut)
  double seconds = 0.;             ///< time spent

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["patches"] = patches;
    r["V"] = vertices;
    r["F"] = faces;
    r["feature_edges"] = feature_edges;
    r["folded_quads"] = folded_quads;
    r["merged_quads"] = merged_quads;
    r["closed_quads"] = closed_quads;
    r["seconds"] = seconds;
    return r;
  }
};

/*!
  \ingroup PkgQuadRemeshingRef
  Thrown by `assemble_quad_mesh()` when the quadrangulations of some patches, glued along the arcs,
  would give two quads the same edge in the same direction. This happens where a patch's boundary meets
  itself (a bridge to an inner loop) and an edge of its pattern joins two boundary points that the
  gluing makes neighbours on an arc of few edges: the pattern's chord and the arc then join the same
  two vertices. More edges on the arcs of the patches named here remove the coincidence (the pipeline
  does so, see `quad_remesh()`). The output mesh is left empty.
*/
struct Quad_assembly_conflict : std::runtime_error
{
  std::vector<std::size_t> patches; ///< the patches whose quads conflict, in increasing order, without repetition

  /// the error message and the patches involved
  Quad_assembly_conflict(const std::string& what, std::vector<std::size_t> involved)
    : std::runtime_error(what), patches(std::move(involved))
  {}
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
  that map and lifted to the surface by barycentric interpolation. A patch whose sides walk an arc
  twice (a slit, a bridge to an inner loop, the seam of a band) is cut open along its sides first: the
  triangles on the two sides of such an arc get separate copies of its vertices, so that the patch is
  a disk with a simple boundary and the map does not fold.

  Three repairs keep the result a manifold quad mesh where a pattern meets a slit: a pattern quad that
  folds onto itself over the tip of a slit (its opposite corners are one vertex) is left out; two
  quads then left on the same four vertices in opposite orientations (a pattern with two rows of
  quads across the slit's end, which would close a sphere) are both left out; and the two quads
  around an inner vertex with only two edges (two flat corners) are merged into one. Each shortens
  the slit, and all are counted in the statistics.

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

  @throws std::invalid_argument if the counts do not match the quadrangulations,
          `Quad_assembly_conflict` (before `qmesh` is changed) if two quads would have the same edge in
          the same direction, and std::runtime_error if a patch is not a disk or the quads do not form
          a manifold mesh for another reason
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
  // the quad mesh is built from an indexed soup first: only the points some quad uses become vertices
  typedef std::size_t q_index;
  const q_index no_index = q_index(-1);
  std::vector<std::array<double, 3>> points;
  auto add_point = [&](const std::array<double, 3>& p) { points.push_back(p); return q_index(points.size() - 1); };

  // Shared vertices: arc end points (keyed by mesh vertex) and the inner subdivision points of every arc.
  std::map<t_vertex, q_index> end_vertex;
  std::vector<std::vector<q_index>> arc_points(layout.arcs.size());
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

  std::vector<std::array<q_index, 4>> quads;
  std::vector<std::size_t> quad_patch; // the patch of every quad, for error messages
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
    std::vector<q_index> vmap(pattern.positions.size(), no_index);
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

    // the patch's triangles as a local indexed mesh, cut open along the patch's sides
    typedef internal::Cut_open_patch<TriangleMesh> Cut;
    const Cut cut(tmesh, patch.faces, Cut::edges_along(tmesh, patch.sides, layout.arcs));
    internal::Patch_map map;
    map.triangles = cut.triangles;
    for(t_vertex v : cut.vertex_of) map.points.push_back(point_of(v));
    map.uv.assign(map.points.size(), {{0., 0.}});
    map.fixed.assign(map.points.size(), false);

    // boundary of the map: every chain vertex of every arc, at its place along its side of the
    // polygon; the copy of a chain vertex is the one of the patch triangle on the left of the walk
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
        const std::size_t m = chain.size();
        // walking position w is chain index at(w)
        auto at = [&](std::size_t w) { return sa.reversed ? m - 1 - w : w; };
        for(std::size_t q = 0; q < m; ++q)
        {
          // the walk step used is (q, q+1), or (q-1, q) at the end
          const std::size_t idx = at(q);
          const std::size_t a = q + 1 < m ? q : q - 1;
          std::size_t local_a, local_b;
          if(!cut.left_of(chain[at(a)], chain[at(a + 1)], local_a, local_b))
            throw std::runtime_error("assemble_quad_mesh: patch " + std::to_string(pi)
                                     + ": a side does not have the patch on its left");
          const std::size_t lv = q + 1 < m ? local_a : local_b;
          const double along = sa.reversed ? 1. - arc_fraction[sa.arc][idx] : arc_fraction[sa.arc][idx];
          const double t = (offset + along * s) / double(side_count[i]);
          if(!map.fixed[lv]) ++fixed_count;
          map.fixed[lv] = true;
          map.uv[lv] = {{c0[0] + t * (c1[0] - c0[0]), c0[1] + t * (c1[1] - c0[1])}};
        }
        offset += s;
      }
    }
    if(fixed_count + 0 == 0) throw std::runtime_error("assemble_quad_mesh: patch without boundary");
    internal::solve_mean_value_map(map);
    internal::build_location_grid(map);

    for(std::size_t v = 0; v < pattern.positions.size(); ++v)
      if(vmap[v] == no_index)
        vmap[v] = add_point(internal::lift(map, {{pattern.positions[v][0], pattern.positions[v][1]}}));
    for(const auto& q : pattern.quads)
    {
      const std::array<q_index, 4> quad{{vmap[q[0]], vmap[q[1]], vmap[q[2]], vmap[q[3]]}};
      // At the tip of a slit (an arc walked there and back) the quad over the tip folds onto itself,
      // (a, tip, a, b): without it, its two neighbours share the edge (a, b) directly and the tip goes.
      if(quad[0] == quad[2] || quad[1] == quad[3])
      {
        ++stats.folded_quads;
        continue;
      }
      quads.push_back(quad);
      quad_patch.push_back(pi);
    }
    ++stats.patches;
  }

  // removes the quads marked in `gone`
  auto drop_quads = [&](const std::vector<bool>& gone) {
    std::vector<std::array<q_index, 4>> kept;
    std::vector<std::size_t> kept_patch;
    for(std::size_t k = 0; k < quads.size(); ++k)
      if(!gone[k])
      {
        kept.push_back(quads[k]);
        kept_patch.push_back(quad_patch[k]);
      }
    quads.swap(kept);
    quad_patch.swap(kept_patch);
  };

  // Where a pattern puts two rows of quads across the end of a slit, leaving out the folded quads
  // leaves two quads on the same four vertices, in opposite orientations: glued along all four edges
  // they would close a sphere, so both go (the slit then ends one quad edge earlier).
  {
    std::map<std::array<q_index, 4>, std::size_t> seen;
    std::vector<bool> gone(quads.size(), false);
    for(std::size_t k = 0; k < quads.size(); ++k)
    {
      std::array<q_index, 4> key = quads[k];
      std::sort(key.begin(), key.end());
      const auto ins = seen.emplace(key, k);
      if(ins.second) continue;
      const std::size_t other = ins.first->second;
      if(gone[other]) { ins.first->second = k; continue; }
      // opposite orientations: quads[k] read backwards is a rotation of quads[other]
      bool facing = false;
      for(int r = 0; r < 4 && !facing; ++r)
      {
        facing = true;
        for(int i = 0; i < 4; ++i)
          facing = facing && quads[k][std::size_t(i)] == quads[other][std::size_t((r + 4 - i) % 4)];
      }
      if(!facing) continue;
      gone[k] = gone[other] = true;
      stats.closed_quads += 2;
    }
    drop_quads(gone);
  }

  // A vertex inside the mesh with only two quads, which share both its edges (the tip of a slit
  // whose pattern has no inner edge there), has two flat corners: the two quads become one (at the
  // tip of a feature slit, this shortens the feature line by one quad edge; flat corners would be
  // degenerate quads).
  {
    std::vector<std::vector<std::size_t>> quads_at(points.size());
    std::vector<bool> gone(quads.size(), false);
    for(std::size_t k = 0; k < quads.size(); ++k)
      for(q_index i : quads[k]) quads_at[i].push_back(k);
    auto corner = [&](std::size_t k, q_index v) {
      for(int i = 0; i < 4; ++i)
        if(quads[k][std::size_t(i)] == v) return i;
      return -1;
    };
    std::vector<q_index> work;
    for(q_index v = 0; v < points.size(); ++v)
      if(quads_at[v].size() == 2) work.push_back(v);
    while(!work.empty())
    {
      const q_index t = work.back();
      work.pop_back();
      std::vector<std::size_t> around;
      for(std::size_t k : quads_at[t])
        if(!gone[k]) around.push_back(k);
      if(around.size() != 2) continue;
      const std::size_t k1 = around[0], k2 = around[1];
      const int c1 = corner(k1, t), c2 = corner(k2, t);
      // k1 = (t, b, x, a) and k2 = (t, a, y, b)
      const q_index b = quads[k1][std::size_t((c1 + 1) % 4)], x = quads[k1][std::size_t((c1 + 2) % 4)],
                    a = quads[k1][std::size_t((c1 + 3) % 4)];
      const q_index y = quads[k2][std::size_t((c2 + 2) % 4)];
      if(quads[k2][std::size_t((c2 + 1) % 4)] != a || quads[k2][std::size_t((c2 + 3) % 4)] != b || x == y) continue;
      quads[k1] = {{b, x, a, y}};
      gone[k2] = true;
      quads_at[y].push_back(k1);
      ++stats.merged_quads;
      for(q_index w : {a, b, x, y}) work.push_back(w);
    }
    drop_quads(gone);
  }

  // Two quads with the same directed edge cannot both be faces: find every such pair before the mesh
  // is touched, so that the caller can change the counts of the patches involved and try again.
  {
    std::map<std::pair<q_index, q_index>, std::size_t> quad_of_edge;
    std::set<std::size_t> involved;
    std::string first;
    for(std::size_t k = 0; k < quads.size(); ++k)
      for(std::size_t i = 0; i < 4; ++i)
      {
        const auto ins = quad_of_edge.emplace(std::make_pair(quads[k][i], quads[k][(i + 1) % 4]), k);
        if(ins.second) continue;
        const std::size_t other = ins.first->second;
        if(first.empty())
          first = "quad " + std::to_string(k) + " of patch " + std::to_string(quad_patch[k]) + " and quad "
                  + std::to_string(other) + " of patch " + std::to_string(quad_patch[other])
                  + " use the same edge in the same direction";
        involved.insert(quad_patch[k]);
        involved.insert(quad_patch[other]);
      }
    if(!involved.empty())
      throw Quad_assembly_conflict("assemble_quad_mesh: the patch quadrangulations do not form a manifold mesh ("
                                     + first + ")",
                                   std::vector<std::size_t>(involved.begin(), involved.end()));
  }

  // Says why a quad cannot be added, naming the patches involved (only called on failure).
  auto why_not_manifold = [&](std::size_t k) {
    const auto& q = quads[k];
    std::string what = "quad " + std::to_string(k) + " of patch " + std::to_string(quad_patch[k]);
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(q[i] == q[j]) return what + " has a repeated vertex";
    for(std::size_t other = 0; other < quads.size(); ++other)
      for(int i = 0; other != k && i < 4; ++i)
        for(int j = 0; j < 4; ++j)
          if(quads[other][j] == q[i] && quads[other][(j + 1) % 4] == q[(i + 1) % 4])
            return what + " and quad " + std::to_string(other) + " of patch " + std::to_string(quad_patch[other])
                   + " use the same edge in the same direction";
    return what + " would make a vertex non-manifold";
  };
  std::vector<q_vertex> vertex_of(points.size(), boost::graph_traits<QuadMesh>::null_vertex());
  for(const auto& q : quads)
    for(q_index i : q)
      if(vertex_of[i] == boost::graph_traits<QuadMesh>::null_vertex())
        vertex_of[i] = add_vertex(Q_point(points[i][0], points[i][1], points[i][2]), qmesh);
  for(std::size_t k = 0; k < quads.size(); ++k)
  {
    std::vector<q_vertex> face;
    for(q_index i : quads[k]) face.push_back(vertex_of[i]);
    if(CGAL::Euler::add_face(face, qmesh) == boost::graph_traits<QuadMesh>::null_face())
      throw std::runtime_error("assemble_quad_mesh: the patch quadrangulations do not form a manifold mesh ("
                               + why_not_manifold(k) + ")");
  }
  for(auto e : edges(qmesh)) put(qmesh_edge_is_feature, e, false);
  for(std::size_t a = 0; a < layout.arcs.size(); ++a)
    if(layout.arcs[a].on_feature)
      for(std::size_t k = 0; k + 1 < arc_points[a].size(); ++k)
      {
        const q_vertex u = vertex_of[arc_points[a][k]], w = vertex_of[arc_points[a][k + 1]];
        if(u == boost::graph_traits<QuadMesh>::null_vertex() || w == boost::graph_traits<QuadMesh>::null_vertex()) continue;
        const auto h = halfedge(u, w, qmesh);
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
              << " quads, " << stats.feature_edges << " feature edges, " << stats.folded_quads << " folded quads left out, "
              << stats.merged_quads << " pairs merged, " << stats.closed_quads << " quads closing a slit left out ("
              << stats.seconds << " s)\n";
  return stats;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_ASSEMBLE_QUAD_MESH_H
