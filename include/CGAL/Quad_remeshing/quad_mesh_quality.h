// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality of a quad mesh (regularity, shape, validity, topology) and its fidelity to the input
// triangle mesh (sampled Hausdorff distance, coverage of the input's feature lines).

#ifndef CGAL_QUAD_REMESHING_QUAD_MESH_QUALITY_H
#define CGAL_QUAD_REMESHING_QUAD_MESH_QUALITY_H

#include <CGAL/Quad_remeshing/internal/bbox_diagonal.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/quality/distances.h>
#include <CGAL/Quad_remeshing/internal/quality/soup_figures.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

/// distance under which an input feature sample counts as covered by an output edge, as a
/// fraction of the input's bounding-box diagonal (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(feature_coverage_tolerance_t, feature_coverage_tolerance, feature_coverage_tolerance)

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `quad_mesh_quality()` and `polygon_soup_quality()`. Counts refer to the polygons as
  given (no repair), so that a defect of an output file cannot be hidden.
*/
struct Quad_mesh_quality
{
  std::size_t vertices = 0;              ///< vertices referenced by a face (V)
  std::size_t unreferenced_vertices = 0; ///< vertices no face refers to
  std::size_t faces = 0;                 ///< F
  std::size_t edges = 0;                 ///< unique undirected edges (E)
  std::size_t triangles = 0;             ///< faces of degree 3
  std::size_t quads = 0;                 ///< faces of degree 4
  std::size_t other_faces = 0;           ///< faces of any other degree
  bool pure_quad = false;                ///< every face is a quad (and there is one)
  std::size_t non_manifold_edges = 0;    ///< edges with more than two faces
  std::size_t non_manifold_vertices = 0; ///< vertices whose faces form more than one edge-connected fan
  bool manifold = false;                 ///< no non-manifold edge and no non-manifold vertex
  std::size_t inconsistent_edges = 0;    ///< two-face edges both faces traverse in the same direction
  std::size_t degenerate_faces = 0;      ///< fewer than 3 vertices, a repeated index or position, or zero area
  std::size_t duplicate_position_vertices = 0; ///< referenced vertices sharing their position with another one
  bool valid = false;                    ///< pure quad, manifold and without degenerate faces
  std::size_t boundary_edges = 0;        ///< edges with one face
  std::size_t interior_vertices = 0;     ///< referenced vertices on no boundary edge
  std::size_t boundary_vertices = 0;     ///< vertices on a boundary edge
  std::size_t irregular_vertices = 0;    ///< interior vertices whose valence is not 4 (I)
  std::size_t irregular_boundary_vertices = 0; ///< boundary vertices whose valence is not 2 or 3
  std::map<std::size_t, std::size_t> interior_valence_histogram; ///< valence -> number of interior vertices
  std::map<std::size_t, std::size_t> boundary_valence_histogram; ///< valence -> number of boundary vertices
  double angle_deviation = 0.;           ///< AD: mean |corner angle - 90| over quad corners, degrees (reflex corners count as 360 - angle)
  double max_angle_deviation = 0.;       ///< the largest such deviation, degrees
  double mean_edge_length = 0.;          ///< over unique edges
  double min_edge_length = 0.;           ///< over unique edges
  double max_edge_length = 0.;           ///< over unique edges
  double edge_length_deviation = 0.;     ///< ED: mean |length - mean length| in percent of the mean length
  double mean_scaled_jacobian = 0.;      ///< mean of the quads' scaled Jacobians (0 without quads)
  double min_scaled_jacobian = 0.;       ///< minimum of the quads' scaled Jacobians (0 without quads)
  std::size_t non_positive_scaled_jacobian = 0; ///< quads with scaled Jacobian <= 0 (inverted, concave, bow-tie or collapsed)
  double non_positive_scaled_jacobian_fraction = 0.; ///< their share of the quads
  /// quads flipped over in the surface: the normal of their diagonals is turned by more than 120 degrees from
  /// that of every quad sharing an edge with them (consistently oriented quads with a normal; a quad with no
  /// such neighbour does not count). Convex, such a quad has a positive scaled Jacobian, which is measured in
  /// its own plane, but it is inverted for any use of the mesh.
  std::size_t flipped_quads = 0;
  long euler_characteristic = 0;         ///< V - E + F
  std::size_t components = 0;            ///< faces connected through shared edges
  std::size_t boundary_loops = 0;        ///< connected components of the boundary edges
  double seconds = 0.;                   ///< time spent

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["vertices"] = vertices;
    r["unreferenced_vertices"] = unreferenced_vertices;
    r["faces"] = faces;
    r["edges"] = edges;
    r["triangles"] = triangles;
    r["quads"] = quads;
    r["other_faces"] = other_faces;
    r["pure_quad"] = pure_quad;
    r["non_manifold_edges"] = non_manifold_edges;
    r["non_manifold_vertices"] = non_manifold_vertices;
    r["manifold"] = manifold;
    r["inconsistent_edges"] = inconsistent_edges;
    r["degenerate_faces"] = degenerate_faces;
    r["duplicate_position_vertices"] = duplicate_position_vertices;
    r["valid"] = valid;
    r["boundary_edges"] = boundary_edges;
    r["interior_vertices"] = interior_vertices;
    r["boundary_vertices"] = boundary_vertices;
    r["irregular_vertices"] = irregular_vertices;
    r["irregular_boundary_vertices"] = irregular_boundary_vertices;
    Report& hi = r["interior_valence_histogram"] = Report::object();
    for(const auto& kv : interior_valence_histogram) hi[std::to_string(kv.first)] = kv.second;
    Report& hb = r["boundary_valence_histogram"] = Report::object();
    for(const auto& kv : boundary_valence_histogram) hb[std::to_string(kv.first)] = kv.second;
    r["angle_deviation"] = angle_deviation;
    r["max_angle_deviation"] = max_angle_deviation;
    r["mean_edge_length"] = mean_edge_length;
    r["min_edge_length"] = min_edge_length;
    r["max_edge_length"] = max_edge_length;
    r["edge_length_deviation"] = edge_length_deviation;
    r["mean_scaled_jacobian"] = mean_scaled_jacobian;
    r["min_scaled_jacobian"] = min_scaled_jacobian;
    r["non_positive_scaled_jacobian"] = non_positive_scaled_jacobian;
    r["non_positive_scaled_jacobian_fraction"] = non_positive_scaled_jacobian_fraction;
    r["flipped_quads"] = flipped_quads;
    r["euler_characteristic"] = euler_characteristic;
    r["components"] = components;
    r["boundary_loops"] = boundary_loops;
    r["seconds"] = seconds;
    return r;
  }
};

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `feature_fidelity()`. Distances are fractions of the bounding-box diagonal of the
  input triangle mesh.
