// Quality metrics and feature fidelity, checked against figures derived by hand.
#include "test_support.h"

#include <CGAL/Quad_remeshing/quad_mesh_quality.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <map>
#include <vector>

namespace {

namespace QR = CGAL::Quad_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;
using qr_test::Mesh;
using qr_test::Point_3;
typedef std::vector<std::vector<std::size_t>> Polygons;

const double pi = 3.14159265358979323846;

Mesh load(const std::string& name)
{
  Mesh m;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(qr_test::data_file(name), m));
  BOOST_REQUIRE(!is_empty(m));
  return m;
}

Mesh soup_to_mesh(const std::vector<Point_3>& pts, const Polygons& polys)
{
  Mesh m;
  BOOST_REQUIRE(PMP::is_polygon_soup_a_polygon_mesh(polys));
  PMP::polygon_soup_to_polygon_mesh(pts, polys, m);
  return m;
}

// Unit cube, 6 outward-oriented quads.
void unit_cube(std::vector<Point_3>& pts, Polygons& polys)
{
  pts.clear();
  for(int i = 0; i < 8; ++i) pts.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  polys = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
}

// A flat n x m grid of unit squares in the plane z = 0.
void grid(int n, int m, std::vector<Point_3>& pts, Polygons& polys)
{
  pts.clear();
  polys.clear();
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i <= n; ++i) pts.emplace_back(i, j, 0);
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i)
    {
      const std::size_t a = std::size_t(j * (n + 1) + i);
      polys.push_back({a, a + 1, a + std::size_t(n) + 2, a + std::size_t(n) + 1});
    }
}

// Splits each triangle into three quads through its centroid and edge midpoints.
void split_into_quads(const Mesh& t, std::vector<Point_3>& pts, Polygons& polys)
{
  pts.clear();
  polys.clear();
  std::map<Mesh::Vertex_index, std::size_t> vid;
  std::map<Mesh::Edge_index, std::size_t> mid;
  for(auto v : vertices(t)) { vid[v] = pts.size(); pts.push_back(t.point(v)); }
  for(auto e : edges(t))
  {
    mid[e] = pts.size();
    pts.push_back(CGAL::midpoint(t.point(source(e, t)), t.point(target(e, t))));
  }
  for(auto f : faces(t))
  {
    const auto h0 = halfedge(f, t), h1 = next(h0, t), h2 = next(h1, t);
    const std::size_t g = pts.size();
    pts.push_back(CGAL::centroid(t.point(source(h0, t)), t.point(source(h1, t)), t.point(source(h2, t))));
    for(auto h : {h0, h1, h2})
      polys.push_back({vid[source(h, t)], mid[edge(h, t)], g, mid[edge(prev(h, t), t)]});
  }
}

} // namespace

BOOST_AUTO_TEST_SUITE(quality)

BOOST_AUTO_TEST_CASE(unit_cube_of_six_quads)
{
  std::vector<Point_3> pts;
  Polygons polys;
  unit_cube(pts, polys);
  const QR::Quad_mesh_quality q = QR::quad_mesh_quality(soup_to_mesh(pts, polys));
  BOOST_TEST(q.vertices == 8u);
  BOOST_TEST(q.faces == 6u);
  BOOST_TEST(q.edges == 12u);
  BOOST_TEST(q.quads == 6u);
  BOOST_TEST(q.pure_quad);
  BOOST_TEST(q.manifold);
  BOOST_TEST(q.valid);
  BOOST_TEST(q.inconsistent_edges == 0u);
  BOOST_TEST(q.irregular_vertices == 8u); // every corner has valence 3
  BOOST_TEST(q.interior_valence_histogram.at(3) == 8u);
  BOOST_TEST(q.boundary_vertices == 0u);
  BOOST_TEST(q.angle_deviation == 0., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.edge_length_deviation == 0., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.mean_scaled_jacobian == 1., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.min_scaled_jacobian == 1., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.euler_characteristic == 2);
  BOOST_TEST(q.components == 1u);
  BOOST_TEST(q.boundary_loops == 0u);

  // the soup version gives the same figures
  const QR::Quad_mesh_quality s = QR::polygon_soup_quality(pts, polys);
  const QR::Report r = s.report();
  BOOST_TEST(r.find("irregular_vertices")->number() == 8.);
  BOOST_TEST(r.find("pure_quad")->boolean());
  BOOST_TEST(r.find("interior_valence_histogram")->find("3")->number() == 8.);
  BOOST_TEST(r.find("seconds") != nullptr);
  BOOST_TEST(s.irregular_vertices == q.irregular_vertices);
  BOOST_TEST(s.edges == q.edges);

  // a flipped face is reported as four inconsistently oriented edges, and only there
  Polygons flipped = polys;
  std::reverse(flipped[0].begin(), flipped[0].end());
  BOOST_TEST(QR::polygon_soup_quality(pts, flipped).inconsistent_edges == 4u);
}

