// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Turns a Patch_layout into the inputs of the quantization and of the assembly.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_LAYOUT_CONVERSION_H
#define CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_LAYOUT_CONVERSION_H

#include <CGAL/Quad_remeshing/Patch_layout.h>
#include <CGAL/Quad_remeshing/assemble_quad_mesh.h>
#include <CGAL/Quad_remeshing/quantize_patch_sides.h>
#include <CGAL/Quad_remeshing/internal/bbox_diagonal.h>
#include <CGAL/Quad_remeshing/internal/pipeline/quad_sizing.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/*
  The polygons the quadrangulation works on. A valid patch of the layout is used as it is: its
  corners are its turns. A patch that is still a disk but breaks the other validity conditions (a
  left turn or U-turn, fewer than 3 or more than 6 corners) is quadrangulated all the same with
  corners chosen among its convex turns: non-convex turns become points of a side (the map onto the
  convex polygon stays one-to-one, the quads there are less regular), with more than 6 corners the
  ones joining the shortest sides are dropped, and with fewer than 3 corners points near the middle of
  the longest sides are added, splitting arcs where needed (the patch on the other side of such an arc
  sees the same split). Patches that are not disks are refused. A patch with 3 corners keeps them (the
  quadrangulation serves triangles): a corner added on a side would be a quad corner where the side is
  straight, a 180-degree angle on a border or a flat corner at a valence-3 vertex inside. Only a sliver
  triangle, whose shortest side is under a quarter of its longest, gets a fourth corner (on the 22
  development meshes, keeping such slivers as triangles stretched angle_block's quads over a
  crease: feature coverage 0.980 instead of 0.995, Hausdorff distance 2.2% instead of 1.0%).
