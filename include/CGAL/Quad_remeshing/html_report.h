// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A self-contained HTML report: an interactive three.js viewer of the stages, histograms, the JSON report.

#ifndef CGAL_QUAD_REMESHING_HTML_REPORT_H
#define CGAL_QUAD_REMESHING_HTML_REPORT_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/cross_field/face_geometry.h>
#include <CGAL/Quad_remeshing/internal/html/viewer_page.h>
#include <CGAL/Quad_remeshing/internal/html/writer.h>
#include <CGAL/Quad_remeshing/internal/quality/soup_figures.h>

#include <CGAL/IO/Color.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/property_map.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

/// directory of the three.js npm package (holding `build/three.module.js`) read by `write_html_report()` (`std::string`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(threejs_directory_t, threejs_directory, threejs_directory)

namespace CGAL {
namespace Quad_remeshing {

/// \ingroup PkgQuadRemeshingRef
/// How a per-face scalar is turned into a colour in the viewer.
enum class Html_color_map
{
  viridis,      ///< perceptually uniform, dark blue (low) to yellow (high)
  red_to_green, ///< red (low, bad) through yellow to green (high, good): quality measures
  blue_to_red   ///< diverging, blue (low) through grey to red (high)
};

/// \ingroup PkgQuadRemeshingRef
/// Polygons of any degree sharing a flat array of points. The face colour is, in order of
/// precedence, `face_colors[f]`, the colour map applied to `face_scalars[f]`, or `color`.
struct Html_polygons
{
  std::vector<std::array<double, 3>> points;      ///< vertex positions
  std::vector<std::vector<std::size_t>> faces;    ///< faces as indices in `points` (at least 3 each)
  std::vector<CGAL::IO::Color> face_colors;       ///< empty or one per face
  std::vector<double> face_scalars;               ///< empty or one per face; NaN is drawn grey
  std::string scalar_name = "value";              ///< shown next to the colour bar
  Html_color_map color_map = Html_color_map::viridis;
  /// range mapped onto the colour map; NaN bounds are taken from the finite scalars
  double scalar_min = std::numeric_limits<double>::quiet_NaN();
  double scalar_max = std::numeric_limits<double>::quiet_NaN();
  CGAL::IO::Color color = CGAL::IO::Color(200, 200, 210); ///< colour without per-face data
  bool wireframe = false;                                 ///< draw the polygon edges too
  CGAL::IO::Color wireframe_color = CGAL::IO::Color(40, 40, 40);
  double opacity = 1.;                                    ///< below 1, the polygons are see-through
};

/// \ingroup PkgQuadRemeshingRef
/// Line segments (feature lines, cross-field crosses, patch boundaries, ...).
struct Html_segments
{
  std::vector<std::array<double, 3>> endpoints; ///< two per segment
  std::vector<CGAL::IO::Color> colors;          ///< empty or one per segment
  CGAL::IO::Color color = CGAL::IO::Color(220, 30, 30); ///< colour when `colors` is empty
};

/// \ingroup PkgQuadRemeshingRef
/// Points drawn as discs of a fixed size on screen (singularities, corners, irregular vertices, ...).
struct Html_points
{
  std::vector<std::array<double, 3>> points;  ///< positions
  std::vector<CGAL::IO::Color> colors;        ///< empty or one per point
  CGAL::IO::Color color = CGAL::IO::Color(20, 20, 200); ///< colour when `colors` is empty
  double size = 9.;                           ///< diameter in pixels
};

/// \ingroup PkgQuadRemeshingRef
/// One line of a layer's legend.
struct Html_legend_entry
{
  std::string label;
  CGAL::IO::Color color;
};

/// \ingroup PkgQuadRemeshingRef
/// A layer of the viewer, shown or hidden as a whole with its check box. Any of its three parts may
/// be empty.
struct Html_layer
{
  std::string name;                       ///< shown in the layer list
  bool visible = true;                    ///< shown when the report opens
  Html_polygons polygons;
  Html_segments segments;
  Html_points points;
  std::vector<Html_legend_entry> legend;  ///< e.g. the colours of valences
};

/// \ingroup PkgQuadRemeshingRef
/// A histogram of `values`, binned when the report is written.
struct Html_histogram
{
  std::string title;
  std::vector<double> values;  ///< non-finite values are ignored
  std::size_t bins = 30;
  /// binned range; NaN bounds are taken from the values
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
};

/// \ingroup PkgQuadRemeshingRef
/// Everything a report shows: the layers of the viewer, histograms, and the JSON report of the run
/// (`"<stage>": {..., "seconds": s}` entries are shown as a timing table, every object as a table).
/// It is independent of any mesh type; the `*_layer()` helpers fill layers from a polygon mesh.
struct Html_report_scene
{
  std::string title = "CGAL Quad_remeshing report";
  std::vector<Html_layer> layers;
  std::vector<Html_histogram> histograms;
  Report report = Report::object();
};

/// \ingroup PkgQuadRemeshingRef
/// Verdict's scaled Jacobian of the quad `f`: the minimum over its corners of
/// `n·(e_prev × e_next)/(|e_prev||e_next|)`, where `n` is the unit vector along
/// `(p2-p0)×(p3-p1)`. It is 1 for a square, below 0 for a concave or inverted corner, and 0 for a quad
/// without a normal or with a zero-length side.
/// @pre `f` has degree 4.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `pmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, pmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
double quad_scaled_jacobian(typename boost::graph_traits<PolygonMesh>::face_descriptor f, const PolygonMesh& pmesh,
                            const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  std::array<Point, 4> p;
  std::size_t n = 0;
  for(auto v : vertices_around_face(halfedge(f, pmesh), pmesh))
  {
    if(n == 4) throw std::invalid_argument("quad_scaled_jacobian: the face is not a quad");
    p[n++] = get(vpm, v);
  }
  if(n != 4) throw std::invalid_argument("quad_scaled_jacobian: the face is not a quad");
  return internal::quality::quad_scaled_jacobian(p);
}

/// \ingroup PkgQuadRemeshingRef
/// A layer holding the faces of `pmesh` (any degree) in the order of `faces(pmesh)`, in one colour.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `pmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, pmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Html_layer polygon_mesh_layer(const std::string& name, const PolygonMesh& pmesh,
                              const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  Html_layer layer;
  layer.name = name;
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), pmesh);
  for(vertex_descriptor v : vertices(pmesh))
  {
    put(index, v, layer.polygons.points.size());
    layer.polygons.points.push_back(internal::html::to_array(get(vpm, v)));
  }
  for(auto f : faces(pmesh))
  {
    std::vector<std::size_t> face;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, pmesh), pmesh)) face.push_back(get(index, v));
    layer.polygons.faces.push_back(std::move(face));
  }
  return layer;
}

