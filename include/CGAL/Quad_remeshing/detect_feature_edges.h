// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Feature-line detection (dihedral angle + erode/dilate) and feature corners.

#ifndef CGAL_QUAD_REMESHING_DETECT_FEATURE_EDGES_H
#define CGAL_QUAD_REMESHING_DETECT_FEATURE_EDGES_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/features/bridge_feature_gaps.h>
#include <CGAL/Quad_remeshing/internal/features/feature_graph.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

/// number of erosion steps followed by as many dilation steps that remove short feature chains (`unsigned`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(feature_erode_dilate_steps_t, feature_erode_dilate_steps, feature_erode_dilate_steps)
/// dihedral angle in degrees above which an edge can close a gap in a feature line (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(feature_gap_angle_t, feature_gap_angle, feature_gap_angle)
/// vertex property map: `true` on feature corners
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(vertex_is_feature_corner_map_t, vertex_is_feature_corner_map, vertex_is_feature_corner_map)
/// turning angle in degrees between consecutive feature edges above which a vertex is a corner (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(feature_corner_angle_t, feature_corner_angle, feature_corner_angle)
/// if `true`, the edges already set in the feature map are kept as they are (no detection) (`bool`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(use_given_feature_edges_t, use_given_feature_edges, use_given_feature_edges)

namespace CGAL {
namespace Quad_remeshing {
namespace internal {
// the default of `feature_gap_angle`: 10 degrees under the feature angle
inline double default_feature_gap_angle(double feature_angle) { return feature_angle - 10.; }
} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `detect_feature_edges()`.
*/
struct Feature_detection_statistics
{
  std::size_t sharp_edges = 0;    ///< non-border edges over the dihedral threshold, before erode/dilate
  std::size_t cap_edges = 0;      ///< sharp edges dropped because they close a cap on the border whose three edges are features
  std::size_t gap_edges = 0;      ///< edges under the dihedral threshold made features to close gaps in feature lines
  std::size_t feature_edges = 0;  ///< feature edges in the result (border edges included)
  std::size_t feature_lines = 0;  ///< chains of feature edges between corners (closed loops count once)
  std::size_t corners = 0;        ///< feature corners
  double seconds = 0.;            ///< time spent

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["sharp_edges"] = sharp_edges;
    r["gap_edges"] = gap_edges;
    r["cap_edges"] = cap_edges;
    r["feature_edges"] = feature_edges;
    r["feature_lines"] = feature_lines;
    r["corners"] = corners;
    r["seconds"] = seconds;
    return r;
  }
};

/*!
  \ingroup PkgQuadRemeshingRef
  Marks the feature edges of a triangle mesh and, optionally, its feature corners.

  An edge is a feature if it is a border edge, or if the angle between the normals of its two faces
  exceeds `feature_angle`. A crease whose dihedral angles waver around the threshold (a coarse fillet, an
  unevenly tessellated rim) then comes out as short pieces; to join them, from every free end of a feature
  chain the cheapest path of at most `feature_erode_dilate_steps` edges whose dihedral angles exceed
  `feature_gap_angle`, each heading within 45 degrees of the end edge's direction, that reaches another
  feature edge becomes feature too (an edge costs its length times `1 + (feature_angle - angle) /
  feature_angle`). Then `feature_erode_dilate_steps` erosion steps remove the free ends of
  feature chains (never an edge incident to a vertex where more than two feature edges meet, never a
  border edge), and as many dilation steps grow the survivors back along the removed edges: chains of
  at most about twice that many edges that touch no other feature vanish, the others are restored.

  A triangle with an angle over 170 degrees (a cap) with a border edge, whose three edges are all
  features, would be a patch thinner than any quad, bounded by lines that its tiny height makes sharp:
  its longest edge stops being a feature (or, if that edge is a border edge, its two other edges do),
  the line then follows the other two edges, within the cap's height.

  A feature corner is a vertex with feature degree 1 (an end) or more than 2 (a junction), or of degree 2
  where the feature line turns by more than `feature_corner_angle`.

  @tparam TriangleMesh a model of `FaceListGraph` and `EdgeListGraph`
  @tparam EdgeIsFeatureMap a model of `ReadWritePropertyMap` with `edge_descriptor` as key and `bool` as value
  @tparam NamedParameters a sequence of named parameters

  @param tmesh the triangle mesh
  @param edge_is_feature_map receives `true` for feature edges and `false` for the others (read
         first if `use_given_feature_edges` is `true`)
  @param np optional named parameters among the ones listed below

  @pre `CGAL::is_triangle_mesh(tmesh)`

  \cgalNamedParamsBegin
    \cgalParamNBegin{feature_angle}
      \cgalParamDescription{dihedral angle in degrees above which an edge is a feature; 180 or more
                            keeps only the border edges}
      \cgalParamType{`double`}
      \cgalParamDefault{35}
    \cgalParamNEnd
    \cgalParamNBegin{feature_gap_angle}
      \cgalParamDescription{dihedral angle in degrees above which an edge can close a gap in a feature line;
                            `feature_angle` or more closes no gap}
      \cgalParamType{`double`}
      \cgalParamDefault{`feature_angle - 10`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_erode_dilate_steps}
      \cgalParamDescription{number of erosion steps, followed by as many dilation steps; also the longest
                            gap, in edges, that `feature_gap_angle` closes}
      \cgalParamType{`unsigned`}
      \cgalParamDefault{4}
    \cgalParamNEnd
    \cgalParamNBegin{use_given_feature_edges}
      \cgalParamDescription{if `true`, the feature set already in `edge_is_feature_map` is kept as is
                            (border edges are added) and only corners and statistics are computed;
                            see `read_feature_edges()`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_corner_angle}
      \cgalParamDescription{turning angle in degrees between two consecutive feature edges above
                            which their common vertex is a corner}
      \cgalParamType{`double`}
      \cgalParamDefault{45}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_is_feature_corner_map}
      \cgalParamDescription{receives `true` on feature corners and `false` elsewhere}
      \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` as key and `bool` as value}
      \cgalParamDefault{unused}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `Point_3` as value}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{a model of `Kernel`}
      \cgalParamDefault{a \cgal Kernel deduced from the point type}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{prints the figures to `std::cerr`, prefixed by `[features]`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the statistics of the detection
  @throws std::invalid_argument if `tmesh` is not a triangle mesh
*/
template <typename TriangleMesh, typename EdgeIsFeatureMap,
          typename NamedParameters = parameters::Default_named_parameters>
Feature_detection_statistics
detect_feature_edges(const TriangleMesh& tmesh, EdgeIsFeatureMap edge_is_feature_map,
                     const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GT::Vector_3 Vector_3;

  CGAL::Real_timer timer;
  timer.start();
  if(!CGAL::is_triangle_mesh(tmesh))
    throw std::invalid_argument("detect_feature_edges: the input is not a triangle mesh");

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const double angle = choose_parameter(get_parameter(np, internal_np::feature_angle), 35.);
  const double gap_angle =
    choose_parameter(get_parameter(np, internal_np::feature_gap_angle), internal::default_feature_gap_angle(angle));
  const unsigned steps = choose_parameter(get_parameter(np, internal_np::feature_erode_dilate_steps), 4u);
  const double corner_angle = choose_parameter(get_parameter(np, internal_np::feature_corner_angle), 45.);
  const bool given = choose_parameter(get_parameter(np, internal_np::use_given_feature_edges), false);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);