BOOST_AUTO_TEST_CASE(flat_grid)
{
  std::vector<Point_3> pts;
  Polygons polys;
  grid(5, 3, pts, polys);
  const QR::Quad_mesh_quality q = QR::quad_mesh_quality(soup_to_mesh(pts, polys));
  BOOST_TEST(q.vertices == 24u);
  BOOST_TEST(q.faces == 15u);
  BOOST_TEST(q.edges == 38u); // 5*4 horizontal + 6*3 vertical
  BOOST_TEST(q.irregular_vertices == 0u);
  BOOST_TEST(q.irregular_boundary_vertices == 0u);
  BOOST_TEST(q.interior_vertices == 8u);
  BOOST_TEST(q.interior_valence_histogram.at(4) == 8u);
  BOOST_TEST(q.boundary_valence_histogram.at(2) == 4u);  // corners
  BOOST_TEST(q.boundary_valence_histogram.at(3) == 12u); // sides
  BOOST_TEST(q.angle_deviation == 0., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.edge_length_deviation == 0., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.mean_scaled_jacobian == 1., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.min_scaled_jacobian == 1., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(q.euler_characteristic == 1);
  BOOST_TEST(q.boundary_loops == 1u);
  BOOST_TEST(q.boundary_edges == 16u);
  BOOST_TEST(q.valid);

  // stretching the grid in x keeps right angles but makes lengths uneven: 20 edges of length 2,
  // 18 of length 1, mean 58/38, mean absolute deviation 2 * 20 * 18 / 38^2
  std::vector<Point_3> stretched;
  for(const Point_3& p : pts) stretched.emplace_back(2 * p.x(), p.y(), 0);
  const QR::Quad_mesh_quality st = QR::polygon_soup_quality(stretched, polys);
  const double mean = 58. / 38., mad = 2. * 20. * 18. / (38. * 38.);
  BOOST_TEST(st.mean_edge_length == mean, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(st.edge_length_deviation == 100. * mad / mean, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(st.angle_deviation == 0., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(st.min_scaled_jacobian == 1., boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(trapezoid_angles)
{
  // isosceles trapezoid: base angles atan(2) = 63.43 deg, top angles 116.57 deg
  const std::vector<Point_3> pts = {Point_3(0, 0, 0), Point_3(4, 0, 0), Point_3(3, 2, 0), Point_3(1, 2, 0)};
  const Polygons polys = {{0, 1, 2, 3}};
  const QR::Quad_mesh_quality q = QR::polygon_soup_quality(pts, polys);
  const double base = std::atan(2.) * 180. / pi;
  BOOST_TEST(q.angle_deviation == 90. - base, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(q.max_angle_deviation == 90. - base, boost::test_tools::tolerance(1e-10));
  BOOST_TEST(q.min_scaled_jacobian == 2. / std::sqrt(5.), boost::test_tools::tolerance(1e-12));
  BOOST_TEST(q.irregular_boundary_vertices == 0u);
  BOOST_TEST(q.boundary_valence_histogram.at(2) == 4u);
}

BOOST_AUTO_TEST_CASE(concave_and_bow_tie_quads)
{
  // arrowhead: the corner at (2,1) is reflex, 360 - acos(-3/5) degrees, and its scaled Jacobian is -4/5
  const std::vector<Point_3> arrow = {Point_3(0, 0, 0), Point_3(2, 1, 0), Point_3(4, 0, 0), Point_3(2, 3, 0)};
  const QR::Quad_mesh_quality a = QR::polygon_soup_quality(arrow, Polygons{{0, 1, 2, 3}});
  const double reflex = 360. - std::acos(-0.6) * 180. / pi;
  BOOST_TEST(a.min_scaled_jacobian == -0.8, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(a.non_positive_scaled_jacobian == 1u);
  BOOST_TEST(a.non_positive_scaled_jacobian_fraction == 1.);
  BOOST_TEST(a.max_angle_deviation == reflex - 90., boost::test_tools::tolerance(1e-10));
  BOOST_TEST(a.valid); // concave but not degenerate: validity does not depend on SJ

  // a 3 x 1 grid whose middle quad is a bow-tie (two vertices swapped)
  std::vector<Point_3> pts;
  Polygons polys;
  grid(3, 1, pts, polys);
  std::swap(polys[1][2], polys[1][3]);
  const QR::Quad_mesh_quality b = QR::polygon_soup_quality(pts, polys);
  BOOST_TEST(b.non_positive_scaled_jacobian == 1u);
  BOOST_TEST(b.min_scaled_jacobian <= 0.);
  BOOST_TEST(b.mean_scaled_jacobian < 1.);
  BOOST_TEST(b.angle_deviation > 0.);

  // a quad reversed inside a flat grid: the scaled Jacobian uses each quad's own normal, so the
  // flip shows as inconsistently oriented edges, not as a bad shape
  grid(3, 3, pts, polys);
  std::reverse(polys[4].begin(), polys[4].end());
  const QR::Quad_mesh_quality r = QR::polygon_soup_quality(pts, polys);
  BOOST_TEST(r.inconsistent_edges == 4u);
  BOOST_TEST(r.min_scaled_jacobian == 1., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(r.flipped_quads == 0u); // (normals are compared across consistent edges only)
}

BOOST_AUTO_TEST_CASE(flipped_over_quads)
{
  // Two unit squares hinged on the edge x = 0, the second turned by `fold` degrees about it: past 120
  // degrees each square is flipped over against its only neighbour, with a scaled Jacobian of 1 each.
  auto hinge = [](double fold) {
    const double t = fold * pi / 180.;
    const std::vector<Point_3> pts = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0),
                                      Point_3(-std::cos(t), 1, std::sin(t)), Point_3(-std::cos(t), 0, std::sin(t))};
    return QR::polygon_soup_quality(pts, Polygons{{0, 1, 2, 3}, {3, 4, 5, 0}});
  };
  BOOST_TEST(hinge(0.).flipped_quads == 0u);
  BOOST_TEST(hinge(110.).flipped_quads == 0u);
  const QR::Quad_mesh_quality folded = hinge(130.);
  BOOST_TEST(folded.flipped_quads == 2u);
  BOOST_TEST(folded.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(folded.min_scaled_jacobian == 1., boost::test_tools::tolerance(1e-12));

  // a Z-fold in a strip of five quads: the middle one runs back under the fourth, upside down, against both
  // its neighbours; the others each have a neighbour that agrees with them
  std::vector<Point_3> strip;
  for(const auto& xz : std::vector<std::pair<double, double>>{{0, 0}, {1, 0}, {2, 0}, {1.2, 0.01}, {2.2, 0.02}, {3.2, 0.02}})
  {
    strip.emplace_back(xz.first, 0, xz.second);
    strip.emplace_back(xz.first, 1, xz.second);
  }
  Polygons quads;
  for(std::size_t i = 0; i < 5; ++i) quads.push_back({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  const QR::Quad_mesh_quality z = QR::polygon_soup_quality(strip, quads);
  BOOST_TEST(z.inconsistent_edges == 0u);
  BOOST_TEST(z.flipped_quads == 1u);
  BOOST_TEST(z.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(z.min_scaled_jacobian > 0.9);

  // a closed cube: every quad's neighbours are at 90 degrees
  Mesh cube;
  CGAL::make_hexahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0), Point_3(0, 1, 1),
                        Point_3(0, 0, 1), Point_3(1, 0, 1), Point_3(1, 1, 1), cube);
  BOOST_TEST(QR::quad_mesh_quality(cube).flipped_quads == 0u);
  BOOST_TEST(qr_test::flipped_over_quads(cube) == 0u);
}

BOOST_AUTO_TEST_CASE(non_manifold_and_degenerate_soups)
{
  // three quads around one edge
  const std::vector<Point_3> pts = {Point_3(0, 0, 0), Point_3(0, 0, 1), Point_3(1, 0, 0), Point_3(1, 0, 1),
                                    Point_3(0, 1, 0), Point_3(0, 1, 1), Point_3(-1, -1, 0), Point_3(-1, -1, 1)};
  const Polygons fin = {{0, 2, 3, 1}, {0, 1, 5, 4}, {0, 6, 7, 1}};
  const QR::Quad_mesh_quality f = QR::polygon_soup_quality(pts, fin);
  BOOST_TEST(f.non_manifold_edges == 1u);
  BOOST_TEST(!f.manifold);
  BOOST_TEST(!f.valid);
  BOOST_TEST(f.pure_quad);

  // two squares touching at one vertex: a pinch, one boundary loop through it
  const std::vector<Point_3> bow = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(1, 1, 0), Point_3(0, 1, 0),
                                    Point_3(2, 1, 0), Point_3(2, 2, 0), Point_3(1, 2, 0)};
  const QR::Quad_mesh_quality p = QR::polygon_soup_quality(bow, Polygons{{0, 1, 2, 3}, {2, 4, 5, 6}});
  BOOST_TEST(p.non_manifold_vertices == 1u);
  BOOST_TEST(p.non_manifold_edges == 0u);
  BOOST_TEST(!p.manifold);
  BOOST_TEST(p.components == 2u);
  BOOST_TEST(p.boundary_loops == 1u);
  BOOST_TEST(p.euler_characteristic == 7 - 8 + 2);

  // a repeated index, a zero-area quad, a triangle: degenerate faces, not pure quad
  const std::vector<Point_3> deg = {Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(2, 0, 0), Point_3(3, 0, 0),
                                    Point_3(0, 1, 0)};
  const QR::Quad_mesh_quality d = QR::polygon_soup_quality(deg, Polygons{{0, 1, 1, 4}, {0, 1, 2, 3}, {0, 1, 4}});
  BOOST_TEST(d.degenerate_faces == 2u);
  BOOST_TEST(d.triangles == 1u);
  BOOST_TEST(!d.pure_quad);
  BOOST_TEST(!d.valid);
  BOOST_TEST(d.min_scaled_jacobian == 0.); // collapsed quads count as 0
  BOOST_CHECK_THROW(QR::polygon_soup_quality(deg, Polygons{{0, 1, 9}}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(split_fandisk_matches_input)
{
  Mesh t = load("fandisk.off");
  std::vector<Point_3> pts;
  Polygons polys;
  split_into_quads(t, pts, polys);
  const Mesh q = soup_to_mesh(pts, polys);
  const QR::Quad_mesh_quality s = QR::quad_mesh_quality(q);
  BOOST_TEST(s.vertices == num_vertices(t) + num_edges(t) + num_faces(t));
  BOOST_TEST(s.faces == 3 * num_faces(t));
  BOOST_TEST(s.pure_quad);
  BOOST_TEST(s.valid);
  BOOST_TEST(s.euler_characteristic == 2);
  BOOST_TEST(s.components == 1u);
  // centroids have valence 3, midpoints valence 4, input vertices keep their valence
  std::size_t irregular_input = 0;
  for(auto v : vertices(t))
    if(degree(v, t) != 4) ++irregular_input;
  BOOST_TEST(s.irregular_vertices == num_faces(t) + irregular_input);
  BOOST_TEST(s.interior_valence_histogram.at(3) >= num_faces(t));
  BOOST_TEST(s.non_positive_scaled_jacobian == 0u);
  // soup and mesh versions agree
  const QR::Quad_mesh_quality u = QR::polygon_soup_quality(pts, polys);
  BOOST_TEST(u.report().to_json(-1).substr(0, 400) == s.report().to_json(-1).substr(0, 400));
  BOOST_TEST(u.mean_scaled_jacobian == s.mean_scaled_jacobian);
  BOOST_TEST(u.angle_deviation == s.angle_deviation);

  auto feature = get(CGAL::edge_is_feature, t);
  const std::size_t n_features = QR::detect_evaluation_feature_edges(t, feature);
  BOOST_TEST(n_features > 100u);
  BOOST_TEST(n_features < num_edges(t) / 4);
  const QR::Feature_fidelity ff =
    QR::feature_fidelity(t, feature, q, CGAL::parameters::number_of_points_on_faces(20000));
  BOOST_TEST(ff.hausdorff_max < 1e-9);
  BOOST_TEST(ff.hausdorff_mean < 1e-10);
  BOOST_TEST(ff.feature_coverage == 1.);
  BOOST_TEST(ff.feature_coverage_tight == 1.);
  BOOST_TEST(ff.feature_max_distance < 1e-9);
  BOOST_TEST(ff.feature_length > 0.);
  // the output's creases are the halves of the input's features, and nothing else
  BOOST_TEST(ff.output_feature_length == ff.feature_length, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(ff.output_features_on_input_features == 1.);
  BOOST_TEST(ff.input_samples > 20000u);
  BOOST_TEST(ff.output_samples > 20000u);

  // a sharper angle keeps fewer features
  auto feature2 = t.add_property_map<Mesh::Edge_index, bool>("e:feature2", false).first;
  BOOST_TEST(QR::detect_evaluation_feature_edges(t, feature2, QR::parameters::feature_angle(80.)) < n_features);
  BOOST_CHECK_THROW(QR::detect_evaluation_feature_edges(t, feature2, QR::parameters::feature_angle(-1.)),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(translated_cube_fidelity)
{
  // input: a triangulated unit cube; output: the quad cube moved by t along x. Every input
  // vertex at x = 0 is exactly t from the output, and no point is farther, so the Hausdorff
  // distance is t. The 8 feature edges across x are t away from the output edges; the 4 edges
  // along x are covered except within t of their start.
  std::vector<Point_3> pts;
  Polygons polys;
  unit_cube(pts, polys);
  Mesh t = soup_to_mesh(pts, polys);
  PMP::triangulate_faces(t);
  const double diag = std::sqrt(3.);
  const double shift = 0.002 * diag;
  std::vector<Point_3> moved;
  for(const Point_3& p : pts) moved.emplace_back(p.x() + shift, p.y(), p.z());
  const Mesh q = soup_to_mesh(moved, polys);

  auto feature = get(CGAL::edge_is_feature, t);
  BOOST_TEST(QR::detect_evaluation_feature_edges(t, feature) == 12u); // the diagonals are flat
  const QR::Feature_fidelity ff = QR::feature_fidelity(t, feature, q, CGAL::parameters::number_of_points_on_faces(5000));
  BOOST_TEST(ff.bbox_diagonal == diag, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(ff.hausdorff_max == 0.002, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(ff.input_to_output_max == 0.002, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(ff.hausdorff_mean > 0.);
  BOOST_TEST(ff.hausdorff_mean < 0.002);
  BOOST_TEST(ff.feature_length == 12., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(ff.feature_max_distance == 0.002, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(ff.feature_coverage == 1.);
  BOOST_TEST(ff.feature_coverage_loose == 1.);
  // each unit edge is cut into ceil(1000 / diag) = 578 pieces, sampled at their midpoints. Within
  // 0.1% of the diagonal: on an edge along x, all but the first piece (its midpoint is 0.5/578
  // from the start, t - 0.5/578 away from the output edge); on the 4 edges across x at x = 1, the
  // two end pieces, which are within 0.5/578 of an output edge along x; nothing else.
  BOOST_TEST(ff.feature_coverage_tight == (4. * 577. + 4. * 2.) / 578. / 12., boost::test_tools::tolerance(1e-12));

  // deterministic and independent of the number of threads
  const QR::Feature_fidelity f2 = QR::feature_fidelity(
    t, feature, q, QR::parameters::number_of_threads(CGAL::parameters::number_of_points_on_faces(5000), 2u));
  BOOST_TEST(f2.hausdorff_mean == ff.hausdorff_mean);
  BOOST_TEST(f2.hausdorff_rms == ff.hausdorff_rms);
  // another seed gives other samples but the same exact figures
  const QR::Feature_fidelity f3 = QR::feature_fidelity(
    t, feature, q, CGAL::parameters::number_of_points_on_faces(5000).random_seed(7));
  BOOST_TEST(f3.hausdorff_mean != ff.hausdorff_mean);
  BOOST_TEST(f3.hausdorff_max == ff.hausdorff_max, boost::test_tools::tolerance(1e-9));

  // a tighter tolerance than the shift uncovers the 8 edges across x
  const QR::Feature_fidelity f4 = QR::feature_fidelity(
    t, feature, q, QR::parameters::feature_coverage_tolerance(0.0015));
  BOOST_TEST(f4.coverage_tolerance == 0.0015);
  BOOST_TEST(f4.feature_coverage < 0.34);
  BOOST_TEST(f4.feature_coverage > 0.33);
  // and the output's 8 crease edges across x are off the input's features too
  BOOST_TEST(ff.output_features_on_input_features == 1.);
  BOOST_TEST(ff.output_feature_length == 12., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(f4.output_features_on_input_features < 0.34);
  BOOST_TEST(f4.output_features_on_input_features > 0.33);
  BOOST_CHECK_THROW(QR::feature_fidelity(t, feature, q, QR::parameters::feature_coverage_tolerance(0.)),
                    std::invalid_argument);

  // the soup version measures the same thing; a face flipped in the soup does not create creases
  Polygons flipped = polys;
  std::reverse(flipped[2].begin(), flipped[2].end());
  const QR::Feature_fidelity s1 = QR::polygon_soup_feature_fidelity(
    t, feature, moved, flipped, CGAL::parameters::number_of_points_on_faces(5000));
  BOOST_TEST(s1.hausdorff_max == ff.hausdorff_max, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s1.feature_coverage_tight == ff.feature_coverage_tight, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s1.output_feature_length == 12., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(s1.output_features_on_input_features == 1.);
  BOOST_CHECK_THROW(QR::polygon_soup_feature_fidelity(t, feature, moved, Polygons{{0, 1, 8}}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(triangle_mesh_is_not_quad)
{
  const Mesh t = load("hemisphere.off");
  const QR::Quad_mesh_quality q = QR::quad_mesh_quality(t);
  BOOST_TEST(q.vertices == num_vertices(t));
  BOOST_TEST(q.faces == num_faces(t));
  BOOST_TEST(q.triangles == q.faces);
  BOOST_TEST(!q.pure_quad);
  BOOST_TEST(!q.valid);
  BOOST_TEST(q.manifold);
  BOOST_TEST(q.boundary_loops == 1u);
  BOOST_TEST(q.euler_characteristic == 1);
  BOOST_TEST(q.mean_scaled_jacobian == 0.); // no quads
}

BOOST_AUTO_TEST_SUITE_END()