*/
struct Feature_fidelity
{
  double bbox_diagonal = 0.;             ///< diagonal of the input's bounding box (absolute units)
  double hausdorff_max = 0.;             ///< larger of the two one-sided maxima
  double hausdorff_mean = 0.;            ///< mean over the area samples of both directions
  double hausdorff_rms = 0.;             ///< root mean square over the area samples of both directions
  double input_to_output_max = 0.;       ///< one-sided maximum, input samples to the output surface
  double output_to_input_max = 0.;       ///< one-sided maximum, output samples to the input surface
  std::array<double, 3> input_to_output_max_point = {{0., 0., 0.}}; ///< the input point farthest from the output (absolute coordinates)
  std::array<double, 3> output_to_input_max_point = {{0., 0., 0.}}; ///< the output point farthest from the input (absolute coordinates)
  std::size_t input_samples = 0;         ///< points sampled on the input (vertices and area)
  std::size_t output_samples = 0;        ///< points sampled on the output (vertices and area)
  double feature_length = 0.;            ///< total length of the input's feature edges (absolute units)
  double coverage_tolerance = 0.;        ///< the tolerance of `feature_coverage` (fraction of the diagonal)
  double feature_coverage = 1.;          ///< length-weighted fraction of feature samples within the tolerance of an output edge
  double feature_coverage_tight = 1.;    ///< the same within 0.1% of the diagonal
  double feature_coverage_loose = 1.;    ///< the same within 1% of the diagonal
  double feature_max_distance = 0.;      ///< largest distance from a feature sample to the output edges
  std::array<double, 3> feature_max_point = {{0., 0., 0.}}; ///< the feature sample farthest from the output edges (absolute coordinates)
  double feature_mean_distance = 0.;     ///< length-weighted mean of those distances
  double output_feature_length = 0.;     ///< total length of the output's own feature edges, found with the same rule as the input's (absolute units)
  double output_features_on_input_features = 1.; ///< length-weighted fraction of the output's feature edges within the tolerance of an input feature edge (1 - the share of spurious creases)
  double seconds = 0.;                   ///< time spent

