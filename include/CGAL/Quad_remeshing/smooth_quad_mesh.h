// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Feature-constrained tangential smoothing of a quad mesh lying on a triangle mesh.

#ifndef CGAL_QUAD_REMESHING_SMOOTH_QUAD_MESH_H
#define CGAL_QUAD_REMESHING_SMOOTH_QUAD_MESH_H

#include <CGAL/Quad_remeshing/internal/bbox_diagonal.h>
#include <CGAL/Quad_remeshing/internal/is_finite_point.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/quality/soup_figures.h>
#include <CGAL/Quad_remeshing/internal/smoothing/closest_point_search.h>
#include <CGAL/Quad_remeshing/internal/smoothing/quad_geometry.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Surface_mesh/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

/// damping factor of each smoothing step, in (0, 1] (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(smoothing_damping_t, smoothing_damping, smoothing_damping)

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `smooth_quad_mesh()`.
*/
struct Quad_smoothing_statistics
{
  unsigned iterations = 0;            ///< smoothing iterations done
  bool stopped_early = false;         ///< whether `maximum_running_time` ended the iterations or the refinement
  std::size_t free_vertices = 0;      ///< vertices that move on the surface
  std::size_t feature_vertices = 0;   ///< vertices that slide along a feature line
  std::size_t fixed_vertices = 0;     ///< vertices that never move (feature corners, constrained vertices)
  std::size_t rejected_moves = 0;     ///< moves refused (even after backing off) because they would worsen a quad too much
  std::size_t inverted_before = 0;    ///< quads with a scaled Jacobian <= 0 before smoothing
  std::size_t inverted_after = 0;     ///< quads with a scaled Jacobian <= 0 after smoothing
  std::size_t untangling_moves = 0;   ///< vertex moves made to untangle quads with a scaled Jacobian <= 0
  std::size_t refined_chords = 0;     ///< chords split in two because a quad on them stayed inverted
  std::size_t inset_quads = 0;        ///< inverted, flat (scaled Jacobian <= 1e-3) or flipped quads replaced by an inner quad and four around it
  std::size_t refinement_quads = 0;   ///< quads added by the chord splits and the insets
  std::size_t flipped_before_mending = 0; ///< quads flipped over among their neighbours (as `Quad_mesh_quality::flipped_quads`) after the refinement
  std::size_t mended_flipped_quads = 0;   ///< how many fewer of them the last step left (its untangling and insets)
  double min_scaled_jacobian_before = 0.;  ///< over all quads, before smoothing
  double min_scaled_jacobian_after = 0.;   ///< over all quads, after smoothing
  double mean_scaled_jacobian_before = 0.; ///< over all quads, before smoothing
  double mean_scaled_jacobian_after = 0.;  ///< over all quads, after smoothing
  double seconds = 0.;                ///< time spent

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["iterations"] = iterations;
    r["stopped_early"] = stopped_early;
    r["free_vertices"] = free_vertices;
    r["feature_vertices"] = feature_vertices;
    r["fixed_vertices"] = fixed_vertices;
    r["rejected_moves"] = rejected_moves;
    r["inverted_before"] = inverted_before;
    r["inverted_after"] = inverted_after;
    r["untangling_moves"] = untangling_moves;
    r["refined_chords"] = refined_chords;
    r["inset_quads"] = inset_quads;
    r["refinement_quads"] = refinement_quads;
    r["flipped_before_mending"] = flipped_before_mending;
    r["mended_flipped_quads"] = mended_flipped_quads;
    r["min_scaled_jacobian_before"] = min_scaled_jacobian_before;
    r["min_scaled_jacobian_after"] = min_scaled_jacobian_after;
    r["mean_scaled_jacobian_before"] = mean_scaled_jacobian_before;
    r["mean_scaled_jacobian_after"] = mean_scaled_jacobian_after;
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {

// The feature lines of the triangle mesh as chains of segments between feature corners
// (vertices where the number of incident feature edges is not 2, or where the line turns sharply).
template <typename TriangleMesh, typename EdgeFeatureMap, typename VPM, typename K>
struct Feature_lines
{
  typedef typename K::Point_3 Point_3;
  typedef typename K::Segment_3 Segment_3;
  std::vector<std::vector<Segment_3>> lines;
  std::vector<Point_3> corners;
  std::vector<CGAL::Bbox_3> boxes; // of each line

  Feature_lines(const TriangleMesh& tm, EdgeFeatureMap efm, VPM vpm, double corner_angle_deg)
  {
    typedef boost::graph_traits<TriangleMesh> GT;
    typedef typename GT::halfedge_descriptor halfedge_descriptor;
    typedef typename GT::vertex_descriptor vertex_descriptor;
    auto degree = get(CGAL::dynamic_vertex_property_t<int>(), tm);
    for(vertex_descriptor v : vertices(tm)) put(degree, v, 0);
    for(auto e : edges(tm))
      if(get(efm, e))
      {
        put(degree, source(e, tm), get(degree, source(e, tm)) + 1);
        put(degree, target(e, tm), get(degree, target(e, tm)) + 1);
      }
    const double cos_limit = std::cos(corner_angle_deg * CGAL_PI / 180.);
    auto is_corner = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
    for(vertex_descriptor v : vertices(tm))
    {
      bool corner = get(degree, v) != 0 && get(degree, v) != 2;
      if(get(degree, v) == 2)
      {
        std::vector<typename K::Vector_3> dirs;
        for(halfedge_descriptor h : halfedges_around_target(halfedge(v, tm), tm))
          if(get(efm, edge(h, tm))) dirs.push_back(typename K::Vector_3(get(vpm, v), get(vpm, source(h, tm))));
        if(dirs.size() == 2)
        {
          const double l0 = std::sqrt(dirs[0].squared_length()), l1 = std::sqrt(dirs[1].squared_length());
          // straight continuation means the two edges point in opposite directions
          if(l0 > 0 && l1 > 0 && -(dirs[0] * dirs[1]) / (l0 * l1) < cos_limit) corner = true;
        }
      }
      put(is_corner, v, corner);
      if(corner) corners.push_back(get(vpm, v));
    }
    // walk the chains
    auto visited = get(CGAL::dynamic_edge_property_t<bool>(), tm);
    for(auto e : edges(tm)) put(visited, e, false);
    for(auto e0 : edges(tm))
    {
      if(!get(efm, e0) || get(visited, e0)) continue;
      // go backwards to the start of the chain (a corner) or around a closed loop
      halfedge_descriptor h = halfedge(e0, tm);
      halfedge_descriptor start = h;
      for(;;)
      {
        vertex_descriptor s = source(h, tm);
        if(get(is_corner, s)) break;
        halfedge_descriptor prev = h;
        bool found = false;
        for(halfedge_descriptor g : halfedges_around_target(s, tm))
          if(get(efm, edge(g, tm)) && edge(g, tm) != edge(h, tm)) { prev = g; found = true; break; }
        if(!found) break;
        h = prev;
        if(h == start || opposite(h, tm) == start) break;
      }
      std::vector<Segment_3> line;
      halfedge_descriptor first = h;
      for(;;)
      {
        if(get(visited, edge(h, tm))) break;
        put(visited, edge(h, tm), true);
        line.emplace_back(get(vpm, source(h, tm)), get(vpm, target(h, tm)));
        vertex_descriptor t = target(h, tm);
        if(get(is_corner, t)) break;
        bool found = false;
        for(halfedge_descriptor g : halfedges_around_source(t, tm))
          if(get(efm, edge(g, tm)) && edge(g, tm) != edge(h, tm) && !get(visited, edge(g, tm))) { h = g; found = true; break; }
        if(!found || h == first) break;
      }
      lines.push_back(std::move(line));
    }
    // the boxes of the lines, a billionth of the mesh's size wider than the lines: the distance to a box
    // is then smaller than any rounding of the distance to its line
    CGAL::Bbox_3 all;
    for(vertex_descriptor v : vertices(tm)) all += get(vpm, v).bbox();
    const double margin = 1e-9 * internal::bbox_diagonal(all);
    for(const std::vector<Segment_3>& line : lines)
    {
      CGAL::Bbox_3 box;
      for(const Segment_3& s : line) box += s.bbox();
      boxes.emplace_back(box.xmin() - margin, box.ymin() - margin, box.zmin() - margin, box.xmax() + margin,
                         box.ymax() + margin, box.zmax() + margin);
    }
  }

  static double squared_distance_to_box(const Point_3& p, const CGAL::Bbox_3& b)
  {
    double d = 0.;
    for(int i = 0; i < 3; ++i)
    {
      const double x = CGAL::to_double(p[i]);
      const double out = (std::max)((std::max)(b.min(i) - x, x - b.max(i)), 0.);
      d += out * out;
    }
    return d;
  }

  // the closest point of line `l` to `p`
  Point_3 project(std::size_t l, const Point_3& p, double* sq_dist = nullptr) const
  {
    double best = std::numeric_limits<double>::max();
    Point_3 best_p = p;
    for(const Segment_3& s : lines[l])
    {
      const typename K::Vector_3 d = s.to_vector();
      const double len2 = d.squared_length();
      double t = len2 > 0 ? ((p - s.source()) * d) / len2 : 0.;
      t = (std::max)(0., (std::min)(1., t));
      const Point_3 q = s.source() + t * d;
      const double dd = CGAL::squared_distance(p, q);
      if(dd < best) { best = dd; best_p = q; }
    }
    if(sq_dist) *sq_dist = best;
    return best_p;
  }

  // the line nearest to `p` (by brute force: done once per feature vertex)
  std::size_t nearest_line(const Point_3& p, double& sq_dist) const
  {
    std::size_t best_l = 0;
    sq_dist = std::numeric_limits<double>::max();
    for(std::size_t l = 0; l < lines.size(); ++l)
    {
      // (a line whose box is as far as the best line cannot be nearer)
      if(!(squared_distance_to_box(p, boxes[l]) < sq_dist)) continue;
      double d;
      project(l, p, &d);
      if(d < sq_dist) { sq_dist = d; best_l = l; }
    }
    return best_l;
  }
};

// An inset (which merges two faces) or an undone refinement leaves removed elements in a `Surface_mesh`:
// they go, so that the output has consecutive indices; other meshes remove elements at once.
template <typename P>
void collect_garbage_of(CGAL::Surface_mesh<P>& m)
{
  if(m.has_garbage()) m.collect_garbage();
}
template <typename Mesh>
void collect_garbage_of(Mesh&) {}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef

  smooths a quad mesh that lies on a triangle mesh, keeping it on the surface and its feature lines
  on the feature lines of the triangle mesh.

  Each iteration fits a square to every quad (the rotated, scaled square closest to the quad in its
  mean plane) and moves every vertex, damped, towards the average of the fitted positions of its
  corners ("tangent-space smoothing" by template fitting). Free vertices are then projected back onto
  the triangle mesh (closest point, AABB tree), on their own side of it: a closest point on a face whose
  normal is turned by 75 degrees or more from that of the face the vertex started on (the other sheet of
  a thin plate, the other side of a crease), or on another connected component (where components pass
  through each other), is replaced by the closest point on the nearby faces of its component that
  agree with it. A free vertex also keeps to its sheet: a closest point on a face that is not connected
  to the face under the vertex through faces near it (within twice the move) is replaced by the closest
  point on those faces (two sheets of one component close together that face the same way). Vertices
  on a feature line slide along it: they are
  projected onto the feature line of the triangle mesh they started on; feature corners and
  constrained vertices do not move. A move that would add an incident quad with a scaled Jacobian
  <= 0, or lower the smallest scaled Jacobian of the incident quads below both its previous value and
  0.3, is halved twice and then refused, so smoothing never inverts a quad (nor worsens an already bad
  one). Here and in the untangling below, a quad flipped over counts as inverted: its normal (of its
  diagonals) turned by more than 120 degrees from its orientation at the start, the sum over its corners
  of the normals of their quads (those with a positive scaled Jacobian). The scaled Jacobian alone, measured
  in the quad's own plane, cannot see such a quad (a convex quad flipped over is as good as any by that
  measure, for the evaluators too), and the untangling mended bow-tie quads by flipping them over: on the
  22 development meshes, 74 quads were turned by more than 120 degrees from all their neighbours, 17 now
  (truck 41 -> 16, spot 2 -> 1, the 15 others that had some none: camelhead 5, bunny 4, draco_test_nm 2).
  The statistics and the connectivity changes below go by the scaled Jacobian alone (splitting the
  chords of a quad that stays flipped cost truck 19223 quads instead of 14649 and 49 s instead of 29).

