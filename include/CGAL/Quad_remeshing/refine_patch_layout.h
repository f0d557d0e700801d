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
  std::size_t straight_cuts = 0;  ///< straight cuts made paths of mesh edges, in all passes
  std::size_t straight_cuts_kept = 0; ///< of those, cuts inserted into the layout
  std::size_t invalid_after = 0;  ///< invalid patches after `repair_patch_layout()` (`invalid_before` if no edge was split)
  double seconds = 0.;            ///< time of the refinement and the repair

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["invalid_before"] = invalid_before;
    r["split_edges"] = split_edges;
    r["passes"] = passes;
    r["straight_cuts"] = straight_cuts;
    r["straight_cuts_kept"] = straight_cuts_kept;
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

// the length of the longer of the two boundary edges `hin` and `hout` at their common vertex (the unit of
// the reach of landings and straight cuts)
template <typename TriangleMesh, typename Layout>
double longer_boundary_edge(const TriangleMesh& tm, const Layout& layout,
                            typename Layout::halfedge_descriptor hin, typename Layout::halfedge_descriptor hout)
{
  const auto& pv = layout.point(target(hin, tm));
  const auto a = layout.point(target(hout, tm)) - pv, b = pv - layout.point(source(hin, tm));
  return (std::max)(std::sqrt(CGAL::to_double(a * a)), std::sqrt(CGAL::to_double(b * b)));
}

// the angle between two vectors, 0 if one is null
template <typename Vector_3>
double fan_angle(const Vector_3& a, const Vector_3& b)
{
  const double la = std::sqrt(CGAL::to_double(a * a)), lb = std::sqrt(CGAL::to_double(b * b));
  if(la == 0. || lb == 0.) return 0.;
  return std::acos((std::max)(-1., (std::min)(1., CGAL::to_double(a * b) / (la * lb))));
}

// A face of a patch at one of its boundary vertices v: its halfedge `g` leaving v, its two edges at v
// (`a` along g, `b` along the edge coming back to v), and the angle of the patch at v before it.
template <typename Layout>
struct Fan_sector
{
  typedef typename Layout::Vector_3 Vector_3;
  typename Layout::halfedge_descriptor g;
  Vector_3 a, b;
  double start, angle;

  // whether the direction `d`, projected into the face's plane (`dp`; the surface may bend between v and
  // where d points), lies between a and b, and d is less than 60 degrees off that plane
  bool contains(const Vector_3& d, Vector_3& dp) const
  {
    const Vector_3 n = CGAL::cross_product(a, b);
    const double nn = CGAL::to_double(n * n);
    if(nn == 0.) return false;
    dp = d - (CGAL::to_double(d * n) / nn) * n;
    if(fan_angle(d, dp) > 60. * (CGAL_PI / 180.)) return false;
    return fan_angle(dp, a) + fan_angle(dp, b) <= angle + 1. * (CGAL_PI / 180.);
  }
};