  Feature_detection_statistics stats;
  const double cos_thr = std::cos(angle * CGAL_PI / 180.);

  auto face_normal = [&](halfedge_descriptor h) {
    const auto& p = get(vpm, source(h, tmesh));
    const auto& q = get(vpm, target(h, tmesh));
    const auto& r = get(vpm, target(next(h, tmesh), tmesh));
    return gt.construct_cross_product_vector_3_object()(q - p, r - p);
  };

  if(given)
  {
    for(edge_descriptor e : edges(tmesh))
      if(is_border(e, tmesh))
        put(edge_is_feature_map, e, true);
  }
  else
  {
    // the sharp edges: dilation only grows back what erosion removed
    std::vector<edge_descriptor> candidates;
    auto dihedral = get(CGAL::dynamic_edge_property_t<double>(), tmesh);
    for(edge_descriptor e : edges(tmesh))
    {
      bool sharp = false;
      put(dihedral, e, 0.);
      if(is_border(e, tmesh))
        sharp = true;
      else if(angle < 180.)
      {
        const halfedge_descriptor h = halfedge(e, tmesh);
        const Vector_3 n1 = face_normal(h), n2 = face_normal(opposite(h, tmesh));
        const double l = std::sqrt(CGAL::to_double(n1 * n1) * CGAL::to_double(n2 * n2));
        // a degenerate face has no normal: no edge is declared sharp from it
        if(l > 0.)
        {
          const double c = CGAL::to_double(n1 * n2) / l;
          sharp = c < cos_thr;
          put(dihedral, e, std::acos((std::max)(-1., (std::min)(1., c))) * 180. / CGAL_PI);
        }
      }
      put(edge_is_feature_map, e, sharp);
      if(sharp && !is_border(e, tmesh))
      {
        ++stats.sharp_edges;
        candidates.push_back(e);
      }
    }

    // A cap (a triangle with an almost flat angle) on the border whose three edges are all features
    // would be a patch of its own, thinner than any quad: its normal, and so the dihedral angles of
    // its edges, come from its tiny height. Its longest edge stops being a feature (the two others
    // carry the line, within the cap's height); if that edge is a border, its two other edges stop
    // instead. (Caps inside the surface are left alone: on camelhead, the only development mesh with
    // such caps, the rule removed a collapsed quad but the feature coverage fell from 0.943 to 0.923.)
    if(angle < 180.)
    {
      const double cos_flat = std::cos(170. * CGAL_PI / 180.); // an angle over 170 degrees makes a cap
      for(auto f : faces(tmesh))
      {
        const halfedge_descriptor h0 = halfedge(f, tmesh);
        const halfedge_descriptor hs[3] = {h0, next(h0, tmesh), next(next(h0, tmesh), tmesh)};
        bool all = true;
        for(halfedge_descriptor h : hs) all = all && get(edge_is_feature_map, edge(h, tmesh));
        if(!all) continue;
        bool on_border = false;
        for(halfedge_descriptor h : hs) on_border = on_border || is_border(edge(h, tmesh), tmesh);
        if(!on_border) continue;
        // the angle opposite hs[i] is at target(next(hs[i]))
        for(int i = 0; i < 3; ++i)
        {
          const halfedge_descriptor a = hs[(i + 1) % 3], b = hs[(i + 2) % 3]; // a ends at the apex, b leaves it
          const Vector_3 u = get(vpm, source(a, tmesh)) - get(vpm, target(a, tmesh));
          const Vector_3 w = get(vpm, target(b, tmesh)) - get(vpm, source(b, tmesh));
          const double l = std::sqrt(CGAL::to_double(u * u) * CGAL::to_double(w * w));
          if(!(l > 0.) || CGAL::to_double(u * w) / l > cos_flat) continue;
          if(!is_border(edge(hs[i], tmesh), tmesh))
          {
            put(edge_is_feature_map, edge(hs[i], tmesh), false);
            ++stats.cap_edges;
          }
          else if(!is_border(edge(a, tmesh), tmesh) && !is_border(edge(b, tmesh), tmesh))
          {
            put(edge_is_feature_map, edge(a, tmesh), false);
            put(edge_is_feature_map, edge(b, tmesh), false);
            stats.cap_edges += 2;
          }
          break;
        }
      }
    }

    if(angle < 180. && steps > 0 && !candidates.empty())
    {
      const std::vector<edge_descriptor> gaps = internal::bridge_feature_gaps(
        tmesh, edge_is_feature_map, vpm, [&](edge_descriptor e) { return get(dihedral, e); }, gap_angle, angle, steps);
      stats.gap_edges = gaps.size();
      candidates.insert(candidates.end(), gaps.begin(), gaps.end());
    }

    if(steps > 0 && !candidates.empty())
    {
      auto degree = [&](vertex_descriptor v) { return internal::feature_degree(v, tmesh, edge_is_feature_map); };
      // junctions of the detected feature graph are never eroded
      auto junction = get(CGAL::dynamic_vertex_property_t<bool>(), tmesh);
      for(vertex_descriptor v : vertices(tmesh))
        put(junction, v, degree(v) > 2);

      std::vector<edge_descriptor> removed;
      for(unsigned s = 0; s < steps; ++s)
      {
        std::vector<edge_descriptor> to_remove;
        for(edge_descriptor e : candidates)
        {
          if(!get(edge_is_feature_map, e)) continue;
          const vertex_descriptor a = source(halfedge(e, tmesh), tmesh), b = target(halfedge(e, tmesh), tmesh);
          if(get(junction, a) || get(junction, b)) continue;
          if(degree(a) == 1 || degree(b) == 1) to_remove.push_back(e);
        }
        if(to_remove.empty()) break;
        for(edge_descriptor e : to_remove) { put(edge_is_feature_map, e, false); removed.push_back(e); }
      }
      for(unsigned s = 0; s < steps && !removed.empty(); ++s)
      {
        std::vector<edge_descriptor> to_add, rest;
        for(edge_descriptor e : removed)
        {
          const vertex_descriptor a = source(halfedge(e, tmesh), tmesh), b = target(halfedge(e, tmesh), tmesh);
          if(degree(a) > 0 || degree(b) > 0) to_add.push_back(e);
          else rest.push_back(e);
        }
        if(to_add.empty()) break;
        for(edge_descriptor e : to_add) put(edge_is_feature_map, e, true);
        removed.swap(rest);
      }
    }
  }