*/
template <typename TriangleMesh, typename Layout>
struct Quadrangulation_layout
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  struct Piece { std::size_t arc; std::size_t first, last; }; // halfedge index range [first, last] of a layout arc
  std::vector<Piece> pieces;                                   // the refined arcs
  std::vector<std::vector<std::vector<std::pair<std::size_t, bool>>>> patch_sides; // piece id, reversed
  std::size_t relaxed_patches = 0;                             // patches whose corners were re-chosen
  std::size_t added_corners = 0, dropped_corners = 0;

  Quadrangulation_layout(const TriangleMesh& tm, const Layout& layout)
  {
    const auto& arcs = layout.arcs();
    const auto& patches = layout.patches();
    std::map<halfedge_descriptor, std::pair<std::size_t, std::size_t>> where; // halfedge -> (arc, index), forward
    for(std::size_t a = 0; a < arcs.size(); ++a)
      for(std::size_t k = 0; k < arcs[a].halfedges.size(); ++k) where[arcs[a].halfedges[k]] = {a, k};
    auto locate = [&](halfedge_descriptor h, bool& reversed) {
      auto it = where.find(h);
      if(it != where.end()) { reversed = false; return it->second; }
      it = where.find(opposite(h, tm));
      if(it == where.end()) throw std::runtime_error("layout conversion: a patch boundary edge is on no arc");
      reversed = true;
      return it->second;
    };
    auto length = [&](halfedge_descriptor h) { return CGAL::to_double(Polygon_mesh_processing::edge_length(h, tm)); };
    // splits[a]: split after these halfedge indices (the vertex target(halfedges[k]))
    std::vector<std::set<std::size_t>> splits(arcs.size());
    std::vector<std::vector<std::size_t>> corners_of(patches.size()); // loop positions i: corner at target(L[i])
    for(std::size_t p = 0; p < patches.size(); ++p)
    {
      const auto& P = patches[p];
      if(P.loops.size() != 1 || P.euler_characteristic != 1)
        throw std::runtime_error("patch " + std::to_string(p) + " of the layout is not a disk");
      const auto& L = P.loops[0];
      const auto& T = P.turns[0];
      const std::size_t m = L.size();
      std::vector<double> cum(m + 1, 0.);
      for(std::size_t i = 0; i < m; ++i) cum[i + 1] = cum[i] + length(L[i]);
      std::vector<std::size_t> corners;
      for(std::size_t i = 0; i < m; ++i)
        if(T[i] == Layout::RIGHT_TURN) corners.push_back(i);
      const bool valid = layout.validity(p) == Layout::SATISFIED;
      if(valid)
      {
        corners.clear();
        for(std::size_t i = 0; i < m; ++i)
          if(T[i] != Layout::STRAIGHT) corners.push_back(i);
      }
      else ++relaxed_patches;
      auto side_length = [&](std::size_t c) { return loop_side_length(cum, corners, c); };
      while(corners.size() > 6)
      {
        std::size_t best = 0;
        double best_len = 1e300;
        for(std::size_t c = 0; c < corners.size(); ++c)
        {
          const double l = side_length((c + corners.size() - 1) % corners.size()) + side_length(c);
          if(l < best_len) { best_len = l; best = c; }
        }
        corners.erase(corners.begin() + std::ptrdiff_t(best));
        ++dropped_corners;
      }
      // a sliver triangle (shortest side under a quarter of the longest) gets a fourth corner: its
      // valence-3 centre would sit near the short side and stretch the quads over the long ones
      std::size_t min_corners = 3;
      if(corners.size() == 3)
      {
        const double a = side_length(0), b = side_length(1), c = side_length(2);
        if((std::min)({a, b, c}) < 0.25 * (std::max)({a, b, c})) min_corners = 4;
      }
      while(corners.size() < min_corners && corners.size() < m)
      {
        const std::size_t best_i = middle_of_longest_side(cum, corners);
        if(best_i == m) break;
        corners.push_back(best_i);
        std::sort(corners.begin(), corners.end());
        ++added_corners;
      }
      if(corners.size() < 2) throw std::runtime_error("patch " + std::to_string(p) + " is too small to be quadrangulated");
      // corners that are not at the end of an arc split that arc
      for(std::size_t i : corners)
      {
        bool r1, r2;
        const auto w1 = locate(L[i], r1);
        const auto w2 = locate(L[(i + 1) % m], r2);
        if(w1.first != w2.first || w1.first == std::size_t(-1)) continue; // already an arc end
        const std::size_t a = w1.first;
        const std::size_t n_he = arcs[a].halfedges.size();
        // the vertex target(L[i]) is target(halfedges[k]) going forward, or source(halfedges[k]) going backwards
        const std::size_t k = r1 ? w1.second - 1 : w1.second;
        if(k + 1 < n_he && k < n_he) splits[a].insert(k);
      }
      corners_of[p] = corners;
    }
    // the refined arcs
    std::vector<std::vector<std::size_t>> piece_of(arcs.size()); // per halfedge index of an arc
    for(std::size_t a = 0; a < arcs.size(); ++a)
    {
      const std::size_t n_he = arcs[a].halfedges.size();
      piece_of[a].resize(n_he);
      std::size_t first = 0;
      for(std::size_t k = 0; k < n_he; ++k)
      {
        piece_of[a][k] = pieces.size();
        if(splits[a].count(k) || k + 1 == n_he)
        {
          pieces.push_back({a, first, k});
          first = k + 1;
        }
      }
    }
    // sides of every patch, as pieces between its corners
    patch_sides.resize(patches.size());
    for(std::size_t p = 0; p < patches.size(); ++p)
    {
      const auto& L = patches[p].loops[0];
      const std::size_t m = L.size();
      const auto& corners = corners_of[p];
      const std::size_t start = (corners.front() + 1) % m;
      std::vector<std::pair<std::size_t, bool>> side;
      std::pair<std::size_t, bool> last(std::size_t(-1), false);
      for(std::size_t j = 0; j < m; ++j)
      {
        const std::size_t i = (start + j) % m;
        bool reversed;
        const auto w = locate(L[i], reversed);
        const std::pair<std::size_t, bool> piece(piece_of[w.first][w.second], reversed);
        // a piece walked there and back (a slit) is two entries: only the direction tells them apart
        if(piece != last) { side.push_back(piece); last = piece; }
        if(std::binary_search(corners.begin(), corners.end(), i))
        {
          patch_sides[p].push_back(side);
          side.clear();
          last = std::make_pair(std::size_t(-1), false);
        }
      }
      if(!side.empty()) throw std::runtime_error("layout conversion: patch loop does not end at a corner");
    }
  }
};