// The faces of the patch at v = target(hin), from the boundary halfedge `hout` leaving v around to the
// boundary halfedge `hin` coming in, and in `total` the patch's angle at v; empty if v is on the patch
// boundary more than once.
template <typename TriangleMesh, typename Layout>
std::vector<Fan_sector<Layout>> patch_fan(const TriangleMesh& tm, const Layout& layout,
                                          typename Layout::halfedge_descriptor hin,
                                          typename Layout::halfedge_descriptor hout, double& total)
{
  typedef typename Layout::halfedge_descriptor halfedge_descriptor;
  const auto& pv = layout.point(target(hin, tm));
  std::vector<Fan_sector<Layout>> fan;
  total = 0.;
  halfedge_descriptor g = hout;
  for(std::size_t guard = 0; guard < 64; ++guard) {
    const halfedge_descriptor p = prev(g, tm); // x -> v
    const auto a = layout.point(target(g, tm)) - pv, b = layout.point(source(p, tm)) - pv;
    fan.push_back(Fan_sector<Layout>{g, a, b, total, fan_angle(a, b)});
    total += fan.back().angle;
    if(p == hin) return fan;
    if(layout.is_cut(edge(p, tm))) break; // the vertex is on the loop more than once
    g = opposite(p, tm);
  }
  fan.clear();
  return fan;
}

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
  double total = 0.;
  const std::vector<Fan_sector<Layout>> fan = patch_fan(tm, layout, hin, hout, total);
  if(fan.empty()) return best;
  const double deg = CGAL_PI / 180.;
  // the cut splits the patch's angle at v into two convex ones, not too sharp; an angle of more than 300
  // degrees (a left turn by the field's measure, but nearly the end of a line) into two about straight ones
  const bool nearly_line_end = total > 300. * deg;
  const double low = (nearly_line_end ? 120. : 30.) * deg, high = (nearly_line_end ? 240. : 178.) * deg;
  const double reach = landing_reach * longer_boundary_edge(tm, layout, hin, hout);
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
    for(const Fan_sector<Layout>& s : fan) {
      Vector_3 dp;
      if(s.contains(d, dp)) { position = s.start + fan_angle(dp, s.a); break; }
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

// A straight cut from a boundary vertex v of a patch into it, to the first boundary edge it meets: where
// the plane through v that holds the cut's direction and the normal of the face it starts in crosses the
// edges of the patch, face after face.
template <typename Layout>
struct Slice_cut
{
  typedef typename Layout::halfedge_descriptor halfedge_descriptor;
  typedef typename Layout::Point_3 Point_3;
  bool found = false;
  std::vector<std::pair<halfedge_descriptor, Point_3>> crossings; // edges inside the patch, each seen from
                                                                  // the face the cut leaves, and the point
  halfedge_descriptor landing_halfedge; // the boundary edge met, seen from the patch
  Point_3 point;                        // where
  double length = 0.;
  double landing_skew = 0.; // how far from a right angle the cut meets that edge (radians)
  std::vector<typename Layout::vertex_descriptor> vertices; // the vertices of the faces it changes, v first
};

// The cut from v = target(L[i]) in direction `d`, if it leaves v inside the patch (between the two
// boundary edges at v), crosses every edge in its inner 80% (no sliver triangles when the edges are
// split there), meets the boundary inside an edge (its inner 70%) at 45 to 135 degrees, and is at most
// `reach` long.
template <typename TriangleMesh, typename Layout>
Slice_cut<Layout> slice_cut(const TriangleMesh& tm, const Layout& layout,
                            const std::vector<typename Layout::halfedge_descriptor>& L, std::size_t i,
                            const typename Layout::Vector_3& d, double reach)
{
  typedef typename Layout::halfedge_descriptor halfedge_descriptor;
  typedef typename Layout::Vector_3 Vector_3;
  Slice_cut<Layout> cut;
  const halfedge_descriptor hin = L[i], hout = L[(i + 1) % L.size()];
  const auto& pv = layout.point(target(hin, tm));
  double total = 0.;
  const std::vector<Fan_sector<Layout>> fan = patch_fan(tm, layout, hin, hout, total);
  // the face the cut starts in, and the plane's normal
  halfedge_descriptor e; // the halfedge crossed next, in the face the cut is in
  Vector_3 normal;
  bool started = false;
  for(const Fan_sector<Layout>& s : fan) {
    Vector_3 dp;
    if(!s.contains(d, dp)) continue;
    normal = CGAL::cross_product(dp, CGAL::cross_product(s.a, s.b));
    e = next(s.g, tm);
    started = CGAL::to_double(normal * normal) > 0.;
    break;
  }
  if(!started) return cut;
  auto side = [&](typename Layout::vertex_descriptor w) { return CGAL::to_double((layout.point(w) - pv) * normal); };
  auto crossing = [&](halfedge_descriptor h, double& t) {
    const double s0 = side(source(h, tm)), s1 = side(target(h, tm));
    t = s0 / (s0 - s1);
    return layout.point(source(h, tm)) + t * (layout.point(target(h, tm)) - layout.point(source(h, tm)));
  };
  auto last = pv;
  std::vector<typename Layout::face_descriptor> faces{face(e, tm)}; // the faces it goes through
  for(std::size_t guard = 0; guard < 64; ++guard) {
    const double s0 = side(source(e, tm)), s1 = side(target(e, tm));
    if(!((s0 < 0. && s1 > 0.) || (s0 > 0. && s1 < 0.))) return cut;
    double t = 0.;
    const auto q = crossing(e, t);
    if(guard == 0 && CGAL::to_double((q - pv) * d) <= 0.) return cut; // behind v
    cut.length += std::sqrt(CGAL::to_double(CGAL::squared_distance(last, q)));
    if(cut.length > reach) return cut;
    if(layout.is_cut(edge(e, tm))) {
      if(t < 0.15 || t > 0.85) return cut;
      // (a patch on both sides of the edge: the face beyond would be split twice)
      const halfedge_descriptor o = opposite(e, tm);
      if(!is_border(o, tm) && std::find(faces.begin(), faces.end(), face(o, tm)) != faces.end()) return cut;
      const double skew = std::abs(CGAL_PI / 2. - fan_angle(q - last, layout.point(target(e, tm)) - layout.point(source(e, tm))));
      if(skew > CGAL_PI / 4.) return cut;
      cut.found = true;
      cut.landing_halfedge = e;
      cut.point = q;
      cut.landing_skew = skew;
      // the vertices of the faces it changes: v, the ends of the edges it splits, the third vertex beyond
      // the boundary edge
      cut.vertices = {target(hin, tm), source(e, tm), target(e, tm)};
      if(!is_border(o, tm)) cut.vertices.push_back(target(next(o, tm), tm));
      for(const auto& c : cut.crossings)
        cut.vertices.insert(cut.vertices.end(), {source(c.first, tm), target(c.first, tm)});
      return cut;
    }
    if(t < 0.1 || t > 0.9) return cut;
    cut.crossings.emplace_back(e, q);
    last = q;
    // into the face beyond, and out through the edge whose ends are on both sides of the plane
    const halfedge_descriptor o = opposite(e, tm);
    if(is_border(o, tm) || std::find(faces.begin(), faces.end(), face(o, tm)) != faces.end()) return cut;
    faces.push_back(face(o, tm));
    const double sc = side(target(next(o, tm), tm));
    if(sc == 0.) return cut;
    e = (sc > 0.) == (side(source(o, tm)) > 0.) ? next(o, tm) : prev(o, tm);
  }
  return cut;
}

// the halfedge of the face of `h` whose target is `w` (the cuts of a pass share no face, so it is there)
template <typename TriangleMesh>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
halfedge_to(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
            typename boost::graph_traits<TriangleMesh>::vertex_descriptor w)
{
  for(auto g : halfedges_around_face(h, tm))
    if(target(g, tm) == w) return g;
  throw std::logic_error("refine_patch_layout: a vertex of a straight cut is not on the face it should cut");
}

// Splits the edge of `h` at the point `q`; the two parts keep its feature flag. Returns the new vertex, the
// target of prev(h) after the split (h then goes from it to its old target).
template <typename TriangleMesh, typename Point_3, typename EdgeIsFeatureMap>
typename boost::graph_traits<TriangleMesh>::vertex_descriptor
split_edge_at(TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const Point_3& q,
              EdgeIsFeatureMap feature)
{
  const bool was_feature = get(feature, edge(h, tm));
  const auto hnew = CGAL::Euler::split_edge(h, tm); // source(h) -> m, then h: m -> target
  put(get(CGAL::vertex_point, tm), target(hnew, tm), q);
  put(feature, edge(hnew, tm), was_feature);
  put(feature, edge(h, tm), was_feature);
  return target(hnew, tm);
}

// Splits the face of `h` (a triangle whose edges were split, so a polygon of 4 or 5 vertices) from
// target(h) to `w`, another of its vertices, then what is not a triangle along its shorter diagonal; every
// part keeps the face's field direction, and the new edges are no features.
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename FaceFieldMap>
void split_face_towards(TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                        typename boost::graph_traits<TriangleMesh>::vertex_descriptor w,
                        EdgeIsFeatureMap feature, FaceFieldMap field)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const auto direction = get(field, face(h, tm));
  auto vpm = get(CGAL::vertex_point, tm);
  auto split = [&](halfedge_descriptor a, halfedge_descriptor b) { // from target(a) to target(b)
    const halfedge_descriptor c = CGAL::Euler::split_face(a, b, tm);
    put(feature, edge(c, tm), false);
    put(field, face(c, tm), direction);
    put(field, face(opposite(c, tm), tm), direction);
  };
  const halfedge_descriptor to_w = halfedge_to(tm, h, w);
  split(h, to_w);
  // the two parts; a quadrilateral along its shorter diagonal
  for(halfedge_descriptor g : {h, to_w}) {
    if(degree(face(g, tm), tm) != 4) continue;
    const halfedge_descriptor g1 = next(g, tm), g2 = next(g1, tm), g3 = next(g2, tm);
    const double d02 = CGAL::to_double(CGAL::squared_distance(get(vpm, target(g, tm)), get(vpm, target(g2, tm))));
    const double d13 = CGAL::to_double(CGAL::squared_distance(get(vpm, target(g1, tm)), get(vpm, target(g3, tm))));
    if(d02 <= d13) split(g, g2);
    else split(g1, g3);
  }
}