  std::vector<vertex_descriptor> corner_list;
  const internal::Feature_graph_figures fig =
    internal::feature_corners_and_lines(tmesh, edge_is_feature_map, vpm, corner_angle, corner_list);
  stats.feature_edges = fig.feature_edges;
  stats.feature_lines = fig.feature_lines;
  stats.corners = corner_list.size();

  internal::write_corner_map(tmesh, corner_list, get_parameter(np, internal_np::vertex_is_feature_corner_map));

  stats.seconds = timer.time();
  if(verbose)
    std::cerr << "[features] " << stats.feature_edges << " feature edges (" << stats.gap_edges
              << " closing gaps), " << stats.feature_lines
              << " lines, " << stats.corners << " corners (" << stats.seconds << " s)" << std::endl;
  return stats;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Reads a user-given feature set and marks the matching edges of `tmesh` in `edge_is_feature_map`
  (the other edges are left untouched: set the map to `false` first for a set that replaces detection,
  then call `detect_feature_edges()` with `use_given_feature_edges(true)`).

  Two formats are recognised, line by line (empty lines and lines starting with `#` are skipped):
  - CGAL polylines (`.polylines.txt`): `n x1 y1 z1 ... xn yn zn`; each point must be exactly the position of
    a mesh vertex (as written by the program that wrote the mesh), each pair of consecutive points a mesh edge;
  - vertex-index pairs: `i j`, 0-based indices in the order of `vertices(tmesh)` (for a `Surface_mesh`
    read from a file, the order of the file).