  Before and after the smoothing iterations, poor quads (a scaled Jacobian <= 0.01: inverted, or so
  close to collapsed that they are as bad) are untangled: each vertex of such a quad and each of its
  neighbours (unless fixed) tries a few positions (the average of its fitted-square corners, the
  average parallelogram completion of its quads, the centroid of its neighbours, halfway to each, and
  small steps along the coordinate axes), then, if one of its quads is still poor, a pattern search in
  the plane of its quads from the best of them (eight directions, the step halved when none helps),
  each position projected like a smoothing move, and takes the best, if that is strictly better than
  where it is. Positions are compared by the number of incident quads with a scaled Jacobian <= 0,
  then the number of poor ones, then the smallest scaled Jacobian, so the number of inverted quads
  never grows. What is still poor after the last untangling is relaxed by regions: the vertices within
  one to four rings of each group of poor quads move together to the centroids of their neighbours
  (twenty times the number of rings, the outer ring held), which unfolds quads folded onto themselves
  that no single move can open, and then try single untangling moves again; the width whose quads score best is kept if it beats the old
  positions, and a last untangling follows. Here and in the smoothing moves a collapsed quad (a
  zero-length edge, or four collinear corners) counts as the worst possible quad, so that no vertex
  slides onto its neighbour or onto the corner at the end of its feature line. A smoothing move must
  not add a quad with a scaled Jacobian <= 0 or a poor quad.

  A quad that is still inverted after all that (folded over a bend of the surface smaller than itself,
  or with a corner at a held vertex), or that has a scaled Jacobian <= 1e-3 (a corner within about
  0.06 degrees of flat, e.g. at a held border vertex of valence 2: a triangle in all but name), gets
  its two chords split (only an inverted one: a flat one goes straight to the inset below): the strips of quads that cross it are
  cut in two along their length (every edge they cross gets its midpoint, put onto the surface or onto
  the feature line of a constrained edge; their quads are cut in two, in four where they cross), which
  keeps the mesh pure-quad and conforming and changes no vertex's valence. The untangling then runs
  around the split, and the split is kept only if fewer quads are inverted or flat than before; otherwise it is
  undone, and each chord alone is tried; chords that cross more than `max(128, #quads / 5)` edges in
  all are not split (on organic meshes one can wind over most of the surface: on elephant, 6572
  edges). A quad still inverted or flat then is inset: it becomes an inner quad and four quads around it, so
  that each of its corners gets an edge into it (which splits a corner at a held vertex that no move
  can mend), kept on the same condition. These are the only changes `smooth_quad_mesh()` makes to the
  connectivity (a `Surface_mesh`'s removed elements are then collected). At most 64 quads are tried
  in each of at most four rounds, and none once `maximum_running_time` is reached.

  Last, the quads that lie flipped over among their neighbours (`Quad_mesh_quality::flipped_quads`: the
  normal of the diagonals turned by more than 120 degrees from that of every quad across an edge; a
  convex quad upside down in the surface has a positive scaled Jacobian) are mended where the
  untangling can: the moves above judge a quad against the orientation of its neighbourhood at the
  start, and the quads made by the chord splits and the insets have none, so a thin quad of an inset
  can end flipped over. The orientations are taken again from the quads as they are (a flipped quad's
  from its neighbours across its edges), and the untangling, then the relaxation of regions, runs
  around each flipped quad in turn; its moves stay only if fewer quads are then flipped over and no
  more have a scaled Jacobian <= 0. Where they do not, the quad is inset as above (its inner quad and
  the four around it take its orientation), which gives the untangling four free vertices to lay the
  fold out with, and the untangling runs again, under the same rule; otherwise the inset is undone.
  A quad that a kept inset's untangling turned over in passing gets its own try. When no quad is
  flipped over, this step changes nothing. On spot it mends the one flipped quad of the output; on
  truck 3 more of the output's flipped quads than the untangling alone (7 left instead of 10; the tries
  on the others do not leave fewer quads flipped over with no more inverted, and are undone).

  @tparam QuadMesh a model of `MutableFaceGraph`; faces that are not quads are kept but not fitted
  @tparam TriangleMesh a model of `FaceListGraph` (triangles)
  @tparam EdgeFeatureMap a model of `ReadablePropertyMap` with the triangle mesh's `edge_descriptor`
          as key type and `bool` as value type
  @tparam NamedParameters a sequence of named parameters

