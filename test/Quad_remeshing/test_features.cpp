// Tests of detect_feature_edges() and read_feature_edges() on bundled meshes.
#include "test_support.h"

#include <CGAL/Quad_remeshing/detect_feature_edges.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <boost/test/unit_test.hpp>

#include <fstream>
#include <iomanip>

namespace QR = CGAL::Quad_remeshing;
using qr_test::Mesh;

namespace {

Mesh load(const std::string& name)
{
  Mesh m;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(qr_test::data_file(name), m));
  BOOST_REQUIRE(CGAL::is_triangle_mesh(m));
  return m;
}

std::size_t count(const Mesh& m, Mesh::Property_map<Mesh::Edge_index, bool> f)
{
  std::size_t n = 0;
  for(auto e : m.edges()) n += f[e];
  return n;
}

} // namespace

BOOST_AUTO_TEST_SUITE(features)

BOOST_AUTO_TEST_CASE(fandisk_features_and_corners)
{
  Mesh m = load("fandisk.off");
  auto f = m.add_property_map<Mesh::Edge_index, bool>("e:f", false).first;
  auto c = m.add_property_map<Mesh::Vertex_index, bool>("v:c", false).first;
  const auto st = QR::detect_feature_edges(m, f, QR::parameters::vertex_is_feature_corner_map(c));
  BOOST_CHECK_EQUAL(st.feature_edges, count(m, f));
  BOOST_CHECK_GT(st.feature_edges, 300u);
  BOOST_CHECK_GT(st.feature_lines, 10u);
  BOOST_CHECK_GT(st.corners, 5u);
  // every feature edge is over the threshold or a border; every end or junction is a corner
  std::size_t corners = 0;
  for(auto v : m.vertices())
  {
    const std::size_t d = QR::internal::feature_degree(v, m, f);
    if(d == 1 || d > 2) BOOST_CHECK(c[v]);
    if(d == 0) BOOST_CHECK(!c[v]);
    corners += c[v];
  }
  BOOST_CHECK_EQUAL(corners, st.corners);
  auto r = st.report();
  BOOST_CHECK_EQUAL(r["feature_edges"].number(), double(st.feature_edges));
  BOOST_CHECK(!r["seconds"].is_null());
}

BOOST_AUTO_TEST_CASE(threshold_off_keeps_only_borders)
{
  Mesh closed = load("fandisk.off");
  auto f = closed.add_property_map<Mesh::Edge_index, bool>("e:f", true).first;
  QR::detect_feature_edges(closed, f, QR::parameters::feature_angle(180.));
  BOOST_CHECK_EQUAL(count(closed, f), 0u);

  Mesh open = load("hemisphere.off");
  auto g = open.add_property_map<Mesh::Edge_index, bool>("e:f", false).first;
  const auto st = QR::detect_feature_edges(open, g, QR::parameters::feature_angle(180.));
  std::size_t borders = 0;
  for(auto e : open.edges())
  {
    BOOST_CHECK_EQUAL(g[e], open.is_border(e));
    borders += open.is_border(e);
  }
  BOOST_CHECK_GT(borders, 0u);
  BOOST_CHECK_EQUAL(st.feature_edges, borders);
  BOOST_CHECK_EQUAL(st.feature_lines, 1u); // one closed border loop without corner
}

BOOST_AUTO_TEST_CASE(erode_dilate_only_removes)
{
  // on an organic mesh the low threshold finds noisy short chains; erode/dilate removes some, adds none
  for(const char* name : {"spot.off", "fertility.off", "abc_00000008.off"})
  {
    Mesh m = load(name);
    auto raw = m.add_property_map<Mesh::Edge_index, bool>("e:raw", false).first;
    auto ed = m.add_property_map<Mesh::Edge_index, bool>("e:ed", false).first;
    const auto s0 = QR::detect_feature_edges(m, raw, QR::parameters::feature_erode_dilate_steps(
                                                       QR::parameters::feature_angle(20.), 0u));
    // (no gap closing here: it adds edges, see gaps_in_a_wavering_crease_are_closed)
    const auto s4 = QR::detect_feature_edges(m, ed, QR::parameters::feature_gap_angle(
                                                       QR::parameters::feature_angle(20.), 20.));
    BOOST_CHECK_EQUAL(s0.sharp_edges, s4.sharp_edges);
    for(auto e : m.edges())
      if(ed[e]) BOOST_CHECK(raw[e]);
    // a vertex where more than two detected lines meet keeps all its feature edges
    for(auto v : m.vertices())
      if(QR::internal::feature_degree(v, m, raw) > 2)
        BOOST_CHECK_EQUAL(QR::internal::feature_degree(v, m, raw), QR::internal::feature_degree(v, m, ed));
    if(std::string(name) == "spot.off")
      BOOST_CHECK_LT(s4.feature_edges, s0.feature_edges);
  }
}