  @tparam TriangleMesh a model of `FaceListGraph`
  @tparam EdgeIsFeatureMap a model of `WritablePropertyMap` with `edge_descriptor` as key and `bool` as value

  @return the number of edges marked
  @throws std::invalid_argument if the file cannot be read, a line is malformed, or a point, vertex
          index or edge does not exist in `tmesh`
*/
template <typename TriangleMesh, typename EdgeIsFeatureMap>
std::size_t read_feature_edges(const std::string& filename, const TriangleMesh& tmesh,
                               EdgeIsFeatureMap edge_is_feature_map)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  std::ifstream in(filename);
  if(!in)
    throw std::invalid_argument("read_feature_edges: cannot open " + filename);
  const auto vpm = get(CGAL::vertex_point, tmesh);
  const std::vector<vertex_descriptor> by_index(vertices(tmesh).begin(), vertices(tmesh).end());
  std::map<std::array<double, 3>, vertex_descriptor> by_point;
  for(vertex_descriptor v : vertices(tmesh))
  {
    const auto& p = get(vpm, v);
    by_point.emplace(std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}}, v);
  }
  std::size_t marked = 0, line_no = 0;
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument("read_feature_edges: " + filename + ", line " + std::to_string(line_no) + ": " + what);
  };
  auto mark = [&](vertex_descriptor a, vertex_descriptor b) {
    const auto he = halfedge(a, b, tmesh);
    if(!he.second) fail("not a mesh edge");
    put(edge_is_feature_map, edge(he.first, tmesh), true);
    ++marked;
  };
  std::string line;
  while(std::getline(in, line))
  {
    ++line_no;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if(first == std::string::npos || line[first] == '#') continue;
    std::istringstream ls(line);
    std::vector<double> values;
    double x;
    while(ls >> x) values.push_back(x);
    if(!ls.eof()) fail("not a list of numbers");
    if(values.size() == 2)
    {
      if(!(values[0] >= 0 && values[1] >= 0 && values[0] < double(by_index.size()) && values[1] < double(by_index.size())))
        fail("vertex index out of range");
      mark(by_index[std::size_t(values[0])], by_index[std::size_t(values[1])]);
      continue;
    }
    const std::size_t n = values.empty() || values[0] < 0 ? 0 : std::size_t(values[0]);
    if(n < 2 || values[0] != double(n) || values.size() != 1 + 3 * n) fail("malformed polyline");
    std::vector<vertex_descriptor> poly;
    for(std::size_t i = 0; i < n; ++i)
    {
      const auto it = by_point.find({{values[1 + 3 * i], values[2 + 3 * i], values[3 + 3 * i]}});
      if(it == by_point.end()) fail("polyline point is not a mesh vertex");
      poly.push_back(it->second);
    }
    for(std::size_t i = 0; i + 1 < poly.size(); ++i)
      mark(poly[i], poly[i + 1]);
  }
  return marked;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_DETECT_FEATURE_EDGES_H
