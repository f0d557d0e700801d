// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Feature-preserving uniform then adaptive triangle remeshing before the cross field (paper, 4.2-4.3),
// and the default density of the quad mesh.

#ifndef CGAL_QUAD_REMESHING_REMESH_FOR_QUADRANGULATION_H
#define CGAL_QUAD_REMESHING_REMESH_FOR_QUADRANGULATION_H

#include <CGAL/Quad_remeshing/internal/bbox_diagonal.h>
#include <CGAL/Quad_remeshing/internal/component_lengths.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/detect_feature_edges.h> // (its named parameters: the feature corners)
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/features/feature_graph.h>
#include <CGAL/Quad_remeshing/internal/remeshing/adaptive_remeshing.h>
#include <CGAL/Quad_remeshing/internal/remeshing/remeshing_helpers.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

/// if `false`, remesh_for_quadrangulation() does the uniform pass only (`bool`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(adaptive_remeshing_t, adaptive_remeshing, adaptive_remeshing)
/// whether remesh_for_quadrangulation()'s uniform pass holds the sharp edges that are not features (`bool`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(hold_sharp_edges_t, hold_sharp_edges, hold_sharp_edges)
/// largest distance between the remeshed and the input surface, as a fraction of the bounding-box diagonal (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(remeshing_tolerance_t, remeshing_tolerance, remeshing_tolerance)
/// how many times remesh_for_quadrangulation() remeshes again, at half the length, the regions of the uniform pass farther than its tolerance from the input (`unsigned`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(far_region_rounds_t, far_region_rounds, far_region_rounds)
/// a connected component's bounding-box diagonal spans at least this many quad edges (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(component_resolution_t, component_resolution, component_resolution)
/// output: the target edge length of every vertex of the remeshed mesh (vertex property map, `double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(vertex_sizing_map_t, vertex_sizing_map, vertex_sizing_map)

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `remesh_for_quadrangulation()`.
*/
struct Remeshing_statistics
{
  double target_edge_length = 0.;        ///< edge length of the uniform pass (half the quad edge length)
  std::size_t vertices_before = 0, faces_before = 0, vertices_after = 0, faces_after = 0;
  double min_angle_before = 0., mean_angle_before = 0.; ///< triangle angles (degrees) of the input
  double min_angle_after = 0., mean_angle_after = 0.;   ///< triangle angles (degrees) of the output
  std::size_t feature_edges_before = 0, feature_edges_after = 0;
  std::size_t split_vertices = 0;        ///< vertices inserted by the final face splitting
  double seconds_uniform = 0., seconds_adaptive = 0., seconds_split = 0., seconds = 0.;
  std::size_t faces_uniform = 0;         ///< faces after the uniform pass
  std::size_t adaptive_rounds = 0;       ///< sizing-field refinements of the adaptive pass
  std::size_t restored_vertices = 0;     ///< vertices the adaptive pass inserted to put constraint lines back on the input lines
  std::size_t sharp_edges_held = 0;      ///< input sharp edges that are not features, held in place (`hold_sharp_edges` or the adaptive pass)
  std::size_t bend_vertices_held = 0;    ///< vertices where a feature line bends away from its simplification by more than the remeshing tolerance, held in place
  double distance_after = 0.;            ///< measured distance to the input after the adaptive pass (fraction of the diagonal)
  double distance_uniform = 0.;          ///< measured distance to the input after the uniform pass, before the far regions are refined (fraction of the diagonal; 0 if not measured)
  double distance_refined = 0.;          ///< measured distance to the input after the far regions are refined (fraction of the diagonal; 0 if not measured)
  std::size_t far_region_rounds = 0;     ///< refinements of the far regions done after the uniform pass
  std::size_t far_region_faces = 0;      ///< faces given to those refinements, summed over them
  double seconds_far_regions = 0.;       ///< time of the far-region measurements and refinements
  double min_size = 0., max_size = 0.;   ///< range of the sizing field of the adaptive pass
  double split_blowup = 0.;              ///< estimate (an overstatement) of how many times the result's faces the first split pass at the target would make (see `remesh_for_quadrangulation()`); 0 with the adaptive pass
  double coarse_edge_length = 0.;        ///< edge length of the coarse pass before the uniform pass, 0 if there was none
  std::size_t faces_coarse = 0;          ///< faces after the coarse pass
  std::size_t even_split_vertices = 0;   ///< vertices inserted on long edges before the uniform pass
  std::size_t components = 0;            ///< connected components
  std::size_t small_components = 0;      ///< components remeshed at a shorter length than `target_edge_length` (`component_resolution`)
  double smallest_target_edge_length = 0.; ///< the shortest target length of a component

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["target_edge_length"] = target_edge_length;
    r["V_before"] = vertices_before;
    r["F_before"] = faces_before;
    r["V"] = vertices_after;
    r["F"] = faces_after;
    r["min_angle_before"] = min_angle_before;
    r["mean_angle_before"] = mean_angle_before;
    r["min_angle_after"] = min_angle_after;
    r["mean_angle_after"] = mean_angle_after;
    r["feature_edges_before"] = feature_edges_before;
    r["feature_edges_after"] = feature_edges_after;
    r["split_vertices"] = split_vertices;
    r["F_uniform"] = faces_uniform;
    r["adaptive_rounds"] = adaptive_rounds;
    r["restored_vertices"] = restored_vertices;
    r["sharp_edges_held"] = sharp_edges_held;
    r["bend_vertices_held"] = bend_vertices_held;
    r["distance_after"] = distance_after;
    r["distance_uniform"] = distance_uniform;
    r["distance_refined"] = distance_refined;
    r["far_region_rounds"] = far_region_rounds;
    r["far_region_faces"] = far_region_faces;
    r["seconds_far_regions"] = seconds_far_regions;
    r["min_size"] = min_size;
    r["max_size"] = max_size;
    r["split_blowup"] = split_blowup;
    r["coarse_edge_length"] = coarse_edge_length;
    r["F_coarse"] = faces_coarse;
    r["even_split_vertices"] = even_split_vertices;
    r["components"] = components;
    r["small_components"] = small_components;
    r["smallest_target_edge_length"] = smallest_target_edge_length;
    r["seconds_uniform"] = seconds_uniform;
    r["seconds_adaptive"] = seconds_adaptive;
    r["seconds_split"] = seconds_split;
    r["seconds"] = seconds;
    return r;
  }
};