// The vertices of a piece of a layout arc, from its first halfedge's source to its last one's target.
template <typename TriangleMesh, typename Layout>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
piece_vertices(const TriangleMesh& tm, const Layout& layout, const typename Quadrangulation_layout<TriangleMesh, Layout>::Piece& piece)
{
  const auto& arc = layout.arcs()[piece.arc];
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> chain{source(arc.halfedges[piece.first], tm)};
  for(std::size_t k = piece.first; k <= piece.last; ++k) chain.push_back(target(arc.halfedges[k], tm));
  return chain;
}

// The arcs' targets are their field-measured lengths in quad edges (a piece of an arc gets the share
// of its arc's field length given by its share of the arc's Euclidean length). With a local quad edge
// length per vertex (`sizing`, by vertex index; empty: `quad_edge_length` everywhere), each edge of a
// piece counts in units of the mean local length of its two ends.
template <typename TriangleMesh, typename Layout>
Side_quantization_problem quantization_problem(const TriangleMesh& tm, const Layout& layout,
                                               const Quadrangulation_layout<TriangleMesh, Layout>& ql,
                                               double quad_edge_length, const std::vector<double>& sizing = {})
{
  if(!(quad_edge_length > 0)) throw std::invalid_argument("quantization_problem: the quad edge length must be positive");
  auto length = [&](typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h) {
    return CGAL::to_double(Polygon_mesh_processing::edge_length(h, tm));
  };
  // the global length over the local one; exactly 1 without sizing (l * 1. == l: uniform targets unchanged)
  auto refinement = [&](typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h) {
    if(sizing.empty()) return 1.;
    return quad_edge_length / (0.5 * (sizing[std::size_t(get(CGAL::vertex_index, tm, source(h, tm)))]
                                      + sizing[std::size_t(get(CGAL::vertex_index, tm, target(h, tm)))]));
  };
  Side_quantization_problem pb;
  for(const auto& piece : ql.pieces)
  {
    const auto& arc = layout.arcs()[piece.arc];
    double total = 0, part = 0;
    for(std::size_t k = 0; k < arc.halfedges.size(); ++k)
    {
      const double l = length(arc.halfedges[k]);
      total += l;
      if(k >= piece.first && k <= piece.last) part += l * refinement(arc.halfedges[k]);
    }
    Side_quantization_problem::Arc a;
    a.target = (std::max)(arc.length * (total > 0 ? part / total : 1.) / quad_edge_length, 1e-3);
    pb.arcs.push_back(a);
  }
  // Arcs with the same two ends (the two sides of a crack, a thin hole or a sliver between two paths)
  // would, each given one edge, become one edge twice: the assembly would zip them into one (angle_block
  // lost a crack of the input so) or fail. All but one of them get at least two edges, and a piece that
  // closes on itself at least three.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> seen_ends;
  for(std::size_t i = 0; i < ql.pieces.size(); ++i)
  {
    const auto chain = piece_vertices(tm, layout, ql.pieces[i]);
    std::size_t u = std::size_t(get(CGAL::vertex_index, tm, chain.front()));
    std::size_t w = std::size_t(get(CGAL::vertex_index, tm, chain.back()));
    if(u == w) { pb.arcs[i].minimum = (std::max)(pb.arcs[i].minimum, 3); continue; }
    if(w < u) std::swap(u, w);
    if(++seen_ends[std::make_pair(u, w)] > 1) pb.arcs[i].minimum = (std::max)(pb.arcs[i].minimum, 2);
  }
  for(const auto& sides : ql.patch_sides)
  {
    std::vector<std::vector<std::size_t>> s;
    for(const auto& side : sides)
    {
      std::vector<std::size_t> ids;
      for(const auto& pr : side) ids.push_back(pr.first);
      s.push_back(ids);
    }
    pb.patches.push_back(s);
  }
  return pb;
}