/// \ingroup PkgQuadRemeshingRef
/// A layer holding the faces of `pmesh` coloured by the scalar `get(face_scalars, f)` through `color_map`.
/// @tparam FaceScalarMap a readable property map from faces to a number type convertible to `double`
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `pmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, pmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PolygonMesh, typename FaceScalarMap, typename NamedParameters = parameters::Default_named_parameters>
Html_layer scalar_polygon_mesh_layer(const std::string& name, const PolygonMesh& pmesh, FaceScalarMap face_scalars,
                                     const std::string& scalar_name, Html_color_map color_map = Html_color_map::viridis,
                                     const NamedParameters& np = parameters::default_values())
{
  Html_layer layer = polygon_mesh_layer(name, pmesh, np);
  for(auto f : faces(pmesh)) layer.polygons.face_scalars.push_back(double(get(face_scalars, f)));
  layer.polygons.scalar_name = scalar_name;
  layer.polygons.color_map = color_map;
  return layer;
}

/// \ingroup PkgQuadRemeshingRef
/// A layer holding the faces of `pmesh` with its wireframe, each quad coloured by its scaled Jacobian
/// (`quad_scaled_jacobian()`) on the fixed range [-1, 1] from red to green; other faces are grey.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `pmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, pmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Html_layer scaled_jacobian_layer(const std::string& name, const PolygonMesh& pmesh,
                                 const NamedParameters& np = parameters::default_values())
{
  Html_layer layer = polygon_mesh_layer(name, pmesh, np);
  for(auto f : faces(pmesh))
    layer.polygons.face_scalars.push_back(degree(f, pmesh) == 4 ? quad_scaled_jacobian(f, pmesh, np)
                                                                 : std::numeric_limits<double>::quiet_NaN());
  layer.polygons.scalar_name = "scaled Jacobian";
  layer.polygons.color_map = Html_color_map::red_to_green;
  layer.polygons.scalar_min = -1.;
  layer.polygons.scalar_max = 1.;
  layer.polygons.wireframe = true;
  return layer;
}