/*!
  \ingroup PkgQuadRemeshingRef
  The default edge length of the quad mesh, after the original QuadWild: `2 L` with
  `L = min(sqrt(2.309 A Sph^2 / 2000), sqrt(2.309 A / 10000))`, `A` the area, `Sph = pi^(1/3) (6V)^(2/3) / A`
  the sphericity and `V` the enclosed volume; `2.309 = 4/sqrt(3)` turns an area into the number of
  equilateral triangles of edge `L`, so the uniform pass of `remesh_for_quadrangulation()` (at `L`)
  makes at least about 10,000 triangles.
  The volume is meaningful only for a closed mesh: if `tmesh` has a border, the sphericity is taken as 1,
  which leaves `L = sqrt(2.309 A / 10000)` (the second term is then the smaller one).
  For several closed components, `V` is the sum of their absolute volumes.

  @tparam TriangleMesh a model of `FaceListGraph`
  @param tmesh the triangle mesh
  @param np optional named parameters: `vertex_point_map`, `geom_traits` (as in `detect_feature_edges()`)
  @throws std::invalid_argument if the area of `tmesh` is zero
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double default_quad_edge_length(const TriangleMesh& tmesh, const NamedParameters& np = parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  const double area = CGAL::to_double(PMP::area(tmesh, CGAL::parameters::vertex_point_map(vpm)));
  if(!(area > 0.))
    throw std::invalid_argument("default_quad_edge_length: the mesh has zero area");
  double sph = 1.;
  if(CGAL::is_closed(tmesh))
  {
    // signed volume of each face against the origin, summed per component
    auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), tmesh);
    const std::size_t nc = PMP::connected_components(tmesh, fcc);
    std::vector<double> vol(nc, 0.);
    for(auto f : faces(tmesh))
    {
      const auto h = halfedge(f, tmesh);
      const auto& p = get(vpm, source(h, tmesh));
      const auto& q = get(vpm, target(h, tmesh));
      const auto& r = get(vpm, target(next(h, tmesh), tmesh));
      vol[get(fcc, f)] += CGAL::to_double(CGAL::determinant(p.x(), p.y(), p.z(), q.x(), q.y(), q.z(),
                                                            r.x(), r.y(), r.z())) / 6.;
    }
    double v = 0.;
    for(double x : vol) v += std::abs(x);
    // (6V)^(2/3) / A written as a power of the scale-free 6V / A^(3/2): a mesh scaled by a power of two
    // gets exactly that multiple of the length (pow() of scaled values may differ in the last bit)
    sph = std::cbrt(CGAL_PI) * std::pow(6. * v / (area * std::sqrt(area)), 2. / 3.);
  }
  const double L = (std::min)(std::sqrt(2.309 * area * sph * sph / 2000.), std::sqrt(2.309 * area / 10000.));
  return 2. * L;
}

/*!
  \ingroup PkgQuadRemeshingRef
  The quad edge length that gives about `number_of_faces` square quads over the area of `tmesh`:
  `sqrt(A / number_of_faces)`.
  @param tmesh the triangle mesh (a model of `FaceListGraph`)
  @param number_of_faces the desired number of quads
  @param np optional named parameters: `vertex_point_map`
  @throws std::invalid_argument if `number_of_faces` is 0 or the area is zero
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double quad_edge_length_from_face_count(const TriangleMesh& tmesh, std::size_t number_of_faces,
                                        const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if(number_of_faces == 0)
    throw std::invalid_argument("quad_edge_length_from_face_count: the number of faces must be positive");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  const double area = CGAL::to_double(CGAL::Polygon_mesh_processing::area(tmesh, CGAL::parameters::vertex_point_map(vpm)));
  if(!(area > 0.))
    throw std::invalid_argument("quad_edge_length_from_face_count: the mesh has zero area");
  return std::sqrt(area / double(number_of_faces));
}

/*!
  \ingroup PkgQuadRemeshingRef
  `scale * default_quad_edge_length(tmesh, np)`: a scale above 1 gives larger (fewer) quads.
  @throws std::invalid_argument if `scale` is not positive
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double quad_edge_length_from_scale(const TriangleMesh& tmesh, double scale,
                                   const NamedParameters& np = parameters::default_values())
{
  if(!(scale > 0.) || !std::isfinite(scale))
    throw std::invalid_argument("quad_edge_length_from_scale: the scale must be positive");
  return scale * default_quad_edge_length(tmesh, np);
}

namespace internal {

constexpr double default_remeshing_tolerance = 0.002; // remesh_for_quadrangulation()'s `remeshing_tolerance`
// after the uniform pass, the faces around a vertex farther than this share of `remeshing_tolerance` from
// the input are remeshed again (the rest is a margin for the points between the samples)
constexpr double far_region_share = 0.7;

// The uniform pass's first split pass cuts every edge longer than 4/3 of the target, so a triangle with a
// long edge `l` ends as up to about (l / target)^2 triangles, while the result has about
// area / (sqrt(3)/4 target^2). The ratio of the two sums does not depend on the target and overstates the
// growth: about 1 for a well-shaped input, 51 for abc_00000009 (long thin CAD triangles: 0.65-1.3M faces
// after the first split pass for 105k in the end), 37-44 for abc_00000006/8, at most 16 for the other
// development meshes.
template <typename TriangleMesh, typename VPM>
double split_blowup_estimate(const TriangleMesh& tmesh, VPM vpm)
{
  double longest = 0., area = 0.;
  for(auto f : faces(tmesh))
  {
    const auto h = halfedge(f, tmesh);
    const auto& p = get(vpm, source(h, tmesh));
    const auto& q = get(vpm, target(h, tmesh));
    const auto& r = get(vpm, target(next(h, tmesh), tmesh));
    longest += CGAL::to_double((std::max)({CGAL::squared_distance(p, q), CGAL::squared_distance(q, r),
                                           CGAL::squared_distance(r, p)}));
    area += std::sqrt(CGAL::to_double(CGAL::squared_area(p, q, r)));
  }
  return area > 0. ? longest * std::sqrt(3.) / 4. / area : 0.;
}
// above this estimate the uniform pass is preceded by a coarse pass. The pass changes the triangles the later
// stages see, and they react strongly to any change: at 25, abc_00000006 (43.5) got a 1.6% Hausdorff distance
// instead of 0.4% for a remeshing 3.4 s shorter, so only the extreme case (abc_00000009, 51: 1M faces after
// the first split, 236 MiB) takes it
constexpr double coarse_pass_blowup = 45.;
// above this estimate (and up to the one above) the long edges are split evenly first
// (split_long_edges_evenly()). Not above: on abc_00000009 (51) that replacing the coarse pass gave a layout
// of 158 patches instead of 489, with quads bridging 9% of the diagonal, in 32 s instead of 20
constexpr double even_split_blowup = 20.;
// the coarse pass's edge length in target lengths: its own split pass then makes about 16 times fewer faces
// (on abc_00000009, factors 3 to 6 gave the same time within noise)
constexpr double coarse_pass_factor = 4.;
// With `hold_sharp_edges`, a long crease beside a narrow facet is held too: an edge at least this many
// target lengths long (1.25 quad edge lengths) whose dihedral angle is above long_crease_angle, though
// below the feature angle, and one of whose faces is narrower than the target length across it. Truck's
// front wheel arches are coarse fillets of a few such facets (creases of 20 to 27 degrees, 0.12 long,
// three target lengths): a remeshed edge spans a facet and both its creases, and the remeshed surface
// was 0.65% of the diagonal away from the input there before any quad was made. Where the facets are
// wider than the target (draco_test_nm's cylinder, 22 degrees), one crease at a time costs little, and
// holding them took its smallest scaled Jacobian from 0.30 to 0.017; shorter edges (twice the target
// length) held on spot put its remeshed surface farther from the input (0.22% of the diagonal), and 25
// degrees left truck at 0.53% (qmeval).
constexpr double long_crease_length = 2.5;
constexpr double long_crease_angle = 20.;

// Pass 2: the sizing field starts from the paper's radius-ratio rule (capped at the uniform length) and
// is refined where the measured distance to the input exceeds 70% of the tolerance (the remaining 30%
// is a margin for the points between the measured samples), by sqrt(target / distance) (the chord error
// of a curve goes with the square of the edge length), never below `uniform / 8`; after each refinement
// the loop (split, collapse, flip, relax and project) runs again. It stops when the measured distance is
// within the target, after 6 refinements, or when the mesh has 2.5 times the faces of the uniform pass.
template <typename TriangleMesh, typename VPM, typename EFM, typename VCM, typename SizeMap, typename GT>
void adaptive_pass(TriangleMesh& tmesh, VPM vpm, EFM efm, VCM vcm, SizeMap size, const Remeshing_reference<GT>& ref,
                   const std::vector<typename GT::Point_3>& line_points, double diagonal, double tolerance,
                   unsigned iterations, Remeshing_statistics& st, bool verbose)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const double uniform = st.target_edge_length;
  const double min_size = uniform / 8.;
  const double target = 0.85 * tolerance * diagonal;
  // the prediction of expected_faces() falls short by up to a third on curved meshes: budgets of 1.3 and
  // 2.2 times the faces of pass 1 keep the result below about 3 times
  const double quality_budget = 1.3, face_budget = 2.2;
  auto count_faces = [&] { return std::size_t(std::distance(faces(tmesh).begin(), faces(tmesh).end())); };

  auto err = get(CGAL::dynamic_vertex_property_t<double>(), tmesh);
  // (a) the paper's multipliers, capped at 1 and floored so that they alone at most add half the faces
  auto mult = get(CGAL::dynamic_vertex_property_t<double>(), tmesh);
  radius_ratio_multipliers(tmesh, vpm, mult);
  const double uniform_faces = expected_faces(tmesh, vpm, Constant_property_map<vertex_descriptor, double>(uniform));
  double lowest = 0.3;
  for(; lowest < 1.; lowest += 0.05)
  {
    for(vertex_descriptor v : vertices(tmesh))
      put(size, v, uniform * (std::min)(1., (std::max)(lowest, get(mult, v))));
    if(expected_faces(tmesh, vpm, size) <= quality_budget * uniform_faces) break;
  }
  if(!(lowest < 1.)) for(vertex_descriptor v : vertices(tmesh)) put(size, v, uniform);
  // (b) where the measured distance exceeds the target; a refinement that would give more than
  // `face_budget` times the faces of the uniform pass is not done
  auto previous = get(CGAL::dynamic_vertex_property_t<double>(), tmesh);
  auto refine = [&] {
    for(vertex_descriptor v : vertices(tmesh))
    {
      put(previous, v, get(size, v));
      if(get(err, v) > target)
        put(size, v, (std::max)(min_size, get(size, v) * (std::max)(0.35, (std::min)(0.9, 0.9 * std::sqrt(target / get(err, v))))));
    }
    limit_size_gradation(tmesh, vpm, size, 0.5);
    // the growth the new field predicts, applied to the actual face count
    const double growth = expected_faces(tmesh, vpm, size) / expected_faces(tmesh, vpm, previous);
    if(growth * double(count_faces()) <= face_budget * double(st.faces_uniform)) return true;
    for(vertex_descriptor v : vertices(tmesh)) put(size, v, get(previous, v));
    return false;
  };
  Adaptive_remesher<TriangleMesh, VPM, EFM, VCM, SizeMap, GT> remesher(tmesh, vpm, efm, vcm, size, ref, 0.5 * target,
                                                                     std::size_t(2.8 * double(st.faces_uniform)));
  CGAL::Real_timer clock;
  clock.start();
  for(unsigned i = 0; i < iterations; ++i) remesher.iterate();
  if(verbose) std::cerr << "[remeshing] first loop: " << count_faces() << " faces (" << clock.time() << " s)" << std::endl;
  clock.reset();
  double worst = measure_distances(tmesh, vpm, ref, err);
  if(verbose) std::cerr << "[remeshing] distance " << worst / diagonal << " (" << clock.time() << " s)" << std::endl;
  for(st.adaptive_rounds = 0; st.adaptive_rounds < 6 && worst > target; ++st.adaptive_rounds)
  {
    if(double(count_faces()) > face_budget * double(st.faces_uniform) || !refine()) break;
    for(unsigned i = 0; i < 2; ++i) remesher.iterate();
    worst = measure_distances(tmesh, vpm, ref, err);
    if(verbose)
      std::cerr << "[remeshing] refinement " << st.adaptive_rounds + 1 << ": " << count_faces() << " faces, distance "
                << worst / diagonal << std::endl;
  }
  // (c) the constraint lines back onto the input lines where collapses along them left chords
  clock.reset();
  st.restored_vertices = remesher.restore_lines(line_points, 0.25 * tolerance * diagonal, 8);
  if(st.restored_vertices > 0) worst = measure_distances(tmesh, vpm, ref, err);
  if(verbose)
    std::cerr << "[remeshing] lines restored: " << st.restored_vertices << " vertices, distance " << worst / diagonal
              << " (" << clock.time() << " s)" << std::endl;
  st.distance_after = worst / diagonal;
  st.min_size = uniform;
  st.max_size = 0.;
  for(vertex_descriptor v : vertices(tmesh))
  {
    st.min_size = (std::min)(st.min_size, get(size, v));
    st.max_size = (std::max)(st.max_size, get(size, v));
  }
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Remeshes a triangle mesh for the cross field and the quad layout, keeping every feature line.

  Pass 1 is a uniform isotropic remeshing at half the quad edge length `L`, by
  `CGAL::Polygon_mesh_processing::isotropic_remeshing()` with the feature edges as constraints and, by
  default (`hold_sharp_edges`), the input's other sharp edges too (see below): held in place, they keep
  the creases that are not features (a coarse fillet, the short chains the erosion of
  `detect_feature_edges()` removes) in the surface the later stages place the quads on. Measured with
  qmeval on the 22 development meshes through `quad_remesh()`, this takes the feature coverage of the
  organic meshes from 0.94-0.99 to 0.977-1 (face 0.968 -> 1, teapot 0.985 -> 1, fertility 0.941 ->
  0.977) and leaves the meshes whose sharp edges are all features as they were; the held creases also
  change the cross field and the layout (teapot's faceted handle and rim: a large patch that is not
  convex, many poorly shaped quads).
  If the input has long thin triangles (the estimate `split_blowup` of the statistics, the sum over the
  faces of `(longest edge / L)^2` over the area in equilateral triangles of edge `L`, is above 45), the
  first split pass at `L` would cut them into many times the faces of the result (1M faces for 105k on
  a CAD mesh); pass 1 then first remeshes at `4 L` (same settings and iterations, and every vertex on a
  feature line is held so that the lines keep their input points), then at `L` projecting onto the input,
  each vertex onto its own patch between the features as `isotropic_remeshing()` does. The result differs
  from that of a single pass. Between 20 and 45, every edge longer than `4 L / 3` is first cut into
  `ceil(length / L)` equal pieces and the faces it bounded are cut into ladders of triangles (ears, the
  shortest diagonal first; the surface does not change), so that the split pass finds short edges only:
  on abc_00000006 (37k faces, estimate 43) the remeshing takes 0.9 s instead of 4.8 s and the whole run
  60 MiB instead of 98 (2.7 KiB per input triangle before, 1.6 after). Other inputs are remeshed
  exactly as before. The adaptive pass starts from this pass 1 too (it used to start from a single
  `isotropic_remeshing()` call, whatever the estimate): with it, `--until remesh` takes 2.7 s and 57 MiB
  on abc_00000006 instead of 6.0 s and 112 MiB, and 8.3 s and 93 MiB on abc_00000009 (estimate 51,
  the coarse pass first) instead of 23 s and 252 MiB, both as close to the input as before (qmeval: 0.10% and 0.015%
  of the diagonal); the trees of the input it projects onto are built after pass 1, out of its peak.

  Without the adaptive pass, pass 1 is followed by the refinement of its far regions (`far_region_rounds`,
  2 by default): a tip of the input narrower than the pass's length `L / 2` is cut off by the collapses, and
  a bend tighter than it is flattened (elephant's tusks and toes: 0.72% of the diagonal from the input, qmeval). The distance
  to the input is measured at the centroid and edge midpoints of every face (to the input) and at every
  input vertex (to the result); the faces farther than 70% of `remeshing_tolerance`, and the face nearest
  to each such input vertex, with the ring of faces around their vertices, are remeshed again by
  `isotropic_remeshing()` at `L / 4` (the features and held vertices as in pass 1), projecting onto the
  input; then, if the largest distance fell, once more at `L / 8`. The components remeshed at a shorter
  length of their own are left out. Measured with qmeval on the 22 development meshes (`--until remesh`,
  symmetric Hausdorff distance): 18 within 0.2% of the diagonal instead of 9 (elephant 0.72% -> 0.19%,
  face 0.50% -> 0.14%, featuretype 0.51% -> 0.20%, bunny 0.40% -> 0.18%, rocker_arm 0.36% -> 0.17%), for up
  to twice the faces (rocker_arm 12.8k -> 25.2k); still above: camelhead 0.81% -> 0.59%, truck 0.62% ->
  0.32%, and teapot (0.48%) and chair_doublesided (0.38%, thin double-sided struts), which the finer mesh
  does not bring closer. The distances are measured as in the adaptive pass (`measure_distances()`).

  Pass 2 (`adaptive_remeshing`, off by default, see below) is the package's own loop of edge splits, edge collapses,
  edge flips, tangential relaxation and projection onto the input, driven by a target edge length per
  vertex (the sizing field; `internal/remeshing/adaptive_remeshing.h`). The sizing field is the smaller of
  - (a) the paper's rule (4.2): a multiplier from the radius ratio (2 inradius / circumradius) of the
    pass-1 triangles around the vertex, mapped linearly to [0.3, 3] from the 10th percentile (the worst
    10% get 0.3) to the best value, times `L`, capped at `L`, and floored (0.3, 0.35, ... up to 1) so that
    this rule alone gives at most about 1.3 times the faces of pass 1;
  - (b) a distance bound: after the loop, the distance to the input is measured (output to input at the
    centroid of every face and the midpoint of every edge, input to output at every input vertex) and,
    around every sample farther than 85% of `remeshing_tolerance` (the remaining 15% is a margin for the
    points between the samples), the target length is multiplied by `0.9 sqrt(target / distance)` (the
    chord error grows with the square of the edge length), kept within [0.35, 0.9]; the length never goes
    below the minimum `L / 8`, and its growth is limited to half the distance between neighbours. The
    loop then runs again (2 iterations), at most 6 times. A refinement that would give more than 2.2
    times the faces of pass 1 (predicted from the field), or once the mesh has that many, is not done,
    and splits stop at 2.8 times the faces of pass 1 (the prediction can fall short where the field
    varies fast), so that the output stays below about 3 times the faces of pass 1.

  With `hold_sharp_edges` (the default) or the adaptive pass, the passes hold in place, besides the
  features, the input's other sharp edges (dihedral angle above `feature_angle`, e.g. the short chains that
  the erosion of `detect_feature_edges()` removed) and its long creases beside a narrow facet: edges at
  least 2.5 target lengths (1.25 `L`) long whose dihedral angle is above 20 degrees (or `feature_angle` if
  smaller) and one of whose two faces is narrower than the target length across the edge. A coarse fillet
  of a few such facets (truck's front wheel arches) was otherwise cut across by the remeshed edges, each
  spanning a facet and both its creases, 0.65% of the diagonal from the input before any quad was made.
  The held lines follow the rules of the features below, their
  ends, junctions and turns of more than 45 degrees never move, so the surface keeps its creases; at the
  end only the edges on an input feature line are features again (an edge goes to the nearer of the two
  kinds of input line). Without the adaptive pass, the vertices where a constrained line bends away
  by more than `remeshing_tolerance` from a Douglas-Peucker simplification of it (between its corners,
  ends and junctions; a closed loop without any is split at two of its vertices far apart, both held) are
  held too: the collapses along a line keep only some of its vertices, and a line that turns a lot over
  edges shorter than the target (a hairpin bend around the end of a slot) was cut short (featuretype:
  0.77% of the diagonal), as was the tip of a narrow closed loop (teapot's spout opening: 0.51%). With the adaptive pass, after the refinements, the lines are put back where collapses along them left chords: while an input line point
  (vertex or edge midpoint) is farther than a quarter of `remeshing_tolerance` from every constrained
  edge, the nearest one is split at that point (up to 8 rounds; not near an endpoint, never folding a face).

  The loop's rules at the features are those of pass 1: a feature edge is split at its midpoint (moved
  onto the nearest input feature segment when it lies within a quarter of the edge length) and never
  flipped; it is collapsed only along its line, removing a vertex that has exactly two feature edges and
  is not a corner, and only if the new edge passes within half the target distance of the removed vertex; a
  non-feature edge is collapsed only onto a vertex, never removing a feature vertex; feature corners,
  line ends and junctions never move nor are removed; feature vertices are not relaxed. Non-feature
  midpoints and relaxed vertices are projected onto the input; a move that folds a face is not done.
  A flip is done if it brings the valences closer to 6 (4 on the border), the two faces are within about
  20 degrees of coplanar, and it does not join two feature vertices.

  Finally (paper, Figure 5), a face whose three edges are features gets a centre vertex, and every
  non-feature edge joining two feature vertices is split at its midpoint (projected on the input), so
  that no face has more than one feature edge and no non-feature edge joins two feature vertices.

  Every component is remeshed, whatever its size, and keeps its features. A component much smaller
  than the largest one is remeshed finer (`component_resolution`): with one length for all, the spokes of
  truck's steering wheel (a part 0.2 across, spokes 0.03 wide, quads 0.08) were one quad wide and the
  quads crossed the holes between them, 1.1% of the diagonal from the input (0.78% with it, measured with
  qmeval through `quad_remesh()`, in 25.7 s instead of 26.8 by the batch runner). Memory stays proportional to
  the input plus the output (planar meshes with holes included: their holes' borders are features).

  @tparam TriangleMesh a model of `MutableFaceGraph` and `FaceListGraph`
  @tparam EdgeIsFeatureMap a model of `ReadWritePropertyMap` with `edge_descriptor` as key and `bool` as
          value, e.g. filled by `detect_feature_edges()`
  @tparam NamedParameters a sequence of named parameters

  @param tmesh the triangle mesh, remeshed in place
  @param edge_is_feature_map the feature edges; kept up to date (the halves of a split feature edge are features)
  @param np optional named parameters among the ones listed below

  @pre `CGAL::is_triangle_mesh(tmesh)`, `tmesh` is valid and manifold
  @pre border edges are marked in `edge_is_feature_map` (they are added if not)

  \cgalNamedParamsBegin
    \cgalParamNBegin{quad_edge_length}
      \cgalParamDescription{edge length of the quad mesh; the uniform pass uses half of it}
      \cgalParamType{`double`}
      \cgalParamDefault{`default_quad_edge_length(tmesh, np)`}
    \cgalParamNEnd
    \cgalParamNBegin{component_resolution}
      \cgalParamDescription{every connected component but the largest (by bounding-box diagonal; those within
                            1% of it count as the largest) gets the quad edge length `min(L, d / R)` for `d`
                            its diagonal and `R` this value, rounded down to `L` over a power of sqrt(2) and
                            never below `L / 4`, and is remeshed at half of it (one call of
                            `isotropic_remeshing()` per length). A small part (a steering wheel inside a
                            truck) then keeps its shape; the largest part keeps the length asked for. `0`:
                            `L` everywhere}
      \cgalParamType{`double`}
      \cgalParamDefault{`8`}
    \cgalParamNEnd
    \cgalParamNBegin{adaptive_remeshing}
      \cgalParamDescription{if `true`, the adaptive pass runs after the uniform one. Off by default: it
                            brings the distance to the input under 0.2% of the diagonal on most meshes,
                            but the later stages do not follow its sizing field. In the full pipeline
                            (`quad_remesh()` with `sizing_tolerance` 0.002, measured with qmeval on the 22
                            development meshes) it brings the organic meshes much closer to the input
                            (teapot 3.2% -> 0.7% of the diagonal, face 2.0% -> 0.5%) and raises their
                            feature coverage (spot 0.82 -> 0.98), but takes the CAD meshes xyz_cube_20mm
                            (0.3% -> 1.2%: the smoothing moves free vertices of an embossed letter's top over its
                            edge, and they land on the floor 0.5 mm below, whose normal is the top's) and
                            draco_test_nm (0.7% -> 1.3%) farther, takes 1.5 times the time, and on
                            chair_doublesided the assembly refuses the quadrangulation of one patch}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{remeshing_tolerance}
      \cgalParamDescription{the largest distance between the result and the input that the adaptive pass
                            aims at, as a fraction of the diagonal of the bounding box of the input. Not a
                            guarantee: it is measured at samples, and the pass stops at the minimum length
                            `L / 8`, after 6 refinements, or at the face budget. Without the adaptive pass,
                            the bends of the constrained lines farther than this from their simplification
                            are held}
      \cgalParamType{`double`}
      \cgalParamDefault{0.002}
    \cgalParamNEnd
    \cgalParamNBegin{far_region_rounds}
      \cgalParamDescription{how many times, at most, the regions that pass 1 leaves farther than 70% of
                            `remeshing_tolerance` from the input are remeshed again, at `L / 4`, then `L / 8`
                            (see above); the rounds stop when the largest measured distance does not fall.
                            0: none. Ignored with the adaptive pass. The sizing field of `vertex_sizing_map`
                            stays that of pass 1}
      \cgalParamType{`unsigned`}
      \cgalParamDefault{2}
    \cgalParamNEnd
    \cgalParamNBegin{hold_sharp_edges}
      \cgalParamDescription{if `true`, the uniform pass holds in place, as it does the features, the input edges
                            that are not features but whose dihedral angle is above `feature_angle`, and the long
                            creases beside a narrow facet (see above); the adaptive pass always holds them. They
                            are not features in the result}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_angle}
      \cgalParamDescription{with `hold_sharp_edges` or the adaptive pass, the dihedral angle in degrees above
                            which an input edge that is not a feature is still held in place (as in
                            `detect_feature_edges()`); 180 or more holds none}
      \cgalParamType{`double`}
      \cgalParamDefault{35}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_sizing_map}
      \cgalParamDescription{receives, for every vertex of the result, the target edge length of the sizing
                            field there (half the quad edge length of the vertex's component without the
                            adaptive pass; a vertex inserted by the
                            final splitting gets the mean of its neighbours). Later stages can size quads
                            locally with it: the quad edge length there is about twice the value}
      \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `double` as value}
      \cgalParamDefault{unused}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{iterations of the uniform pass, and of the first loop of the adaptive pass}
      \cgalParamType{`unsigned`}
      \cgalParamDefault{5}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_feature_corner_map}
      \cgalParamDescription{the feature corners (never moved nor removed); if given it is read before
                            remeshing and rewritten after it (new vertices are not corners); if absent,
                            corners are computed as in `detect_feature_edges()` with a 45 degree turn}
      \cgalParamType{a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `bool` as value}
      \cgalParamDefault{unused}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `Point_3` as value}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{prints progress and timing to `std::cerr`, lines prefixed by `[remeshing]`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the statistics of the remeshing
  @throws std::invalid_argument if `tmesh` is not a triangle mesh, has a degenerate face (three collinear
          corners) or `quad_edge_length` is not positive
*/
template <typename TriangleMesh, typename EdgeIsFeatureMap,
          typename NamedParameters = parameters::Default_named_parameters>