  /// the figures as a report record
  Report report() const
  {
    auto point_report = [](const std::array<double, 3>& p) {
      Report a = Report::array();
      for(double c : p) a.push_back(c);
      return a;
    };
    Report r = Report::object();
    r["bbox_diagonal"] = bbox_diagonal;
    r["hausdorff_max"] = hausdorff_max;
    r["hausdorff_mean"] = hausdorff_mean;
    r["hausdorff_rms"] = hausdorff_rms;
    r["input_to_output_max"] = input_to_output_max;
    r["output_to_input_max"] = output_to_input_max;
    r["input_to_output_max_point"] = point_report(input_to_output_max_point);
    r["output_to_input_max_point"] = point_report(output_to_input_max_point);
    r["input_samples"] = input_samples;
    r["output_samples"] = output_samples;
    r["feature_length"] = feature_length;
    r["coverage_tolerance"] = coverage_tolerance;
    r["feature_coverage"] = feature_coverage;
    r["feature_coverage_0.1%"] = feature_coverage_tight;
    r["feature_coverage_1%"] = feature_coverage_loose;
    r["feature_max_distance"] = feature_max_distance;
    r["feature_max_point"] = point_report(feature_max_point);
    r["feature_mean_distance"] = feature_mean_distance;
    r["output_feature_length"] = output_feature_length;
    r["output_features_on_input_features"] = output_features_on_input_features;
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {
namespace quality {

template <typename PolygonMesh, typename VPM, typename Point_3>
void mesh_to_soup(const PolygonMesh& pmesh, VPM vpm, std::vector<Point_3>& points, Index_polygons& polygons)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  std::unordered_map<vertex_descriptor, std::size_t> index;
  // sized up front: grown by doubling, these arrays and their copies set the peak of the measure
  index.reserve(std::size_t(num_vertices(pmesh)));
  points.reserve(points.size() + std::size_t(num_vertices(pmesh)));
  polygons.reserve(polygons.size() + std::size_t(num_faces(pmesh)));
  for(vertex_descriptor v : vertices(pmesh))
  {
    index.emplace(v, points.size());
    points.push_back(get(vpm, v));
  }
  for(auto f : faces(pmesh))
  {
    const auto around = vertices_around_face(halfedge(f, pmesh), pmesh);
    polygons.emplace_back();
    polygons.back().reserve(std::size_t(std::distance(around.begin(), around.end())));
    for(vertex_descriptor v : around) polygons.back().push_back(index.at(v));
  }
}

inline void print_summary(const Quad_mesh_quality& q)
{
  std::cerr << "[quality] V=" << q.vertices << " F=" << q.faces << " I=" << q.irregular_vertices
            << " AD=" << q.angle_deviation << " ED=" << q.edge_length_deviation << " SJ=" << q.mean_scaled_jacobian
            << " minSJ=" << q.min_scaled_jacobian << " pure_quad=" << q.pure_quad << " valid=" << q.valid << ", "
            << q.seconds << " s\n";
}

inline Quad_mesh_quality to_quality(const Soup_figures& s)
{
  Quad_mesh_quality q;
  q.vertices = s.vertices;
  q.unreferenced_vertices = s.unreferenced_vertices;
  q.faces = s.faces;
  q.edges = s.edges;
  q.triangles = s.triangles;
  q.quads = s.quads;
  q.other_faces = s.other_faces;
  q.pure_quad = s.faces > 0 && s.quads == s.faces;
  q.non_manifold_edges = s.non_manifold_edges;
  q.non_manifold_vertices = s.non_manifold_vertices;
  q.manifold = s.non_manifold_edges == 0 && s.non_manifold_vertices == 0;
  q.inconsistent_edges = s.inconsistent_edges;
  q.degenerate_faces = s.degenerate_faces;
  q.duplicate_position_vertices = s.duplicate_position_vertices;
  q.valid = q.pure_quad && q.manifold && s.degenerate_faces == 0;
  q.boundary_edges = s.boundary_edges;
  q.interior_vertices = s.interior_vertices;
  q.boundary_vertices = s.boundary_vertices;
  q.irregular_vertices = s.irregular_vertices;
  q.irregular_boundary_vertices = s.irregular_boundary_vertices;
  q.interior_valence_histogram = s.interior_valences;
  q.boundary_valence_histogram = s.boundary_valences;
  q.angle_deviation = s.angle_deviation;
  q.max_angle_deviation = s.max_angle_deviation;
  q.mean_edge_length = s.mean_edge_length;
  q.min_edge_length = s.min_edge_length;
  q.max_edge_length = s.max_edge_length;
  q.edge_length_deviation = s.edge_length_deviation;
  q.mean_scaled_jacobian = s.mean_scaled_jacobian;
  q.min_scaled_jacobian = s.min_scaled_jacobian;
  q.non_positive_scaled_jacobian = s.non_positive_scaled_jacobian;
  q.non_positive_scaled_jacobian_fraction = s.quads > 0 ? double(s.non_positive_scaled_jacobian) / double(s.quads) : 0.;
  q.flipped_quads = s.flipped_quads;
  q.euler_characteristic = s.euler_characteristic;
  q.components = s.components;
  q.boundary_loops = s.boundary_loops;
  return q;
}

// Newell (vector area) normal of a face, robust for non-planar polygons; null for a zero-area face.
template <typename PolygonMesh, typename VPM, typename K>
typename K::Vector_3 newell_normal(typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                                   const PolygonMesh& pmesh, VPM vpm, const K&)
{
  double n[3] = {0., 0., 0.};
  const auto h0 = halfedge(f, pmesh);
  for(auto h : halfedges_around_face(h0, pmesh))
  {
    const auto& p = get(vpm, source(h, pmesh));
    const auto& q = get(vpm, target(h, pmesh));
    const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y()), pz = CGAL::to_double(p.z());
    const double qx = CGAL::to_double(q.x()), qy = CGAL::to_double(q.y()), qz = CGAL::to_double(q.z());
    n[0] += (py - qy) * (pz + qz);
    n[1] += (pz - qz) * (px + qx);
    n[2] += (px - qx) * (py + qy);
  }
  return typename K::Vector_3(n[0], n[1], n[2]);
}

// Calls `out(e, is_feature)` for every edge: boundary edges, and edges whose faces' unit Newell
// normals make an angle above `feature_angle` (faces without area never make an edge sharp).
template <typename PolygonMesh, typename NamedParameters, typename Output>
void classify_evaluation_edges(const PolygonMesh& pmesh, const NamedParameters& np, const Output& out)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::const_type VPM;
  typedef typename GetGeomTraits<PolygonMesh, NamedParameters>::type K;
  typedef typename K::Vector_3 Vector_3;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, pmesh));
  const double angle = choose_parameter(get_parameter(np, Quad_remeshing::internal_np::feature_angle), 35.);
  if(!(angle >= 0. && angle <= 180.))
    throw std::invalid_argument("detect_evaluation_feature_edges: feature_angle must be in [0, 180]");
  const double cos_threshold = std::cos(angle * 3.14159265358979323846 / 180.);

  std::unordered_map<typename boost::graph_traits<PolygonMesh>::face_descriptor, Vector_3> normals;
  for(auto f : faces(pmesh))
  {
    Vector_3 n = newell_normal(f, pmesh, vpm, K());
    const double l = std::sqrt(CGAL::to_double(n.squared_length()));
    normals.emplace(f, l > 0. ? n / l : Vector_3(0., 0., 0.));
  }
  for(auto e : edges(pmesh))
  {
    bool feature = is_border(e, pmesh);
    if(!feature)
    {
      const Vector_3& n0 = normals.at(face(halfedge(e, pmesh), pmesh));
      const Vector_3& n1 = normals.at(face(opposite(halfedge(e, pmesh), pmesh), pmesh));
      feature = n0.squared_length() > 0. && n1.squared_length() > 0. && CGAL::to_double(n0 * n1) < cos_threshold;
    }
    out(e, feature);
  }
}

} // namespace quality
} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Computes the quality figures of a polygon soup: counts, faces by degree, validity (non-manifold
  edges and vertices, degenerate faces, orientation), irregular vertices and valence histograms,
  corner-angle deviation, edge-length deviation, Verdict's quad scaled Jacobian, Euler
  characteristic, components and boundary loops. Use it to judge a file that may be non-manifold.

  @tparam PointRange a model of `RandomAccessContainer` whose value type is a point
  @tparam PolygonRange a model of `Range` whose value type is a range of indices into `points`
  @tparam NamedParameters a sequence of named parameters

  @param points the vertex positions
  @param polygons the faces, each a sequence of vertex indices
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{point_map}
      \cgalParamDescription{a property map giving the position of an element of `points`}
      \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type of `PointRange` and whose value type is a CGAL `Point_3`}
      \cgalParamDefault{`CGAL::Identity_property_map`}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether a summary and the timing are printed to `std::cerr`}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @pre every index of `polygons` is smaller than `points.size()` (checked: `std::invalid_argument`)

  The scaled Jacobian of a quad is the minimum over its corners of `n·(e_in × e_out)/(|e_in||e_out|)`
  with `n` the unit normal of `(p2-p0)×(p3-p1)`, clamped to [-1, 1] and 0 for a collapsed quad.
  A corner angle is reflex when the corner turns against `n`; it then counts as 360° minus the angle.