// abc_00000008 has a rim whose dihedral angles waver around 35 degrees: the threshold leaves it in
// pieces that erosion removes, and 4.6% of the length of its sharp edges is lost. Closing the gaps
// along edges over 25 degrees keeps the rim.
BOOST_AUTO_TEST_CASE(gaps_in_a_wavering_crease_are_closed)
{
  Mesh m = load("abc_00000008.off");
  auto dihedral = [&](Mesh::Edge_index e) {
    const auto h = m.halfedge(e);
    const auto n1 = CGAL::Polygon_mesh_processing::compute_face_normal(m.face(h), m);
    const auto n2 = CGAL::Polygon_mesh_processing::compute_face_normal(m.face(m.opposite(h)), m);
    return std::acos((std::max)(-1., (std::min)(1., CGAL::to_double(n1 * n2)))) * 180. / CGAL_PI;
  };
  // the share of the length of the edges over 35 degrees that is feature
  auto sharp_share = [&](Mesh::Property_map<Mesh::Edge_index, bool> f) {
    double all = 0., kept = 0.;
    for(auto e : m.edges())
      if(!m.is_border(e) && dihedral(e) > 35.)
      {
        const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(m.point(m.source(m.halfedge(e))),
                                                                          m.point(m.target(m.halfedge(e))))));
        all += l;
        if(f[e]) kept += l;
      }
    return kept / all;
  };
  auto plain = m.add_property_map<Mesh::Edge_index, bool>("e:plain", false).first;
  auto closed = m.add_property_map<Mesh::Edge_index, bool>("e:closed", false).first;
  const auto s0 = QR::detect_feature_edges(m, plain, QR::parameters::feature_gap_angle(35.));
  const auto s1 = QR::detect_feature_edges(m, closed);
  BOOST_CHECK_EQUAL(s0.gap_edges, 0u);
  BOOST_CHECK_GT(s1.gap_edges, 10u);
  BOOST_CHECK_EQUAL(s1.report()["gap_edges"].number(), double(s1.gap_edges));
  BOOST_CHECK_LT(sharp_share(plain), 0.97);
  BOOST_CHECK_GT(sharp_share(closed), 0.99);
  // closing gaps only adds features: the non-sharp ones are gap edges, all over 25 degrees; a gap has
  // at most 4 edges and starts at an end of a chain of the sharp edges (before erosion)
  auto raw = m.add_property_map<Mesh::Edge_index, bool>("e:raw", false).first;
  QR::detect_feature_edges(m, raw, QR::parameters::feature_erode_dilate_steps(0u));
  std::size_t added = 0, ends = 0;
  for(auto e : m.edges())
  {
    if(plain[e]) BOOST_CHECK(closed[e]);
    if(closed[e] && !raw[e])
    {
      ++added;
      BOOST_CHECK_GT(dihedral(e), 25.);
      BOOST_CHECK_LE(dihedral(e), 35.);
    }
  }
  for(auto v : m.vertices()) ends += (QR::internal::feature_degree(v, m, raw) == 1);
  BOOST_CHECK_GT(added, 0u);
  BOOST_CHECK_LE(added, s1.gap_edges);
  BOOST_CHECK_LE(s1.gap_edges, 4 * ends);
  BOOST_CHECK_GT(s1.feature_edges, s0.feature_edges);

  // a clean CAD mesh has no gap to close
  Mesh fandisk = load("fandisk.off");
  auto g = fandisk.add_property_map<Mesh::Edge_index, bool>("e:g", false).first;
  BOOST_CHECK_EQUAL(QR::detect_feature_edges(fandisk, g).gap_edges, 0u);
}