/// \ingroup PkgQuadRemeshingRef
/// A layer of segments: the edges `e` of `pmesh` with `get(edge_is_feature, e)` true, in `color`.
/// @tparam EdgeIsFeatureMap a readable property map from edges to `bool`
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `pmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, pmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PolygonMesh, typename EdgeIsFeatureMap, typename NamedParameters = parameters::Default_named_parameters>
Html_layer feature_edges_layer(const std::string& name, const PolygonMesh& pmesh, EdgeIsFeatureMap edge_is_feature,
                               CGAL::IO::Color color = CGAL::IO::Color(220, 30, 30),
                               const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  Html_layer layer;
  layer.name = name;
  layer.segments.color = color;
  for(auto e : edges(pmesh))
  {
    if(!get(edge_is_feature, e)) continue;
    layer.segments.endpoints.push_back(internal::html::to_array(get(vpm, source(e, pmesh))));
    layer.segments.endpoints.push_back(internal::html::to_array(get(vpm, target(e, pmesh))));
  }
  return layer;
}

/// \ingroup PkgQuadRemeshingRef
/// The colour the report gives to the valence `valence` of a vertex (shared by the layers of
/// singularities and irregular vertices so that they read alike): blue below 4, red above.
inline CGAL::IO::Color valence_color(std::size_t valence)
{
  switch(valence)
  {
    case 0: case 1: case 2: return CGAL::IO::Color(120, 0, 160);
    case 3: return CGAL::IO::Color(30, 90, 230);
    case 4: return CGAL::IO::Color(120, 120, 120);
    case 5: return CGAL::IO::Color(240, 130, 20);
    case 6: return CGAL::IO::Color(220, 20, 20);
    default: return CGAL::IO::Color(120, 0, 20);
  }
}

/// \ingroup PkgQuadRemeshingRef
/// A layer of points: the irregular vertices of the quad mesh `pmesh`, i.e. the interior vertices whose
/// valence is not 4, coloured by valence (`valence_color()`), with a legend giving their counts.
/// Boundary vertices are not marked: their ideal valence depends on the boundary angle.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `pmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, pmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Html_layer irregular_vertices_layer(const std::string& name, const PolygonMesh& pmesh,
                                    const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  Html_layer layer;
  layer.name = name;
  std::map<std::size_t, std::size_t> counts;
  for(auto v : vertices(pmesh))
  {
    if(halfedge(v, pmesh) == boost::graph_traits<PolygonMesh>::null_halfedge() || is_border(v, pmesh)) continue;
    const std::size_t valence = degree(v, pmesh);
    if(valence == 4) continue;
    ++counts[valence];
    layer.points.points.push_back(internal::html::to_array(get(vpm, v)));
    layer.points.colors.push_back(valence_color(valence));
  }
  for(const auto& c : counts)
    layer.legend.push_back({"valence " + std::to_string(c.first) + ": " + std::to_string(c.second), valence_color(c.first)});
  return layer;
}

/// \ingroup PkgQuadRemeshingRef
/// The `i`-th of a sequence of distinct, saturated colours (golden-ratio steps of the hue, alternating
/// lightness), for categorical data such as patch ids: neighbouring indices get far apart hues.
inline CGAL::IO::Color categorical_color(std::size_t i)
{
  const double h = std::fmod(0.11 + 0.6180339887498949 * double(i), 1.) * 6.;
  const double s = 0.55, l = (i % 3 == 0) ? 0.52 : (i % 3 == 1 ? 0.66 : 0.42);
  const double c = (1. - std::abs(2. * l - 1.)) * s, x = c * (1. - std::abs(std::fmod(h, 2.) - 1.)), m = l - c / 2.;
  const int sector = int(h) % 6;
  const double r = (sector == 0 || sector == 5) ? c : (sector == 1 || sector == 4) ? x : 0.;
  const double g = (sector == 1 || sector == 2) ? c : (sector == 0 || sector == 3) ? x : 0.;
  const double b = (sector == 3 || sector == 4) ? c : (sector == 2 || sector == 5) ? x : 0.;
  const auto byte = [&](double v) { return static_cast<unsigned char>(std::lround(255. * (v + m))); };
  return CGAL::IO::Color(byte(r), byte(g), byte(b));
}