// The fewest straight edges, with ends at equal arc-length steps along the polyline `p`, that stay
// within `tolerance` of it (every vertex of `p` within `tolerance` of the edge spanning it), at most `cap`.
// With `normals` (one per point of `p`), only the part of that distance along the point's normal counts.
template <typename Point, typename Vector = typename CGAL::Kernel_traits<Point>::Kernel::Vector_3>
int chord_minimum(const std::vector<Point>& p, double tolerance, int cap, const std::vector<Vector>& normals = {})
{
  if(p.size() < 3 || cap <= 1) return 1;
  std::vector<double> at(p.size(), 0.); // arc length at every point
  for(std::size_t i = 1; i < p.size(); ++i)
    at[i] = at[i - 1] + std::sqrt(CGAL::to_double(CGAL::squared_distance(p[i - 1], p[i])));
  const double total = at.back();
  if(!(total > 0)) return 1;
  auto point_at = [&](double l) { // the point at arc length l
    const std::size_t i = std::size_t(std::upper_bound(at.begin(), at.end(), l) - at.begin());
    if(i == 0) return p.front();
    if(i >= p.size()) return p.back();
    const double d = at[i] - at[i - 1];
    return d > 0 ? p[i - 1] + (p[i] - p[i - 1]) * ((l - at[i - 1]) / d) : p[i];
  };
  const double tol2 = tolerance * tolerance;
  for(int n = 1; n < cap; ++n) {
    bool fits = true;
    for(std::size_t i = 1; i + 1 < p.size() && fits; ++i) {
      const int k = (std::min)(n - 1, int(at[i] / total * n)); // the edge spanning point i
      const typename CGAL::Kernel_traits<Point>::Kernel::Segment_3 chord(point_at(total * k / n), point_at(total * (k + 1) / n));
      if(normals.empty())
        fits = CGAL::to_double(CGAL::squared_distance(p[i], chord)) <= tol2;
      else
      {
        // only the part along the surface normal: the bend of the surface under the chord, not the
        // zigzag of an edge path in the tangent plane
        const auto d = chord.to_vector();
        const double dd = CGAL::to_double(d * d);
        const double t = dd > 0. ? (std::min)(1., (std::max)(0., CGAL::to_double((p[i] - chord.source()) * d) / dd)) : 0.;
        const double h = CGAL::to_double((p[i] - (chord.source() + t * d)) * normals[i]);
        fits = h * h <= tol2;
      }
    }
    if(fits) return n;
  }
  return cap;
}

constexpr double default_feature_tolerance = 0.002; // quad_remesh()'s `feature_tolerance`
constexpr double default_sizing_tolerance = 0.002;  // quad_remesh()'s `sizing_tolerance`
constexpr double default_surface_tolerance = 0.002; // quad_remesh()'s `surface_tolerance`
constexpr double default_fidelity_tolerance = 0.004; // quad_remesh()'s `fidelity_tolerance`

// Raises the minimum edge count of arcs so that their quad edges, placed at equal arc-length steps as the
// assembly does, follow them: an arc along a feature line (the boundary included) within
// `feature_tolerance`, and, when `surface_tolerance` > 0, any other arc within `surface_tolerance` along
// the surface normal (the bend of the surface the arc crosses, not the zigzag of its edge path in the
// tangent plane), both times the bounding-box diagonal. The quantization may otherwise give a bent
// feature line, or a fillet crossed by an arc, so few edges that they cut its bends. Capped at
// 2 ceil(target) + 1 (quads there at most about twice as long as wide). A tolerance <= 0 leaves those
// minimums at 1. Returns the number of arcs along features and of other arcs whose minimum was raised.
template <typename TriangleMesh, typename Layout, typename EdgeIsFeatureMap>
std::pair<std::size_t, std::size_t> set_chord_minimums(Side_quantization_problem& pb, const TriangleMesh& tm,
                                                       const Layout& layout,
                                                       const Quadrangulation_layout<TriangleMesh, Layout>& ql,
                                                       EdgeIsFeatureMap edge_is_feature, double feature_tolerance,
                                                       double surface_tolerance = 0.)
{
  std::pair<std::size_t, std::size_t> raised(0, 0);
  if(!(feature_tolerance > 0 || surface_tolerance > 0) || num_vertices(tm) == 0) return raised;
  const double diagonal = mesh_bbox_diagonal(tm);
  typedef typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  std::vector<Point> p;
  std::vector<typename CGAL::Kernel_traits<Point>::Kernel::Vector_3> normals;
  for(std::size_t i = 0; i < ql.pieces.size() && i < pb.arcs.size(); ++i) {
    const auto& piece = ql.pieces[i];
    const auto& arc = layout.arcs()[piece.arc];
    const bool feature = get(edge_is_feature, edge(arc.halfedges[piece.first], tm));
    const double tolerance = (feature ? feature_tolerance : surface_tolerance) * diagonal;
    if(!(tolerance > 0)) continue;
    p.clear();
    normals.clear();
    for(auto v : piece_vertices(tm, layout, piece)) {
      p.push_back(get(CGAL::vertex_point, tm, v));
      if(!feature) normals.push_back(CGAL::Polygon_mesh_processing::compute_vertex_normal(v, tm));
    }
    const int cap = 2 * static_cast<int>(std::ceil(pb.arcs[i].target)) + 1;
    const int m = chord_minimum(p, tolerance, cap, normals);
    if(m > pb.arcs[i].minimum) {
      pb.arcs[i].minimum = m;
      ++(feature ? raised.first : raised.second);
    }
  }
  return raised;
}

