// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The HTML report's file: self-contained (three.js inlined, nothing fetched), holding the layers, the
// histograms and the report JSON. The browser test (html/browser_test.mjs) opens the fandisk report
// written here and checks that it renders.

#include <CGAL/Quad_remeshing/IO.h>
#include <CGAL/Quad_remeshing/cross_field.h>
#include <CGAL/Quad_remeshing/detect_feature_edges.h>
#include <CGAL/Quad_remeshing/remesh_for_quadrangulation.h>
#include <CGAL/Quad_remeshing/trace_patch_layout.h>
#include <CGAL/Quad_remeshing/html_report.h>
#include <CGAL/Quad_remeshing/quad_mesh_quality.h>
#include <CGAL/Quad_remeshing/smooth_quad_mesh.h>

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <cstdio>
#include <memory>
#include <tuple>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace QR = CGAL::Quad_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;
using qr_test::Mesh;
using qr_test::Point_3;
using CGAL::Quad_remeshing::Report;

namespace {

std::string slurp(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string decode_base64(const std::string& s)
{
  static const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned v = 0;
  int bits = 0;
  for(char c : s)
  {
    if(c == '=') break;
    const std::size_t d = digits.find(c);
    BOOST_REQUIRE(d != std::string::npos);
    v = (v << 6) | unsigned(d);
    bits += 6;
    if(bits >= 8)
    {
      bits -= 8;
      out += char((v >> bits) & 255u);
    }
  }
  return out;
}

// the text between `open` and the next "</script>"
std::string script_content(const std::string& page, const std::string& open)
{
  const std::size_t b = page.find(open);
  BOOST_REQUIRE_MESSAGE(b != std::string::npos, "missing " << open);
  const std::size_t s = b + open.size();
  const std::size_t e = page.find("</script>", s);
  BOOST_REQUIRE(e != std::string::npos);
  return page.substr(s, e - s);
}

std::size_t count(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

// Each triangle becomes 3 quads (centroid, edge midpoints shared between neighbours); the two quad
// edges halving a feature edge are features of the quad mesh.
template <typename FeatureMap, typename QFeatureMap>
void split_into_quads(const Mesh& t, FeatureMap t_feature, Mesh& q, QFeatureMap q_feature)
{
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> corner;
  for(auto v : t.vertices()) corner[v] = q.add_vertex(t.point(v));
  std::map<Mesh::Edge_index, Mesh::Vertex_index> middle;
  for(auto e : t.edges())
    middle[e] = q.add_vertex(CGAL::midpoint(t.point(t.source(t.halfedge(e))), t.point(t.target(t.halfedge(e)))));
  for(auto f : t.faces())
  {
    const auto h0 = t.halfedge(f), h1 = t.next(h0), h2 = t.next(h1);
    const auto c = q.add_vertex(CGAL::centroid(t.point(t.source(h0)), t.point(t.source(h1)), t.point(t.source(h2))));
    for(auto h : {h0, h1, h2})
    {
      const auto m_in = middle[t.edge(t.prev(h))], m_out = middle[t.edge(h)];
      BOOST_REQUIRE(q.add_face(corner[t.source(h)], m_out, c, m_in) != Mesh::null_face());
    }
  }
  for(auto e : q.edges()) put(q_feature, e, false);
  for(auto e : t.edges())
    if(get(t_feature, e))
      for(auto end : {corner[t.source(t.halfedge(e))], corner[t.target(t.halfedge(e))]})
      {
        const auto h = CGAL::halfedge(middle[e], end, q);
        BOOST_REQUIRE(h.second);
        put(q_feature, q.edge(h.first), true);
      }
}

std::string threejs_dir()
{
  if(const char* env = std::getenv("QR_THREEJS_DIR")) return env;
#ifdef QR_THREEJS_DIR
  return QR_THREEJS_DIR;
#else
  return std::string();
#endif
}

// fandisk, its feature lines, its triangles split into quads, and these quads smoothed: the layers and
// figures the stages that exist can give (built once, shared by the test cases).
struct Fandisk_report
{
  Mesh input, quads, smoothed;
  QR::Html_report_scene scene;
  std::size_t features = 0;

  Fandisk_report()
  {
    const QR::Repair_statistics repair = QR::read_and_repair(qr_test::data_file("fandisk.off"), input);
    auto is_feature = input.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
    PMP::detect_sharp_edges(input, 60., is_feature);
    for(auto e : input.edges()) features += is_feature[e] ? 1 : 0;
    auto q_feature = quads.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
    split_into_quads(input, is_feature, quads, q_feature);
    smoothed = quads;
    const QR::Quad_smoothing_statistics smoothing = QR::smooth_quad_mesh(
      smoothed, input, is_feature,
      CGAL::parameters::edge_is_constrained_map(smoothed.property_map<Mesh::Edge_index, bool>("e:feature").first)
        .number_of_iterations(10));

    scene.title = "fandisk: feature lines, split and smoothed quads";
    QR::Html_layer in = QR::polygon_mesh_layer("input", input);
    in.visible = false;
    scene.layers.push_back(in);
    scene.layers.push_back(QR::feature_edges_layer("feature lines", input, is_feature));
    QR::Html_layer split = QR::scaled_jacobian_layer("split quads (scaled Jacobian)", quads);
    split.visible = false;
    scene.layers.push_back(split);
    scene.layers.push_back(QR::irregular_vertices_layer("irregular vertices", smoothed));
    scene.layers.back().points.size = 5.; // every input vertex and face centre is irregular here
    scene.layers.push_back(QR::scaled_jacobian_layer("smoothed quads (scaled Jacobian)", smoothed));
    scene.histograms = QR::quad_mesh_histograms(smoothed);
    // shaped like the command-line program's report
    scene.report["status"] = "ok";
    scene.report["input"]["file"] = "fandisk.off";
    scene.report["stages"] = Report::array();
    Report stage = repair.report();
    stage["name"] = "repair";
    scene.report["stages"].push_back(stage);
    stage = smoothing.report();
    stage["name"] = "smooth";
    scene.report["stages"].push_back(stage);
    scene.report["output"]["quality"] = QR::quad_mesh_quality(smoothed).report();
  }
};

const Fandisk_report& fandisk()
{
  static const Fandisk_report f;
  return f;
}

// fandisk through the stages up to the patch layout, as the command-line program runs them: the
// data of the cross field, singularity and layout layers.
struct Fandisk_layout
{
  typedef CGAL::Quad_remeshing::Patch_layout<Mesh> Layout;
  Mesh tm;
  Mesh::Property_map<Mesh::Face_index, qr_test::Kernel::Vector_3> field;
  Mesh::Property_map<Mesh::Vertex_index, int> singularity;
  std::unique_ptr<Layout> layout;

  Fandisk_layout()
  {
    QR::read_and_repair(qr_test::data_file("fandisk.off"), tm);
    auto feature = tm.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
    auto corner = tm.add_property_map<Mesh::Vertex_index, bool>("v:corner", false).first;
    QR::detect_feature_edges(tm, feature, QR::parameters::vertex_is_feature_corner_map(corner));
    QR::remesh_for_quadrangulation(tm, feature, // (as quad_remesh() by default)
                                   QR::parameters::combine(QR::parameters::quad_edge_length(QR::quad_edge_length_from_scale(tm, 1.)),
                                                           QR::parameters::vertex_is_feature_corner_map(corner),
                                                           QR::parameters::far_region_rounds(0u)));
    tm.collect_garbage();
    field = tm.add_property_map<Mesh::Face_index, qr_test::Kernel::Vector_3>("f:field", CGAL::NULL_VECTOR).first;
    singularity = tm.add_property_map<Mesh::Vertex_index, int>("v:singularity", 0).first;
    QR::compute_cross_field(tm, feature, field);
    QR::compute_cross_field_singularities(tm, feature, field, singularity);
    layout = std::make_unique<Layout>(tm, field, singularity);
    QR::trace_patch_layout(tm, feature, *layout);
  }
};

} // namespace

BOOST_AUTO_TEST_SUITE(html_report)

BOOST_AUTO_TEST_CASE(layers_of_the_field_and_layout_stages)
{
  const Fandisk_layout f;
  const std::size_t F = f.tm.number_of_faces();

  // one cross (two segments through the centroid, orthogonal, in the face plane) per face
  const QR::Html_layer cross = QR::cross_field_layer("cross field", f.tm, f.field);
  BOOST_CHECK_EQUAL(cross.segments.endpoints.size(), 4 * F);
  BOOST_CHECK_EQUAL(cross.segments.colors.size(), 2 * F);
  const auto& e = cross.segments.endpoints;
  for(std::size_t i = 0; i < e.size(); i += 4)
  {
    double dot = 0., l0 = 0., l1 = 0.;
    for(int d = 0; d < 3; ++d)
    {
      const double a = e[i + 1][d] - e[i][d], b = e[i + 3][d] - e[i + 2][d];
      dot += a * b; l0 += a * a; l1 += b * b;
      BOOST_REQUIRE_SMALL((e[i][d] + e[i + 1][d]) - (e[i + 2][d] + e[i + 3][d]), 1e-9); // same centre
    }
    BOOST_REQUIRE_GT(l0, 0.);
    BOOST_REQUIRE_CLOSE(l0, l1, 1e-6);
    BOOST_REQUIRE_SMALL(dot / l0, 1e-9);
  }
  // the cap keeps every k-th face only
  const QR::Html_layer capped = QR::cross_field_layer("cross field", f.tm, f.field, F / 10);
  BOOST_CHECK_LE(capped.segments.endpoints.size(), 4 * (F / 10));
  BOOST_CHECK_GE(capped.segments.endpoints.size(), 4 * (F / 11));

  // singularities: the vertices of non-zero index, by valence 4 - index
  const QR::Html_layer sing = QR::singularities_layer("singularities", f.tm, f.singularity);
  std::map<int, std::size_t> by_valence;
  for(auto v : f.tm.vertices())
    if(f.singularity[v] != 0) ++by_valence[4 - f.singularity[v]];
  BOOST_REQUIRE(!by_valence.empty()); // fandisk has singularities (valence 3 and 5 at least)
  std::size_t total = 0;
  for(const auto& c : by_valence) total += c.second;
  BOOST_CHECK_EQUAL(sing.points.points.size(), total);
  BOOST_REQUIRE_EQUAL(sing.legend.size(), by_valence.size());
  std::size_t i = 0;
  for(const auto& c : by_valence)
    BOOST_CHECK_EQUAL(sing.legend[i++].label, "valence " + std::to_string(c.first) + ": " + std::to_string(c.second));

  // the layout: one colour per patch (the same within a patch, distinct between neighbouring patches),
  // every arc edge as a segment, corners and T-junctions as points
  const QR::Html_layer lay = QR::patch_layout_layer("patch layout", *f.layout);
  BOOST_REQUIRE_EQUAL(lay.polygons.faces.size(), F);
  BOOST_REQUIRE_EQUAL(lay.polygons.face_colors.size(), F);
  std::map<std::size_t, CGAL::IO::Color> patch_color;
  i = 0;
  for(auto face : f.tm.faces())
  {
    const auto it = patch_color.emplace(f.layout->patch_id(face), lay.polygons.face_colors[i++]).first;
    BOOST_REQUIRE(it->second == lay.polygons.face_colors[i - 1]);
  }
  BOOST_CHECK_EQUAL(patch_color.size(), f.layout->number_of_patches());
  BOOST_CHECK_GT(patch_color.size(), 20u);
  std::size_t arc_edges = 0;
  for(const auto& a : f.layout->arcs()) arc_edges += a.halfedges.size();
  BOOST_CHECK_EQUAL(lay.segments.endpoints.size(), 2 * arc_edges);
  std::set<Mesh::Vertex_index> corners;
  for(const auto& P : f.layout->patches()) corners.insert(P.corners.begin(), P.corners.end());
  const std::size_t t_junctions = f.layout->statistics().t_junctions;
  BOOST_CHECK_EQUAL(lay.points.points.size(), corners.size() + t_junctions);
  BOOST_REQUIRE_EQUAL(lay.legend.size(), 3u);
  BOOST_CHECK_EQUAL(lay.legend[0].label, std::to_string(f.layout->number_of_patches()) + " patches");
  BOOST_CHECK_EQUAL(lay.legend[1].label, "corners: " + std::to_string(corners.size()));
  BOOST_CHECK_EQUAL(lay.legend[2].label, "T-junctions: " + std::to_string(t_junctions));
  // categorical colours: the first patches get distinct colours
  std::set<std::tuple<int, int, int>> first;
  for(std::size_t k = 0; k < 40; ++k)
  {
    const CGAL::IO::Color c = QR::categorical_color(k);
    first.emplace(c.red(), c.green(), c.blue());
  }
  BOOST_CHECK_EQUAL(first.size(), 40u);
}

BOOST_AUTO_TEST_CASE(scaled_jacobian_of_simple_quads)
{
  Mesh m;
  const auto a = m.add_vertex(Point_3(0, 0, 0)), b = m.add_vertex(Point_3(1, 0, 0)), c = m.add_vertex(Point_3(1, 1, 0)),
             d = m.add_vertex(Point_3(0, 1, 0)), g = m.add_vertex(Point_3(2, 0, 0)),
             h = m.add_vertex(Point_3(2, 1, 0));
  const auto square = m.add_face(a, b, c, d);
  BOOST_CHECK_CLOSE(QR::quad_scaled_jacobian(square, m), 1., 1e-9);
  // a parallelogram with 45 degree corners: every corner sine is sin(45 deg)
  Mesh p;
  const auto pf = p.add_face(p.add_vertex(Point_3(0, 0, 0)), p.add_vertex(Point_3(1, 0, 0)),
                             p.add_vertex(Point_3(2, 1, 0)), p.add_vertex(Point_3(1, 1, 0)));
  BOOST_CHECK_CLOSE(QR::quad_scaled_jacobian(pf, p), std::sqrt(0.5), 1e-9);
  // a concave quad (reflex corner at (0.2, 0.2)) has a negative scaled Jacobian
  Mesh k;
  const auto kf = k.add_face(k.add_vertex(Point_3(0, 0, 0)), k.add_vertex(Point_3(1, 0, 0)),
                             k.add_vertex(Point_3(0.2, 0.2, 0)), k.add_vertex(Point_3(0, 1, 0)));
  BOOST_CHECK_LT(QR::quad_scaled_jacobian(kf, k), 0.);
  const auto tri = m.add_face(b, g, h);
  BOOST_CHECK_THROW(QR::quad_scaled_jacobian(tri, m), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(layers_from_a_polygon_mesh)
{
  const Fandisk_report& f = fandisk();
  BOOST_CHECK_GT(f.features, 100u);
  const QR::Html_layer& in = f.scene.layers[0];
  BOOST_CHECK_EQUAL(in.polygons.points.size(), f.input.number_of_vertices());
  BOOST_CHECK_EQUAL(in.polygons.faces.size(), f.input.number_of_faces());
  BOOST_CHECK_EQUAL(f.scene.layers[1].segments.endpoints.size(), 2 * f.features);
  const QR::Html_layer& q = f.scene.layers[2];
  BOOST_CHECK_EQUAL(q.polygons.faces.size(), 3 * f.input.number_of_faces());
  BOOST_CHECK_EQUAL(q.polygons.face_scalars.size(), q.polygons.faces.size());
  BOOST_CHECK(q.polygons.wireframe);
  for(double sj : q.polygons.face_scalars) BOOST_CHECK(sj > -1.000001 && sj < 1.000001);
  // irregular vertices of a split closed triangle mesh: face centres (3) and input vertices (valence != 4)
  std::size_t expected = f.input.number_of_faces();
  for(auto v : f.input.vertices()) expected += f.input.degree(v) != 4 ? 1 : 0;
  // the smoothed layer has the split connectivity and the smoothed positions
  const QR::Html_layer& s = f.scene.layers[4];
  BOOST_CHECK(s.polygons.faces == q.polygons.faces);
  BOOST_CHECK(s.polygons.points != q.polygons.points);
  BOOST_CHECK_EQUAL(s.polygons.points.size(), f.smoothed.number_of_vertices());
  const QR::Html_layer& irr = f.scene.layers[3];
  BOOST_CHECK_EQUAL(irr.points.points.size(), expected);
  BOOST_CHECK_EQUAL(irr.points.colors.size(), expected);
  BOOST_CHECK(!irr.legend.empty());
  std::map<std::size_t, std::size_t> valences;
  valences[3] = f.input.number_of_faces();
  for(auto v : f.input.vertices())
    if(f.input.degree(v) != 4) ++valences[f.input.degree(v)];
  BOOST_REQUIRE_EQUAL(irr.legend.size(), valences.size());
  std::size_t i = 0;
  for(const auto& v : valences)
    BOOST_CHECK_EQUAL(irr.legend[i++].label, "valence " + std::to_string(v.first) + ": " + std::to_string(v.second));
  BOOST_REQUIRE_EQUAL(f.scene.histograms.size(), 3u);
  BOOST_CHECK_EQUAL(f.scene.histograms[0].values.size(), f.quads.number_of_faces());
  BOOST_CHECK_EQUAL(f.scene.histograms[1].values.size(), 4 * f.quads.number_of_faces());
  BOOST_CHECK_EQUAL(f.scene.histograms[2].values.size(), f.quads.number_of_edges());
}

BOOST_AUTO_TEST_CASE(fandisk_report_is_self_contained)
{
  const Fandisk_report& f = fandisk();
  const std::string path = qr_test::output_file("fandisk_report.html");
  std::remove(path.c_str());
  QR::write_html_report(path, f.scene, QR::parameters::threejs_directory(threejs_dir()));
  const std::string page = slurp(path);
  BOOST_REQUIRE(!page.empty());
  BOOST_CHECK_EQUAL(page.rfind("<!DOCTYPE html>", 0), 0u);
  BOOST_CHECK_EQUAL(page.substr(page.size() - 8), "</html>\n");
  BOOST_CHECK_EQUAL(count(page, "<html"), 1u);
  BOOST_CHECK_EQUAL(count(page, "<body>"), 1u);
  BOOST_CHECK_EQUAL(count(page, "</body>"), 1u);
  // the only scripts: guard, import map, scene data, report data, viewer module; none fetched
  BOOST_CHECK_EQUAL(count(page, "<script"), 5u);
  BOOST_CHECK_EQUAL(count(page, "</script>"), 5u);
  BOOST_CHECK_EQUAL(count(page, " src="), 0u);
  BOOST_CHECK_EQUAL(count(page, "http://"), 0u);
  BOOST_CHECK_EQUAL(count(page, "https://"), 0u);
  BOOST_CHECK_EQUAL(count(page, "<title>fandisk: feature lines, split and smoothed quads</title>"), 1u);

  // the import map inlines three.js (core, module) and OrbitControls as data: URLs
  const Report imports = Report::parse(script_content(page, "<script type=\"importmap\">"));
  const Report* imports_map = imports.find("imports");
  BOOST_REQUIRE(imports_map);
  std::string all_three;
  for(const char* key : {"three", "three/addons/controls/OrbitControls.js"})
  {
    const Report* url = imports_map->find(key);
    BOOST_REQUIRE_MESSAGE(url, "import map entry " << key);
    const std::string prefix = "data:text/javascript;base64,";
    BOOST_REQUIRE_EQUAL(url->string().rfind(prefix, 0), 0u);
    all_three += decode_base64(url->string().substr(prefix.size()));
  }
  if(const Report* core = imports_map->find("three/core"))
    all_three += decode_base64(core->string().substr(core->string().find(',') + 1));
  BOOST_CHECK(all_three.find("class WebGLRenderer") != std::string::npos);
  BOOST_CHECK(all_three.find("class OrbitControls") != std::string::npos);
  BOOST_CHECK(all_three.find("class BufferGeometry") != std::string::npos);
  BOOST_CHECK_EQUAL(count(all_three, "from './"), 0u);
  // OrbitControls is inlined unchanged
  const std::string controls = imports_map->find("three/addons/controls/OrbitControls.js")->string();
  BOOST_CHECK(decode_base64(controls.substr(controls.find(',') + 1)) ==
              slurp(threejs_dir() + "/examples/jsm/controls/OrbitControls.js"));

  // the scene data: the layers in order, with their sizes
  const Report scene = Report::parse(script_content(page, "<script type=\"application/json\" id=\"qr-scene\">"));
  BOOST_CHECK_EQUAL(scene.find("title")->string(), f.scene.title);
  const auto& layers = scene.find("layers")->elements();
  BOOST_REQUIRE_EQUAL(layers.size(), 5u);
  BOOST_CHECK_EQUAL(layers[0].find("name")->string(), "input");
  BOOST_CHECK(!layers[0].find("visible")->boolean());
  BOOST_CHECK(!layers[2].find("visible")->boolean());
  BOOST_CHECK(layers[4].find("visible")->boolean());
  BOOST_CHECK_EQUAL(layers[0].find("polygons")->find("faces")->elements().size(), f.input.number_of_faces());
  BOOST_CHECK_EQUAL(layers[0].find("polygons")->find("points")->elements().size(), 3 * f.input.number_of_vertices());
  BOOST_CHECK_EQUAL(layers[1].find("segments")->find("endpoints")->elements().size(), 6 * f.features);
  const Report& quads = *layers[4].find("polygons");
  BOOST_CHECK_EQUAL(quads.find("faces")->elements().size(), f.quads.number_of_faces());
  BOOST_CHECK_EQUAL(quads.find("faces")->elements().front().elements().size(), 4u);
  BOOST_CHECK_EQUAL(quads.find("face_scalars")->elements().size(), f.quads.number_of_faces());
  BOOST_CHECK_EQUAL(quads.find("color_map")->string(), "red_to_green");
  BOOST_CHECK_EQUAL(quads.find("range")->elements()[0].number(), -1.);
  BOOST_CHECK_EQUAL(layers[3].find("points")->find("points")->elements().size(),
                    3 * f.scene.layers[3].points.points.size());

  // histograms are binned: the counts add up to the finite values in range
  const auto& hist = scene.find("histograms")->elements();
  BOOST_REQUIRE_EQUAL(hist.size(), 3u);
  double sum = 0.;
  for(const Report& c : hist[0].find("counts")->elements()) sum += c.number();
  BOOST_CHECK_EQUAL(sum, double(f.quads.number_of_faces()));
  BOOST_CHECK_EQUAL(hist[0].find("counts")->elements().size(), 30u);
  BOOST_CHECK_EQUAL(hist[1].find("counts")->elements().size(), 36u);
  sum = 0.;
  for(const Report& c : hist[2].find("counts")->elements()) sum += c.number();
  BOOST_CHECK_EQUAL(sum, double(f.quads.number_of_edges()));

  // the run's report, as given
  const Report report = Report::parse(script_content(page, "<script type=\"application/json\" id=\"qr-report\">"));
  BOOST_CHECK_EQUAL(report.to_json(), f.scene.report.to_json());
}

BOOST_AUTO_TEST_CASE(missing_threejs_writes_nothing)
{
  const Fandisk_report& f = fandisk();
  const std::string path = qr_test::output_file("html_report_missing_three.html");
  std::remove(path.c_str());
  BOOST_CHECK_THROW(QR::write_html_report(path, f.scene, QR::parameters::threejs_directory(std::string("/nonexistent/three"))),
                    std::runtime_error);
  BOOST_CHECK(!std::ifstream(path).good());
}

BOOST_AUTO_TEST_CASE(inconsistent_layers_are_refused)
{
  QR::Html_report_scene scene;
  QR::Html_layer bad;
  bad.name = "bad";
  bad.polygons.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  bad.polygons.faces = {{0, 1, 3}};
  scene.layers.push_back(bad);
  std::ostringstream os;
  BOOST_CHECK_THROW(QR::write_html_report(os, scene, QR::parameters::threejs_directory(threejs_dir())),
                    std::invalid_argument);
  scene.layers[0].polygons.faces = {{0, 1, 2}};
  scene.layers[0].polygons.face_scalars = {1., 2.};
  BOOST_CHECK_THROW(QR::write_html_report(os, scene, QR::parameters::threejs_directory(threejs_dir())),
                    std::invalid_argument);
  scene.layers[0].polygons.face_scalars = {1.};
  // text that would close a <script> element is escaped in the data and in the title
  scene.layers[0].name = "a </script><script>alert(1)</script> b";
  scene.title = "<b>";
  QR::write_html_report(os, scene, QR::parameters::threejs_directory(threejs_dir()));
  const std::string page = os.str();
  BOOST_CHECK_EQUAL(count(page, "</script>"), 5u);
  BOOST_CHECK_EQUAL(count(page, "<title>&lt;b&gt;</title>"), 1u);
  const Report data = Report::parse(script_content(page, "<script type=\"application/json\" id=\"qr-scene\">"));
  BOOST_CHECK_EQUAL(data.find("layers")->elements()[0].find("name")->string(), scene.layers[0].name);
}

BOOST_AUTO_TEST_SUITE_END()
