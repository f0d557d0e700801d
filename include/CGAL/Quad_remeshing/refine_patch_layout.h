// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Refining the triangle mesh under a traced patch layout where a patch stays non-convex for want of a
// vertex: a cut from a concave boundary vertex straight across the patch needs a vertex where it meets the
// other side at a right angle.

#ifndef CGAL_QUAD_REMESHING_REFINE_PATCH_LAYOUT_H
#define CGAL_QUAD_REMESHING_REFINE_PATCH_LAYOUT_H

#include <CGAL/Quad_remeshing/Patch_layout.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/trace_patch_layout.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Real_timer.h>

#include <stdexcept>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <map>
#include <memory>
#include <utility>
#include <vector>

/// whether quad_remesh() runs refine_patch_layout() after the layout (`bool`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(layout_refinement_t, layout_refinement, layout_refinement)

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `refine_patch_layout()`
*/
struct Refine_patch_layout_statistics
{
  std::size_t invalid_before = 0; ///< invalid patches of the layout given
  std::size_t split_edges = 0;    ///< edges of the triangle mesh split, in all passes
  std::size_t passes = 0;         ///< passes that split edges
  std::size_t invalid_after = 0;  ///< invalid patches after `repair_patch_layout()` (`invalid_before` if no edge was split)
  double seconds = 0.;            ///< time of the refinement and the repair

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["invalid_before"] = invalid_before;
    r["split_edges"] = split_edges;
    r["passes"] = passes;
    r["invalid_after"] = invalid_after;
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {

// at most this many passes of refine_patch_layout()
constexpr unsigned max_layout_refinement_passes = 4;
// a landing point is at most this many times the longer boundary edge at the concave vertex away (2 left
// fertility's wedge of 15 faces without one; 8 finds no other)
constexpr double landing_reach = 4.;

// The point where a cut from the concave boundary vertex `target(L[i])` of a patch whose first loop is `L`
// would meet another boundary edge of `L` at a right angle, if it lies inside that edge (away from its ends
// by 15% of its length), near (within `landing_reach` times the longer of the vertex's two boundary edges)
// and splits the angle of the patch at the vertex into two angles of 30 to 178 degrees (120 to 240 if it is
// over 300; measured through the patch's fan of faces, the direction projected into each face's plane). Of
// those, the nearest; `found` is false if there is none.
template <typename Layout>
struct Cut_landing
{
  typedef typename Layout::halfedge_descriptor halfedge_descriptor;
  typedef typename Layout::Point_3 Point_3;
  bool found = false;
  halfedge_descriptor edge_halfedge; // a halfedge of the patch, on the edge to split
  Point_3 point;
  double distance = 0.;
};

template <typename TriangleMesh, typename Layout>
Cut_landing<Layout> cut_landing(const TriangleMesh& tm, const Layout& layout,
                                              const std::vector<typename Layout::halfedge_descriptor>& L, std::size_t i)
{
  typedef typename Layout::halfedge_descriptor halfedge_descriptor;
  typedef typename Layout::vertex_descriptor vertex_descriptor;
  typedef typename Layout::Vector_3 Vector_3;
  Cut_landing<Layout> best;
  const std::size_t m = L.size();
  const halfedge_descriptor hin = L[i], hout = L[(i + 1) % m];
  const vertex_descriptor v = target(hin, tm);
  const auto& pv = layout.point(v);
  auto length = [](const Vector_3& a) { return std::sqrt(CGAL::to_double(a * a)); };
  auto angle = [&](const Vector_3& a, const Vector_3& b) {
    const double la = length(a), lb = length(b);
    if(la == 0. || lb == 0.) return 0.;
    return std::acos((std::max)(-1., (std::min)(1., CGAL::to_double(a * b) / (la * lb))));
  };
  // the fan of the patch at v, from hout to hin: for each face, its two edges at v and the angle before it
  struct Sector { Vector_3 a, b; double start, angle; };
  std::vector<Sector> fan;
  double total = 0.;
  halfedge_descriptor g = hout;
  for(std::size_t guard = 0; guard < 64; ++guard) {
    const halfedge_descriptor p = prev(g, tm); // x -> v
    const Vector_3 a = layout.point(target(g, tm)) - pv, b = layout.point(source(p, tm)) - pv;
    fan.push_back(Sector{a, b, total, angle(a, b)});
    total += fan.back().angle;
    if(p == hin) break;
    if(layout.is_cut(edge(p, tm))) return best; // the vertex is on the loop more than once
    g = opposite(p, tm);
  }
  if(prev(g, tm) != hin) return best;
  const double deg = CGAL_PI / 180.;
  // the cut splits the patch's angle at v into two convex ones, not too sharp; an angle of more than 300
  // degrees (a left turn by the field's measure, but nearly the end of a line) into two about straight ones
  const bool nearly_line_end = total > 300. * deg;
  const double low = (nearly_line_end ? 120. : 30.) * deg, high = (nearly_line_end ? 240. : 178.) * deg;
  const double reach = landing_reach * (std::max)(length(layout.point(target(hout, tm)) - pv), length(pv - layout.point(source(hin, tm))));
  for(std::size_t j = 0; j < m; ++j) {
    const halfedge_descriptor e = L[j];
    const vertex_descriptor x = source(e, tm), y = target(e, tm);
    if(x == v || y == v) continue;
    const Vector_3 xy = layout.point(y) - layout.point(x);
    const double l2 = CGAL::to_double(xy * xy);
    if(l2 == 0.) continue;
    const double t = CGAL::to_double((pv - layout.point(x)) * xy) / l2;
    if(t < 0.15 || t > 0.85) continue;
    const auto f = layout.point(x) + t * xy;
    const Vector_3 d = f - pv;
    const double dist = length(d);
    if(dist == 0. || dist > reach || (best.found && dist >= best.distance)) continue;
    // where d is in the fan: in the sector whose two edges it lies between
    double position = -1.;
    for(const Sector& s : fan) {
      // d projected into the sector's plane (the surface may bend between v and the foot)
      const Vector_3 n = CGAL::cross_product(s.a, s.b);
      const double nn = CGAL::to_double(n * n);
      if(nn == 0.) continue;
      const Vector_3 dp = d - (CGAL::to_double(d * n) / nn) * n;
      if(angle(d, dp) > 60. * deg) continue;
      if(angle(dp, s.a) + angle(dp, s.b) <= s.angle + 1. * deg) { position = s.start + angle(dp, s.a); break; }
    }
    if(position < 0. || position < low || position > high || total - position < low || total - position > high)
      continue;
    best.found = true;
    best.edge_halfedge = e;
    best.point = f;
    best.distance = dist;
  }
  return best;
}

// Whether moving `z` to `moved` keeps every face around it turned the same way (the normals before and
// after at less than 90 degrees), the face of `h` (which has z as third vertex) counted as the two faces
// it becomes when its edge is split at `f`.
template <typename TriangleMesh, typename Layout>
bool move_keeps_orientation(const TriangleMesh& tm, const Layout& layout, typename Layout::vertex_descriptor z,
                            const typename Layout::Point_3& moved, typename Layout::halfedge_descriptor h,
                            const typename Layout::Point_3& f)
{
  typedef typename Layout::Point_3 Point_3;
  auto same_side = [&](const Point_3& a, const Point_3& b, const Point_3& c_before, const Point_3& c_after) {
    const auto n0 = CGAL::cross_product(b - a, c_before - a), n1 = CGAL::cross_product(b - a, c_after - a);
    return CGAL::to_double(n0 * n1) > 0.;
  };
  const Point_3& pz = layout.point(z);
  for(auto g : halfedges_around_target(z, tm)) {
    if(is_border(g, tm)) continue;
    const auto a = layout.point(target(next(g, tm), tm)), b = layout.point(source(g, tm)); // face (b, z, a)
    if(face(g, tm) == face(h, tm)) continue;
    if(!same_side(a, b, pz, moved)) return false;
  }
  const Point_3& x = layout.point(source(h, tm));
  const Point_3& y = layout.point(target(h, tm));
  return same_side(x, f, pz, moved) && same_side(f, y, pz, moved) && same_side(x, y, pz, moved);
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Refines the triangle mesh where patches of a traced layout stay non-convex for want of a vertex, moves
  the layout onto the refined mesh (same paths and corners) and repairs it there
  (`repair_patch_layout()`).

  A patch is not convex where its boundary turns left (a concave vertex, typically where a feature line
  bends back or a path leaves it near a sharp tip). A cut from that vertex across the patch removes the
  turn only if it meets the other side at about a right angle, which needs a vertex there; in a thin
  wedge between two feature lines (the teeth of a serrated rim, the tip of an ear) the remeshed
  triangles often have none, and every cut the last resorts try leaves a U-turn (a sharp angle between
  the cut and the other side). For every left turn `v` of a non-convex patch, the point of another
  boundary edge of the same patch where the perpendicular from `v` meets it is the landing point: the
  nearest such point inside an edge (away from its ends by 15% of its length), within four times the
  longer boundary edge at `v` (twice left fertility's wedge of 15 faces without one), whose direction
  from `v`, projected into the faces of the patch around `v`, splits the patch's angle there into two
  angles of 30 to 178 degrees; if that angle is more than 300 degrees (a left turn by the field's measure,
  but nearly the end of a line: one of rocker_arm's patches), into two of 120 to 240 degrees, about
  straight ones. The edge is split at the landing
  point, and its two faces towards their third vertices. If the third vertex `z` on the patch's side is
  not `v`, it must be a neighbour of `v` inside the patch (no path through it): it moves onto the segment
  from `v` to the landing point (its nearest point there, between 20% and 80% of the way), unless that
  turns one of its faces over (a normal reversed), in which case that left turn is left alone. A vertex
  takes part in one landing at most in a pass. The cut `v`, `z`, landing point is then straight; the
  repair finds it among its candidates. The passes (landings, splits, a new layout, the repair) go on
  while they lower the number of invalid patches, at most 4: a cut can leave a patch whose left turn has
  a landing point only then. New faces take the field of the face they come from, a split feature edge
  gives two feature edges, and the other elements of the mesh keep their descriptors (new ones are
  appended, as `CGAL::Surface_mesh` does when it has no removed elements). The moved vertices stay within
  the thin wedges, so the surface barely changes.

  Every patch that was valid stays valid, and the number of invalid patches does not grow (the repair's
  rule). On the 22 development meshes (`quad_remesh()`, which runs it by default), 54 invalid patches of 8677
  become 24: truck 34 -> 13 (in two passes), elephant 7 -> 3, rocker_arm 7 -> 5, camelhead 3 -> 2, bunny
  and fertility 1 -> 0; spot keeps its one (no landing point qualifies). Of the 24 left, 6 have a sharp
  U-turn (21 to 43 degrees: two paths, or a path and a line, meeting at a sharp angle) and 3 a U-turn of
  about 360 degrees in a hairpin of a line a few hundredths of the quad edge length across (the
  refinement looks at left turns only: a landing point for those hairpins, the perpendicular splitting
  their angle into two about straight ones, was tried and found none); the others are left turns without
  a landing point, most of them concave corners between two feature lines whose far side is out of
  reach even at eight times the boundary edge. A pass
  takes a few hundredths of a second for the landings and the splits, and then as long as the rounds of
  `repair_patch_layout()`.

  \tparam TriangleMesh a model of `MutableFaceGraph` with triangle faces, whose descriptors stay valid when
          elements are added (`CGAL::Surface_mesh` without removed elements)
  \tparam GeomTraits the traits of the layout
  \tparam EdgeIsFeatureMap a read-write property map, key `edge_descriptor`, value `bool`
  \tparam FaceFieldMap a read-write property map, key `face_descriptor`, value `Vector_3`
  \tparam VertexSingularityMap a readable property map, key `vertex_descriptor`, value `int`, that reads 0
          for new vertices (a `CGAL::Surface_mesh` property map created with the default 0)
  \tparam NamedParameters a sequence of named parameters

  \param tmesh the mesh the layout was built on
  \param edge_is_feature_map the feature edges
  \param field the cross field the layout was built with
  \param singularities the singularity indices the layout was built with
  \param layout the traced layout (`trace_patch_layout()`); replaced by the layout of the refined mesh if
         an edge was split (the mesh is unchanged otherwise)
  \param trace_statistics the figures of `trace_patch_layout()`: the repair's rounds are appended and
         the layout's figures updated
  \param np optional named parameters: `number_of_threads` and `verbose`, as for `trace_patch_layout()`

  \pre `&layout->mesh() == &tmesh`
*/
template <typename TriangleMesh, typename GeomTraits, typename EdgeIsFeatureMap, typename FaceFieldMap,
          typename VertexSingularityMap, typename NamedParameters = parameters::Default_named_parameters>
Refine_patch_layout_statistics
refine_patch_layout(TriangleMesh& tmesh, EdgeIsFeatureMap edge_is_feature_map, FaceFieldMap field,
                    VertexSingularityMap singularities, std::unique_ptr<Patch_layout<TriangleMesh, GeomTraits>>& layout,
                    Trace_patch_layout_statistics& trace_statistics,
                    const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const unsigned threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 1u);
  if(!layout || &layout->mesh() != &tmesh)
    throw std::invalid_argument("refine_patch_layout: the layout is not built on this mesh");
  Refine_patch_layout_statistics stats;
  typedef Patch_layout<TriangleMesh, GeomTraits> Layout;
  typedef typename Layout::halfedge_descriptor halfedge_descriptor;
  typedef typename Layout::vertex_descriptor vertex_descriptor;
  typedef typename Layout::face_descriptor face_descriptor;
  typedef typename Layout::Point_3 Point_3;
  CGAL::Real_timer timer;
  timer.start();

  // passes while they help: a cut of one pass can leave a patch whose left turn has a landing point only
  // then, and a vertex takes part in one landing per pass
  for(unsigned pass = 0; pass < internal::max_layout_refinement_passes; ++pass) {
    const auto& traced = *layout;
    // the landing points, one per edge
    std::vector<std::pair<halfedge_descriptor, Point_3>> splits;
    std::vector<vertex_descriptor> touched; // one landing per vertex: the moves and splits do not interact
    std::vector<std::pair<vertex_descriptor, Point_3>> moves;
    std::size_t invalid = 0;
    for(std::size_t p = 0; p < traced.number_of_patches(); ++p) {
      const auto condition = traced.validity(p);
      if(condition == Layout::SATISFIED) continue;
      ++invalid;
      if(condition != Layout::NOT_CONVEX) continue;
      const auto& P = traced.patch(p);
      const auto& L = P.loops[0];
      for(std::size_t i = 0; i < L.size(); ++i) {
        if(P.turns[0][i] != Layout::LEFT_TURN) continue;
        const auto landing = internal::cut_landing(tmesh, traced, L, i);
        if(!landing.found) continue;
        // the cut goes from v to the landing point through the patch-side face of the edge: straight through
        // its third vertex z, moved onto the segment, if z is not v (z must then be a neighbour of v inside
        // the patch, and the move must not turn any of its faces over)
        const vertex_descriptor v = target(L[i], tmesh), z = target(next(landing.edge_halfedge, tmesh), tmesh);
        const vertex_descriptor x = source(landing.edge_halfedge, tmesh), y = target(landing.edge_halfedge, tmesh);
        auto is_touched = [&](vertex_descriptor w) { return std::find(touched.begin(), touched.end(), w) != touched.end(); };
        if(is_touched(v) || is_touched(z) || is_touched(x) || is_touched(y)) continue;
        if(z != v) {
          if(!edge(v, z, tmesh).second) continue;
          bool inside = true;
          for(halfedge_descriptor g : halfedges_around_target(z, tmesh)) inside = inside && !traced.is_cut(edge(g, tmesh));
          if(!inside) continue;
          const auto pv = traced.point(v);
          const auto vf = landing.point - pv;
          const double t = (std::max)(0.2, (std::min)(0.8, CGAL::to_double((traced.point(z) - pv) * vf) / CGAL::to_double(vf * vf)));
          const Point_3 moved = pv + t * vf;
          if(!internal::move_keeps_orientation(tmesh, traced, z, moved, landing.edge_halfedge, landing.point)) continue;
          moves.emplace_back(z, moved);
        }
        touched.insert(touched.end(), {v, x, y, z});
        splits.emplace_back(landing.edge_halfedge, landing.point);
      }
    }
    if(pass == 0) stats.invalid_before = stats.invalid_after = invalid;
    if(splits.empty()) break;
    stats.split_edges += splits.size();
    ++stats.passes;

    // the paths and corners of the layout, read before the mesh changes
    std::vector<typename Layout::Path> paths;
    for(std::size_t id : traced.path_ids())
      if(!traced.path(id).is_feature) paths.push_back(traced.path(id));
    const std::vector<halfedge_descriptor> corners = traced.added_corners();

    // the splits; the new vertex of each split edge, by its two ends
    auto vpm = get(CGAL::vertex_point, tmesh);
    std::map<std::pair<vertex_descriptor, vertex_descriptor>, vertex_descriptor> inserted;
    for(const auto& s : splits) {
      const halfedge_descriptor h = s.first;
      const vertex_descriptor a = source(h, tmesh), b = target(h, tmesh);
      const bool was_feature = get(edge_is_feature_map, edge(h, tmesh));
      const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, tmesh); // a -> m, then h: m -> b
      const vertex_descriptor m = target(hnew, tmesh);
      put(vpm, m, s.second);
      put(edge_is_feature_map, edge(hnew, tmesh), was_feature);
      put(edge_is_feature_map, edge(h, tmesh), was_feature);
      inserted[std::make_pair((std::min)(a, b), (std::max)(a, b))] = m;
      // each face beside the edge is cut from m to its opposite vertex; both parts keep its field
      for(const halfedge_descriptor side : {h, opposite(h, tmesh)}) {
        if(is_border(side, tmesh)) continue;
        const face_descriptor f = face(side, tmesh);
        const auto direction = get(field, f);
        const halfedge_descriptor cut = side == h ? CGAL::Euler::split_face(hnew, next(h, tmesh), tmesh)
                                                  : CGAL::Euler::split_face(side, next(next(side, tmesh), tmesh), tmesh);
        put(edge_is_feature_map, edge(cut, tmesh), false);
        put(field, face(cut, tmesh), direction);
        put(field, face(opposite(cut, tmesh), tmesh), direction);
      }
    }

    for(const auto& mv : moves) put(vpm, mv.first, mv.second);
    // the new layout, with the same paths
    auto refined = std::make_unique<Layout>(tmesh, field, singularities);
    refined->add_feature_paths(edge_is_feature_map);
    for(typename Layout::Path& path : paths) {
      typename Layout::Path q;
      q.is_feature = path.is_feature;
      q.vertices.push_back(path.vertices.front());
      for(std::size_t k = 0; k + 1 < path.vertices.size(); ++k) {
        const vertex_descriptor a = path.vertices[k], b = path.vertices[k + 1];
        if(!edge(a, b, tmesh).second) {
          const auto it = inserted.find(std::make_pair((std::min)(a, b), (std::max)(a, b)));
          if(it != inserted.end()) {
            q.vertices.push_back(it->second);
            if(k < path.directions.size()) q.directions.push_back(path.directions[k]);
          }
        }
        q.vertices.push_back(b);
        if(k < path.directions.size()) q.directions.push_back(path.directions[k]);
      }
      refined->add_path(std::move(q));
    }
    for(halfedge_descriptor h : corners)
      if(!is_border(h, tmesh) && refined->is_cut(edge(h, tmesh))) refined->add_corner(h);
    layout = std::move(refined);

    const Trace_patch_layout_statistics repair =
      repair_patch_layout(tmesh, *layout, parameters::combine(CGAL::parameters::verbose(verbose),
                                                                  parameters::number_of_threads(threads)));
    for(Trace_patch_layout_statistics::Round r : repair.rounds) {
      r.name = "refined_" + r.name; // the rounds of the repair after the refinement
      trace_statistics.rounds.push_back(r);
    }
    trace_statistics.layout = repair.layout;
    stats.invalid_after = repair.layout.patches - repair.layout.valid_patches;
    if(stats.invalid_after == 0 || stats.invalid_after >= invalid) break;
  }
  stats.seconds = timer.time();
  trace_statistics.seconds += stats.seconds;
  if(verbose)
    std::cerr << "[layout] refinement: " << stats.split_edges << " edges split, invalid patches " << stats.invalid_before
              << " -> " << stats.invalid_after << ", " << stats.seconds << " s\n";
  return stats;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_REFINE_PATCH_LAYOUT_H