/// \ingroup PkgQuadRemeshingRef
/// A layer of segments showing the cross field of the triangle mesh `tmesh`: a cross at the centroid of
/// every face, made of the field direction `get(face_field, f)` projected into the face plane and its
/// rotation by a quarter turn about the face normal, each arm `0.3` times the mean edge length of the
/// face. The first direction is drawn in `color`, the second one a little darker, so that the crosses
/// read as crosses and not as stars. Faces with a null field or a degenerate normal get no cross.
///
/// The page holds two segments per drawn face; on a mesh with more than `max_crosses` faces, only every
/// `ceil(num_faces / max_crosses)`-th face in the order of `faces(tmesh)` gets a cross (deterministic), which
/// keeps the report small on huge meshes (about 150 bytes per cross). `max_crosses == 0` means no limit.
/// @tparam FaceFieldMap a readable property map from faces to a vector type with `x()`, `y()`, `z()`
///         (one direction of the cross, as computed by `compute_cross_field()`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `tmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, tmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename FaceFieldMap, typename NamedParameters = parameters::Default_named_parameters>
Html_layer cross_field_layer(const std::string& name, const TriangleMesh& tmesh, FaceFieldMap face_field,
                             std::size_t max_crosses = 60000, CGAL::IO::Color color = CGAL::IO::Color(20, 110, 200),
                             const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tmesh));
  typedef internal::Vec3d A;
  using internal::v_cross;
  using internal::v_dot;
  using internal::v_sub;
  const std::size_t n = static_cast<std::size_t>(num_faces(tmesh));
  const std::size_t stride = (max_crosses == 0 || n <= max_crosses) ? 1 : (n + max_crosses - 1) / max_crosses;
  const CGAL::IO::Color second(static_cast<unsigned char>(color.red() * 0.6), static_cast<unsigned char>(color.green() * 0.6),
                               static_cast<unsigned char>(color.blue() * 0.6));
  Html_layer layer;
  layer.name = name;
  std::size_t i = 0;
  for(auto f : faces(tmesh))
  {
    if(i++ % stride != 0) continue;
    std::vector<A> p;
    for(auto v : vertices_around_face(halfedge(f, tmesh), tmesh)) p.push_back(internal::html::to_array(get(vpm, v)));
    if(p.size() < 3) continue;
    A c{0., 0., 0.}, normal{0., 0., 0.};
    double perimeter = 0.;
    for(std::size_t k = 0; k < p.size(); ++k)
    {
      for(int d = 0; d < 3; ++d) c[d] += p[k][d] / double(p.size());
      const A e = v_sub(p[(k + 1) % p.size()], p[k]);
      perimeter += std::sqrt(v_dot(e, e));
      const A t = v_cross(p[k], p[(k + 1) % p.size()]); // Newell's normal
      for(int d = 0; d < 3; ++d) normal[d] += t[d];
    }
    const double nn = std::sqrt(v_dot(normal, normal));
    if(!(nn > 0.)) continue;
    for(double& x : normal) x /= nn;
    const auto w = get(face_field, f);
    A u{CGAL::to_double(w.x()), CGAL::to_double(w.y()), CGAL::to_double(w.z())};
    const double un = v_dot(u, normal);
    for(int d = 0; d < 3; ++d) u[d] -= un * normal[d];
    const double ul = std::sqrt(v_dot(u, u));
    if(!(ul > 0.) || !std::isfinite(ul)) continue;
    const double arm = 0.3 * perimeter / double(p.size());
    for(double& x : u) x *= arm / ul;
    const A v = v_cross(normal, u);
    for(const A& d : {u, v})
    {
      layer.segments.endpoints.push_back(A{c[0] - d[0], c[1] - d[1], c[2] - d[2]});
      layer.segments.endpoints.push_back(A{c[0] + d[0], c[1] + d[1], c[2] + d[2]});
    }
    layer.segments.colors.push_back(color);
    layer.segments.colors.push_back(second);
  }
  layer.legend.push_back({"field direction", color});
  layer.legend.push_back({"quarter turn", second});
  if(stride > 1) layer.legend.push_back({"one face in " + std::to_string(stride), CGAL::IO::Color(255, 255, 255)});
  return layer;
}

