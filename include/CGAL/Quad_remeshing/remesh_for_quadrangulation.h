// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Feature-preserving uniform then adaptive triangle remeshing before the cross field (paper, 4.2-4.3),
// and the default density of the quad mesh.

#ifndef CGAL_QUAD_REMESHING_REMESH_FOR_QUADRANGULATION_H
#define CGAL_QUAD_REMESHING_REMESH_FOR_QUADRANGULATION_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/features/feature_graph.h>
#include <CGAL/Quad_remeshing/internal/remeshing/remeshing_helpers.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <vector>

/// if `false`, remesh_for_quadrangulation() does the uniform pass only (`bool`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(adaptive_remeshing_t, adaptive_remeshing, adaptive_remeshing)

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
    sph = std::cbrt(CGAL_PI) * std::pow(6. * v, 2. / 3.) / area;
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

/*!
  \ingroup PkgQuadRemeshingRef
  Remeshes a triangle mesh for the cross field and the quad layout, keeping every feature line.

  Pass 1 is a uniform isotropic remeshing at half the quad edge length. Pass 2 (`adaptive_remeshing`,
  experimental and off by default, see below) gives each face a length multiplier from the radius ratio
  (2 inradius / circumradius) of the pass-1 triangles around it, mapped linearly to [0.3, 3] from the
  10th percentile (the worst 10% get 0.3) to the best value. CGAL 5.5's `isotropic_remeshing()` has no
  sizing field, so the multipliers are rounded to five levels (0.3, 0.55, 1, 1.75, 3) and each level's
  faces are remeshed by one call restricted to them.

  Both passes call `CGAL::Polygon_mesh_processing::isotropic_remeshing()` (split, collapse, flip,
  tangential relaxation, projection onto the input) with the feature edges as constraints: a feature
  edge is split at its midpoint and never flipped; a feature vertex never moves (no 1-D relaxation), so
  splits stay on the feature polyline; feature edges may be collapsed along their line, which removes a
  vertex of the line (on a curved line the new edge is a chord of the old two), never across it;
  feature corners are never removed nor moved.

  Finally (paper, Figure 5), a face whose three edges are features gets a centre vertex, and every
  non-feature edge joining two feature vertices is split at its midpoint (projected on the input), so
  that no face has more than one feature edge and no non-feature edge joins two feature vertices.

  Every component is remeshed, whatever its size, and keeps its features. Memory stays proportional to
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
    \cgalParamNBegin{adaptive_remeshing}
      \cgalParamDescription{if `true`, the adaptive pass runs after the uniform one. Experimental, hence
                            off by default: with five levels remeshed one call each, the level borders
                            get split from both sides and, on fandisk, the result has near-degenerate
                            triangles and a larger distance to the input than the uniform pass alone}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{iterations of each isotropic remeshing pass}
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
  @throws std::invalid_argument if `tmesh` is not a triangle mesh or `quad_edge_length` is not positive
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
  typedef typename GT::Triangle_3 Triangle_3;
  typedef typename std::vector<Triangle_3>::const_iterator Tri_iterator;
  typedef CGAL::AABB_triangle_primitive<GT, Tri_iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GT, Primitive>> Tree;

  CGAL::Real_timer total;
  total.start();
  if(!CGAL::is_triangle_mesh(tmesh))
    throw std::invalid_argument("remesh_for_quadrangulation: the input is not a triangle mesh");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_property_map(CGAL::vertex_point, tmesh));
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const bool adaptive = choose_parameter(get_parameter(np, internal_np::adaptive_remeshing), false);
  const unsigned iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 5u);

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

  std::tie(st.min_angle_before, st.mean_angle_before) = internal::triangle_angles(tmesh, vpm);
  for(auto e : edges(tmesh))
  {
    if(is_border(e, tmesh)) put(edge_is_feature_map, e, true);
    if(get(edge_is_feature_map, e)) ++st.feature_edges_before;
  }

  // copy of the input for the projection of inserted midpoints
  std::vector<Triangle_3> input;
  input.reserve(st.faces_before);
  for(face_descriptor f : faces(tmesh))
  {
    const auto h = halfedge(f, tmesh);
    input.emplace_back(get(vpm, source(h, tmesh)), get(vpm, target(h, tmesh)), get(vpm, target(next(h, tmesh), tmesh)));
  }

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

  auto remesh_np = CGAL::parameters::number_of_iterations(iterations)
                     .edge_is_constrained_map(edge_is_feature_map)
                     .vertex_is_constrained_map(vcm)
                     .protect_constraints(false)
                     .collapse_constraints(true)
                     .relax_constraints(false)
                     .vertex_point_map(vpm);

  CGAL::Real_timer timer;
  timer.start();
  PMP::isotropic_remeshing(faces(tmesh), st.target_edge_length, tmesh, remesh_np);
  st.seconds_uniform = timer.time();
  if(verbose)
    std::cerr << "[remeshing] uniform pass at " << st.target_edge_length << ": "
              << std::distance(faces(tmesh).begin(), faces(tmesh).end()) << " faces (" << st.seconds_uniform << " s)" << std::endl;

  if(adaptive)
  {
    timer.reset();
    auto label = get(CGAL::dynamic_face_property_t<int>(), tmesh);
    internal::sizing_buckets(tmesh, vpm, label);
    // A level's faces are collected just before its call: the calls on other levels split faces across
    // their border, and a new face may take the slot (and label) of a removed one. Such a face is simply
    // left as it is; 0 marks a face that no later call takes.
    for(std::size_t b = 0; b < internal::sizing_levels().size(); ++b)
    {
      std::vector<face_descriptor> range;
      for(face_descriptor f : faces(tmesh))
        if(get(label, f) == int(b + 1)) range.push_back(f);
      for(face_descriptor f : range) put(label, f, 0);
      if(range.empty() || internal::sizing_levels()[b] == 1.) continue;
      // one patch id for all faces: CGAL 5.5 computes the ids of a face range's feature-bounded patches
      // only inside the range and fails on a border face outside it
      PMP::isotropic_remeshing(range, st.target_edge_length * internal::sizing_levels()[b], tmesh,
                               remesh_np.face_patch_map(CGAL::Constant_property_map<face_descriptor, int>(0))
                                        .collapse_constraints(true));
      for(face_descriptor f : faces(tmesh))
        if(get(label, f) <= int(b + 1)) put(label, f, 0);
    }
    st.seconds_adaptive = timer.time();
    if(verbose)
      std::cerr << "[remeshing] adaptive pass: " << std::distance(faces(tmesh).begin(), faces(tmesh).end()) << " faces (" << st.seconds_adaptive
                << " s)" << std::endl;
  }

  timer.reset();
  Tree tree(input.begin(), input.end());
  tree.accelerate_distance_queries();
  st.split_vertices = internal::split_feature_faces(tmesh, vpm, edge_is_feature_map, tree);
  st.seconds_split = timer.time();

  if constexpr(has_corner_map)
  {
    for(vertex_descriptor v : vertices(tmesh)) put(given_corners, v, false);
    for(vertex_descriptor v : corners) put(given_corners, v, true);
  }

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