// The quantization problem of a traced layout as the pipeline builds it (quad_remesh(), the command
// line and the stage benchmark share it): the targets in the local quad edge length of quad_sizing()
// (uniform when `sizing_tolerance` <= 0 and no component is too small for `quad_edge_length`), then the minimums of the bent arcs (set_chord_minimums()).
struct Pipeline_quantization_problem
{
  Side_quantization_problem problem;
  std::vector<double> sizing;        // the local quad edge length per vertex (empty: uniform)
  std::size_t bent_feature_arcs = 0; // arcs along features whose minimum set_chord_minimums() raised
  std::size_t bent_surface_arcs = 0; // other arcs whose minimum it raised
};

template <typename TriangleMesh, typename Layout, typename EdgeIsFeatureMap>
Pipeline_quantization_problem pipeline_quantization_problem(const TriangleMesh& tm, const Layout& layout,
                                                            const Quadrangulation_layout<TriangleMesh, Layout>& ql,
                                                            EdgeIsFeatureMap edge_is_feature, double quad_edge_length,
                                                            double sizing_tolerance, double feature_tolerance,
                                                            double surface_tolerance = 0.,
                                                            double component_resolution = default_component_resolution)
{
  Pipeline_quantization_problem r;
  r.sizing = quad_sizing(tm, edge_is_feature, quad_edge_length, sizing_tolerance, component_resolution);
  r.problem = quantization_problem(tm, layout, ql, quad_edge_length, r.sizing);
  std::tie(r.bent_feature_arcs, r.bent_surface_arcs) =
    set_chord_minimums(r.problem, tm, layout, ql, edge_is_feature, feature_tolerance, surface_tolerance);
  return r;
}

// Arcs as vertex chains and patches as ordered, oriented arcs, for assemble_quad_mesh().
template <typename TriangleMesh, typename Layout, typename EdgeIsFeatureMap>
Patch_layout_description<TriangleMesh> layout_description(const TriangleMesh& tm, const Layout& layout,
                                                          const Quadrangulation_layout<TriangleMesh, Layout>& ql,
                                                          EdgeIsFeatureMap edge_is_feature)
{
  typedef Patch_layout_description<TriangleMesh> Description;
  Description d;
  for(const auto& piece : ql.pieces)
  {
    const auto& arc = layout.arcs()[piece.arc];
    typename Description::Arc a;
    a.vertices = piece_vertices(tm, layout, piece);
    a.on_feature = get(edge_is_feature, edge(arc.halfedges[piece.first], tm));
    d.arcs.push_back(a);
  }
  const auto& patches = layout.patches();
  for(std::size_t p = 0; p < patches.size(); ++p)
  {
    typename Description::Patch P;
    P.faces = patches[p].faces;
    for(const auto& side : ql.patch_sides[p])
    {
      std::vector<typename Description::Side_arc> s;
      for(const auto& pr : side)
      {
        typename Description::Side_arc sa;
        sa.arc = pr.first;
        sa.reversed = pr.second;
        s.push_back(sa);
      }
      P.sides.push_back(s);
    }
    d.patches.push_back(P);
  }
  return d;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