Remeshing_statistics remesh_for_quadrangulation(TriangleMesh& tmesh, EdgeIsFeatureMap edge_is_feature_map,
                                                const NamedParameters& np = parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GTr;
  typedef typename GTr::vertex_descriptor vertex_descriptor;
  typedef typename GTr::face_descriptor face_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;

  CGAL::Real_timer total;
  total.start();
  if(!CGAL::is_triangle_mesh(tmesh))
    throw std::invalid_argument("remesh_for_quadrangulation: the input is not a triangle mesh");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, tmesh));
  // CGAL's isotropic_remeshing reads out of its arrays on a face with collinear corners (found by the
  // fuzz target fuzz_quad_remesh: a segmentation fault in its tangential relaxation)
  std::size_t degenerate_faces = 0;
  for(face_descriptor f : faces(tmesh))
    if(PMP::is_degenerate_triangle_face(f, tmesh, CGAL::parameters::vertex_point_map(vpm))) ++degenerate_faces;
  if(degenerate_faces > 0)
    throw std::invalid_argument("remesh_for_quadrangulation: " + std::to_string(degenerate_faces) +
                                " degenerate face(s) (collinear corners) that read_and_repair() could not remove");
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const bool adaptive = choose_parameter(get_parameter(np, internal_np::adaptive_remeshing), false);
  const double tolerance =
    choose_parameter(get_parameter(np, internal_np::remeshing_tolerance), internal::default_remeshing_tolerance);
  auto sizing_out = get_parameter(np, internal_np::vertex_sizing_map);
  constexpr bool has_sizing_map = !std::is_same<decltype(sizing_out), CGAL::internal_np::Param_not_found>::value;
  const unsigned iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 5u);
  const double sharp_angle = choose_parameter(get_parameter(np, internal_np::feature_angle), 35.);
  // the adaptive pass always holds them
  const bool hold_sharp = adaptive || choose_parameter(get_parameter(np, internal_np::hold_sharp_edges), true);
  const unsigned refine_rounds = adaptive ? 0u : choose_parameter(get_parameter(np, internal_np::far_region_rounds), 2u);

  Remeshing_statistics st;
  // (num_faces() of a Surface_mesh counts removed elements)
  st.vertices_before = std::size_t(std::distance(vertices(tmesh).begin(), vertices(tmesh).end()));
  st.faces_before = std::size_t(std::distance(faces(tmesh).begin(), faces(tmesh).end()));
  if(st.faces_before == 0)
    return st;
  const double qlen = parameters::is_default_parameter<NamedParameters, internal_np::quad_edge_length_t>::value
                        ? default_quad_edge_length(tmesh, np)
                        : double(choose_parameter(get_parameter(np, internal_np::quad_edge_length), 0.));
  if(!(qlen > 0.) || !std::isfinite(qlen))
    throw std::invalid_argument("remesh_for_quadrangulation: quad_edge_length must be positive");
  st.target_edge_length = qlen / 2.;

  // each component at its length: the largest ones at the global length (one call), each smaller one at
  // its own (internal::component_quad_edge_lengths(); one call per length). The faces are grouped again
  // before each call: the passes and the even splits of long edges remove faces and make new ones.
  const double resolution = choose_parameter(get_parameter(np, internal_np::component_resolution),
                                             internal::default_component_resolution);
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), tmesh);
  struct Face_groups
  {
    std::vector<face_descriptor> large;                               // at the global length
    std::vector<std::pair<double, std::vector<face_descriptor>>> small; // (quad edge length, faces)
  };
  auto group_faces = [&]() {
    Face_groups g;
    const std::vector<double> lengths = internal::component_quad_edge_lengths(tmesh, vpm, component, qlen, resolution);
    for(face_descriptor f : faces(tmesh))
    {
      const double l = lengths[get(component, f)];
      if(!(l < qlen)) { g.large.push_back(f); continue; }
      auto it = std::find_if(g.small.begin(), g.small.end(), [l](const auto& s) { return s.first == l; });
      if(it == g.small.end()) it = g.small.insert(g.small.end(), {l, {}});
      it->second.push_back(f);
    }
    return g;
  };
  {
    const std::vector<double> lengths = internal::component_quad_edge_lengths(tmesh, vpm, component, qlen, resolution);
    st.components = lengths.size();
    st.smallest_target_edge_length = st.target_edge_length;
    for(double l : lengths)
      if(l < qlen)
      {
        ++st.small_components;
        st.smallest_target_edge_length = (std::min)(st.smallest_target_edge_length, l / 2.);
      }
  }

  std::tie(st.min_angle_before, st.mean_angle_before) = internal::triangle_angles(tmesh, vpm);
  for(auto e : edges(tmesh))
  {
    if(is_border(e, tmesh)) put(edge_is_feature_map, e, true);
    if(get(edge_is_feature_map, e)) ++st.feature_edges_before;
  }

  // the input surface, its feature lines and its vertices: projections and distances. Without the
  // adaptive pass only the surface is used (by the final splitting). The trees are built after the
  // uniform pass, so that they do not add to the peak memory of isotropic_remeshing() (which builds
  // its own trees of the input)
  internal::Remeshing_reference<GT> reference;
  reference.triangles.reserve(st.faces_before);
  for(face_descriptor f : faces(tmesh))
  {
    const auto h = halfedge(f, tmesh);
    reference.triangles.emplace_back(get(vpm, source(h, tmesh)), get(vpm, target(h, tmesh)),
                                     get(vpm, target(next(h, tmesh), tmesh)));
  }
  if(hold_sharp) // the input feature lines tell them from the held edges afterwards
    for(auto e : edges(tmesh))
      if(get(edge_is_feature_map, e))
        reference.feature_segments.emplace_back(get(vpm, source(halfedge(e, tmesh), tmesh)),
                                                get(vpm, target(halfedge(e, tmesh), tmesh)));
  // (the adaptive pass appends the held edges to them)
  const std::size_t input_feature_segments = reference.feature_segments.size();
  if(adaptive || refine_rounds > 0) // (the distances from the input are measured at them)
  {
    reference.points.reserve(st.vertices_before);
    for(vertex_descriptor v : vertices(tmesh)) reference.points.push_back(get(vpm, v));
  }
  const CGAL::Bbox_3 box = PMP::bbox(tmesh, CGAL::parameters::vertex_point_map(vpm));
  const double diagonal = internal::bbox_diagonal(box);

  // corners: given, or computed from the features
  const auto given_corners = get_parameter(np, internal_np::vertex_is_feature_corner_map);
  constexpr bool has_corner_map = !std::is_same<std::decay_t<decltype(given_corners)>, CGAL::internal_np::Param_not_found>::value;
  auto vcm = get(CGAL::dynamic_vertex_property_t<bool>(), tmesh);
  std::vector<vertex_descriptor> corners;
  if constexpr(has_corner_map)
  {
    for(vertex_descriptor v : vertices(tmesh))
      if(get(given_corners, v)) corners.push_back(v);
  }
  else
    internal::feature_corners_and_lines(tmesh, edge_is_feature_map, vpm, 45., corners);
  for(vertex_descriptor v : vertices(tmesh)) put(vcm, v, false);
  for(vertex_descriptor v : corners) put(vcm, v, true);

  // the settings of every isotropic_remeshing() call: the constrained edges are split and collapsed along
  // their lines but not relaxed, the constrained vertices never move
  auto remeshing_np = [&](auto constrained_edges, auto constrained_vertices) {
    return CGAL::parameters::number_of_iterations(iterations)
             .edge_is_constrained_map(constrained_edges)
             .vertex_is_constrained_map(constrained_vertices)
             .protect_constraints(false)
             .collapse_constraints(true)
             .relax_constraints(false)
             .vertex_point_map(vpm);
  };
  // each smaller component at its own length, after the call on the large ones (which does not touch them)
  auto remesh_small_components = [&](auto C, auto F) {
    for(const auto& group : group_faces().small)
      PMP::isotropic_remeshing(group.second, group.first / 2., tmesh, remeshing_np(C, F));
  };

  CGAL::Real_timer timer;
  timer.start();
  // the uniform pass, with the constrained edges `C` and vertices `F`
  auto uniform_pass = [&](auto C, auto F) {
    st.split_blowup = internal::split_blowup_estimate(tmesh, vpm);
    if(st.split_blowup > internal::even_split_blowup && st.split_blowup <= internal::coarse_pass_blowup)
    {
      st.even_split_vertices = internal::split_long_edges_evenly(tmesh, vpm, C, F,
                                                                 st.target_edge_length);
      if(verbose)
        std::cerr << "[remeshing] split estimate " << st.split_blowup << ": " << st.even_split_vertices
                  << " vertices on the long edges, " << num_faces(tmesh) << " faces (" << timer.time() << " s)" << std::endl;
    }
    if(st.split_blowup <= internal::coarse_pass_blowup)
      PMP::isotropic_remeshing(group_faces().large, st.target_edge_length, tmesh, remeshing_np(C, F));
    else
    {
      // Long thin input triangles: the first split pass at the target would cut them into many times the
      // faces of the result (about 10x, 1M faces, on a CAD mesh) before the collapses. A pass at a
      // coarser length first makes well-shaped triangles, so that the pass at the target splits little.
      // In the coarse pass every vertex on a feature line is held, so the lines keep all their input
      // points; the pass at the target then has the usual settings, projects onto the input (not onto
      // the coarse mesh), each vertex onto its own patch as isotropic_remeshing() does by default.
      st.coarse_edge_length = internal::coarse_pass_factor * st.target_edge_length;
      auto patch = get(CGAL::dynamic_face_property_t<std::size_t>(), tmesh);
      const std::size_t patches =
        PMP::connected_components(tmesh, patch, CGAL::parameters::edge_is_constrained_map(C));
      typedef typename internal::Remeshing_reference<GT>::Triangle Triangle;
      typedef typename internal::Remeshing_reference<GT>::Tri_tree Tri_tree;
      std::vector<std::vector<Triangle>> patch_triangles(patches);
      for(face_descriptor f : faces(tmesh))
      {
        const auto h = halfedge(f, tmesh);
        patch_triangles[get(patch, f)].emplace_back(get(vpm, source(h, tmesh)), get(vpm, target(h, tmesh)),
                                                    get(vpm, target(next(h, tmesh), tmesh)));
      }
      auto held = get(CGAL::dynamic_vertex_property_t<bool>(), tmesh);
      for(vertex_descriptor v : vertices(tmesh))
        put(held, v, get(F, v) || internal::feature_degree(v, tmesh, C) > 0);
      PMP::isotropic_remeshing(group_faces().large, st.coarse_edge_length, tmesh,
                               remeshing_np(C, held).face_patch_map(patch));
      st.faces_coarse = std::size_t(std::distance(faces(tmesh).begin(), faces(tmesh).end()));
      if(verbose)
        std::cerr << "[remeshing] split estimate " << st.split_blowup << ", coarse pass at " << st.coarse_edge_length
                  << ": " << st.faces_coarse << " faces (" << timer.time() << " s)" << std::endl;
      std::vector<std::unique_ptr<Tri_tree>> trees;
      for(const std::vector<Triangle>& t : patch_triangles)
      {
        trees.push_back(std::make_unique<Tri_tree>(t.begin(), t.end()));
        trees.back()->accelerate_distance_queries();
      }
      auto project = [&](vertex_descriptor v) {
        const face_descriptor f = face(halfedge(v, tmesh), tmesh);
        if(f == GTr::null_face()) return get(vpm, v);
        return trees[get(patch, f)]->closest_point(get(vpm, v));
      };
      PMP::isotropic_remeshing(group_faces().large, st.target_edge_length, tmesh,
                               remeshing_np(C, F).face_patch_map(patch).projection_functor(project));
    }
    remesh_small_components(C, F);
    reference.build_surface();
  };
  // When sharp edges are held (always with the adaptive pass), the constraints of both passes are the
  // features plus the input's other sharp edges (dihedral angle above `feature_angle`: the short chains
  // that the erosion of detect_feature_edges() removed), held in place so that the surface keeps its
  // creases; their ends, junctions and turns never move. Afterwards every constrained edge is a feature
  // again only if it lies on an input feature line.
  auto constrained = get(CGAL::dynamic_edge_property_t<bool>(), tmesh);
  auto fixed = get(CGAL::dynamic_vertex_property_t<bool>(), tmesh);
  std::vector<typename GT::Point_3> line_points;
  std::vector<typename GT::Segment_3> held_segments;
  if(hold_sharp)
  {
    const double cos_sharp = std::cos(sharp_angle * CGAL_PI / 180.);
    const double cos_long_crease = std::cos((std::min)(sharp_angle, internal::long_crease_angle) * CGAL_PI / 180.);
    const double long_crease_squared = CGAL::square(internal::long_crease_length * st.target_edge_length);
    for(auto e : edges(tmesh))
    {
      bool c = get(edge_is_feature_map, e);
      if(!c && sharp_angle < 180.)
      {
        const auto h = halfedge(e, tmesh);
        auto normal = [&](auto g) {
          return CGAL::cross_product(get(vpm, target(g, tmesh)) - get(vpm, source(g, tmesh)),
                                     get(vpm, target(next(g, tmesh), tmesh)) - get(vpm, source(g, tmesh)));
        };
        const auto n1 = normal(h);
        const auto n2 = normal(opposite(h, tmesh));
        const double l = std::sqrt(CGAL::to_double(n1 * n1) * CGAL::to_double(n2 * n2));
        // a long crease beside a narrow facet: the widths of the faces across the edge are |n| / length
        const double length_squared =
          CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tmesh)), get(vpm, target(h, tmesh))));
        const bool long_crease =
          length_squared >= long_crease_squared &&
          (std::min)(CGAL::to_double(n1 * n1), CGAL::to_double(n2 * n2)) < CGAL::square(st.target_edge_length) * length_squared;
        if(l > 0. && CGAL::to_double(n1 * n2) / l < (long_crease ? cos_long_crease : cos_sharp))
        {
          c = true;
          ++st.sharp_edges_held;
          held_segments.emplace_back(get(vpm, source(h, tmesh)), get(vpm, target(h, tmesh)));
        }
      }
      put(constrained, e, c);
      if(c && adaptive)
        line_points.push_back(CGAL::midpoint(get(vpm, source(halfedge(e, tmesh), tmesh)),
                                             get(vpm, target(halfedge(e, tmesh), tmesh))));
    }
    std::vector<vertex_descriptor> held_corners;
    internal::feature_corners_and_lines(tmesh, constrained, vpm, 45., held_corners);
    for(vertex_descriptor v : vertices(tmesh))
    {
      put(fixed, v, bool(get(vcm, v)));
      if(!adaptive) continue;
      for(auto h : halfedges_around_target(v, tmesh))
        if(get(constrained, edge(h, tmesh))) { line_points.push_back(get(vpm, v)); break; }
    }
    for(vertex_descriptor v : held_corners) put(fixed, v, true);
    if(adaptive) // the splits of the adaptive pass project onto either kind of line
      reference.feature_segments.insert(reference.feature_segments.end(), held_segments.begin(), held_segments.end());
  }
  else
    for(vertex_descriptor v : vertices(tmesh)) put(fixed, v, bool(get(vcm, v)));
  // The collapses along a constrained line keep some of its vertices only: a line that turns a lot over
  // edges shorter than the target (a hairpin bend) would be cut short. Its bends stay (see
  // internal::feature_bend_vertices()): those farther than the remeshing tolerance from the simplified
  // line. (A quarter of the target length instead, only the bends of lines finer than the mesh: the
  // outputs of chair_doublesided, angle_block, spot and truck were worse, measured with qmeval.) The
  // adaptive pass restores lines its own way, and the bends held in the pass before it took spot from
  // 0.18% to 0.20% of the diagonal: not there.
  const double bend_tolerance = tolerance * diagonal;
  if(!adaptive)
  {
    std::vector<vertex_descriptor> stops;
    for(vertex_descriptor v : vertices(tmesh))
      if(get(fixed, v)) stops.push_back(v);
    const std::vector<vertex_descriptor> bends =
      hold_sharp ? internal::feature_bend_vertices(tmesh, constrained, vpm, stops, bend_tolerance)
                 : internal::feature_bend_vertices(tmesh, edge_is_feature_map, vpm, stops, bend_tolerance);
    for(vertex_descriptor v : bends) put(fixed, v, true);
    st.bend_vertices_held = bends.size();
  }
  if(hold_sharp) // (always with the adaptive pass)
    uniform_pass(constrained, fixed);
  else
    uniform_pass(edge_is_feature_map, fixed);
  if(adaptive) // (uniform_pass() built the surface's tree)
    reference.build_features();
  st.seconds_uniform = timer.time();
  if(verbose)
    std::cerr << "[remeshing] uniform pass at " << st.target_edge_length << ": "
              << std::distance(faces(tmesh).begin(), faces(tmesh).end()) << " faces (" << st.seconds_uniform << " s)" << std::endl;

  st.faces_uniform = std::size_t(std::distance(faces(tmesh).begin(), faces(tmesh).end()));
  // The far regions, where the uniform pass left the surface farther than 70% of the tolerance from the
  // input (a tip narrower than the edge length cut off, a bend tighter than it), remeshed again at half the
  // length, projecting onto the input; in rounds while the largest distance falls
  if(refine_rounds > 0)
  {
    CGAL::Real_timer far_timer;
    far_timer.start();
    auto project = [&](vertex_descriptor v) { return reference.surface.closest_point(get(vpm, v)); };
    double length = st.target_edge_length, previous_largest = 0.;
    for(unsigned round = 0;; ++round)
    {
      // the faces around the vertices where the distance measured on their faces (either way) is too large,
      // but not those of the components remeshed at a shorter length of their own
      auto error = get(CGAL::dynamic_vertex_property_t<double>(), tmesh);
      const double largest = internal::measure_distances(tmesh, vpm, reference, error) / diagonal;
      std::vector<face_descriptor> far;
      for(face_descriptor f : group_faces().large)
        for(vertex_descriptor v : vertices_around_face(halfedge(f, tmesh), tmesh))
          if(get(error, v) > internal::far_region_share * tolerance * diagonal)
          {
            far.push_back(f);
            break;
          }
      std::sort(far.begin(), far.end());
      if(round == 0) st.distance_uniform = largest;
      else st.distance_refined = largest;
      if(verbose)
        std::cerr << "[remeshing] " << (round == 0 ? "after the uniform pass" : "after far-region refinement " + std::to_string(round))
                  << ": largest distance " << largest << " of the diagonal, " << far.size() << " faces farther ("
                  << far_timer.time() << " s)" << std::endl;
      if(far.empty() || round == refine_rounds || (round > 0 && !(largest < previous_largest))) break;
      previous_largest = largest;
      length /= 2.;
      if(hold_sharp)
        PMP::isotropic_remeshing(far, length, tmesh, remeshing_np(constrained, fixed).projection_functor(project));
      else
        PMP::isotropic_remeshing(far, length, tmesh, remeshing_np(edge_is_feature_map, fixed).projection_functor(project));
      ++st.far_region_rounds;
      st.far_region_faces += far.size();
    }
    st.seconds_far_regions = far_timer.time();
  }
  auto size = get(CGAL::dynamic_vertex_property_t<double>(), tmesh);
  {
    // the length of each vertex's component (computed again: the remeshing made new faces)
    const std::vector<double> lengths = internal::component_quad_edge_lengths(tmesh, vpm, component, qlen, resolution);
    for(vertex_descriptor v : vertices(tmesh)) put(size, v, st.target_edge_length);
    for(face_descriptor f : faces(tmesh))
      for(vertex_descriptor v : vertices_around_face(halfedge(f, tmesh), tmesh))
        put(size, v, lengths[get(component, f)] / 2.);
  }
  st.min_size = st.smallest_target_edge_length;
  st.max_size = st.target_edge_length;
  if(hold_sharp)
  {
    timer.reset();
    if(adaptive)
      adaptive_pass(tmesh, vpm, constrained, fixed, size, reference, line_points, diagonal, tolerance, iterations,
                    st, verbose);
    // features again: the constrained edges that lie on an input feature line rather than on a held sharp edge
    {
      typedef typename GT::Segment_3 Segment;
      typedef CGAL::AABB_segment_primitive<GT, typename std::vector<Segment>::const_iterator> Prim;
      typedef CGAL::AABB_tree<CGAL::AABB_traits<GT, Prim>> Seg_tree;
      const std::vector<Segment> feature_segments(reference.feature_segments.begin(),
                                                  reference.feature_segments.begin() +
                                                    std::ptrdiff_t(input_feature_segments));
      Seg_tree ftree(feature_segments.begin(), feature_segments.end()), htree(held_segments.begin(), held_segments.end());
      if(!feature_segments.empty()) ftree.accelerate_distance_queries();
      if(!held_segments.empty()) htree.accelerate_distance_queries();
      for(auto e : edges(tmesh))
      {
        bool f = get(constrained, e);
        if(f && !held_segments.empty())
        {
          const auto m = CGAL::midpoint(get(vpm, source(halfedge(e, tmesh), tmesh)), get(vpm, target(halfedge(e, tmesh), tmesh)));
          f = !feature_segments.empty() && CGAL::to_double(ftree.squared_distance(m)) <= CGAL::to_double(htree.squared_distance(m));
        }
        put(edge_is_feature_map, e, f || is_border(e, tmesh));
      }
    }
    if(adaptive) st.seconds_adaptive = timer.time();
    if(verbose && adaptive)
      std::cerr << "[remeshing] adaptive pass: " << std::distance(faces(tmesh).begin(), faces(tmesh).end())
                << " faces, distance " << st.distance_after << " of the diagonal, "
                << st.adaptive_rounds << " refinements (" << st.seconds_adaptive << " s)" << std::endl;
  }

  timer.reset();
  std::vector<vertex_descriptor> inserted;
  st.split_vertices = internal::split_feature_faces(tmesh, vpm, edge_is_feature_map, reference.surface, &inserted);
  for(vertex_descriptor v : inserted)
  {
    double s = 0.;
    int n = 0;
    for(vertex_descriptor w : vertices_around_target(halfedge(v, tmesh), tmesh))
      if(std::find(inserted.begin(), inserted.end(), w) == inserted.end()) { s += get(size, w); ++n; }
    put(size, v, n ? s / n : st.target_edge_length);
  }
  if constexpr(has_sizing_map)
    for(vertex_descriptor v : vertices(tmesh)) put(sizing_out, v, get(size, v));
  st.seconds_split = timer.time();

  if constexpr(has_corner_map)
    for(vertex_descriptor v : vertices(tmesh)) put(given_corners, v, bool(get(vcm, v)));

  st.vertices_after = std::size_t(std::distance(vertices(tmesh).begin(), vertices(tmesh).end()));
  st.faces_after = std::size_t(std::distance(faces(tmesh).begin(), faces(tmesh).end()));
  std::tie(st.min_angle_after, st.mean_angle_after) = internal::triangle_angles(tmesh, vpm);
  for(auto e : edges(tmesh))
    if(get(edge_is_feature_map, e)) ++st.feature_edges_after;
  st.seconds = total.time();
  if(verbose)
    std::cerr << "[remeshing] " << st.vertices_after << " vertices, " << st.faces_after << " faces, min angle "
              << st.min_angle_before << " -> " << st.min_angle_after << " degrees, " << st.feature_edges_after
              << " feature edges (" << st.seconds << " s)" << std::endl;
  return st;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_REMESH_FOR_QUADRANGULATION_H