  @param qmesh the quad mesh, changed in place
  @param tmesh the triangle mesh that `qmesh` approximates
  @param tmesh_edge_is_feature the feature edges of `tmesh`
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{the number of smoothing iterations}
      \cgalParamType{unsigned int}
      \cgalParamDefault{`30`}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_running_time}
      \cgalParamDescription{a time limit in seconds: once it is reached, no more smoothing iterations start
                            after the first third of `number_of_iterations` (the untangling that follows the
                            iterations still runs); `stopped_early` of the result says so}
      \cgalParamType{`double`}
      \cgalParamDefault{`0` (no limit)}
    \cgalParamNEnd
    \cgalParamNBegin{smoothing_damping}
      \cgalParamDescription{the fraction of the way to its target a vertex moves in one iteration}
      \cgalParamType{double in (0, 1]}
      \cgalParamDefault{`0.5`}
    \cgalParamNEnd
    \cgalParamNBegin{edge_is_constrained_map}
      \cgalParamDescription{the edges of `qmesh` that lie on feature lines of `tmesh`}
      \cgalParamType{a model of `ReadWritePropertyMap` with `qmesh`'s `edge_descriptor` as key type and `bool` as value type}
      \cgalParamDefault{the boundary edges of `qmesh`}
      \cgalParamExtra{a vertex with two incident constrained edges slides along its feature line; with another number it does not move. Both halves of a constrained edge that a chord split cuts are set to `true`, every other new edge to `false`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_constrained_map}
      \cgalParamDescription{vertices of `qmesh` that must not move}
      \cgalParamType{a model of `ReadablePropertyMap` with `qmesh`'s `vertex_descriptor` as key type and `bool` as value type}
      \cgalParamDefault{no vertex (vertices at feature corners of `tmesh` are fixed anyway)}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether progress and timing are printed to `std::cerr`}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @pre `tmesh` is a triangle mesh and `qmesh` lies on it.
*/
template <typename QuadMesh, typename TriangleMesh, typename EdgeFeatureMap,
          typename NamedParameters = parameters::Default_named_parameters>
Quad_smoothing_statistics smooth_quad_mesh(QuadMesh& qmesh,
                                           const TriangleMesh& tmesh,
                                           EdgeFeatureMap tmesh_edge_is_feature,
                                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type K;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Vector_3 Vector_3;
  typedef boost::graph_traits<QuadMesh> QGT;
  typedef typename QGT::vertex_descriptor q_vertex;
  typedef typename QGT::face_descriptor q_face;
  typedef typename QGT::halfedge_descriptor q_halfedge;

  CGAL::Real_timer timer;
  timer.start();
  Quad_smoothing_statistics stats;
  const unsigned iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 30u);
  const double time_limit = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  const double damping = choose_parameter(get_parameter(np, internal_np::smoothing_damping), 0.5);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  if(!(damping > 0. && damping <= 1.)) throw std::invalid_argument("smooth_quad_mesh: damping must be in (0, 1]");

  auto qvpm = get(CGAL::vertex_point, qmesh);
  auto tvpm = get(CGAL::vertex_point, tmesh);

  // constrained (feature) edges of the quad mesh; default: its boundary
  auto q_border = get(CGAL::dynamic_edge_property_t<bool>(), qmesh);
  for(auto e : edges(qmesh)) put(q_border, e, is_border(e, qmesh));
  auto qecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained), q_border);
  typedef CGAL::Static_boolean_property_map<q_vertex, false> No_vertex_constraint;
  auto qvcm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained), No_vertex_constraint());

  const internal::Feature_lines<TriangleMesh, EdgeFeatureMap, decltype(tvpm), K> lines(tmesh, tmesh_edge_is_feature,
                                                                                       tvpm, 45.);
  // a scale for "at the same place"
  CGAL::Bbox_3 bb;
  for(auto v : vertices(tmesh)) bb += get(tvpm, v).bbox();
  const double same_sq = CGAL::square(1e-7 * internal::bbox_diagonal(bb));

  // classify the quad vertices: 0 free, 1 on a feature line, 2 fixed
  auto kind = get(CGAL::dynamic_vertex_property_t<int>(), qmesh);
  auto line_of = get(CGAL::dynamic_vertex_property_t<std::size_t>(), qmesh);
  for(q_vertex v : vertices(qmesh))
  {
    int constrained = 0;
    for(q_halfedge h : halfedges_around_target(halfedge(v, qmesh), qmesh))
      if(get(qecm, edge(h, qmesh))) ++constrained;
    int k = constrained == 0 ? 0 : (constrained == 2 ? 1 : 2);
    if(get(qvcm, v)) k = 2;
    const Point_3 p = get(qvpm, v);
    if(k == 1)
    {
      for(const Point_3& c : lines.corners)
        if(CGAL::squared_distance(p, c) <= same_sq) { k = 2; break; }
    }
    if(k == 1)
    {
      if(lines.lines.empty()) k = 2; // no feature line to slide on
      else
      {
        double d;
        put(line_of, v, lines.nearest_line(p, d));
      }
    }
    put(kind, v, k);
    if(k == 0) ++stats.free_vertices;
    else if(k == 1) ++stats.feature_vertices;
    else ++stats.fixed_vertices;
  }

  // The projections onto the surface are most of the smoothing's time: the primitives keep their
  // triangles (72 bytes each) rather than gather the three points from the mesh at every visit.
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, CGAL::Default, CGAL::Tag_true, CGAL::Tag_true> Primitive;
  typedef CGAL::AABB_traits<K, Primitive> Traits;
  CGAL::AABB_tree<Traits> tree(faces(tmesh).first, faces(tmesh).second, tmesh);
  tree.accelerate_distance_queries();

  auto quad_points = [&](q_face f, std::array<Point_3, 4>& pts) -> bool {
    int i = 0;
    for(q_halfedge h : halfedges_around_face(halfedge(f, qmesh), qmesh))
    {
      if(i == 4) return false;
      pts[i++] = get(qvpm, target(h, qmesh));
    }
    return i == 4;
  };
  // The orientation of every quad at the start, from its neighbourhood: the sum over its corners of the
  // unit normals (of the diagonals) of their quads, leaving out the quads whose scaled Jacobian is not
  // positive (a bow-tie's normal means nothing). A quad whose own normal is turned by more than 120
  // degrees from it lies flipped over in the surface, which its scaled Jacobian cannot show: measured in
  // the quad's own plane, a convex quad flipped over is as good as any (the evaluators measure it so too),
  // and the untangling below mended bow-tie quads by flipping them over (1 to 6 on most development
  // meshes). The neighbourhood rather than the triangle mesh: on a thin double-sided plate the face
  // nearest a quad can be on the other sheet. Quads made later by the connectivity changes have no
  // reference.
  auto orientation = get(CGAL::dynamic_face_property_t<Vector_3>(), qmesh);
  auto has_orientation = get(CGAL::dynamic_face_property_t<bool>(), qmesh);
  auto set_orientations = [&]() {
    auto corner_normal = get(CGAL::dynamic_vertex_property_t<Vector_3>(), qmesh);
    for(q_vertex v : vertices(qmesh)) put(corner_normal, v, CGAL::NULL_VECTOR);
    for(q_face f : faces(qmesh))
    {
      std::array<Point_3, 4> pts;
      if(!quad_points(f, pts) || !(internal::quality::quad_scaled_jacobian(pts) > 0.)) continue;
      const Vector_3 n = CGAL::cross_product(pts[2] - pts[0], pts[3] - pts[1]);
      const Vector_3 u = n / std::sqrt(CGAL::to_double(n.squared_length())); // (not zero: the SJ is positive)
      for(q_vertex v : vertices_around_face(halfedge(f, qmesh), qmesh)) put(corner_normal, v, get(corner_normal, v) + u);
    }
    for(q_face f : faces(qmesh))
    {
      Vector_3 n = CGAL::NULL_VECTOR;
      for(q_vertex v : vertices_around_face(halfedge(f, qmesh), qmesh)) n = n + get(corner_normal, v);
      const double l = std::sqrt(CGAL::to_double(n.squared_length()));
      put(has_orientation, f, l > 0.);
      if(l > 0.) put(orientation, f, n / l);
    }
  };
  set_orientations();
  // The scaled Jacobian of the four corners of a quad.
  // A collapsed quad (a (nearly) zero-length edge, or all four corners (nearly) collinear, as the
  // evaluator's degenerate faces) counts as the worst quad, so that no move trades an inverted quad
  // for a collapsed one (sliding along a feature line can put a vertex onto the corner at its end).
  auto corners_sj = [&](const std::array<Point_3, 4>& pts) {
    for(int i = 0; i < 4; ++i)
      if(CGAL::to_double(CGAL::squared_distance(pts[i], pts[(i + 1) % 4])) <= same_sq) return -1.;
    // a wider margin than the evaluator's (1e-12): nearly collinear is as bad as collinear here
    if(internal::quality::polygon_corners_are_flat(4, [&](std::size_t i) -> const Point_3& { return pts[i]; }, 1e-8))
      return -1.;
    const double s = internal::quality::quad_scaled_jacobian(pts);
    return s == 0. ? -1. : s;
  };
  auto quad_sj = [&](q_face f) {
    std::array<Point_3, 4> pts;
    return quad_points(f, pts) ? corners_sj(pts) : 1.;
  };
  // the scaled Jacobian the moves are judged by: a flipped quad (see above) counts as the worst quad, so
  // that no move flips a quad over and the untangling tries to turn a flipped one back (the statistics and
  // the connectivity changes go by `quad_sj`, see the documentation)
  auto oriented_sj = [&](q_face f) {
    std::array<Point_3, 4> pts;
    if(!quad_points(f, pts)) return 1.;
    if(get(has_orientation, f))
    {
      const Vector_3 n = CGAL::cross_product(pts[2] - pts[0], pts[3] - pts[1]);
      if(CGAL::to_double(n * get(orientation, f)) < -0.5 * std::sqrt(CGAL::to_double(n.squared_length())))
        return -1.;
    }
    return corners_sj(pts);
  };
  auto sj_figures = [&](double& mn, double& mean, std::size_t& inverted) {
    mn = 1.;
    mean = 0.;
    inverted = 0;
    std::size_t n = 0;
    for(q_face f : faces(qmesh))
    {
      std::array<Point_3, 4> pts;
      if(!quad_points(f, pts)) continue;
      const double s = quad_sj(f);
      mn = (std::min)(mn, s);
      mean += s;
      if(s <= 0.) ++inverted;
      ++n;
    }
    if(n) mean /= double(n);
  };
  sj_figures(stats.min_scaled_jacobian_before, stats.mean_scaled_jacobian_before, stats.inverted_before);

  // Untangling: the vertices of poor quads, and their neighbours, try a few positions (the
  // fitted-square target, the neighbours' centroid, the parallelogram completions of their quads,
  // halfway to each, axis steps), then, while one of its quads is still poor, a pattern search in the
  // tangent plane from the best one (eight directions, the step halved when none helps), each position
  // put back on the surface or on the vertex's feature line. Only strict improvements of the score of
  // the vertex's quads are taken, so the number of quads with a scaled Jacobian <= 0 never grows.
  // A position is scored by its quads: first the number with a scaled Jacobian <= 0, then the number
  // below `poor_sj` (a quad at 1e-12 is as good as collapsed: a corner at 180 degrees, or two corners
  // on one point), then the smallest scaled Jacobian; negated counts, so that a larger tuple is better.
  const double poor_sj = 0.01;
  typedef std::tuple<int, int, double> Score;
  auto add_to_score = [&](Score& score, q_face f) {
    const double s = oriented_sj(f);
    if(s <= 0.) --std::get<0>(score);
    if(s <= poor_sj) --std::get<1>(score);
    std::get<2>(score) = (std::min)(std::get<2>(score), s);
  };
  auto local_score = [&](q_vertex v) {
    Score score(0, 0, 1.);
    for(q_face f : faces_around_target(halfedge(v, qmesh), qmesh))
      if(f != QGT::null_face()) add_to_score(score, f);
    return score;
  };
  // A free vertex goes to the closest point of the surface on its own side. On a thin plate (the two
  // sheets of a double-sided surface, the floor and ceiling of a slot) the closest point can be on the
  // other sheet, and across a crease on the other side of it: there the surface's normal is turned by
  // more than 75 degrees from the normal of the face the vertex was first placed on (`home_normal`, a unit
  // vector). Such a projection is replaced by the closest point on the nearby faces that agree with that
  // normal, searched in growing boxes around the position; the plain closest point only if none is found.
  // With the sign of the dot product as the test (90 degrees), a vertex of angle_block's floor went up
  // the curved wall next to it (with the adaptive pass), across a crease of 90 degrees where the wall
  // leans by 2 degrees towards the floor: 0.9% of the diagonal off the input.
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor t_face;
  auto has_home = get(CGAL::dynamic_vertex_property_t<int>(), qmesh);
  auto home_normal = get(CGAL::dynamic_vertex_property_t<Vector_3>(), qmesh);
  for(q_vertex v : vertices(qmesh)) put(has_home, v, 0);
  // Where two components of the surface pass through each other (teapot's spout through its body), the
  // closest point can be on the other component: a vertex keeps to the component it was placed on.
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), tmesh);
  auto home_component = get(CGAL::dynamic_vertex_property_t<std::size_t>(), qmesh);
  CGAL::Polygon_mesh_processing::connected_components(tmesh, component);
  auto triangle_of = [&](t_face f) {
    const auto h = halfedge(f, tmesh);
    return typename K::Triangle_3(get(tvpm, source(h, tmesh)), get(tvpm, target(h, tmesh)),
                                  get(tvpm, target(next(h, tmesh), tmesh)));
  };
  auto face_normal = [&](t_face f) {
    const auto h = halfedge(f, tmesh);
    return CGAL::normal(get(tvpm, source(h, tmesh)), get(tvpm, target(h, tmesh)), get(tvpm, target(next(h, tmesh), tmesh)));
  };
  const double box_scale = 1e-3 * internal::bbox_diagonal(bb);
  // m * n > cos(75 degrees) |m| for the unit home normal n, squared so that the box search, which tests
  // every face in its box, takes no square root
  auto on_own_side = [&](t_face f, q_vertex v) {
    if(get(component, f) != get(home_component, v)) return false;
    const double cos2_75_degrees = 0.2588 * 0.2588;
    const Vector_3 m = face_normal(f);
    const double dot = CGAL::to_double(m * get(home_normal, v));
    return dot > 0. && dot * dot > cos2_75_degrees * CGAL::to_double(m.squared_length());
  };
  // A free vertex also keeps to the sheet it is on. Where two sheets of one component lie close together
  // and face the same way (truck's hood, 0.017 above a sheet whose faces the repair turned up too), the
  // closest point of a position tried by the untangling (a step off the surface) can be on the other
  // sheet: truck's output was 0.0007 from a hood point before the smoothing, 0.0136 after. The sheet
  // near a vertex is the faces connected to the one under its current position through faces whose
  // bounding boxes overlap the box of half-width `reach` around it (twice the move, plus a margin); a
  // closest point on a face that is not among them is replaced by the closest point on them (on a face
  // on the vertex's own side if there is one).
  const t_face no_face = boost::graph_traits<TriangleMesh>::null_face();
  std::vector<t_face> sheet;
  auto in_sheet = get(CGAL::dynamic_face_property_t<bool>(), tmesh); // (false outside a flood)
  for(t_face f : faces(tmesh)) put(in_sheet, f, false);
  // the face under each vertex's position, remembered from the projection that put it there or from a
  // closest-point query, which spares one query per move
  auto last_point = get(CGAL::dynamic_vertex_property_t<Point_3>(), qmesh);
  auto last_face = get(CGAL::dynamic_vertex_property_t<t_face>(), qmesh);
  for(q_vertex v : vertices(qmesh)) put(last_face, v, no_face);
  auto remember = [&](q_vertex v, const Point_3& q, t_face f) {
    put(last_point, v, q);
    put(last_face, v, f);
    return q;
  };
  // The closest point of the surface to `p`, a position of `v`, and its face. A vertex moves little, so
  // the distance to the face last under it bounds the search (the same answer, in less time: the
  // projections were two fifths of truck's whole run). The bound is widened by more than the rounding
  // of that distance (a position put onto the surface is at about zero from it, and any box nearer
  // than the closest point must pass).
  auto closest_to = [&](q_vertex v, const Point_3& p) {
    const t_face f = get(last_face, v);
    if(f == no_face) return internal::closest_point_and_primitive(tree, p);
    const double d = CGAL::to_double(CGAL::squared_distance(p, triangle_of(f)));
    return internal::closest_point_and_primitive(tree, p, d * (1. + 1e-6) + same_sq);
  };
  auto face_under = [&](q_vertex v) {
    const Point_3& current = get(qvpm, v);
    if(get(last_face, v) == no_face || get(last_point, v) != current)
      remember(v, current, closest_to(v, current).second);
    return get(last_face, v);
  };
  // the closest point to `p` on `candidates` (only on those on the own side of `v` if `own_only`), its
  // face and squared distance; false if there is no such face
  auto closest_on_faces = [&](const std::vector<t_face>& candidates, q_vertex v, const Point_3& p, bool own_only,
                              Point_3& best, t_face& best_face, double& best_d) {
    bool found = false;
    for(t_face f : candidates)
    {
      if(own_only && !on_own_side(f, v)) continue;
      const Point_3 q = K().construct_projected_point_3_object()(triangle_of(f), p);
      const double d = CGAL::to_double(CGAL::squared_distance(p, q));
      if(!found || d < best_d)
      {
        found = true;
        best = q;
        best_face = f;
        best_d = d;
      }
    }
    return found;
  };
  // `p` projected onto the sheet of `v` when its closest face `target` is not on it (else false)
  auto off_sheet_projection = [&](q_vertex v, const Point_3& p, t_face target, Point_3& projection) -> bool {
    const Point_3& current = get(qvpm, v);
    const t_face start = face_under(v);
    if(start == target) return false;
    // (the faces around the corners of the start face first: most moves end there)
    for(auto th : halfedges_around_face(halfedge(start, tmesh), tmesh))
      for(t_face g : faces_around_target(th, tmesh))
        if(g == target) return false;
    const double reach = 2. * std::sqrt(CGAL::to_double(CGAL::squared_distance(p, current))) + box_scale;
    const double x = CGAL::to_double(current.x()), y = CGAL::to_double(current.y()), z = CGAL::to_double(current.z());
    const CGAL::Bbox_3 within_reach(x - reach, y - reach, z - reach, x + reach, y + reach, z + reach);
    sheet.assign(1, start);
    put(in_sheet, start, true);
    bool reached = false;
    for(std::size_t i = 0; i < sheet.size() && !reached; ++i)
      for(auto th : halfedges_around_face(halfedge(sheet[i], tmesh), tmesh))
      {
        const t_face g = face(opposite(th, tmesh), tmesh);
        if(g == no_face || get(in_sheet, g) || !CGAL::do_overlap(triangle_of(g).bbox(), within_reach)) continue;
        if(g == target) { reached = true; break; }
        put(in_sheet, g, true);
        sheet.push_back(g);
      }
    for(t_face f : sheet) put(in_sheet, f, false);
    if(reached) return false;
    t_face best_face = no_face;
    double best_d = 0.;
    if(!closest_on_faces(sheet, v, p, true, projection, best_face, best_d))
      closest_on_faces(sheet, v, p, false, projection, best_face, best_d);
    remember(v, projection, best_face);
    return true;
  };
  auto project_on_own_side = [&](q_vertex v, const Point_3& p) {
    const auto closest = closest_to(v, p);
    Point_3 on_sheet;
    if(get(has_home, v) && off_sheet_projection(v, p, closest.second, on_sheet)) return on_sheet;
    if(!get(has_home, v)) {
      const Vector_3 m = face_normal(closest.second);
      const double length = std::sqrt(CGAL::to_double(m.squared_length()));
      put(home_normal, v, length > 0. ? m / length : m);
      put(home_component, v, get(component, closest.second));
      put(has_home, v, 1);
      return remember(v, closest.first, closest.second);
    }
    if(on_own_side(closest.second, v)) return remember(v, closest.first, closest.second);
    // at a crease the closest point is often on the crease itself (an edge or a vertex of the face),
    // shared with a face on the own side
    for(auto th : halfedges_around_face(halfedge(closest.second, tmesh), tmesh)) {
      const typename K::Segment_3 side(get(tvpm, source(th, tmesh)), get(tvpm, target(th, tmesh)));
      if(!(CGAL::to_double(CGAL::squared_distance(closest.first, side)) <= same_sq)) continue;
      for(auto tv : {source(th, tmesh), target(th, tmesh)})
        for(t_face g : faces_around_target(halfedge(tv, tmesh), tmesh))
          if(g != boost::graph_traits<TriangleMesh>::null_face() && on_own_side(g, v) &&
             CGAL::to_double(CGAL::squared_distance(closest.first, triangle_of(g))) <= same_sq)
            return closest.first;
    }
    double r = 2. * std::sqrt(CGAL::to_double(CGAL::squared_distance(p, closest.first))) + box_scale;
    std::vector<t_face> near;
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    for(int k = 0; k < 4; ++k, r *= 4.) {
      near.clear();
      tree.all_intersected_primitives(CGAL::Bbox_3(x - r, y - r, z - r, x + r, y + r, z + r), std::back_inserter(near));
      Point_3 best;
      t_face best_face = no_face;
      double best_d = 0.;
      // (nothing outside the box can be closer)
      if(closest_on_faces(near, v, p, true, best, best_face, best_d) && best_d <= r * r) return best;
    }
    return closest.first;
  };
  auto place = [&](q_vertex v, const Point_3& p) {
    // (a target from a collapsed quad can be NaN: the vertex stays where it is)
    if(!internal::is_finite_point(p))
      return get(qvpm, v);
    return get(kind, v) == 1 ? lines.project(get(line_of, v), p) : project_on_own_side(v, p);
  };
  for(q_vertex v : vertices(qmesh)) // the vertices lie on the surface: each is at home where it is
    if(get(kind, v) == 0) project_on_own_side(v, get(qvpm, v));
  auto untangle_vertex = [&](q_vertex v) -> bool {
    if(get(kind, v) == 2) return false;
    const Point_3 old_p = get(qvpm, v);
    std::vector<Point_3> tries;
    Vector_3 square_sum = CGAL::NULL_VECTOR, completion_sum = CGAL::NULL_VECTOR, normal = CGAL::NULL_VECTOR;
    int quads_around = 0;
    for(q_halfedge h : halfedges_around_target(halfedge(v, qmesh), qmesh))
    {
      if(is_border(h, qmesh)) continue;
      std::array<Point_3, 4> pts;
      if(!quad_points(face(h, qmesh), pts)) continue;
      // the corner of v in this quad: the face's halfedges start after h
      const std::array<Point_3, 4> sq = internal::best_fit_square<Vector_3>(pts);
      int i = 0, iv = -1;
      for(q_halfedge g : halfedges_around_face(halfedge(face(h, qmesh), qmesh), qmesh))
      {
        if(g == h) iv = i;
        ++i;
      }
      if(iv < 0) continue;
      square_sum = square_sum + (sq[iv] - CGAL::ORIGIN);
      completion_sum = completion_sum + ((pts[(iv + 1) % 4] - CGAL::ORIGIN) + (pts[(iv + 3) % 4] - pts[(iv + 2) % 4]));
      normal = normal + CGAL::cross_product(pts[2] - pts[0], pts[3] - pts[1]);
      ++quads_around;
    }
    if(quads_around == 0) return false;
    tries.push_back(CGAL::ORIGIN + square_sum / double(quads_around));
    tries.push_back(CGAL::ORIGIN + completion_sum / double(quads_around));
    Vector_3 centroid = CGAL::NULL_VECTOR;
    double mean_length = 0.;
    int neighbours = 0;
    for(q_vertex w : vertices_around_target(halfedge(v, qmesh), qmesh))
    {
      centroid = centroid + (get(qvpm, w) - CGAL::ORIGIN);
      mean_length += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(qvpm, w), old_p)));
      ++neighbours;
    }
    centroid = centroid / double(neighbours);
    mean_length /= double(neighbours);
    tries.push_back(CGAL::ORIGIN + centroid);
    for(std::size_t k = 0, n = tries.size(); k < n; ++k) tries.push_back(old_p + 0.5 * (tries[k] - old_p));
    for(double step : {0.5, 0.25, 0.1})
      for(int axis = 0; axis < 3; ++axis)
        for(double sign : {-1., 1.})
        {
          double d[3] = {0., 0., 0.};
          d[axis] = sign * step * mean_length;
          tries.push_back(old_p + Vector_3(d[0], d[1], d[2]));
        }
    auto best = local_score(v);
    Point_3 best_p = old_p;
    auto try_position = [&](const Point_3& t) {
      const Point_3 p = place(v, t);
      put(qvpm, v, p);
      const auto score = local_score(v);
      if(score > best) { best = score; best_p = p; return true; }
      return false;
    };
    for(const Point_3& t : tries) try_position(t);

    // when v still has a poor quad: pattern search in the plane of its quads (any plane when they are degenerate)
    const double nl = std::sqrt(CGAL::to_double(normal.squared_length()));
    Vector_3 n = nl > 0. ? normal / nl : Vector_3(0., 0., 1.);
    Vector_3 t1 = std::abs(CGAL::to_double(n.x())) < 0.9 ? CGAL::cross_product(n, Vector_3(1., 0., 0.))
                                                         : CGAL::cross_product(n, Vector_3(0., 1., 0.));
    t1 = t1 / std::sqrt(CGAL::to_double(t1.squared_length()));
    const Vector_3 t2 = CGAL::cross_product(n, t1);
    const double s2 = std::sqrt(0.5);
    const std::array<Vector_3, 8> directions = {{t1, -t1, t2, -t2, s2 * (t1 + t2), s2 * (t1 - t2), s2 * (t2 - t1),
                                                 -s2 * (t1 + t2)}};
    double step = 0.5 * mean_length;
    for(int evaluations = 0; step > 1e-3 * mean_length && evaluations < 240 && std::get<1>(best) < 0;)
    {
      bool improved = false;
      const Point_3 from = best_p;
      for(const Vector_3& d : directions)
      {
        ++evaluations;
        if(try_position(from + step * d)) { improved = true; break; }
      }
      if(!improved) step *= 0.5;
    }
    put(qvpm, v, best_p);
    return best_p != old_p;
  };
  // A vertex's tries depend only on the corners of its quads: one that found no better place is not
  // tried again until one of them has moved, as long as only untangle_vertex() moves vertices (this
  // halves the untangling's time on truck). The memo keeps stamps of one clock: when each vertex last
  // moved, and when each last found nothing.
  struct Untangling_memo
  {
    std::size_t clock = 0;
    std::map<q_vertex, std::size_t> moved_at, failed_at;
    static std::size_t stamp(const std::map<q_vertex, std::size_t>& at, q_vertex v)
    {
      const auto it = at.find(v);
      return it == at.end() ? std::size_t(0) : it->second;
    }
  };
  auto untangle_vertex_again = [&](q_vertex v, Untangling_memo& memo) {
    const std::size_t failed = Untangling_memo::stamp(memo.failed_at, v);
    if(failed != 0)
    {
      bool moved = false;
      for(q_face f : faces_around_target(halfedge(v, qmesh), qmesh))
        if(f != QGT::null_face())
          for(q_vertex w : vertices_around_face(halfedge(f, qmesh), qmesh))
            moved = moved || Untangling_memo::stamp(memo.moved_at, w) > failed;
      if(!moved) return false;
    }
    if(untangle_vertex(v))
    {
      memo.moved_at[v] = ++memo.clock;
      return true;
    }
    memo.failed_at[v] = ++memo.clock;
    return false;
  };
  // the poor quads among `within`, or among all quads
  auto poor_quads = [&](const std::vector<q_face>* within) {
    std::vector<q_face> poor;
    auto collect = [&](const auto& range) {
      for(q_face f : range)
        if(oriented_sj(f) <= poor_sj) poor.push_back(f);
    };
    if(within) collect(*within);
    else collect(faces(qmesh));
    return poor;
  };
  // (`within`: only the poor quads among these to start with; by default all)
  auto untangle = [&](unsigned max_passes, const std::vector<q_face>* within = nullptr) {
    // every quad that gets worse is around a vertex that moved, so the work list of a pass is the bad
    // quads around the previous pass's candidates
    std::vector<q_face> bad = poor_quads(within);
    Untangling_memo memo;
    for(unsigned pass = 0; pass < max_passes && !bad.empty(); ++pass)
    {
      std::vector<q_vertex> candidates;
      for(q_face f : bad)
        for(q_vertex v : vertices_around_face(halfedge(f, qmesh), qmesh))
        {
          candidates.push_back(v);
          for(q_vertex w : vertices_around_target(halfedge(v, qmesh), qmesh)) candidates.push_back(w);
        }
      std::sort(candidates.begin(), candidates.end());
      candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
      std::size_t moves = 0;
      for(q_vertex v : candidates)
        if(untangle_vertex_again(v, memo)) ++moves;
      stats.untangling_moves += moves;
      if(moves == 0) return;
      bad.clear();
      for(q_vertex v : candidates)
        for(q_face f : faces_around_target(halfedge(v, qmesh), qmesh))
          if(f != QGT::null_face() && oriented_sj(f) <= poor_sj) bad.push_back(f);
      std::sort(bad.begin(), bad.end());
      bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
    }
  };
  untangle(20);

  // What one vertex cannot undo (a quad folded over onto itself, whose opening needs its neighbours
  // to move too) a region can: the vertices within a few rings of a bad quad go, all together, to the
  // centroid of their neighbours, again and again with the outer ring held (a Tutte-like relaxation,
  // which unfolds a disk), each position put back on the surface or feature line. The region's new
  // positions are kept only if its quads score better (fewer bad ones, then a larger smallest
  // scaled Jacobian); wider regions are tried when a narrow one does not help.
  auto region_score = [&](const std::vector<q_face>& region) {
    Score score(0, 0, 1.);
    for(q_face f : region) add_to_score(score, f);
    return score;
  };
  // relaxes the vertices within `rings` rings of `seeds` (the outer ring held); returns the score of the
  // quads around the moved vertices before and after, gives the moved vertices' new positions in
  // `relaxed` and puts the old positions back
  typedef std::vector<std::pair<q_vertex, Point_3>> Positions;
  auto relax_region = [&](const std::vector<q_vertex>& seeds, int rings, Positions& relaxed) {
    std::vector<q_vertex> region, ring(seeds), movable;
    for(int r = 0; r <= rings && !ring.empty(); ++r)
    {
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      std::vector<q_vertex> next;
      for(q_vertex v : ring)
      {
        if(std::binary_search(region.begin(), region.end(), v)) continue;
        if(r < rings && get(kind, v) != 2) movable.push_back(v); // the last ring holds the region
        for(q_vertex w : vertices_around_target(halfedge(v, qmesh), qmesh)) next.push_back(w);
      }
      region.insert(region.end(), ring.begin(), ring.end());
      std::sort(region.begin(), region.end());
      region.erase(std::unique(region.begin(), region.end()), region.end());
      ring.swap(next);
    }
    std::vector<q_face> quads;
    for(q_vertex v : movable)
      for(q_face f : faces_around_target(halfedge(v, qmesh), qmesh))
        if(f != QGT::null_face()) quads.push_back(f);
    std::sort(quads.begin(), quads.end());
    quads.erase(std::unique(quads.begin(), quads.end()), quads.end());
    const Score before = region_score(quads);
    std::vector<Point_3> old_positions, new_positions(movable.size());
    for(q_vertex v : movable) old_positions.push_back(get(qvpm, v));
    for(int it = 0; it < 20 * rings; ++it)
    {
      for(std::size_t i = 0; i < movable.size(); ++i)
      {
        Vector_3 sum = CGAL::NULL_VECTOR;
        int n = 0;
        for(q_vertex w : vertices_around_target(halfedge(movable[i], qmesh), qmesh))
        {
          sum = sum + (get(qvpm, w) - CGAL::ORIGIN);
          ++n;
        }
        new_positions[i] = place(movable[i], CGAL::ORIGIN + sum / double(n));
      }
      for(std::size_t i = 0; i < movable.size(); ++i) put(qvpm, movable[i], new_positions[i]);
    }
    // the relaxation opens the fold; single moves then mend what it squeezed
    Untangling_memo memo;
    for(int pass = 0; pass < 3; ++pass)
      for(q_vertex v : movable) untangle_vertex_again(v, memo);
    const Score after = region_score(quads);
    relaxed.clear();
    for(std::size_t i = 0; i < movable.size(); ++i)
    {
      relaxed.emplace_back(movable[i], get(qvpm, movable[i]));
      put(qvpm, movable[i], old_positions[i]);
    }
    return std::make_pair(before, after);
  };
  // each group of poor quads that share vertices is relaxed with the width (1 to 4 rings) that scores best
  auto relax_tangled_regions = [&](const std::vector<q_face>* within = nullptr) {
    std::vector<q_face> poor = poor_quads(within);
    std::sort(poor.begin(), poor.end());
    std::vector<bool> grouped(poor.size(), false);
    bool changed = false;
    for(std::size_t i = 0; i < poor.size(); ++i)
    {
      if(grouped[i]) continue;
      std::vector<q_face> group(1, poor[i]);
      grouped[i] = true;
      std::vector<q_vertex> seeds;
      for(std::size_t k = 0; k < group.size(); ++k)
        for(q_vertex v : vertices_around_face(halfedge(group[k], qmesh), qmesh))
        {
          seeds.push_back(v);
          for(q_face f : faces_around_target(halfedge(v, qmesh), qmesh))
          {
            const auto it = std::lower_bound(poor.begin(), poor.end(), f);
            if(it != poor.end() && *it == f && !grouped[it - poor.begin()])
            {
              grouped[it - poor.begin()] = true;
              group.push_back(f);
            }
          }
        }
      bool found = false;
      Score best;
      Positions best_positions, positions;
      for(int rings = 1; rings <= 4; ++rings)
      {
        const auto scores = relax_region(seeds, rings, positions);
        if(scores.second > scores.first && (!found || scores.second > best))
        {
          best = scores.second;
          best_positions.swap(positions);
          found = true;
        }
      }
      for(const auto& vp : best_positions) put(qvpm, vp.first, vp.second);
      changed = changed || found;
    }
    return changed;
  };

  auto target_sum = get(CGAL::dynamic_vertex_property_t<Vector_3>(), qmesh);
  auto target_count = get(CGAL::dynamic_vertex_property_t<int>(), qmesh);
  for(unsigned it = 0; it < iterations; ++it)
  {
    // a third of the iterations always run: fewer leave too many quads tangled for the untangling
    if(time_limit > 0. && 3 * it >= iterations && timer.time() >= time_limit) { stats.stopped_early = true; break; }
    for(q_vertex v : vertices(qmesh)) { put(target_sum, v, CGAL::NULL_VECTOR); put(target_count, v, 0); }
    for(q_face f : faces(qmesh))
    {
      std::array<Point_3, 4> pts;
      if(!quad_points(f, pts)) continue;
      const std::array<Point_3, 4> sq = internal::best_fit_square<Vector_3>(pts);
      int i = 0;
      for(q_halfedge h : halfedges_around_face(halfedge(f, qmesh), qmesh))
      {
        const q_vertex v = target(h, qmesh);
        put(target_sum, v, get(target_sum, v) + (sq[i++] - CGAL::ORIGIN));
        put(target_count, v, get(target_count, v) + 1);
      }
    }
    for(q_vertex v : vertices(qmesh))
    {
      const int k = get(kind, v);
      if(k == 2 || get(target_count, v) == 0) continue;
      const Point_3 old_p = get(qvpm, v);
      const Point_3 target_p = CGAL::ORIGIN + get(target_sum, v) / double(get(target_count, v));
      const auto old_score = local_score(v);
      bool accepted = false;
      double step = damping;
      for(int attempt = 0; attempt < 3 && !accepted; ++attempt, step *= 0.5)
      {
        put(qvpm, v, place(v, old_p + step * (target_p - old_p)));
        const auto new_score = local_score(v);
        if(std::get<0>(new_score) >= std::get<0>(old_score) && std::get<1>(new_score) >= std::get<1>(old_score) &&
           std::get<2>(new_score) >= (std::min)(std::get<2>(old_score), 0.3))
          accepted = true;
      }
      if(!accepted)
      {
        put(qvpm, v, old_p);
        ++stats.rejected_moves;
      }
    }
    ++stats.iterations;
  }
  untangle(20);
  if(relax_tangled_regions()) untangle(20);

  // Refinement, for what no move undoes: a quad folded over a bend of the surface smaller than itself,
  // or with a corner at a vertex that is held. Both chords through such a quad (the strips of quads
  // that enter and leave through opposite edges) are split in two along their length: every edge they
  // cross gets its midpoint, every quad on one of them is cut in two (in four where they cross), and no
  // vertex's valence changes, so the mesh stays pure-quad and conforming with no new irregular vertex.
  // The new vertices go onto the surface (onto the feature line for the midpoint of a constrained
  // edge), the untangling runs again, and the split is kept only if fewer quads are inverted than
  // before; otherwise it is undone. When no split mends the quad, it is inset (see inset_quad()).
  // Chords that cross more than `max_split_edges` edges are not split (on organic meshes a chord can
  // wind over most of the surface).
  typedef typename QGT::edge_descriptor q_edge;
  const std::size_t n_faces = std::size_t(std::distance(faces(qmesh).begin(), faces(qmesh).end()));
  const std::size_t max_split_edges = (std::max<std::size_t>)(128, n_faces / 5);
  // the quads this step mends: inverted, or with a corner within about 0.06 degrees of flat (a
  // scaled Jacobian of 1e-10 is a triangle in all but name, and no vertex move opens a flat corner
  // at a held vertex)
  const double mended_sj = 1e-3;
  // the quads whose scaled Jacobian is at most `sj`
  auto count_quads_at_most = [&](double sj) {
    std::size_t n = 0;
    for(q_face f : faces(qmesh))
      if(quad_sj(f) <= sj) ++n;
    return n;
  };
  auto count_quads_to_mend = [&]() { return count_quads_at_most(mended_sj); };
  auto is_quad = [&](q_face f) { return CGAL::halfedges_around_face(halfedge(f, qmesh), qmesh).size() == 4; };
  auto on_chord = get(CGAL::dynamic_edge_property_t<bool>(), qmesh);
  for(q_edge e : edges(qmesh)) put(on_chord, e, false);
  // the edges of the chords through quad f (which: 1 or 2 the one through the edge of halfedge(f) or
  // the next one, 3 both), or nothing when one is too long or meets a non-quad
  auto chords_through = [&](q_face f, int which, std::vector<q_edge>& chord) {
    chord.clear();
    bool ok = is_quad(f);
    const q_halfedge h0 = halfedge(f, qmesh);
    std::vector<q_halfedge> starts;
    if(which & 1) { starts.push_back(h0); starts.push_back(next(next(h0, qmesh), qmesh)); }
    if(which & 2) { starts.push_back(next(h0, qmesh)); starts.push_back(prev(h0, qmesh)); }
    for(q_halfedge start : starts)
      for(q_halfedge g = start; ok && !get(on_chord, edge(g, qmesh));)
      {
        put(on_chord, edge(g, qmesh), true);
        chord.push_back(edge(g, qmesh));
        const q_halfedge o = opposite(g, qmesh);
        if(is_border(o, qmesh)) break;
        if(chord.size() > max_split_edges || !is_quad(face(o, qmesh))) ok = false;
        else g = next(next(o, qmesh), qmesh);
      }
    for(q_edge e : chord) put(on_chord, e, false);
    if(!ok) chord.clear();
    return ok;
  };
  auto is_new = get(CGAL::dynamic_vertex_property_t<bool>(), qmesh);
  for(q_vertex v : vertices(qmesh)) put(is_new, v, false);
  // splits the chords: fills the undo list, in order, with a halfedge of each added edge (joining its
  // faces undoes it) and, for each vertex added by splitting an edge, the halfedge from that vertex along
  // the added half (joining along it removes both and leaves the original edge)
  enum Op { ADDED_VERTEX, ADDED_EDGE, REMOVED_EDGE };
  struct Undo_entry
  {
    Op op;
    q_halfedge h;
    std::size_t entry = 0; // REMOVED_EDGE: the entry to point at the edge that undoing it adds
    Undo_entry(Op o, q_halfedge g, std::size_t k = 0) : op(o), h(g), entry(k) {}
  };
  auto split_chords = [&](const std::vector<q_edge>& chord, std::vector<Undo_entry>& ops,
                          std::vector<q_vertex>& added) {
    std::vector<q_face> cut;
    for(q_edge e : chord)
      for(q_halfedge h : {halfedge(e, qmesh), opposite(halfedge(e, qmesh), qmesh)})
        if(!is_border(h, qmesh)) cut.push_back(face(h, qmesh));
    std::sort(cut.begin(), cut.end());
    cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
    for(q_edge e : chord)
    {
      const q_halfedge h = halfedge(e, qmesh);
      const Point_3 a = get(qvpm, source(h, qmesh)), b = get(qvpm, target(h, qmesh));
      const bool constrained = get(qecm, e);
      const q_halfedge hn = CGAL::Euler::split_edge(h, qmesh); // source(h) -> m, then h: m -> target(h)
      const q_vertex m = target(hn, qmesh);
      put(qecm, edge(hn, qmesh), constrained);
      put(is_new, m, true);
      const Point_3 mid = CGAL::midpoint(a, b);
      // a constrained midpoint slides on its feature line; without lines it is held where it is
      if(constrained && !lines.lines.empty())
      {
        double d;
        put(line_of, m, lines.nearest_line(mid, d));
        put(kind, m, 1);
      }
      else
        put(kind, m, constrained ? 2 : 0);
      put(has_home, m, 0);
      put(qvpm, m, get(kind, m) == 2 ? mid : place(m, mid));
      ops.emplace_back(ADDED_VERTEX, opposite(hn, qmesh));
      added.push_back(m);
    }
    // a face with 6 corners (two midpoints) is cut between them; one with 8 (four) between two
    // opposite ones, and that cut is split at a centre joined to the other two
    auto cut_hexagon = [&](q_face f, auto is_end) { // from a corner `is_end` to the third one after it
      std::vector<q_halfedge> hs;
      for(q_halfedge h : halfedges_around_face(halfedge(f, qmesh), qmesh)) hs.push_back(h);
      if(hs.size() != 6) return;
      for(std::size_t i = 0; i < 6; ++i)
        if(is_end(target(hs[i], qmesh)))
        {
          ops.emplace_back(ADDED_EDGE, CGAL::Euler::split_face(hs[i], hs[(i + 3) % 6], qmesh));
          return;
        }
    };
    for(q_face f : cut)
    {
      std::vector<q_halfedge> hs;
      for(q_halfedge h : halfedges_around_face(halfedge(f, qmesh), qmesh)) hs.push_back(h);
      if(hs.size() == 6)
        cut_hexagon(f, [&](q_vertex v) { return get(is_new, v); });
      else if(hs.size() == 8)
      {
        std::size_t i = get(is_new, target(hs[0], qmesh)) ? 0 : 1;
        const q_halfedge d = CGAL::Euler::split_face(hs[i], hs[i + 4], qmesh);
        ops.emplace_back(ADDED_EDGE, d);
        const Point_3 c = CGAL::midpoint(CGAL::midpoint(get(qvpm, target(hs[i], qmesh)), get(qvpm, target(hs[i + 4], qmesh))),
                                         CGAL::midpoint(get(qvpm, target(hs[i + 2], qmesh)), get(qvpm, target(hs[i + 6], qmesh))));
        const q_halfedge hc = CGAL::Euler::split_edge(d, qmesh);
        const q_vertex o = target(hc, qmesh);
        put(qecm, edge(hc, qmesh), false);
        put(kind, o, 0);
        put(has_home, o, 0);
        put(qvpm, o, place(o, c));
        ops.emplace_back(ADDED_VERTEX, opposite(hc, qmesh));
        added.push_back(o);
        const q_face f1 = face(d, qmesh), f2 = face(opposite(d, qmesh), qmesh);
        for(q_face g : {f1, f2}) cut_hexagon(g, [&](q_vertex v) { return v == o; });
      }
    }
    for(q_vertex v : added) put(is_new, v, false);
  };
  // Inset: quad (c0, c1, c2, c3) becomes an inner quad (r, q, s, p) and four quads around it, so that
  // every corner gets an edge into the quad (c0-p, c1-r, c2-q, c3-s), which splits a corner that no
  // move can mend (a held vertex whose corner is at 180 degrees or more). Built from the diagonal c0-c2,
  // split at p and q; c1 is joined to q, that edge split at r and r joined to p; c3 is joined to p,
  // that edge split at s and s joined to q; the two triangles (r, q, p) and (s, p, q) are then merged.
  // Undoing the merge splits the face again from e1's target (q) to e3's target (p); the undo entry of
  // q, which named the merged edge, is then pointed at the new one.
  auto inset_quad = [&](q_face f, std::vector<Undo_entry>& ops, std::vector<q_vertex>& added) {
    std::vector<q_halfedge> hs; // hs[i] ends at corner i
    for(q_halfedge h : halfedges_around_face(halfedge(f, qmesh), qmesh)) hs.push_back(h);
    if(hs.size() != 4) return false;
    Vector_3 centre = CGAL::NULL_VECTOR;
    for(q_halfedge h : hs) centre = centre + (get(qvpm, target(h, qmesh)) - CGAL::ORIGIN) / 4.;
    auto new_vertex = [&](q_halfedge hn, int corner) {
      const q_vertex v = target(hn, qmesh);
      const Point_3 c = get(qvpm, target(hs[corner], qmesh));
      put(kind, v, 0);
      put(has_home, v, 0);
      put(qvpm, v, place(v, c + 0.35 * ((CGAL::ORIGIN + centre) - c)));
      put(qecm, edge(hn, qmesh), false);
      added.push_back(v);
      ops.emplace_back(ADDED_VERTEX, opposite(hn, qmesh));
    };
    auto new_edge = [&](q_halfedge h1, q_halfedge h2) {
      const q_halfedge e = CGAL::Euler::split_face(h1, h2, qmesh);
      put(qecm, edge(e, qmesh), false);
      ops.emplace_back(ADDED_EDGE, e);
      return e;
    };
    const q_halfedge d = new_edge(hs[0], hs[2]);                 // c0 -> c2
    const q_halfedge h1 = CGAL::Euler::split_edge(d, qmesh);     // c0 -> p, d: p -> c2
    new_vertex(h1, 0);
    const q_halfedge h2 = CGAL::Euler::split_edge(d, qmesh);     // p -> q, d: q -> c2
    new_vertex(h2, 2);
    const std::size_t q_entry = ops.size() - 1;
    const q_halfedge e1 = new_edge(hs[1], opposite(d, qmesh));  // c1 -> q
    const q_halfedge hr = CGAL::Euler::split_edge(e1, qmesh);    // c1 -> r, e1: r -> q
    new_vertex(hr, 1);
    new_edge(hr, opposite(h2, qmesh));                           // r -> p
    const q_halfedge e3 = new_edge(hs[3], h1);                   // c3 -> p
    const q_halfedge hs3 = CGAL::Euler::split_edge(e3, qmesh);   // c3 -> s, e3: s -> p
    new_vertex(hs3, 3);
    new_edge(hs3, h2);                                           // s -> q
    CGAL::Euler::join_face(h2, qmesh);
    ops.emplace_back(REMOVED_EDGE, e1, q_entry);
    ops.emplace_back(REMOVED_EDGE, e3, q_entry);
    return true;
  };
  auto undo = [&](std::vector<Undo_entry>& ops) {
    for(std::size_t k = ops.size(); k-- > 0;)
    {
      if(ops[k].op == REMOVED_EDGE)
      {
        // entries k - 1 and k: e1 and e3 of an inset
        ops[ops[k].entry].h = CGAL::Euler::split_face(ops[k - 1].h, ops[k].h, qmesh);
        --k;
      }
      else if(ops[k].op == ADDED_EDGE) CGAL::Euler::join_face(ops[k].h, qmesh);
      else CGAL::Euler::join_vertex(ops[k].h, qmesh);
    }
  };
  // quads flipped over among their neighbours, counted as quad_mesh_quality() counts them (see below)
  auto diagonal_normal = [&](q_face f, Vector_3& n) {
    std::array<Point_3, 4> pts;
    if(!quad_points(f, pts)) return false;
    n = CGAL::cross_product(pts[2] - pts[0], pts[3] - pts[1]);
    return CGAL::to_double(n.squared_length()) > 0.;
  };
  auto is_flipped_over = [&](q_face f) {
    Vector_3 n, m;
    if(!diagonal_normal(f, n)) return false;
    std::size_t neighbours = 0, against = 0;
    for(q_halfedge h : halfedges_around_face(halfedge(f, qmesh), qmesh))
    {
      const q_halfedge o = opposite(h, qmesh);
      if(is_border(o, qmesh) || !diagonal_normal(face(o, qmesh), m)) continue;
      ++neighbours;
      if(internal::quality::normals_turned_over(n, m)) ++against;
    }
    return neighbours > 0 && against == neighbours;
  };
  auto flipped_over_quads = [&]() {
    std::vector<q_face> flipped;
    for(q_face f : faces(qmesh))
      if(is_flipped_over(f)) flipped.push_back(f);
    return flipped;
  };
  // the untangling, then the relaxation of regions, among the quads around the vertices `seeds`
  auto untangle_around = [&](const std::vector<q_vertex>& seeds) {
    std::vector<q_face> near;
    for(q_vertex v : seeds)
      for(q_face g : faces_around_target(halfedge(v, qmesh), qmesh))
        if(g != QGT::null_face()) near.push_back(g);
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    untangle(20, &near);
    if(relax_tangled_regions(&near)) untangle(20, &near);
  };
  // one try: `change` alters the mesh around the quad of halfedge `fh` (filling the undo list and the
  // added vertices); the untangling runs around it, and it stays if fewer quads are then inverted
  bool changed_connectivity = false;
  auto try_change = [&](q_halfedge fh, auto change) {
    const std::size_t before = count_quads_to_mend();
    std::vector<std::pair<q_vertex, Point_3>> positions;
    for(q_vertex v : vertices(qmesh)) positions.emplace_back(v, get(qvpm, v));
    std::vector<Undo_entry> ops;
    std::vector<q_vertex> added;
    const std::size_t faces_before = std::size_t(std::distance(faces(qmesh).begin(), faces(qmesh).end()));
    if(!change(ops, added)) return false;
    changed_connectivity = true;
    // the untangling starts at the quads around the change and the inverted quad
    std::vector<q_vertex> seeds(added);
    for(q_vertex v : vertices_around_face(fh, qmesh)) seeds.push_back(v);
    untangle_around(seeds);
    if(count_quads_to_mend() < before)
    {
      stats.refinement_quads += std::size_t(std::distance(faces(qmesh).begin(), faces(qmesh).end())) - faces_before;
      return true;
    }
    undo(ops);
    for(const auto& vp : positions) put(qvpm, vp.first, vp.second);
    return false;
  };
  const std::size_t max_refined_quads = 64;
  for(int round = 0; round < 4; ++round)
  {
    // the inverted quads by one of their halfedges: an edge of the mesh before a change survives any
    // later change and its undoing, while a face index may not
    std::vector<q_halfedge> inverted;
    for(q_face f : faces(qmesh))
      if(quad_sj(f) <= mended_sj) inverted.push_back(halfedge(f, qmesh));
    if(inverted.empty()) break;
    // every try counts the inverted quads over the whole mesh: a bounded number of tries keeps a mesh
    // with very many inverted quads from taking quadratic time, and the time limit is respected
    if(inverted.size() > max_refined_quads) inverted.resize(max_refined_quads);
    bool changed = false;
    for(q_halfedge fh : inverted)
    {
      if(time_limit > 0. && timer.time() >= time_limit) { stats.stopped_early = true; break; }
      // a flat quad that is not inverted goes straight to the inset, which splits its flat corner: chord
      // splits change no valence and do not open a flat corner at a held vertex (and each try costs an
      // untangling)
      if(quad_sj(face(fh, qmesh)) <= 0.)
        for(int which : {3, 1, 2})
        {
          if(quad_sj(face(fh, qmesh)) > mended_sj) break; // mended by an earlier change
          std::vector<q_edge> chord;
          if(!chords_through(face(fh, qmesh), which, chord) || chord.empty()) continue;
          if(try_change(fh, [&](std::vector<Undo_entry>& ops, std::vector<q_vertex>& added) {
               split_chords(chord, ops, added);
               return true;
             }))
          {
            ++stats.refined_chords;
            changed = true;
          }
        }
      if(quad_sj(face(fh, qmesh)) <= mended_sj &&
         try_change(fh, [&](std::vector<Undo_entry>& ops, std::vector<q_vertex>& added) {
           return inset_quad(face(fh, qmesh), ops, added);
         }))
      {
        ++stats.inset_quads;
        changed = true;
      }
    }
    if(!changed) break;
  }
  // Last, the quads that lie flipped over among their neighbours, as quad_mesh_quality() counts them (the
  // normal of the diagonals turned by more than 120 degrees from that of every quad across an edge). The
  // references above are those of the quads at the start, and the quads made by the connectivity changes
  // have none: an inset's thin quad can end flipped over. The references are taken again from the
  // neighbourhoods as they are now, and the untangling runs around those quads; its moves stay only if
  // fewer quads are then flipped over and no more have a scaled Jacobian <= 0. Nothing changes when no
  // quad is flipped over.
  const std::vector<q_face> flipped = flipped_over_quads();
  stats.flipped_before_mending = flipped.size();
  if(!flipped.empty())
  {
    set_orientations();
    // a quad flipped over is judged against its neighbours across its edges, as it is counted
    for(q_face f : flipped)
    {
      Vector_3 sum = CGAL::NULL_VECTOR, m;
      for(q_halfedge h : halfedges_around_face(halfedge(f, qmesh), qmesh))
      {
        const q_halfedge o = opposite(h, qmesh);
        if(!is_border(o, qmesh) && diagonal_normal(face(o, qmesh), m))
          sum = sum + m / std::sqrt(CGAL::to_double(m.squared_length()));
      }
      const double l = std::sqrt(CGAL::to_double(sum.squared_length()));
      put(has_orientation, f, l > 0.);
      if(l > 0.) put(orientation, f, sum / l);
    }
    std::size_t flipped_now = flipped.size(), inverted_now = count_quads_at_most(0.);
    // (by a halfedge: an inset and its undoing may renumber the faces, not the edges of the mesh before)
    std::vector<q_halfedge> flipped_by_halfedge;
    for(q_face f : flipped) flipped_by_halfedge.push_back(halfedge(f, qmesh));
    // whether the moves since `positions` (and the change `ops`, if any) stay: only with fewer quads
    // flipped over and no more inverted; otherwise they are undone
    auto keep_if_fewer_flipped = [&](const std::vector<std::pair<q_vertex, Point_3>>& positions,
                                     std::vector<Undo_entry>* ops) {
      const std::size_t flipped_after = flipped_over_quads().size(), inverted_after = count_quads_at_most(0.);
      if(flipped_after < flipped_now && inverted_after <= inverted_now)
      {
        stats.mended_flipped_quads += flipped_now - flipped_after;
        flipped_now = flipped_after;
        inverted_now = inverted_after;
        return true;
      }
      if(ops) undo(*ops);
      for(const auto& vp : positions) put(qvpm, vp.first, vp.second);
      return false;
    };
    // one try per quad flipped over (unless an earlier try mended it), kept or undone on its own: the
    // untangling around it; if that fails, the quad is inset first (see inset_quad()), which gives the
    // untangling four more vertices to lay the fold out with (the inner quad and those around it take the
    // flipped quad's reference)
    for(std::size_t k = 0; k < flipped_by_halfedge.size(); ++k)
    {
      if(time_limit > 0. && timer.time() >= time_limit) { stats.stopped_early = true; break; }
      const q_face f = face(flipped_by_halfedge[k], qmesh);
      if(!is_flipped_over(f)) continue;
      std::vector<std::pair<q_vertex, Point_3>> positions;
      for(q_vertex v : vertices(qmesh)) positions.emplace_back(v, get(qvpm, v));
      std::vector<q_vertex> seeds;
      for(q_vertex v : vertices_around_face(halfedge(f, qmesh), qmesh)) seeds.push_back(v);
      untangle_around(seeds);
      if(keep_if_fewer_flipped(positions, nullptr)) continue;
      const bool oriented = get(has_orientation, f);
      const Vector_3 reference = get(orientation, f);
      const std::size_t faces_before = std::size_t(std::distance(faces(qmesh).begin(), faces(qmesh).end()));
      std::vector<Undo_entry> ops;
      std::vector<q_vertex> added;
      if(!inset_quad(f, ops, added)) continue;
      changed_connectivity = true;
      for(q_vertex v : added)
        for(q_face g : faces_around_target(halfedge(v, qmesh), qmesh))
          if(g != QGT::null_face())
          {
            put(has_orientation, g, oriented);
            put(orientation, g, reference);
          }
      seeds.insert(seeds.end(), added.begin(), added.end());
      untangle_around(seeds);
      if(keep_if_fewer_flipped(positions, &ops))
      {
        ++stats.inset_quads;
        stats.refinement_quads += std::size_t(std::distance(faces(qmesh).begin(), faces(qmesh).end())) - faces_before;
        // the untangling may have turned other quads over: they get their tries too
        for(q_face g : flipped_over_quads())
          if(std::find_if(flipped_by_halfedge.begin(), flipped_by_halfedge.end(),
                          [&](q_halfedge h) { return face(h, qmesh) == g; }) == flipped_by_halfedge.end())
            flipped_by_halfedge.push_back(halfedge(g, qmesh));
      }
    }
  }
  if(changed_connectivity) internal::collect_garbage_of(qmesh);
  sj_figures(stats.min_scaled_jacobian_after, stats.mean_scaled_jacobian_after, stats.inverted_after);
  stats.seconds = timer.time();
  if(verbose)
    std::cerr << "[smooth] " << stats.iterations << " iterations, " << stats.free_vertices << " free, "
              << stats.feature_vertices << " feature, " << stats.fixed_vertices << " fixed vertices; scaled Jacobian min "
              << stats.min_scaled_jacobian_before << " -> " << stats.min_scaled_jacobian_after << ", mean "
              << stats.mean_scaled_jacobian_before << " -> " << stats.mean_scaled_jacobian_after << ", quads with scaled Jacobian <= 0 "
              << stats.inverted_before << " -> " << stats.inverted_after << " (" << stats.untangling_moves
              << " untangling moves, " << stats.refined_chords << " chord splits and " << stats.inset_quads << " insets adding " << stats.refinement_quads
              << " quads) (" << stats.seconds << " s)\n";
  return stats;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_SMOOTH_QUAD_MESH_H