// Makes the cut `cut` from v a path of mesh edges: splits the edges it crosses and the boundary edge it
// meets at its points, then the faces it goes through along it (their other parts into triangles), and
// the face beyond the boundary edge towards its third vertex. Returns the cut's vertices, v first; the
// boundary edge's ends and new vertex go to `inserted`.
template <typename TriangleMesh, typename Layout, typename EdgeIsFeatureMap, typename FaceFieldMap>
std::vector<typename Layout::vertex_descriptor>
embed_slice_cut(TriangleMesh& tm, const Slice_cut<Layout>& cut, typename Layout::vertex_descriptor v,
                EdgeIsFeatureMap feature, FaceFieldMap field,
                std::map<std::pair<typename Layout::vertex_descriptor, typename Layout::vertex_descriptor>,
                         typename Layout::vertex_descriptor>& inserted)
{
  typedef typename Layout::halfedge_descriptor halfedge_descriptor;
  typedef typename Layout::vertex_descriptor vertex_descriptor;
  typedef typename Layout::face_descriptor face_descriptor;
  // the faces the cut goes through, in order (face descriptors survive the edge splits)
  std::vector<face_descriptor> faces;
  for(const auto& c : cut.crossings) faces.push_back(face(c.first, tm));
  faces.push_back(face(cut.landing_halfedge, tm));
  const halfedge_descriptor beyond = opposite(cut.landing_halfedge, tm);
  const bool beyond_face = !is_border(beyond, tm);
  const face_descriptor outer = beyond_face ? face(beyond, tm) : face_descriptor();
  // the edge splits
  std::vector<vertex_descriptor> path{v};
  for(const auto& c : cut.crossings) path.push_back(split_edge_at(tm, c.first, c.second, feature));
  const vertex_descriptor x = source(cut.landing_halfedge, tm), y = target(cut.landing_halfedge, tm);
  const vertex_descriptor m = split_edge_at(tm, cut.landing_halfedge, cut.point, feature);
  inserted[std::make_pair((std::min)(x, y), (std::max)(x, y))] = m;
  path.push_back(m);
  // each face split along the cut
  for(std::size_t k = 0; k < faces.size(); ++k)
    split_face_towards(tm, halfedge_to(tm, halfedge(faces[k], tm), path[k]), path[k + 1], feature, field);
  if(beyond_face) {
    // the face beyond: from m to its vertex that is not on the split edge
    const halfedge_descriptor h = halfedge_to(tm, halfedge(outer, tm), m);
    split_face_towards(tm, h, target(next(next(h, tm), tm), tm), feature, field);
  }
  return path;
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

  Where a left turn has no landing point (or its vertex `z` may not move), and at a U-turn of more than a
  half turn (a hairpin), the refinement tries a straight cut instead: one of the two sides at `v`
  extended into the patch (its direction is that from the vertex three boundary edges back along the side,
  or fewer if the side ends before), made of the points where the plane through `v` that holds this
  direction and the normal of the face it enters crosses the edges of the patch, face after face, until
  it meets the boundary. It must cross every edge within its inner 80% (no sliver triangles), meet the
  boundary within the inner 70% of an edge at 45 to 135 degrees, and be at most eight times as long as the
  longer boundary edge at `v`; of the two sides, the cut meeting the boundary closer to a right angle is
  taken. The edges it crosses and the one it meets are split at those points, the faces it goes through
  along it (what is left of them along their shorter diagonal), and the face beyond the boundary edge
  towards its third vertex, so the surface does not change at all. The cut is inserted into the new
  layout if it lowers the number of invalid patches where it is (before the repair). A vertex takes part
  in one landing or straight cut at most in a pass (for a straight cut, every vertex of the faces it
  changes).

  Every patch that was valid stays valid, and the number of invalid patches does not grow (the repair's
  rule). On the 22 development meshes (`quad_remesh()`, which runs it by default), 54 invalid patches of 8677
  become 12 of 8751: truck 34 -> 5 (in two passes), elephant 7 -> 2, rocker_arm 7 -> 2, camelhead 3 -> 2,
  bunny and fertility 1 -> 0; spot keeps its one (no landing point or straight cut qualifies). The
  straight cuts (truck 11 inserted, rocker_arm 3, elephant 1) took the count from 24 to 12. Of the 12 left,
  9 turn back by U-turns only: sharp ones (two paths, or a path and a line, meeting at a sharp angle),
  which no cut from that vertex can mend, or hairpins of a line too small for a straight cut; the other 3
  are left turns whose cuts meet the boundary too far, too close to a vertex or too slanted. A pass
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
    std::vector<std::pair<vertex_descriptor, internal::Slice_cut<Layout>>> slices; // straight cuts, by their start
    std::size_t invalid = 0;
    for(std::size_t p = 0; p < traced.number_of_patches(); ++p) {
      const auto condition = traced.validity(p);
      if(condition == Layout::SATISFIED) continue;
      ++invalid;
      if(condition != Layout::NOT_CONVEX) continue;
      const auto& P = traced.patch(p);
      const auto& L = P.loops[0];
      auto is_touched = [&](vertex_descriptor w) { return std::find(touched.begin(), touched.end(), w) != touched.end(); };
      // a landing point for the left turn i (see above); whether one was taken
      auto land = [&](std::size_t i) {
        const auto landing = internal::cut_landing(tmesh, traced, L, i);
        if(!landing.found) return false;
        // the cut goes from v to the landing point through the patch-side face of the edge: straight through
        // its third vertex z, moved onto the segment, if z is not v (z must then be a neighbour of v inside
        // the patch, and the move must not turn any of its faces over)
        const vertex_descriptor v = target(L[i], tmesh), z = target(next(landing.edge_halfedge, tmesh), tmesh);
        const vertex_descriptor x = source(landing.edge_halfedge, tmesh), y = target(landing.edge_halfedge, tmesh);
        if(is_touched(v) || is_touched(z) || is_touched(x) || is_touched(y)) return false;
        if(z != v) {
          if(!edge(v, z, tmesh).second) return false;
          bool inside = true;
          for(halfedge_descriptor g : halfedges_around_target(z, tmesh)) inside = inside && !traced.is_cut(edge(g, tmesh));
          if(!inside) return false;
          const auto pv = traced.point(v);
          const auto vf = landing.point - pv;
          const double t = (std::max)(0.2, (std::min)(0.8, CGAL::to_double((traced.point(z) - pv) * vf) / CGAL::to_double(vf * vf)));
          const Point_3 moved = pv + t * vf;
          if(!internal::move_keeps_orientation(tmesh, traced, z, moved, landing.edge_halfedge, landing.point)) return false;
          moves.emplace_back(z, moved);
        }
        touched.insert(touched.end(), {v, x, y, z});
        splits.emplace_back(landing.edge_halfedge, landing.point);
        return true;
      };
      // else a straight cut extending one of the two sides at the turn i (see above)
      auto slice = [&](std::size_t i) {
        const vertex_descriptor v = target(L[i], tmesh);
        if(is_touched(v)) return;
        const auto pv = traced.point(v);
        // a side's direction: from its vertex up to 3 edges away from v (fewer if it turns before)
        auto side_end = [&](bool backwards) {
          std::size_t k = i;
          for(std::size_t n = 0; n < 3; ++n) {
            k = backwards ? (k + L.size() - 1) % L.size() : (k + 1) % L.size();
            if(k == i || P.turns[0][k] != Layout::STRAIGHT) break; // a corner ends the side
          }
          return traced.point(target(L[k], tmesh));
        };
        const double reach =
          2. * internal::landing_reach * internal::longer_boundary_edge(tmesh, traced, L[i], L[(i + 1) % L.size()]);
        internal::Slice_cut<Layout> best;
        for(bool backwards : {true, false}) {
          const auto d = pv - side_end(backwards);
          if(CGAL::to_double(d * d) == 0.) continue;
          internal::Slice_cut<Layout> cut = internal::slice_cut(tmesh, traced, L, i, d, reach);
          if(!cut.found || std::any_of(cut.vertices.begin() + 1, cut.vertices.end(), is_touched)) continue;
          if(!best.found || cut.landing_skew < best.landing_skew) best = std::move(cut);
        }
        if(!best.found) return;
        touched.insert(touched.end(), best.vertices.begin(), best.vertices.end());
        slices.emplace_back(v, std::move(best));
      };
      for(std::size_t i = 0; i < L.size(); ++i) {
        const bool left = P.turns[0][i] == Layout::LEFT_TURN;
        if(left && land(i)) continue;
        if(left || (P.turns[0][i] == Layout::U_TURN)) slice(i);
      }
    }
    if(pass == 0) stats.invalid_before = stats.invalid_after = invalid;
    if(splits.empty() && slices.empty()) break;
    stats.split_edges += splits.size();
    for(const auto& sl : slices) stats.split_edges += sl.second.crossings.size() + 1;
    stats.straight_cuts += slices.size();
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
      const halfedge_descriptor h = s.first, o = opposite(h, tmesh);
      const vertex_descriptor a = source(h, tmesh), b = target(h, tmesh);
      // the third vertices of the faces beside the edge, each cut from the new vertex m to it
      const vertex_descriptor za = is_border(h, tmesh) ? vertex_descriptor() : target(next(h, tmesh), tmesh);
      const vertex_descriptor zb = is_border(o, tmesh) ? vertex_descriptor() : target(next(o, tmesh), tmesh);
      const vertex_descriptor m = internal::split_edge_at(tmesh, h, s.second, edge_is_feature_map); // h: m -> b
      inserted[std::make_pair((std::min)(a, b), (std::max)(a, b))] = m;
      if(!is_border(h, tmesh)) internal::split_face_towards(tmesh, prev(h, tmesh), za, edge_is_feature_map, field);
      if(!is_border(o, tmesh)) internal::split_face_towards(tmesh, o, zb, edge_is_feature_map, field);
    }

    // the straight cuts made paths of mesh edges
    std::vector<std::vector<vertex_descriptor>> straight_cuts;
    for(const auto& sl : slices)
      straight_cuts.push_back(internal::embed_slice_cut(tmesh, sl.second, sl.first, edge_is_feature_map, field, inserted));

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
    // and each straight cut, if it lowers the number of invalid patches where it is
    for(std::vector<vertex_descriptor>& vs : straight_cuts) {
      typename Layout::Path q = internal::straight_path(*refined, std::move(vs));
      typename Layout::Patch_change change = refined->preview_add_path(q);
      std::size_t before = 0, after = 0;
      for(std::size_t p : change.old_patches) before += refined->validity(p) != Layout::SATISFIED;
      for(const auto& N : change.new_patches) after += refined->validity(N) != Layout::SATISFIED;
      if(after >= before) continue;
      refined->add_path(std::move(q), std::move(change));
      ++stats.straight_cuts_kept;
    }
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