/// \ingroup PkgQuadRemeshingRef
/// A layer of points: the singularities of a cross field on `tmesh`, i.e. the vertices `v` with
/// `get(vertex_singularity, v) != 0`. The index `k` is in quarter turns as computed by
/// `compute_cross_field_singularities()`; the valence `4 - k` gives the colour (`valence_color()`), and the
/// legend gives the count per valence.
/// @tparam VertexSingularityMap a readable property map from vertices to `int`
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `tmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, tmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename VertexSingularityMap, typename NamedParameters = parameters::Default_named_parameters>
Html_layer singularities_layer(const std::string& name, const TriangleMesh& tmesh, VertexSingularityMap vertex_singularity,
                               const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tmesh));
  Html_layer layer;
  layer.name = name;
  layer.points.size = 11.;
  std::map<int, std::size_t> counts;
  for(auto v : vertices(tmesh))
  {
    const int k = int(get(vertex_singularity, v));
    if(k == 0) continue;
    const std::size_t valence = k >= 4 ? 0 : std::size_t(4 - k);
    ++counts[4 - k];
    layer.points.points.push_back(internal::html::to_array(get(vpm, v)));
    layer.points.colors.push_back(valence_color(valence));
  }
  for(const auto& c : counts)
    layer.legend.push_back({"valence " + std::to_string(c.first) + ": " + std::to_string(c.second),
                            valence_color(c.first <= 0 ? 0 : std::size_t(c.first))});
  return layer;
}

/// \ingroup PkgQuadRemeshingRef
/// A layer showing a patch layout traced on its triangle mesh: the faces of the mesh coloured by patch
/// (`categorical_color()` of the patch id), the patch boundaries (the arcs) as dark segments, and as
/// points the corners of the patches (black) and the T-junctions (magenta), i.e. the vertices where a
/// boundary goes straight on in a patch while a third boundary edge meets it there, counted as in the
/// layout's statistics. The legend gives the numbers of patches, corners and T-junctions.
///
/// The layout type is a template parameter so that this header does not depend on `Patch_layout.h`.
/// @tparam PatchLayout `CGAL::Quad_remeshing::Patch_layout` (or a class with its `mesh()`, `patches()`,
///         `patch_id()`, `arcs()` and `is_cut()`)
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `layout.mesh()`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of the mesh}
///     \cgalParamDefault{`get(CGAL::vertex_point, layout.mesh())`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PatchLayout, typename NamedParameters = parameters::Default_named_parameters>
Html_layer patch_layout_layer(const std::string& name, const PatchLayout& layout,
                              const NamedParameters& np = parameters::default_values())
{
  const auto& tmesh = layout.mesh();
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tmesh));
  Html_layer layer = polygon_mesh_layer(name, tmesh, np);
  for(auto f : faces(tmesh)) layer.polygons.face_colors.push_back(categorical_color(layout.patch_id(f)));
  layer.segments.color = CGAL::IO::Color(25, 25, 25);
  for(const auto& arc : layout.arcs())
    for(auto h : arc.halfedges)
    {
      layer.segments.endpoints.push_back(internal::html::to_array(get(vpm, source(h, tmesh))));
      layer.segments.endpoints.push_back(internal::html::to_array(get(vpm, target(h, tmesh))));
    }
  const auto& patches = layout.patches();
  typedef typename boost::graph_traits<std::decay_t<decltype(tmesh)>>::vertex_descriptor vertex_descriptor;
  std::set<vertex_descriptor> corners, t_junctions;
  for(const auto& P : patches)
  {
    corners.insert(P.corners.begin(), P.corners.end());
    if(P.loops.empty()) continue;
    for(std::size_t i = 0; i < P.loops[0].size(); ++i)
    {
      if(P.turns[0][i] != PatchLayout::STRAIGHT) continue;
      const vertex_descriptor v = target(P.loops[0][i], tmesh);
      std::size_t cut_degree = 0;
      for(auto h : halfedges_around_target(v, tmesh))
        if(layout.is_cut(edge(h, tmesh))) ++cut_degree;
      if(cut_degree >= 3) t_junctions.insert(v);
    }
  }
  const CGAL::IO::Color corner_color(0, 0, 0), junction_color(230, 0, 200);
  for(vertex_descriptor v : corners)
  {
    layer.points.points.push_back(internal::html::to_array(get(vpm, v)));
    layer.points.colors.push_back(corner_color);
  }
  for(vertex_descriptor v : t_junctions)
  {
    layer.points.points.push_back(internal::html::to_array(get(vpm, v)));
    layer.points.colors.push_back(junction_color);
  }
  layer.points.size = 7.;
  layer.legend.push_back({std::to_string(patches.size()) + " patches", categorical_color(0)});
  layer.legend.push_back({"corners: " + std::to_string(corners.size()), corner_color});
  layer.legend.push_back({"T-junctions: " + std::to_string(t_junctions.size()), junction_color});
  return layer;
}

/// \ingroup PkgQuadRemeshingRef
/// Three histograms of the quad mesh `pmesh`: the scaled Jacobian of its quads (on [-1, 1]), their
/// corner angles in degrees (reflex corners count as 360 minus the angle), and its edge lengths.
/// Faces that are not quads count for the edge lengths only.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` whose key type is the vertex descriptor of `pmesh`}
///     \cgalParamDefault{`get(CGAL::vertex_point, pmesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Html_histogram> quad_mesh_histograms(const PolygonMesh& pmesh,
                                                 const NamedParameters& np = parameters::default_values())
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, pmesh));
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  Html_histogram sj, angles, lengths;
  sj.title = "scaled Jacobian";
  sj.min = -1.;
  sj.max = 1.;
  angles.title = "quad corner angle (degrees)";
  angles.min = 0.;
  angles.max = 360.;
  angles.bins = 36;
  lengths.title = "edge length";
  for(auto f : faces(pmesh))
  {
    if(degree(f, pmesh) != 4) continue;
    std::array<Point, 4> p;
    std::size_t n = 0;
    for(auto v : vertices_around_face(halfedge(f, pmesh), pmesh)) p[n++] = get(vpm, v);
    sj.values.push_back(internal::quality::quad_scaled_jacobian(p));
    for(double a : internal::quality::quad_corner_angles(p))
      if(a >= 0.) angles.values.push_back(a);
  }
  for(auto e : edges(pmesh))
    lengths.values.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(e, pmesh)),
                                                                              get(vpm, target(e, pmesh))))));
  return {sj, angles, lengths};
}