*/
template <typename PointRange, typename PolygonRange,
          typename NamedParameters = parameters::Default_named_parameters>
Quad_mesh_quality polygon_soup_quality(const PointRange& points, const PolygonRange& polygons,
                                       const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GetPointMap<PointRange, NamedParameters>::const_type Point_map;
  typedef typename boost::property_traits<Point_map>::value_type Point_3;
  CGAL::Real_timer timer;
  timer.start();
  const Point_map pm = choose_parameter<Point_map>(get_parameter(np, CGAL::internal_np::point_map));
  std::vector<Point_3> pts;
  pts.reserve(points.size());
  for(const auto& p : points) pts.push_back(get(pm, p));
  internal::quality::Index_polygons polys;
  for(const auto& poly : polygons)
  {
    polys.emplace_back();
    for(const auto& i : poly) polys.back().push_back(std::size_t(i));
  }
  Quad_mesh_quality q = internal::quality::to_quality(internal::quality::compute_soup_figures(pts, polys));
  q.seconds = timer.time();
  if(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false)) internal::quality::print_summary(q);
  return q;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Computes the quality figures of a polygon mesh (see `polygon_soup_quality()` for the figures).
  Faces may have any degree; only quads contribute to the angle and scaled-Jacobian figures.
  A halfedge data structure is manifold by construction: judge a file through
  `polygon_soup_quality()` to detect non-manifold configurations.

  @tparam PolygonMesh a model of `FaceListGraph`
  @tparam NamedParameters a sequence of named parameters

  @param pmesh the mesh
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, pmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether a summary and the timing are printed to `std::cerr`}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @pre every face of `pmesh` has at least one halfedge
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Quad_mesh_quality quad_mesh_quality(const PolygonMesh& pmesh,
                                    const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  CGAL::Real_timer timer;
  timer.start();
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, pmesh));
  std::vector<Point_3> pts;
  internal::quality::Index_polygons polys;
  internal::quality::mesh_to_soup(pmesh, vpm, pts, polys);
  Quad_mesh_quality q = internal::quality::to_quality(internal::quality::compute_soup_figures(pts, polys));
  q.seconds = timer.time();
  if(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false)) internal::quality::print_summary(q);
  return q;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Marks the edges used as feature lines when a remeshing is evaluated: boundary edges, and edges
  whose two faces have Newell normals at an angle larger than `feature_angle`. An edge next to a
  zero-area face is never marked for its angle. This is the definition of the independent
  evaluator the package is checked against; the remesher may choose its features differently.

  @tparam PolygonMesh a model of `FaceListGraph` and `EdgeListGraph`
  @tparam EdgeIsFeatureMap a model of `WritablePropertyMap` with `boost::graph_traits<PolygonMesh>::%edge_descriptor` as key type and `bool` as value type
  @tparam NamedParameters a sequence of named parameters

  @param pmesh the mesh
  @param edge_is_feature receives `true` for each feature edge and `false` for every other edge
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{feature_angle}
      \cgalParamDescription{the angle between face normals, in degrees, above which an edge is a feature}
      \cgalParamType{`double`}
      \cgalParamDefault{`35.`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, pmesh)`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the number of feature edges
  @pre `0 <= feature_angle <= 180` (checked: `std::invalid_argument`)
*/
template <typename PolygonMesh, typename EdgeIsFeatureMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t detect_evaluation_feature_edges(const PolygonMesh& pmesh, EdgeIsFeatureMap edge_is_feature,
                                            const NamedParameters& np = parameters::default_values())
{
  std::size_t n_features = 0;
  internal::quality::classify_evaluation_edges(pmesh, np, [&](auto e, bool feature) {
    put(edge_is_feature, e, feature);
    if(feature) ++n_features;
  });
  return n_features;
}

namespace internal {
namespace quality {

struct Fidelity_settings
{
  std::size_t n_samples;
  unsigned seed;
  unsigned threads;
  double tolerance;
  double crease_angle;
};

// Creases of a soup by the rule of `detect_evaluation_feature_edges()`, plus its non-manifold
// edges; the second normal is flipped when the two faces disagree in orientation.
template <typename K>
std::vector<typename K::Segment_3> soup_creases(const std::vector<typename K::Point_3>& pts,
                                                const Index_polygons& polygons, const Soup_edges& soup_edges,
                                                double angle)
{
  typedef typename K::Vector_3 Vector_3;
  std::vector<Vector_3> normals;
  normals.reserve(polygons.size());
  for(const std::vector<std::size_t>& f : polygons)
  {
    double n[3] = {0., 0., 0.};
    for(std::size_t i = 0; i < f.size(); ++i)
    {
      const auto& p = pts[f[i]];
      const auto& q = pts[f[(i + 1) % f.size()]];
      n[0] += CGAL::to_double((p.y() - q.y()) * (p.z() + q.z()));
      n[1] += CGAL::to_double((p.z() - q.z()) * (p.x() + q.x()));
      n[2] += CGAL::to_double((p.x() - q.x()) * (p.y() + q.y()));
    }
    const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    normals.push_back(l > 0. ? Vector_3(n[0] / l, n[1] / l, n[2] / l) : Vector_3(0., 0., 0.));
  }
  const double cos_threshold = std::cos(angle * 3.14159265358979323846 / 180.);
  std::vector<typename K::Segment_3> creases;
  for(std::size_t e = 0; e < soup_edges.size(); ++e)
  {
    const Edge_uses u = soup_edges.uses(e);
    bool crease = u.size() != 2;
    if(!crease)
    {
      const Vector_3& n0 = normals[u[0].face];
      const Vector_3 n1 = u[0].forward == u[1].forward ? -normals[u[1].face] : normals[u[1].face];
      crease = n0.squared_length() > 0. && n1.squared_length() > 0. && CGAL::to_double(n0 * n1) < cos_threshold;
    }
    if(crease) creases.emplace_back(pts[soup_edges.ends[e].first], pts[soup_edges.ends[e].second]);
  }
  return creases;
}

// Hausdorff distance and feature coverage between an input soup with its feature edges and an
// output soup; both public versions come here so that they measure exactly the same thing.
template <typename K>
Feature_fidelity soup_fidelity(const std::vector<typename K::Point_3>& tpts, const Index_polygons& tpolys,
                               const std::vector<typename K::Segment_3>& features,
                               const std::vector<typename K::Point_3>& qpts, const Index_polygons& qpolys,
                               const Fidelity_settings& settings)
{
  typedef typename K::Point_3 Point_3;
  typedef Tree_types<K> Trees;
  // the triangles and their trees live in the Hausdorff block only, and one tree at a time: they are
  // the largest part of the measure
  typename Trees::Triangles ttris = triangulate_soup<K>(tpts, tpolys);
  typename Trees::Triangles qtris = triangulate_soup<K>(qpts, qpolys);
  if(ttris.empty()) throw std::invalid_argument("feature_fidelity: the input mesh has no face with non-zero area");
  if(qpolys.empty()) throw std::invalid_argument("feature_fidelity: the output mesh has no face");

  Feature_fidelity r;
  CGAL::Bbox_3 box;
  for(const auto& f : tpolys)
    for(std::size_t v : f) box += tpts[v].bbox();
  const double diag = internal::bbox_diagonal(box);
  r.bbox_diagonal = diag;
  r.coverage_tolerance = settings.tolerance;

  // Hausdorff distance, both directions
  {
    One_sided_distance qt;
    {
      typename Trees::Triangle_tree ttree(ttris.begin(), ttris.end());
      ttree.accelerate_distance_queries();
      if(qtris.empty())
      {
        // a flat output has no area: only its vertices can be measured
        qt = one_sided_distance<K>(qpts, qpolys, qtris, ttree, 0, settings.seed, settings.threads);
      }
      else
        qt = one_sided_distance<K>(qpts, qpolys, qtris, ttree, settings.n_samples, settings.seed, settings.threads);
    }
    One_sided_distance tq;
    if(!qtris.empty())
    {
      typename Trees::Triangle_tree qtree(qtris.begin(), qtris.end());
      qtree.accelerate_distance_queries();
      tq = one_sided_distance<K>(tpts, tpolys, ttris, qtree, settings.n_samples, settings.seed, settings.threads);
    }
    else
      tq.max = std::numeric_limits<double>::infinity();
    r.input_to_output_max = tq.max / diag;
    r.output_to_input_max = qt.max / diag;
    r.input_to_output_max_point = tq.max_point;
    r.output_to_input_max_point = qt.max_point;
    r.hausdorff_max = (std::max)(r.input_to_output_max, r.output_to_input_max);
    const std::size_t n_area = tq.area_samples + qt.area_samples;
    if(n_area > 0)
    {
      r.hausdorff_mean = (tq.sum + qt.sum) / double(n_area) / diag;
      r.hausdorff_rms = std::sqrt((tq.sum_squares + qt.sum_squares) / double(n_area)) / diag;
    }
    r.input_samples = tq.area_samples + tq.vertex_samples;
    r.output_samples = qt.area_samples + qt.vertex_samples;
  }
  typename Trees::Triangles().swap(ttris);
  typename Trees::Triangles().swap(qtris);

  // coverage of the feature lines by the output's edges
  {
    typename Trees::Segments qedges;
    const Soup_edges qsoup_edges(qpts.size(), qpolys);
    qedges.reserve(qsoup_edges.size());
    for(const auto& e : qsoup_edges.ends)
    {
      typename K::Segment_3 s(qpts[e.first], qpts[e.second]);
      if(!s.is_degenerate()) qedges.push_back(s);
    }
    std::vector<Point_3> samples;
    std::vector<double> weights;
    sample_segments<K>(features, diag / 1000., samples, weights);
    for(const auto& s : features) r.feature_length += std::sqrt(CGAL::to_double(s.squared_length()));
    if(!samples.empty())
    {
      typename Trees::Segment_tree etree(qedges.begin(), qedges.end());
      etree.accelerate_distance_queries();
      const std::vector<double> d = distances_to_tree(etree, samples, settings.threads);
      const double eps[3] = {0.001 * diag, settings.tolerance * diag, 0.01 * diag};
      double covered[3] = {0., 0., 0.}, total = 0., mean = 0., max = 0.;
      for(std::size_t i = 0; i < samples.size(); ++i)
      {
        if(d[i] > max)
        {
          max = d[i];
          r.feature_max_point = {{CGAL::to_double(samples[i].x()), CGAL::to_double(samples[i].y()),
                                  CGAL::to_double(samples[i].z())}};
        }
        total += weights[i];
        mean += weights[i] * d[i];
        for(int k = 0; k < 3; ++k)
          if(d[i] < eps[k]) covered[k] += weights[i];
      }
      if(total > 0.)
      {
        r.feature_coverage_tight = covered[0] / total;
        r.feature_coverage = covered[1] / total;
        r.feature_coverage_loose = covered[2] / total;
        r.feature_mean_distance = mean / total / diag;
      }
      r.feature_max_distance = max / diag;
    }

    // The output's own creases, found with the same rule, should lie on input features; the
    // others are spurious creases (folds or features the input does not have).
    const typename Trees::Segments qfeatures = soup_creases<K>(qpts, qpolys, qsoup_edges, settings.crease_angle);
    std::vector<Point_3> qsamples;
    std::vector<double> qweights;
    sample_segments<K>(qfeatures, diag / 1000., qsamples, qweights);
    for(const auto& s : qfeatures) r.output_feature_length += std::sqrt(CGAL::to_double(s.squared_length()));
    double near = 0., total = 0.;
    if(!qsamples.empty())
    {
      typename Trees::Segment_tree ftree(features.begin(), features.end());
      if(!features.empty()) ftree.accelerate_distance_queries();
      const std::vector<double> d = distances_to_tree(ftree, qsamples, settings.threads);
      for(std::size_t i = 0; i < qsamples.size(); ++i)
      {
        total += qweights[i];
        if(d[i] < settings.tolerance * diag) near += qweights[i];
      }
    }
    r.output_features_on_input_features = total > 0. ? near / total : 1.;
  }
  return r;
}

template <typename NamedParameters>
Fidelity_settings fidelity_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Fidelity_settings s;
  s.n_samples = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_points_on_faces), std::size_t(100000));
  s.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  s.threads = choose_parameter(get_parameter(np, Quad_remeshing::internal_np::number_of_threads), 1u);
  s.tolerance = choose_parameter(get_parameter(np, Quad_remeshing::internal_np::feature_coverage_tolerance), 0.005);
  s.crease_angle = choose_parameter(get_parameter(np, Quad_remeshing::internal_np::feature_angle), 35.);
  if(!(s.tolerance > 0.)) throw std::invalid_argument("feature_fidelity: feature_coverage_tolerance must be positive");
  if(!(s.crease_angle >= 0. && s.crease_angle <= 180.)) throw std::invalid_argument("feature_fidelity: feature_angle must be in [0, 180]");
  return s;
}

inline void print_summary(const Feature_fidelity& r)
{
  std::cerr << "[quality] hausdorff max " << r.hausdorff_max << " mean " << r.hausdorff_mean
            << " (fractions of the diagonal), feature coverage " << r.feature_coverage
            << ", feature max distance " << r.feature_max_distance << ", " << r.seconds << " s\n";
}

} // namespace quality
} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Measures how well a quad mesh reproduces a triangle mesh: the two-sided Hausdorff distance,
  estimated from the vertices and area-uniform random samples of both surfaces (quads are cut
  along their shorter diagonal), and the coverage of the given feature lines by the edges of
  `qmesh`: feature edges are sampled every 1/1000 of the bounding-box diagonal and each sample's
  distance to the nearest edge of `qmesh` is measured. Conversely, the creases of `qmesh` (found by
  the rule of `detect_evaluation_feature_edges()`) are measured against the feature edges. The samples are drawn with a fixed seed,
  so the result is deterministic and does not depend on the number of threads.

  @tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph`
  @tparam EdgeIsFeatureMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `bool` as value type
  @tparam PolygonMesh a model of `FaceListGraph` and `EdgeListGraph`
  @tparam NamedParameters1 a sequence of named parameters
  @tparam NamedParameters2 a sequence of named parameters

  @param tmesh the input triangle mesh (any polygon mesh is accepted)
  @param edge_is_feature the feature edges of `tmesh` (e.g. from `detect_evaluation_feature_edges()`)
  @param qmesh the output quad mesh (faces of any degree are accepted)
  @param np1 an optional sequence of named parameters among the ones listed below
  @param np2 an optional sequence of named parameters for `qmesh`: `vertex_point_map`

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{a model of `Kernel`}
      \cgalParamDefault{a \cgalFootnote{See `GetGeomTraits`.} kernel deduced from the point type}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_points_on_faces}
      \cgalParamDescription{the number of random area samples in each direction (vertices are sampled as well)}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{`100000`}
    \cgalParamNEnd
    \cgalParamNBegin{random_seed}
      \cgalParamDescription{the seed of the area sampling}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_coverage_tolerance}
      \cgalParamDescription{distance, as a fraction of the input's bounding-box diagonal, under which a feature sample is covered}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.005`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_angle}
      \cgalParamDescription{the angle of `detect_evaluation_feature_edges()` used to find the output's own creases, in degrees}
      \cgalParamType{`double`}
      \cgalParamDefault{`35.`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_threads}
      \cgalParamDescription{threads for the distance queries}
      \cgalParamType{`unsigned`}
      \cgalParamDefault{`1`}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether the figures and the timing are printed to `std::cerr`}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @pre `tmesh` has a face with non-zero area and `qmesh` has a face (checked: `std::invalid_argument`)
  @pre `feature_coverage_tolerance > 0` (checked: `std::invalid_argument`)
*/
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename PolygonMesh,
          typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Feature_fidelity feature_fidelity(const TriangleMesh& tmesh, EdgeIsFeatureMap edge_is_feature,
                                  const PolygonMesh& qmesh,
                                  const NamedParameters1& np1 = parameters::default_values(),
                                  const NamedParameters2& np2 = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters1>::const_type TVPM;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters2>::const_type QVPM;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters1>::type K;
  typedef typename K::Point_3 Point_3;

  CGAL::Real_timer timer;
  timer.start();
  const TVPM tvpm = choose_parameter(get_parameter(np1, CGAL::internal_np::vertex_point),
                                     get_const_property_map(CGAL::vertex_point, tmesh));
  const QVPM qvpm = choose_parameter(get_parameter(np2, CGAL::internal_np::vertex_point),
                                     get_const_property_map(CGAL::vertex_point, qmesh));
  const internal::quality::Fidelity_settings settings = internal::quality::fidelity_settings(np1);

  std::vector<Point_3> tpts, qpts;
  internal::quality::Index_polygons tpolys, qpolys;
  internal::quality::mesh_to_soup(tmesh, tvpm, tpts, tpolys);
  internal::quality::mesh_to_soup(qmesh, qvpm, qpts, qpolys);
  std::vector<typename K::Segment_3> features;
  for(auto e : edges(tmesh))
    if(get(edge_is_feature, e)) features.emplace_back(get(tvpm, source(e, tmesh)), get(tvpm, target(e, tmesh)));
  Feature_fidelity r = internal::quality::soup_fidelity<K>(tpts, tpolys, features, qpts, qpolys, settings);
  r.seconds = timer.time();
  if(choose_parameter(get_parameter(np1, CGAL::internal_np::verbose), false)) internal::quality::print_summary(r);
  return r;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Same as `feature_fidelity()`, with the output given as a polygon soup, so that an output file
  that is not a valid polygon mesh (non-manifold, inconsistently oriented) can still be measured.
  Non-manifold edges of the soup count as creases.

  @tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph`
  @tparam EdgeIsFeatureMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `bool` as value type
  @tparam PointRange a model of `RandomAccessContainer` whose value type is a point
  @tparam PolygonRange a model of `Range` whose value type is a range of indices into `points`
  @tparam NamedParameters1 a sequence of named parameters
  @tparam NamedParameters2 a sequence of named parameters

  @param tmesh the input triangle mesh
  @param edge_is_feature the feature edges of `tmesh`
  @param points the output's vertex positions
  @param polygons the output's faces, each a sequence of indices into `points`
  @param np1 an optional sequence of named parameters: those of `feature_fidelity()`
  @param np2 an optional sequence of named parameters for the soup: `point_map` (default `CGAL::Identity_property_map`)

  @pre every index of `polygons` is smaller than `points.size()`, `tmesh` has a face with non-zero area and
       `polygons` is not empty (checked: `std::invalid_argument`)
*/
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename PointRange, typename PolygonRange,
          typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Feature_fidelity polygon_soup_feature_fidelity(const TriangleMesh& tmesh, EdgeIsFeatureMap edge_is_feature,
                                               const PointRange& points, const PolygonRange& polygons,
                                               const NamedParameters1& np1 = parameters::default_values(),
                                               const NamedParameters2& np2 = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters1>::const_type TVPM;
  typedef typename GetPointMap<PointRange, NamedParameters2>::const_type Point_map;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters1>::type K;
  typedef typename K::Point_3 Point_3;

  CGAL::Real_timer timer;
  timer.start();
  const TVPM tvpm = choose_parameter(get_parameter(np1, CGAL::internal_np::vertex_point),
                                     get_const_property_map(CGAL::vertex_point, tmesh));
  const Point_map pm = choose_parameter<Point_map>(get_parameter(np2, CGAL::internal_np::point_map));
  const internal::quality::Fidelity_settings settings = internal::quality::fidelity_settings(np1);

  std::vector<Point_3> tpts, qpts;
  internal::quality::Index_polygons tpolys, qpolys;
  internal::quality::mesh_to_soup(tmesh, tvpm, tpts, tpolys);
  for(const auto& p : points) qpts.push_back(get(pm, p));
  for(const auto& poly : polygons)
  {
    qpolys.emplace_back();
    for(const auto& i : poly)
    {
      if(std::size_t(i) >= qpts.size())
        throw std::invalid_argument("polygon_soup_feature_fidelity: a polygon refers to a vertex index out of range");
      qpolys.back().push_back(std::size_t(i));
    }
  }
  std::vector<typename K::Segment_3> features;
  for(auto e : edges(tmesh))
    if(get(edge_is_feature, e)) features.emplace_back(get(tvpm, source(e, tmesh)), get(tvpm, target(e, tmesh)));
  Feature_fidelity r = internal::quality::soup_fidelity<K>(tpts, tpolys, features, qpts, qpolys, settings);
  r.seconds = timer.time();
  if(choose_parameter(get_parameter(np1, CGAL::internal_np::verbose), false)) internal::quality::print_summary(r);
  return r;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_QUAD_MESH_QUALITY_H