// A cap (angle over 170 degrees) whose three edges are features would be a patch thinner than any
// quad (truck, next to a window): its longest edge is no feature, the two others carry the line.
BOOST_AUTO_TEST_CASE(cap_with_three_feature_edges_loses_its_long_edge)
{
  Mesh m = qr_test::cap_plate();
  BOOST_REQUIRE(m.number_of_faces() == 10u && CGAL::is_valid_polygon_mesh(m));
  const auto P = Mesh::Vertex_index(6), Q = Mesh::Vertex_index(5), R = Mesh::Vertex_index(8);
  auto f = m.add_property_map<Mesh::Edge_index, bool>("e:f", false).first;
  const auto st = QR::detect_feature_edges(m, f);
  BOOST_CHECK_EQUAL(st.cap_edges, 1u);
  BOOST_CHECK(f[m.edge(m.halfedge(P, Q))]);  // border
  BOOST_CHECK(f[m.edge(m.halfedge(Q, R))]);  // sharp
  BOOST_CHECK(!f[m.edge(m.halfedge(P, R))]); // sharp, but the long edge of the cap
  BOOST_CHECK_EQUAL(st.sharp_edges, 2u);     // PR and QR were over the threshold
  BOOST_CHECK_EQUAL(st.report()["cap_edges"].number(), 1.);
  // not a cap without the lift (QR and PR are flat), nor with a threshold above the cap's dihedral angles
  Mesh flat = qr_test::cap_plate(0.);
  auto g = flat.add_property_map<Mesh::Edge_index, bool>("e:g", false).first;
  BOOST_CHECK_EQUAL(QR::detect_feature_edges(flat, g).cap_edges, 0u);
  BOOST_CHECK_EQUAL(QR::detect_feature_edges(m, f, QR::parameters::feature_angle(80.)).cap_edges, 0u);
}

BOOST_AUTO_TEST_CASE(read_feature_files)
{
  Mesh m = load("fandisk.off");
  auto f = m.add_property_map<Mesh::Edge_index, bool>("e:f", false).first;
  QR::detect_feature_edges(m, f);
  const std::string pairs = qr_test::output_file("fandisk_features.txt");
  const std::string polylines = qr_test::output_file("fandisk_features.polylines.txt");
  {
    std::ofstream p(pairs), l(polylines);
    p << "# feature edges as vertex index pairs\n";
    l << std::setprecision(17);
    for(auto e : m.edges())
      if(f[e])
      {
        const auto a = m.source(m.halfedge(e)), b = m.target(m.halfedge(e));
        p << std::size_t(a) << " " << std::size_t(b) << "\n";
        l << "2 " << m.point(a) << " " << m.point(b) << "\n";
      }
  }
  for(const std::string& file : {pairs, polylines})
  {
    auto g = m.add_property_map<Mesh::Edge_index, bool>("e:g", false).first;
    const std::size_t n = QR::read_feature_edges(file, m, g);
    BOOST_CHECK_EQUAL(n, count(m, f));
    for(auto e : m.edges()) BOOST_CHECK_EQUAL(f[e], g[e]);
    // a given set is kept as is by detection
    auto c = m.add_property_map<Mesh::Vertex_index, bool>("v:c", false).first;
    const auto st = QR::detect_feature_edges(m, g, QR::parameters::use_given_feature_edges(
                                                     QR::parameters::vertex_is_feature_corner_map(c), true));
    BOOST_CHECK_EQUAL(st.feature_edges, n);
    m.remove_property_map(g);
    m.remove_property_map(c);
  }
  {
    std::ofstream bad(qr_test::output_file("bad_features.txt"));
    bad << "0 99999999\n";
  }
  BOOST_CHECK_THROW(QR::read_feature_edges(qr_test::output_file("bad_features.txt"), m, f), std::invalid_argument);
  {
    std::ofstream bad(qr_test::output_file("bad_features2.txt"));
    bad << "2 0 0 0 hello\n";
  }
  BOOST_CHECK_THROW(QR::read_feature_edges(qr_test::output_file("bad_features2.txt"), m, f), std::invalid_argument);
  BOOST_CHECK_THROW(QR::read_feature_edges(qr_test::output_file("no_such_file.txt"), m, f), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