/// \ingroup PkgQuadRemeshingRef
/// Writes `scene` as one self-contained HTML page to `os`: a three.js viewer (orbit with the left
/// button, pan with the right one, zoom with the wheel; a check box per layer), the layers' legends and
/// colour bars, the histograms and the report tables. three.js is read from its npm package and
/// inlined (as `data:` URLs of an import map), so that the page opens offline.
///
/// The three.js package directory is, in order: the named parameter `threejs_directory`, the
/// environment variable `QR_THREEJS_DIR`, the macro `QR_THREEJS_DIR` (the build passes
/// `viewer/node_modules/three`, installed by `npm ci` in `viewer/`).
///
/// @throws std::runtime_error if the three.js files cannot be read; nothing is written to `os` then.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{threejs_directory}
///     \cgalParamDescription{the directory of the npm package `three` (holding `build/three.module.js` and
///                           `examples/jsm/controls/OrbitControls.js`)}
///     \cgalParamType{`std::string`}
///     \cgalParamDefault{see above}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename NamedParameters = parameters::Default_named_parameters>
void write_html_report(std::ostream& os, const Html_report_scene& scene,
                       const NamedParameters& np = parameters::default_values())
{
  std::string dir = parameters::choose_parameter(parameters::get_parameter(np, internal_np::threejs_directory),
                                                 std::string());
  if(dir.empty())
  {
    if(const char* env = std::getenv("QR_THREEJS_DIR")) dir = env;
  }
#ifdef QR_THREEJS_DIR
  if(dir.empty()) dir = QR_THREEJS_DIR;
#endif
  const internal::html::Threejs_modules modules = internal::html::read_threejs(dir);
  std::ostringstream page;
  internal::html::write_page(page, scene, modules);
  os << page.str();
}

/// \ingroup PkgQuadRemeshingRef
/// Writes `scene` to the file `filename` (see the stream version).
/// @throws std::runtime_error if three.js cannot be read (the file is then not created) or the file cannot be written.
template <typename NamedParameters = parameters::Default_named_parameters>
void write_html_report(const std::string& filename, const Html_report_scene& scene,
                       const NamedParameters& np = parameters::default_values())
{
  std::ostringstream page;
  write_html_report(page, scene, np); // throws before the file is opened
  std::ofstream out(filename, std::ios::binary);
  out << page.str();
  out.close();
  if(!out) throw std::runtime_error("write_html_report: cannot write '" + filename + "'");
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_HTML_REPORT_H
