// Tests of Patch_layout: cutting along features, boundary classification, validity, tracing in G.
#include "test_support.h"

#include <CGAL/Quad_remeshing/Patch_layout.h>
#include <CGAL/Quad_remeshing/cross_field.h>
#include <CGAL/Quad_remeshing/detect_feature_edges.h>
#include <CGAL/Quad_remeshing/IO.h>
#include <CGAL/Quad_remeshing/refine_patch_layout.h>
#include <CGAL/Quad_remeshing/remesh_for_quadrangulation.h>
#include <CGAL/Quad_remeshing/trace_patch_layout.h>
#include <CGAL/Quad_remeshing/internal/pipeline/quad_sizing.h>
#include <CGAL/Quad_remeshing/internal/pipeline/layout_conversion.h>
#include <CGAL/Quad_remeshing/internal/bbox_diagonal.h>

#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/property_map.h>
#include <CGAL/Real_timer.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <tuple>

namespace {

using qr_test::Mesh;
using qr_test::Point_3;
typedef qr_test::Kernel::Vector_3 Vector_3;
typedef CGAL::Quad_remeshing::Patch_layout<Mesh> Layout;
typedef Mesh::Vertex_index V;
typedef Mesh::Face_index F;
typedef Mesh::Edge_index E;

// an n x n grid of unit squares in the plane z = 0, each split by the diagonal (i,j)-(i+1,j+1);
// vertex (i,j) has index j*(n+1)+i
Mesh grid(int n)
{
  Mesh m;
  std::vector<V> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) v.push_back(m.add_vertex(Point_3(i, j, 0)));
  auto at = [&](int i, int j) { return v[std::size_t(j * (n + 1) + i)]; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

// the closed box [0,n]^3 with an n x n grid of split squares on each side
Mesh box(int n)
{
  Mesh m;
  std::map<std::array<int, 3>, V> index;
  auto vertex = [&](std::array<int, 3> p) {
    auto it = index.find(p);
    if(it != index.end()) return it->second;
    return index[p] = m.add_vertex(Point_3(p[0], p[1], p[2]));
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for(int a = 0; a < n; ++a)
        for(int b = 0; b < n; ++b) {
          std::array<std::array<int, 3>, 4> q;
          const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
          for(int k = 0; k < 4; ++k) { q[k][axis] = side * n; q[k][u] = a + du[k]; q[k][w] = b + dw[k]; }
          V c[4];
          for(int k = 0; k < 4; ++k) c[k] = vertex(q[k]);
          if(side == 1) { m.add_face(c[0], c[1], c[2]); m.add_face(c[0], c[2], c[3]); }
          else { m.add_face(c[0], c[2], c[1]); m.add_face(c[0], c[3], c[2]); }
        }
    }
  return m;
}

// per face: the first coordinate axis lying in the face plane (the box's faces are axis-aligned)
Mesh::Property_map<F, Vector_3> axis_field(Mesh& m)
{
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(0, 0, 0)).first;
  for(F f : m.faces()) {
    const Vector_3 n = CGAL::Polygon_mesh_processing::compute_face_normal(f, m);
    const Vector_3 axes[3] = {Vector_3(1, 0, 0), Vector_3(0, 1, 0), Vector_3(0, 0, 1)};
    for(const Vector_3& a : axes)
      if(std::abs(a * n) < 0.5) { field[f] = a; break; }
  }
  return field;
}

// edges whose faces meet at a dihedral angle above 60 degrees
Mesh::Property_map<E, bool> sharp_edges(Mesh& m)
{
  auto feature = m.add_property_map<E, bool>("e:feature", false).first;
  for(E e : m.edges()) {
    if(m.is_border(e)) continue;
    const Vector_3 a = CGAL::Polygon_mesh_processing::compute_face_normal(m.face(m.halfedge(e, 0)), m);
    const Vector_3 b = CGAL::Polygon_mesh_processing::compute_face_normal(m.face(m.halfedge(e, 1)), m);
    feature[e] = a * b < 0.5;
  }
  return feature;
}

CGAL::Constant_property_map<V, int> no_singularity(0);

// a stand-in cross field: per face the coordinate axis closest to its plane (no cross-field stage needed)
Mesh::Property_map<F, Vector_3> stand_in_field(Mesh& m)
{
  auto field = m.add_property_map<F, Vector_3>("f:cross", Vector_3(0, 0, 0)).first;
  for(F f : m.faces()) {
    const Vector_3 nn = CGAL::Polygon_mesh_processing::compute_face_normal(f, m);
    const Vector_3 axes[3] = {Vector_3(1, 0, 0), Vector_3(0, 1, 0), Vector_3(0, 0, 1)};
    double best = 2.;
    for(const Vector_3& a : axes) if(std::abs(a * nn) < best) { best = std::abs(a * nn); field[f] = a; }
  }
  return field;
}

// the vertex at `p` (within 1e-6): the hand checks name vertices by their coordinates in the OFF file
V vertex_at(const Mesh& m, const Point_3& p)
{
  for(V v : m.vertices())
    if(CGAL::squared_distance(m.point(v), p) < 1e-12) return v;
  BOOST_FAIL("no vertex at " << p);
  return V();
}

// one passage of a patch boundary loop through a vertex: where it comes from, where it goes, the turn
struct Passage
{
  std::size_t patch;
  V from, to;
  Layout::Turn turn;
};

std::vector<Passage> passages(const Layout& layout, V v)
{
  const Mesh& m = layout.mesh();
  std::vector<Passage> r;
  const auto& patches = layout.patches();
  for(std::size_t p = 0; p < patches.size(); ++p)
    for(std::size_t l = 0; l < patches[p].loops.size(); ++l) {
      const auto& loop = patches[p].loops[l];
      for(std::size_t i = 0; i < loop.size(); ++i)
        if(m.target(loop[i]) == v)
          r.push_back(Passage{p, m.source(loop[i]), m.target(loop[(i + 1) % loop.size()]), patches[p].turns[l][i]});
    }
  return r;
}

// A flat disk around the origin O: rings of radius 1..n on rays at 0 and 6 degrees, then every 30 degrees
// from 30 to 330; O is vertex 0, the vertex of ring r (1..n) on ray j is 1 + (r-1)*13 + j.
Mesh fan_disk(int n)
{
  Mesh m;
  std::vector<double> rays{0., 6.};
  for(int d = 30; d < 360; d += 30) rays.push_back(d);
  const int k = int(rays.size());
  std::vector<V> v{m.add_vertex(Point_3(0, 0, 0))};
  for(int r = 1; r <= n; ++r)
    for(double a : rays) v.push_back(m.add_vertex(Point_3(r * std::cos(a * CGAL_PI / 180.), r * std::sin(a * CGAL_PI / 180.), 0)));
  auto at = [&](int r, int j) { return v[std::size_t(1 + (r - 1) * k + (j % k))]; };
  for(int j = 0; j < k; ++j) {
    m.add_face(v[0], at(1, j), at(1, j + 1));
    for(int r = 1; r < n; ++r) {
      m.add_face(at(r, j), at(r + 1, j), at(r + 1, j + 1));
      m.add_face(at(r, j), at(r + 1, j + 1), at(r, j + 1));
    }
  }
  return m;
}

} // namespace

BOOST_AUTO_TEST_SUITE(layout)

BOOST_AUTO_TEST_CASE(box_features_give_six_valid_quads)
{
  Mesh m = box(4);
  auto field = axis_field(m);
  Layout layout(m, field, no_singularity);
  BOOST_TEST(layout.add_feature_paths(sharp_edges(m)) == 12u); // the 12 box edges (corners have feature degree 3)
  BOOST_TEST(layout.patches().size() == 6u);
  for(std::size_t p = 0; p < layout.patches().size(); ++p) {
    const Layout::Patch& P = layout.patches()[p];
    BOOST_TEST(P.faces.size() == 32u);
    BOOST_TEST(P.corners.size() == 4u);
    BOOST_TEST(P.sides.size() == 4u);
    BOOST_TEST(P.euler_characteristic == 1);
    for(double l : P.side_lengths) BOOST_TEST(l == 4., boost::test_tools::tolerance(1e-9));
    BOOST_TEST(layout.validity(p) == Layout::SATISFIED);
    BOOST_TEST(layout.quality(p) == Layout::SATISFIED);
  }
  // 12 arcs, each between two different patches
  BOOST_TEST(layout.arcs().size() == 12u);
  for(const Layout::Arc& a : layout.arcs()) {
    BOOST_TEST(a.patches[0] >= 0);
    BOOST_TEST(a.patches[1] >= 0);
    BOOST_TEST(a.patches[0] != a.patches[1]);
  }
  const auto s = layout.statistics();
  BOOST_TEST(s.patches == 6u);
  BOOST_TEST(s.valid_patches == 6u);
  BOOST_TEST(s.quality_patches == 6u);
  BOOST_TEST(s.patches_by_valence.at(4) == 6u);
  BOOST_TEST(s.report()["paths"].number() == 12.);
}

BOOST_AUTO_TEST_CASE(partial_feature_line_is_a_u_turn)
{
  // a path from the left border into the middle of a grid: its free end is a U-turn, the patch is not valid
  Mesh m = grid(6);
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  Layout layout(m, field, no_singularity);
  BOOST_TEST(layout.patches().size() == 1u);
  BOOST_TEST(layout.validity(0) == Layout::SATISFIED); // the square: four right turns
  Layout::Path p;
  for(int i = 0; i <= 3; ++i) {
    p.vertices.push_back(V(3 * 7 + i));
    if(i < 3) p.directions.push_back(Vector_3(1, 0, 0));
  }
  const std::size_t id = layout.add_path(p);
  BOOST_TEST(layout.patches().size() == 1u);
  const Layout::Patch& P = layout.patches()[0];
  std::map<std::size_t, Layout::Turn> turn;
  for(std::size_t i = 0; i < P.loops[0].size(); ++i) turn[std::size_t(target(P.loops[0][i], m))] = P.turns[0][i];
  // hand check: the free end (3,3) is a U-turn; where the path leaves the border at (0,3) both sides turn
  // right (convex 90 degree corners); a border vertex like (0,1) is straight; the square corners turn right
  BOOST_TEST(turn.at(3 * 7 + 3) == Layout::U_TURN);
  BOOST_TEST(turn.at(3 * 7 + 0) == Layout::RIGHT_TURN);
  BOOST_TEST(turn.at(1 * 7 + 0) == Layout::STRAIGHT);
  BOOST_TEST(turn.at(0) == Layout::RIGHT_TURN);
  BOOST_TEST(layout.validity(0) == Layout::NOT_CONVEX);
  // continuing the path from its free end, away from it, is allowed and not tangential; it makes two squares
  std::vector<Layout::Node> right;
  for(int j = 0; j <= 6; ++j) right.push_back(layout.closest_node(V(j * 7 + 6), Vector_3(1, 0, 0)));
  auto extension = layout.trace(layout.closest_node(V(3 * 7 + 3), Vector_3(1, 0, 0)), right);
  BOOST_REQUIRE(extension);
  BOOST_TEST(extension->vertices.size() == 4u);
  BOOST_TEST(!layout.cross_tangentially(p, *extension));
  // going back along it is refused
  std::vector<Layout::Node> left;
  for(int j = 0; j <= 6; ++j) left.push_back(layout.closest_node(V(j * 7), Vector_3(-1, 0, 0)));
  BOOST_TEST(!layout.trace(layout.closest_node(V(3 * 7 + 3), Vector_3(-1, 0, 0)), left));
  const std::size_t id2 = layout.add_path(*extension);
  BOOST_TEST(layout.patches().size() == 2u);
  BOOST_TEST(layout.statistics().valid_patches == 2u);
  layout.remove_path(id2);
  layout.remove_path(id);
  BOOST_TEST(layout.patches().size() == 1u);
  BOOST_TEST(layout.validity(0) == Layout::SATISFIED);
}

BOOST_AUTO_TEST_CASE(traced_path_on_flat_grid_is_a_grid_line)
{
  const int n = 10;
  Mesh m = grid(n);
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  Layout layout(m, field, no_singularity);
  const V start(5 * (n + 1)); // (0,5)
  const Layout::Node s = layout.closest_node(start, Vector_3(1, 0, 0));
  std::vector<Layout::Node> ends;
  for(int j = 0; j <= n; ++j) ends.push_back(layout.closest_node(V(j * (n + 1) + n), Vector_3(1, 0, 0)));
  auto path = layout.trace(s, ends);
  BOOST_REQUIRE(path);
  BOOST_TEST(path->vertices.size() == std::size_t(n + 1));
  for(std::size_t i = 0; i < path->vertices.size(); ++i) {
    const Point_3& p = m.point(path->vertices[i]);
    BOOST_TEST(p.x() == double(i));
    BOOST_TEST(p.y() == 5.);
  }
  // deterministic: a second layout traces the same vertices
  Layout again(m, field, no_singularity);
  auto path2 = again.trace(s, ends);
  BOOST_REQUIRE(path2);
  BOOST_TEST(path2->vertices == path->vertices);

  // the row is a path now; a column traced across it crosses it orthogonally, never along it
  layout.add_path(*path);
  std::vector<Layout::Node> top;
  for(int i = 0; i <= n; ++i) top.push_back(layout.closest_node(V(n * (n + 1) + i), Vector_3(0, 1, 0)));
  auto column = layout.trace(layout.closest_node(V(3), Vector_3(0, 1, 0)), top);
  BOOST_REQUIRE(column);
  BOOST_TEST(!layout.cross_tangentially(*path, *column));
  BOOST_TEST(layout.cross_tangentially(*path, *path));
  for(std::size_t i = 0; i < column->vertices.size(); ++i) BOOST_TEST(m.point(column->vertices[i]).x() == 3.);
  layout.add_path(*column);
  BOOST_TEST(layout.patches().size() == 4u);
  for(std::size_t p = 0; p < 4; ++p) BOOST_TEST(layout.validity(p) == Layout::SATISFIED);
  // starting on the row in its own direction is tangential: no node there
  auto along = layout.trace(layout.closest_node(V(5 * (n + 1) + 1), Vector_3(1, 0, 0)), ends);
  BOOST_TEST(!along);
  // a loop needs a closed field line: on the flat grid there is none
  const Layout::Node c = layout.closest_node(V(2 * (n + 1) + 2), Vector_3(1, 0, 0));
  BOOST_TEST(!layout.trace(c, {c}));
}

BOOST_AUTO_TEST_CASE(t_junction_splits_arc)
{
  // a column from the bottom border to the row path ends in a T-junction: the upper patch sees a straight
  // vertex there, so its side along the row has two arcs
  const int n = 8;
  Mesh m = grid(n);
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  Layout layout(m, field, no_singularity);
  Layout::Path row;
  for(int i = 0; i <= n; ++i) {
    row.vertices.push_back(V(4 * (n + 1) + i));
    if(i < n) row.directions.push_back(Vector_3(1, 0, 0));
  }
  layout.add_path(row);
  std::vector<Layout::Node> ends;
  for(int i = 0; i <= n; ++i) ends.push_back(layout.closest_node(V(4 * (n + 1) + i), Vector_3(0, 1, 0)));
  auto col = layout.trace(layout.closest_node(V(4), Vector_3(0, 1, 0)), ends);
  BOOST_REQUIRE(col);
  BOOST_TEST(col->vertices.size() == 5u);
  layout.add_path(*col);
  const auto s = layout.statistics();
  BOOST_TEST(s.patches == 3u);
  BOOST_TEST(s.valid_patches == 3u);
  BOOST_TEST(s.t_junctions == 1u);
  const std::size_t upper = layout.patch_id(F(std::size_t(2 * n * (n - 1))));
  std::size_t max_arcs = 0;
  for(const auto& side : layout.patches()[upper].sides) max_arcs = (std::max)(max_arcs, side.size());
  BOOST_TEST(max_arcs == 2u);
  BOOST_TEST(layout.quality(upper) == Layout::SATISFIED);
}

BOOST_AUTO_TEST_CASE(fandisk_features_and_tracing)
{
  Mesh m;
  BOOST_REQUIRE(CGAL::IO::read_OFF(qr_test::data_file("fandisk.off"), m));
  // a stand-in field until the cross field stage lands: the first axis most in each face plane
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(0, 0, 0)).first;
  for(F f : m.faces()) {
    const Vector_3 nn = CGAL::Polygon_mesh_processing::compute_face_normal(f, m);
    const Vector_3 axes[3] = {Vector_3(1, 0, 0), Vector_3(0, 1, 0), Vector_3(0, 0, 1)};
    double best = 2.;
    for(const Vector_3& a : axes) if(std::abs(a * nn) < best) { best = std::abs(a * nn); field[f] = a; }
  }
  auto feature = sharp_edges(m);
  Layout layout(m, field, no_singularity);
  const std::size_t added = layout.add_feature_paths(feature);
  BOOST_TEST(added > 0u);
  // every feature edge is on the boundary of patches, with a patch on both sides
  std::size_t covered = 0, features = 0;
  for(E e : m.edges()) if(feature[e]) ++features;
  for(const Layout::Arc& a : layout.arcs()) covered += a.halfedges.size();
  BOOST_TEST(covered == features);
  BOOST_TEST(layout.patches().size() > 1u);
  for(const Layout::Arc& a : layout.arcs()) BOOST_TEST((a.patches[0] >= 0 && a.patches[1] >= 0));

  // tracing 1000 candidate paths towards the feature lines (speed is printed, not checked)
  CGAL::Real_timer t;
  t.start();
  const auto size = layout.direction_graph_size();
  const double build = t.time();
  std::vector<Layout::Node> ends;
  for(V v : m.vertices())
    for(int k = 0; k < 4; ++k) {
      bool on_feature = false;
      for(auto h : CGAL::halfedges_around_target(v, m)) on_feature = on_feature || feature[m.edge(h)];
      if(on_feature) ends.push_back(Layout::Node{v, k});
    }
  std::size_t traced = 0, tangential = 0;
  std::vector<Layout::Path> found;
  for(std::size_t i = 0; i < 1000; ++i) {
    const V v(std::size_t((i * 7919) % m.number_of_vertices()));
    auto p = layout.trace(Layout::Node{v, int(i % 4)}, ends);
    if(!p) continue;
    ++traced;
    for(const auto& id : layout.path_ids()) tangential += layout.cross_tangentially(layout.path(id), *p) ? 1 : 0;
    found.push_back(*p);
  }
  t.stop();
  BOOST_TEST_MESSAGE("fandisk: G " << size.first << " nodes " << size.second << " arcs built in " << build
                     << " s; 1000 candidates (" << traced << " found) in " << t.time() << " s total");
  std::cerr << "[layout test] fandisk G: " << size.first << " nodes, " << size.second << " arcs, build " << build
            << " s; 1000 traces (" << traced << " found): " << t.time() << " s total\n";
  BOOST_TEST(traced > 500u);
  // a path ends on a feature but never runs along one
  BOOST_TEST(tangential == 0u);
  // consecutive vertices of a traced path are adjacent
  for(const auto& p : found)
    for(std::size_t i = 0; i + 1 < p.vertices.size(); ++i) BOOST_TEST(CGAL::edge(p.vertices[i], p.vertices[i + 1], m).second);

  std::ostringstream ply, pl;
  layout.write_ply(ply);
  layout.write_polylines(pl);
  BOOST_TEST(ply.str().find("element face " + std::to_string(m.number_of_faces())) != std::string::npos);
  const std::string lines = pl.str();
  BOOST_TEST(std::count(lines.begin(), lines.end(), '\n') == long(added));
}

// Issue #5: on fandisk, the patches cut by the feature paths alone (nothing traced yet) must turn at a few
// chosen vertices the way the geometry says. Feature edges: dihedral angle above 60 degrees (sharp_edges);
// the real cross field (compute_cross_field, aligned to those edges) and its singularities.
//
// How a turn is found (Patch_layout::classify): the field carried across the patch's fan from the incoming
// to the outgoing boundary edge gives the turn modulo 4 quarter turns; among those the one nearest to
// (pi - fan) / (pi / 2) is taken, the fan angle being scaled by 2 pi / (total angle at the vertex) when the
// vertex is a cone. The angles below were measured in fandisk.off (sum of the triangle angles at the vertex
// inside each patch).
BOOST_AUTO_TEST_CASE(fandisk_feature_patches_match_hand_check)
{
  Mesh m;
  BOOST_REQUIRE(CGAL::IO::read_OFF(qr_test::data_file("fandisk.off"), m));
  auto feature = sharp_edges(m);
  auto field = m.add_property_map<F, Vector_3>("f:cross_field", Vector_3(0, 0, 0)).first;
  auto singularity = m.add_property_map<V, int>("v:singularity", 0).first;
  CGAL::Quad_remeshing::compute_cross_field(m, feature, field);
  CGAL::Quad_remeshing::compute_cross_field_singularities(m, feature, field, singularity);
  Layout layout(m, field, singularity);
  BOOST_TEST(layout.add_feature_paths(feature) > 0u);

  typedef std::tuple<std::size_t, std::size_t, Layout::Turn> Seen; // (from, to, turn) of a passage
  auto seen = [&](V v) {
    std::set<Seen> s;
    for(const Passage& p : passages(layout, v)) s.insert(Seen{std::size_t(p.from), std::size_t(p.to), p.turn});
    return s;
  };
  // what the layout says, for the failure messages: patch, from -> to, turn (0 straight, 1 right, 2 left, 3 U)
  auto describe = [&](V v) {
    std::ostringstream o;
    for(const Passage& p : passages(layout, v))
      o << " [patch " << p.patch << ": " << p.from << " -> " << p.to << ", turn " << int(p.turn) << "]";
    return o.str();
  };
  auto distinct_patches = [&](V v) {
    std::set<std::size_t> s;
    for(const Passage& p : passages(layout, v)) s.insert(p.patch);
    return s.size();
  };
  const auto S = Layout::STRAIGHT, R = Layout::RIGHT_TURN, L = Layout::LEFT_TURN, U = Layout::U_TURN;

  // 1. Middle of a straight feature line: (-0.92, 0.962, -0.511) on the convex 90 degree edge between the
  // flat side x = -0.92 and the bottom z = -0.511, between feature neighbours a (towards the corner of check
  // 2) and b. Both sides are planar, each patch sees 180 degrees (total 360): measured 0; the field follows
  // the edge on both faces: turn 0 mod 4. Both patches: STRAIGHT.
  {
    const V v = vertex_at(m, Point_3(-0.9205710888, 0.9624140263, -0.5110649467));
    const V a = vertex_at(m, Point_3(-0.9205710888, 1.0, -0.5110649467));
    const V b = vertex_at(m, Point_3(-0.9205710888, 0.9248269796, -0.5110649467));
    BOOST_TEST((seen(v) == std::set<Seen>{{a, b, S}, {b, a, S}}), describe(v));
    BOOST_TEST(distinct_patches(v) == 2u);
  }
  // 2. Convex corner where three feature lines meet: (-0.92, 1, -0.511), a box corner of the flat side,
  // the bottom and the back y = 1; its three edges (to x, y and z neighbours) are convex, about 90 degrees.
  // Each patch sees 90 degrees of a 270 degree cone: scaled to 120, measured 2/3; the field turns by one
  // quarter: RIGHT_TURN in all three patches.
  {
    const V v = vertex_at(m, Point_3(-0.9205710888, 1.0, -0.5110649467));
    const V x = vertex_at(m, Point_3(-0.8830050826, 0.999473989, -0.5110649467));
    const V y = vertex_at(m, Point_3(-0.9205710888, 0.9624140263, -0.5110649467));
    const V z = vertex_at(m, Point_3(-0.9205710888, 0.9999009967, -0.4745078981));
    BOOST_TEST((seen(v) == std::set<Seen>{{x, z, R}, {z, y, R}, {y, x, R}}), describe(v));
    BOOST_TEST(distinct_patches(v) == 3u);
  }
  // 3. Concave corner: (-0.92, 0.159, -0.449), the inner corner of a notch of the flat side x = -0.92:
  // two convex edges on the flat side (to p and q) and a concave 90 degree edge into the body (to c).
  // On the flat side the patch sees 270 degrees (a reflex corner), of a 449 degree saddle: scaled to 216.5,
  // measured -0.41, the field turns by -1 quarter mod 4: LEFT_TURN (so that patch is not convex). On either
  // side of the concave edge the surface sees 90 degrees (scaled to 72, measured 1.2): RIGHT_TURN. Those two
  // sides are one patch: the valley line leaving towards c fades out (dihedral angle below 60 degrees) and
  // ends at (-0.230, 0.172, -0.155), 29 edges further, where that patch turns around it: a U_TURN.
  {
    const V v = vertex_at(m, Point_3(-0.9205710888, 0.1588989943, -0.4490569234));
    const V p = vertex_at(m, Point_3(-0.9205710888, 0.1969850063, -0.4423419237));
    const V q = vertex_at(m, Point_3(-0.9205710888, 0.1518210024, -0.4089189172));
    const V c = vertex_at(m, Point_3(-0.8845120668, 0.1587850004, -0.4483999014));
    BOOST_TEST((seen(v) == std::set<Seen>{{q, p, L}, {p, c, R}, {c, q, R}}), describe(v));
    BOOST_TEST(distinct_patches(v) == 2u);
    std::size_t valley_patch = 0;
    for(const Passage& s : passages(layout, v)) {
      if(s.turn == L) BOOST_TEST(layout.validity(s.patch) == Layout::NOT_CONVEX);
      else valley_patch = s.patch;
    }
    const V end = vertex_at(m, Point_3(-0.229738012, 0.1721359938, -0.1552259922));
    const auto at_end = passages(layout, end);
    BOOST_REQUIRE(at_end.size() == 1u);
    BOOST_TEST(at_end[0].turn == U);
    BOOST_TEST(at_end[0].from == at_end[0].to);
    BOOST_TEST(at_end[0].patch == valley_patch);
  }
  // 4. A feature line that bends in the bottom plane z = -0.511: (0.0022, -0.868, -0.511), between
  // neighbours a and b, with 157.3 degrees inside the bottom patch and 180 in the other (total 337.4):
  // scaled 167.9 / 192.1, measured +-0.13; the field, aligned to each edge, turns by less than 45 degrees
  // across the fan: turn 0 mod 4. A 23 degree bend is not a corner: STRAIGHT on both sides.
  {
    const V v = vertex_at(m, Point_3(0.0022240153, -0.8676739931, -0.5110650063));
    const V a = vertex_at(m, Point_3(-0.0053199446, -0.8305029869, -0.5110650063));
    const V b = vertex_at(m, Point_3(0.0230231546, -0.89833498, -0.5110650063));
    BOOST_TEST((seen(v) == std::set<Seen>{{a, b, S}, {b, a, S}}), describe(v));
  }
  // 5. The end of a feature line: (0.466, 0.184, -0.163), the only feature neighbour e (the ridge's
  // dihedral angle drops below 60 degrees past this vertex). The one patch around it comes in from e and
  // goes back to e around the whole fan (360 degrees): measured -2; the field turns by 2 quarters: U_TURN,
  // a dangling path end, so that patch is not convex.
  {
    const V v = vertex_at(m, Point_3(0.4664509892, 0.1840379983, -0.1631870419));
    const V e = vertex_at(m, Point_3(0.435608983, 0.2021259964, -0.1737110466));
    BOOST_TEST((seen(v) == std::set<Seen>{{e, e, U}}), describe(v));
    for(const Passage& s : passages(layout, v)) BOOST_TEST(layout.validity(s.patch) != Layout::SATISFIED);
  }
  // 6. A spike: at (-0.144, 0.092, -0.069) a convex ridge (to r, 75.6 degrees) turns back into a concave
  // valley (to w, 89.8 degrees); the edges are 18.5 degrees apart in one passage (measured 1.79) and 341.5
  // apart in the other (measured -1.79); in both the field turns by 2 quarters. The 18.5 degree tip between
  // two feature lines is a corner (Patch_layout::max_tip_angle): RIGHT_TURN from w to r; the other side,
  // which a path continuing the lines can fix, stays a U_TURN.
  {
    const V v = vertex_at(m, Point_3(-0.1437640041, 0.091902703, -0.0691067874));
    const V r = vertex_at(m, Point_3(-0.1654330194, 0.1088540033, -0.0941183865));
    const V w = vertex_at(m, Point_3(-0.1661170125, 0.0968298018, -0.0970444828));
    BOOST_TEST((seen(v) == std::set<Seen>{{r, w, U}, {w, r, R}}), describe(v));
  }
  // 7. A whole patch: the end face x = +0.92 is a planar quadrilateral bounded by four feature lines meeting
  // at four convex box corners like the one of check 2 (RIGHT_TURN each); the rest of its boundary is
  // straight. A 4-sided convex disk: valid.
  {
    const V corners[4] = {vertex_at(m, Point_3(0.9205709696, 0.0790281966, -0.5110620856)),
                          vertex_at(m, Point_3(0.9205709696, -0.2069880068, -0.5110650659)),
                          vertex_at(m, Point_3(0.9205710888, -0.2920680046, 0.4613988996)),
                          vertex_at(m, Point_3(0.9205710888, -0.0103957001, 0.5110649467))};
    std::optional<std::size_t> end_face;
    for(const Passage& s : passages(layout, corners[0]))
      if(m.point(s.from).x() > 0.92 && m.point(s.to).x() > 0.92) end_face = s.patch;
    BOOST_REQUIRE(end_face);
    const Layout::Patch& P = layout.patches()[*end_face];
    BOOST_TEST(P.corners.size() == 4u);
    for(const V c : corners) BOOST_TEST(std::count(P.corners.begin(), P.corners.end(), c) == 1);
    for(const Layout::Turn t : P.turns.at(0)) BOOST_TEST((t == S || t == R));
    BOOST_TEST(layout.validity(*end_face) == Layout::SATISFIED);
  }

  // Determinism: the same candidates traced on a second layout built the same way give the same paths.
  Layout again(m, field, singularity);
  again.add_feature_paths(feature);
  std::vector<Layout::Node> ends;
  for(V v : m.vertices())
    if(layout.is_on_cut(v)) for(int k = 0; k < 4; ++k) ends.push_back(Layout::Node{v, k});
  std::size_t compared = 0;
  for(std::size_t i = 0; i < 200; ++i) {
    const Layout::Node start{V(std::size_t((i * 7919) % m.number_of_vertices())), int(i % 4)};
    auto p1 = layout.trace(start, ends);
    auto p2 = again.trace(start, ends);
    BOOST_TEST(bool(p1) == bool(p2));
    if(p1 && p2) {
      ++compared;
      BOOST_TEST((p1->vertices == p2->vertices));
      BOOST_TEST((p1->directions == p2->directions));
    }
  }
  BOOST_TEST(compared > 100u);
}

BOOST_AUTO_TEST_CASE(rounds_repair_a_dangling_feature)
{
  // a feature line from the left border ending inside: the convexity round continues it to the border
  Mesh m = grid(6);
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  auto feature = m.add_property_map<E, bool>("e:feature", false).first;
  for(int i = 0; i < 3; ++i) feature[m.edge(m.halfedge(V(3 * 7 + i), V(3 * 7 + i + 1)))] = true;
  Layout layout(m, field, no_singularity);
  const auto s = CGAL::Quad_remeshing::trace_patch_layout(m, feature, layout);
  BOOST_TEST(s.layout.patches == 2u);
  BOOST_TEST(s.layout.valid_patches == s.layout.patches);
  BOOST_TEST(s.layout.quality_patches == 2u);
  const std::vector<std::string> names{"features", "convexity", "loops", "border_to_border", "recursion", "last_resort",
                                       "singularity_separation", "last_resort_cuts", "path_part_removal", "corners"};
  BOOST_TEST(s.rounds.size() == names.size());
  for(std::size_t i = 0; i < names.size() && i < s.rounds.size(); ++i) BOOST_TEST(s.rounds[i].name == names[i]);
  BOOST_TEST(s.rounds[1].paths >= 1u);
  // after the clean-up only the feature and its continuation remain
  BOOST_TEST(s.layout.paths == 2u);
  BOOST_TEST(s.report()["rounds"].size() == names.size());

  // the box: the features alone are a valid layout, nothing is added
  Mesh b = box(3);
  auto bf = axis_field(b);
  Layout box_layout(b, bf, no_singularity);
  const auto bs = CGAL::Quad_remeshing::trace_patch_layout(b, sharp_edges(b), box_layout);
  BOOST_TEST(bs.layout.patches == 6u);
  BOOST_TEST(bs.layout.paths == 12u);
  BOOST_TEST(bs.layout.valid_patches == 6u);
}

BOOST_AUTO_TEST_CASE(last_resort_cut_splits_a_concave_patch)
{
  // A feature line from the left border to (3,3), then up to the top border, leaves an L-shaped patch
  // with a left turn at (3,3): the last-resort cut continues one of the two legs to the border.
  const int n = 6;
  Mesh m = grid(n);
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  auto feature = m.add_property_map<E, bool>("e:feature", false).first;
  auto at = [&](int i, int j) { return V(j * (n + 1) + i); };
  for(int i = 0; i < 3; ++i) feature[m.edge(m.halfedge(at(i, 3), at(i + 1, 3)))] = true;
  for(int j = 3; j < n; ++j) feature[m.edge(m.halfedge(at(3, j), at(3, j + 1)))] = true;
  Layout layout(m, field, no_singularity);
  layout.add_feature_paths(feature);
  BOOST_REQUIRE(layout.number_of_patches() == 2u);
  std::size_t concave = 0, cuts_before = 0;
  for(std::size_t p = 0; p < 2; ++p) if(layout.validity(p) == Layout::NOT_CONVEX) concave = p;
  BOOST_REQUIRE(layout.validity(concave) == Layout::NOT_CONVEX);
  BOOST_REQUIRE(layout.validity(1 - concave) == Layout::SATISFIED);
  for(E e : m.edges()) cuts_before += layout.is_cut(e);

  CGAL::Quad_remeshing::internal::Layout_tracer<Layout> tracer(layout);
  BOOST_TEST(tracer.last_resort_cut(1 - concave) == 0u); // a valid patch is left alone
  BOOST_TEST(tracer.last_resort_cut(concave) == 1u);
  BOOST_TEST(layout.number_of_patches() == 3u);
  for(std::size_t p = 0; p < layout.number_of_patches(); ++p) BOOST_TEST(layout.validity(p) == Layout::SATISFIED);
  // the cut is one of the two straight continuations: three grid edges, from (3,3) to the border
  std::size_t cuts_after = 0;
  for(E e : m.edges()) cuts_after += layout.is_cut(e);
  BOOST_TEST(cuts_after == cuts_before + 3u);
  const bool right = layout.is_cut(m.edge(m.halfedge(at(3, 3), at(4, 3)))) && layout.is_cut(m.edge(m.halfedge(at(5, 3), at(6, 3))));
  const bool down = layout.is_cut(m.edge(m.halfedge(at(3, 3), at(3, 2)))) && layout.is_cut(m.edge(m.halfedge(at(3, 1), at(3, 0))));
  BOOST_TEST((right || down));
  for(E e : m.edges()) if(feature[e]) BOOST_TEST(layout.is_cut(e));
  // nothing is left to cut
  for(std::size_t p = 0; p < layout.number_of_patches(); ++p) BOOST_TEST(tracer.last_resort_cut(p) == 0u);
}

BOOST_AUTO_TEST_CASE(last_resort_split_follows_the_field)
{
  // A square feature loop inside a grid leaves an annulus around it. The last resort joins its two loops;
  // with the field at atan(1/2) (26.6 degrees) from the x axis, the Euclidean shortest cut would run along
  // a grid axis, perpendicular to the border, and make turns all along; the traced cut follows the field.
  const int n = 12;
  Mesh m = grid(n);
  const Vector_3 d(2. / std::sqrt(5.), 1. / std::sqrt(5.), 0.);
  auto field = m.add_property_map<F, Vector_3>("f:field", d).first;
  auto feature = m.add_property_map<E, bool>("e:feature", false).first;
  auto at = [&](int i, int j) { return V(j * (n + 1) + i); };
  for(int k = 5; k < 7; ++k) {
    feature[m.edge(m.halfedge(at(k, 5), at(k + 1, 5)))] = true;
    feature[m.edge(m.halfedge(at(k, 7), at(k + 1, 7)))] = true;
    feature[m.edge(m.halfedge(at(5, k), at(5, k + 1)))] = true;
    feature[m.edge(m.halfedge(at(7, k), at(7, k + 1)))] = true;
  }
  Layout layout(m, field, no_singularity);
  layout.add_feature_paths(feature);
  BOOST_REQUIRE(layout.number_of_patches() == 2u);
  std::size_t annulus = 0;
  for(std::size_t p = 0; p < 2; ++p) if(layout.validity(p) == Layout::NOT_A_DISK) annulus = p;
  BOOST_REQUIRE(layout.validity(annulus) == Layout::NOT_A_DISK);
  std::vector<char> was_cut;
  for(E e : m.edges()) was_cut.push_back(layout.is_cut(e));

  CGAL::Quad_remeshing::internal::Layout_tracer<Layout> tracer(layout);
  BOOST_TEST(tracer.last_resort_split(annulus) == 1u);
  for(std::size_t p = 0; p < layout.number_of_patches(); ++p) BOOST_TEST(layout.validity(p) != Layout::NOT_A_DISK);
  // the new cut edges: their sum (the chord of the cut, up to sign per edge) is within 15 degrees of a field direction
  Vector_3 chord(0, 0, 0);
  std::size_t added = 0;
  for(E e : m.edges()) {
    if(!layout.is_cut(e) || was_cut[std::size_t(e)]) continue;
    ++added;
    Vector_3 u = m.point(m.target(m.halfedge(e))) - m.point(m.source(m.halfedge(e)));
    if(u * d < 0. || (u * d == 0. && u * Vector_3(-d.y(), d.x(), 0.) < 0.)) u = -u;
    chord = chord + u;
  }
  BOOST_TEST(added >= 2u);
  const double l = std::sqrt(chord * chord);
  const double cosine = (std::max)(std::abs(chord * d), std::abs(chord * Vector_3(-d.y(), d.x(), 0.))) / l;
  BOOST_TEST_MESSAGE("last-resort split: " << added << " edges, chord " << chord << ", cosine to the field " << cosine);
  BOOST_TEST(cosine > std::cos(15. * CGAL_PI / 180.));
}

BOOST_AUTO_TEST_CASE(path_part_removal_merges_a_concave_patch)
{
  // Path A runs along row 4 from border to border. Path U comes down column 1 from the top border, crosses
  // A, turns right along row 2 and comes back up column 4 to end on A. The patch under A, outside U, has
  // two left turns at (1,2) and (4,2); the whole of U cannot go (its upper part splits the top strip), but
  // its part from the crossing (1,4) to (4,4) can: the patch then merges with the one inside U.
  const int n = 6;
  Mesh m = grid(n);
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  auto at = [&](int i, int j) { return V(j * (n + 1) + i); };
  auto path = [&](const std::vector<std::pair<int, int>>& ij) {
    Layout::Path p;
    for(const auto& c : ij) p.vertices.push_back(at(c.first, c.second));
    for(std::size_t k = 0; k + 1 < p.vertices.size(); ++k) {
      const Vector_3 d = m.point(p.vertices[k + 1]) - m.point(p.vertices[k]);
      p.directions.push_back(d / std::sqrt(d.squared_length()));
    }
    return p;
  };
  const Layout::Path a = path({{0, 4}, {1, 4}, {2, 4}, {3, 4}, {4, 4}, {5, 4}, {6, 4}});
  const Layout::Path u = path({{1, 6}, {1, 5}, {1, 4}, {1, 3}, {1, 2}, {2, 2}, {3, 2}, {4, 2}, {4, 3}, {4, 4}});
  Layout layout(m, field, no_singularity);
  layout.add_path(a);
  const std::size_t u_id = layout.add_path(u);
  BOOST_REQUIRE(layout.number_of_patches() == 4u);
  const std::size_t outside = layout.patch_id(m.face(m.halfedge(at(0, 0), at(1, 0))));
  BOOST_REQUIRE(layout.validity(outside) == Layout::NOT_CONVEX);
  BOOST_TEST(layout.is_on_feature_path(m.edge(m.halfedge(at(0, 4), at(1, 4)))) == false);
  BOOST_TEST(layout.number_of_paths(m.edge(m.halfedge(at(1, 4), at(1, 3)))) == 1);

  // the public operation: preview, then remove the part of U from its vertex 2 to its vertex 9
  auto change = layout.preview_remove_path_part(u_id, 2, 9);
  BOOST_TEST(change.old_patches.size() == 2u);
  BOOST_TEST(change.new_patches.size() == 1u);
  BOOST_TEST(layout.number_of_patches() == 4u); // a preview changes nothing
  BOOST_CHECK_THROW(layout.preview_remove_path_part(u_id, 5, 5), std::invalid_argument);
  const std::vector<std::size_t> kept = layout.remove_path_part(u_id, 2, 9, std::move(change));
  BOOST_TEST_REQUIRE(kept.size() == 1u); // the upper piece; nothing comes after vertex 9
  BOOST_TEST((layout.path(kept[0]).vertices == std::vector<V>{at(1, 6), at(1, 5), at(1, 4)}));
  BOOST_TEST(layout.path(kept[0]).directions.size() == 2u);
  BOOST_TEST(layout.path_ids().size() == 2u);
  BOOST_TEST(layout.number_of_patches() == 3u);
  for(std::size_t p = 0; p < layout.number_of_patches(); ++p) BOOST_TEST(layout.validity(p) == Layout::SATISFIED);
  BOOST_TEST(!layout.is_cut(m.edge(m.halfedge(at(1, 3), at(1, 4)))));
  BOOST_TEST(layout.is_cut(m.edge(m.halfedge(at(1, 4), at(1, 5)))));
  // the same patches as a layout built with the paths left
  Layout fresh(m, field, no_singularity);
  fresh.add_path(a);
  fresh.add_path(layout.path(kept[0]));
  BOOST_TEST_REQUIRE(fresh.number_of_patches() == layout.number_of_patches());
  for(F f : m.faces())
    for(F g : m.faces()) if((fresh.patch_id(f) == fresh.patch_id(g)) != (layout.patch_id(f) == layout.patch_id(g))) BOOST_FAIL("patches differ");

  // the tracer finds that part by itself: between the junctions (1,4) and (4,4), the only part whose
  // removal makes the concave patch valid
  Layout traced(m, field, no_singularity);
  traced.add_path(a);
  traced.add_path(u);
  CGAL::Quad_remeshing::internal::Layout_tracer<Layout> tracer(traced);
  const std::size_t concave = traced.patch_id(m.face(m.halfedge(at(0, 0), at(1, 0))));
  for(std::size_t p = 0; p < traced.number_of_patches(); ++p)
    if(p != concave) BOOST_TEST(tracer.merge_across_path_part(p, false) == 0u); // valid patches are left alone
  BOOST_TEST(tracer.merge_across_path_part(concave, false) == 1u);
  BOOST_TEST(traced.number_of_patches() == 3u);
  BOOST_TEST(tracer.invalid_patches() == 0u);
  BOOST_TEST(!traced.is_cut(m.edge(m.halfedge(at(2, 2), at(3, 2)))));
  BOOST_TEST(traced.is_cut(m.edge(m.halfedge(at(1, 5), at(1, 6)))));
  BOOST_TEST(traced.is_cut(m.edge(m.halfedge(at(3, 4), at(4, 4)))));
}

BOOST_AUTO_TEST_CASE(fandisk_rounds)
{
  Mesh m;
  BOOST_REQUIRE(CGAL::IO::read_OFF(qr_test::data_file("fandisk.off"), m));
  auto feature = sharp_edges(m);
  // stand-in field (see fandisk_features_and_tracing) so that this test does not depend on the cross-field
  // stage; the integrator should switch it to compute_cross_field
  auto field = stand_in_field(m);
  Layout layout(m, field, no_singularity);
  const auto s = CGAL::Quad_remeshing::trace_patch_layout(m, feature, layout);
  std::cerr << "[layout test] fandisk rounds: " << s.layout.valid_patches << "/" << s.layout.patches << " valid, "
            << s.layout.quality_patches << " quality, " << s.layout.paths << " paths, " << s.seconds << " s\n";
  // every feature edge stays on a patch boundary
  for(E e : m.edges()) if(feature[e]) BOOST_TEST(layout.is_cut(e));
  // every patch valid (309 of 309 with the stand-in field)
  BOOST_TEST(s.layout.valid_patches == s.layout.patches);
  BOOST_TEST(s.layout.paths >= s.rounds[0].paths);
  BOOST_TEST(s.stopped_in_round.empty());
  BOOST_TEST(s.rounds.size() == 10u);

  // the candidates traced in three threads: the same layout
  Layout parallel(m, field, no_singularity);
  const auto sp = CGAL::Quad_remeshing::trace_patch_layout(m, feature, parallel,
                                                           CGAL::Quad_remeshing::parameters::number_of_threads(3));
  BOOST_TEST(sp.layout.paths == s.layout.paths);
  BOOST_TEST_REQUIRE(parallel.number_of_patches() == layout.number_of_patches());
  std::size_t same_patch = 0;
  for(F f : m.faces()) same_patch += parallel.patch_id(f) == layout.patch_id(f);
  BOOST_TEST(same_patch == m.number_of_faces());

  // A time limit stops the rounds after the convexity round (which always runs) and skips the later ones
  // but the last resort: the layout is still one of disks with every feature on a patch boundary.
  Layout cut(m, field, no_singularity);
  const auto sc = CGAL::Quad_remeshing::trace_patch_layout(m, feature, cut, CGAL::parameters::maximum_running_time(1e-9));
  BOOST_TEST(sc.stopped_in_round == "loops");
  std::vector<std::string> names;
  for(const auto& r : sc.rounds) names.push_back(r.name);
  BOOST_TEST((names == std::vector<std::string>{"features", "convexity", "loops", "last_resort", "last_resort_cuts",
                                                     "path_part_removal", "corners"}));
  BOOST_TEST(sc.rounds[1].paths == s.rounds[1].paths); // the convexity round ran to its end
  BOOST_TEST(sc.rounds[2].paths == 0u);
  BOOST_TEST(sc.report().find("stopped_early")->boolean());
  BOOST_TEST(sc.layout.paths < s.layout.paths);
  for(std::size_t p = 0; p < cut.number_of_patches(); ++p) BOOST_TEST(cut.validity(p) != Layout::NOT_A_DISK);
  for(E e : m.edges()) if(feature[e]) BOOST_TEST(cut.is_cut(e));
}

// The stages before the layout refinement, as quad_remesh() runs them, on the mesh in `file`.
struct Traced_for_refinement
{
  Mesh m;
  Mesh::Property_map<E, bool> feature;
  Mesh::Property_map<F, Vector_3> field;
  Mesh::Property_map<V, int> singularity;
  std::unique_ptr<Layout> layout;
  CGAL::Quad_remeshing::Trace_patch_layout_statistics st;

  // `shift`: a translation of the input, in bounding-box diagonals along (1, -2, 3)
  explicit Traced_for_refinement(const std::string& file, double shift = 0.)
  {
    namespace QR = CGAL::Quad_remeshing;
    QR::read_and_repair(qr_test::data_file(file), m);
    if(shift != 0.) {
      const double d = QR::internal::mesh_bbox_diagonal(m);
      const Vector_3 t(shift * d, -2. * shift * d, 3. * shift * d);
      for(V v : m.vertices()) m.point(v) = m.point(v) + t;
    }
    feature = m.add_property_map<E, bool>("e:feature", false).first;
    auto corner = m.add_property_map<V, bool>("v:corner", false).first;
    QR::detect_feature_edges(m, feature, QR::parameters::vertex_is_feature_corner_map(corner));
    // (without the far-region refinement, as quad_remesh() by default)
    QR::remesh_for_quadrangulation(m, feature, QR::parameters::combine(QR::parameters::quad_edge_length(QR::default_quad_edge_length(m)),
                                                                       QR::parameters::vertex_is_feature_corner_map(corner),
                                                                       QR::parameters::far_region_rounds(0u)));
    m.collect_garbage();
    field = m.add_property_map<F, Vector_3>("f:cross_field", Vector_3(0, 0, 0)).first;
    singularity = m.add_property_map<V, int>("v:singularity", 0).first;
    QR::compute_cross_field(m, feature, field);
    QR::compute_cross_field_singularities(m, feature, field, singularity);
    layout = std::make_unique<Layout>(m, field, singularity);
    st = QR::trace_patch_layout(m, feature, *layout);
  }
};

// elephant moved by ten diagonals: the rounding of the moved coordinates changes the remeshing a little,
// and the layout before the clean-up then left a three-sided patch of 878 triangles around 9 singularities
// (a bulge the field turns around), whose quads were stretched over it, 6.3% of the diagonal from the
// input (qmeval). The singularity separation splits such patches until every part has fewer
// singularities, each part valid.
BOOST_AUTO_TEST_CASE(singularity_separation_splits_a_bulge)
{
  Traced_for_refinement t("elephant.off", 10.);
  const auto& st = t.st;
  const auto& layout = *t.layout;
  auto round = std::find_if(st.rounds.begin(), st.rounds.end(),
                            [](const auto& r) { return r.name == "singularity_separation"; });
  BOOST_TEST_REQUIRE((round != st.rounds.end()));
  BOOST_TEST(round->paths >= 1u);
  std::size_t most = 0, faces = 0;
  for(std::size_t p = 0; p < layout.number_of_patches(); ++p) {
    const auto& P = layout.patch(p);
    if(layout.validity(p) != Layout::SATISFIED || P.singularities.size() < 2) continue;
    most = (std::max)(most, P.singularities.size());
    faces += P.faces.size();
  }
  BOOST_TEST_MESSAGE("  elephant moved: " << round->paths << " separating paths, at most " << most
                     << " singularities in a valid patch, " << faces << " faces in the valid patches with several");
  // without the round: 9 singularities, 1042 faces
  BOOST_TEST(most <= 4u);
  BOOST_TEST(faces <= 300u);
  for(E e : t.m.edges()) if(t.feature[e]) BOOST_TEST(layout.is_cut(e));
}

// bunny through the stages as quad_remesh() runs them: a held crease ends in a sharp tip, and the patch
// beside it keeps a left turn where the crease bends back, because no vertex of the remeshed triangles
// lies where a cut from there would meet the other side of the thin wedge at a right angle.
// refine_patch_layout() makes that vertex (and puts the one between on the cut's line); the repair then
// cuts the patch, and every patch is valid.
BOOST_AUTO_TEST_CASE(refinement_gives_the_tip_cut_its_vertex)
{
  namespace QR = CGAL::Quad_remeshing;
  Traced_for_refinement t("bunny.off");
  Mesh& m = t.m;
  auto& feature = t.feature;
  auto& field = t.field;
  auto& singularity = t.singularity;
  auto& layout = t.layout;
  auto& st = t.st;
  const std::size_t rounds = st.rounds.size(), invalid = st.layout.patches - st.layout.valid_patches;
  BOOST_TEST_REQUIRE(invalid >= 1u);
  std::size_t features_before = 0, paths_before = 0;
  for(E e : m.edges()) features_before += feature[e];
  for(std::size_t id : layout->path_ids()) paths_before += !layout->path(id).is_feature;
  const std::size_t vertices_before = m.number_of_vertices(), faces_before = m.number_of_faces();

  const QR::Refine_patch_layout_statistics rs = QR::refine_patch_layout(m, feature, field, singularity, layout, st);
  BOOST_TEST_MESSAGE("  bunny: " << rs.split_edges << " edges split, invalid patches " << rs.invalid_before << " -> "
                     << rs.invalid_after);
  BOOST_TEST(rs.invalid_before == invalid);
  BOOST_TEST_REQUIRE(rs.split_edges >= 1u);
  BOOST_TEST(rs.passes == 1u); // no invalid patch is left for a second
  BOOST_TEST(rs.invalid_after < rs.invalid_before);
  BOOST_TEST(rs.invalid_after == st.layout.patches - st.layout.valid_patches);
  BOOST_TEST(st.layout.valid_patches == st.layout.patches);
  // the repair's rounds follow the trace's
  BOOST_TEST_REQUIRE(st.rounds.size() == rounds + 3u);
  BOOST_TEST(st.rounds.back().name == "refined_corners");
  // each split adds a vertex and, inside a closed mesh, two faces; a split feature edge is two of them
  BOOST_TEST(m.is_valid(false));
  BOOST_TEST(CGAL::is_triangle_mesh(m));
  BOOST_TEST(m.number_of_vertices() == vertices_before + rs.split_edges);
  BOOST_TEST(m.number_of_faces() == faces_before + 2u * rs.split_edges);
  std::size_t features_after = 0;
  for(E e : m.edges()) {
    features_after += feature[e];
    if(feature[e]) BOOST_TEST(layout->is_cut(e));
  }
  BOOST_TEST(features_after >= features_before);
  BOOST_TEST(features_after <= features_before + rs.split_edges);
  // the traced paths are all there, and the repair's cuts with them
  std::size_t paths_after = 0;
  for(std::size_t id : layout->path_ids()) paths_after += !layout->path(id).is_feature;
  BOOST_TEST(paths_after > paths_before);
  for(std::size_t p = 0; p < layout->number_of_patches(); ++p) BOOST_TEST(layout->validity(p) == Layout::SATISFIED);

  // a layout whose patches are all valid is left alone
  const Layout* same = layout.get();
  const QR::Refine_patch_layout_statistics again = QR::refine_patch_layout(m, feature, field, singularity, layout, st);
  BOOST_TEST(again.split_edges == 0u);
  BOOST_TEST(layout.get() == same);
  BOOST_TEST(m.number_of_vertices() == vertices_before + rs.split_edges);
}

// Fertility's invalid patch is a wedge of 15 faces whose landing point lies between two and four times
// the concave vertex's longer boundary edge away: the reach is four.
BOOST_AUTO_TEST_CASE(refinement_reaches_across_a_wider_wedge)
{
  namespace QR = CGAL::Quad_remeshing;
  Traced_for_refinement t("fertility.off");
  const std::size_t invalid = t.st.layout.patches - t.st.layout.valid_patches;
  BOOST_TEST_REQUIRE(invalid >= 1u);
  const QR::Refine_patch_layout_statistics rs = QR::refine_patch_layout(t.m, t.feature, t.field, t.singularity, t.layout, t.st);
  BOOST_TEST_MESSAGE("  fertility: " << rs.split_edges << " edges split, invalid patches " << rs.invalid_before << " -> "
                     << rs.invalid_after);
  BOOST_TEST(rs.invalid_before == invalid);
  BOOST_TEST(rs.split_edges >= 1u);
  BOOST_TEST(rs.invalid_after == 0u);
  BOOST_TEST(t.m.is_valid(false));
  for(std::size_t p = 0; p < t.layout->number_of_patches(); ++p) BOOST_TEST(t.layout->validity(p) == Layout::SATISFIED);
  for(E e : t.m.edges())
    if(t.feature[e]) BOOST_TEST(t.layout->is_cut(e));
}

// Elephant's layout keeps non-convex patches whose left turn or hairpin has no landing point: a sharp tip
// of a held crease, where a path leaves the line. A straight cut extending a side at the turn, its
// crossings of the triangles made vertices, is inserted and lowers the number of invalid patches; the
// split faces lie in the triangles they come from, so that part of the refinement leaves the surface as
// it was.
BOOST_AUTO_TEST_CASE(refinement_cuts_straight_where_no_landing_point)
{
  namespace QR = CGAL::Quad_remeshing;
  Traced_for_refinement t("elephant.off");
  Mesh& m = t.m;
  const std::size_t invalid = t.st.layout.patches - t.st.layout.valid_patches;
  BOOST_TEST_REQUIRE(invalid >= 1u);
  const std::size_t vertices_before = m.number_of_vertices(), faces_before = m.number_of_faces();
  const QR::Refine_patch_layout_statistics rs = QR::refine_patch_layout(m, t.feature, t.field, t.singularity, t.layout, t.st);
  BOOST_TEST_MESSAGE("  elephant: " << rs.split_edges << " edges split, " << rs.straight_cuts << " straight cuts ("
                     << rs.straight_cuts_kept << " inserted), invalid patches " << rs.invalid_before << " -> " << rs.invalid_after);
  BOOST_TEST(rs.invalid_before == invalid);
  BOOST_TEST_REQUIRE(rs.straight_cuts_kept >= 1u);
  BOOST_TEST(rs.straight_cuts_kept <= rs.straight_cuts);
  BOOST_TEST(rs.invalid_after < rs.invalid_before);
  BOOST_TEST(rs.invalid_after == t.st.layout.patches - t.st.layout.valid_patches);
  // a closed triangle mesh still, each split vertex with two more faces
  BOOST_TEST(m.is_valid(false));
  BOOST_TEST(CGAL::is_triangle_mesh(m));
  BOOST_TEST(CGAL::is_closed(m));
  BOOST_TEST(m.number_of_vertices() == vertices_before + rs.split_edges);
  BOOST_TEST(m.number_of_faces() == faces_before + 2u * rs.split_edges);
  for(F f : m.faces()) BOOST_TEST(CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, m)) > 0.);
  for(E e : m.edges())
    if(t.feature[e]) BOOST_TEST(t.layout->is_cut(e));
  // a straight cut is in the layout: a path that is not a feature, at least two edges long, whose inner
  // vertices are all new, and the cut is straight there (each inner vertex between its neighbours)
  std::size_t straight = 0;
  for(std::size_t id : t.layout->path_ids()) {
    const Layout::Path& q = t.layout->path(id);
    if(q.is_feature || q.vertices.size() < 3) continue;
    bool cut = true;
    for(std::size_t k = 1; k + 1 < q.vertices.size() && cut; ++k) {
      cut = std::size_t(q.vertices[k]) >= vertices_before;
      const Vector_3 a = m.point(q.vertices[k]) - m.point(q.vertices[k - 1]);
      const Vector_3 b = m.point(q.vertices[k + 1]) - m.point(q.vertices[k]);
      cut = cut && a * b > 0.;
    }
    straight += cut;
  }
  BOOST_TEST(straight >= 1u);
}

BOOST_AUTO_TEST_CASE(quad_sizing_follows_curvature)
{
  namespace QRI = CGAL::Quad_remeshing::internal;
  const double L = 0.4;
  // a cap of the unit sphere: normal curvature 1, so a quad diagonal's sagitta h^2 / 4 meets the
  // tolerance 0.01 at h = 0.2, inside the clamp [L/4, L]
  Mesh cap;
  BOOST_REQUIRE(CGAL::IO::read_OFF(qr_test::data_file("hemisphere.off"), cap));
  const CGAL::Constant_property_map<E, bool> no_feature(false);
  std::vector<double> h = QRI::curvature_quad_sizing(cap, no_feature, L, 0.01);
  BOOST_REQUIRE(h.size() == num_vertices(cap));
  for(double x : h)
  {
    BOOST_TEST(x > 0.16);
    BOOST_TEST(x < 0.21);
  }
  for(double x : QRI::curvature_quad_sizing(cap, no_feature, L, 1e-6)) BOOST_TEST(x == L / 4, boost::test_tools::tolerance(1e-12));
  for(double x : QRI::curvature_quad_sizing(cap, no_feature, L, 1.)) BOOST_TEST(x == L);

  // a flat grid bounded by straight feature lines keeps the global length: corners are not bends
  Mesh flat = grid(8);
  auto border = flat.add_property_map<E, bool>("e:border", false).first;
  for(E e : flat.edges()) border[e] = flat.is_border(e);
  for(double x : QRI::curvature_quad_sizing(flat, border, 2., 1e-3)) BOOST_TEST(x == 2.);

  // fandisk mixes flat and curved parts: sizes vary, graded by at most half the edge length
  Mesh fan;
  BOOST_REQUIRE(CGAL::IO::read_OFF(qr_test::data_file("fandisk.off"), fan));
  const auto fan_features = sharp_edges(fan);
  h = QRI::curvature_quad_sizing(fan, fan_features, 0.1, 1e-4);
  BOOST_TEST(*std::min_element(h.begin(), h.end()) < 0.05);
  BOOST_TEST(*std::max_element(h.begin(), h.end()) == 0.1);
  for(E e : fan.edges())
  {
    const std::size_t a = std::size_t(source(e, fan)), b = std::size_t(target(e, fan));
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(fan.point(source(e, fan)), fan.point(target(e, fan)))));
    BOOST_TEST(std::abs(h[a] - h[b]) <= 0.5 * d + 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(bad_input)
{
  Mesh m = grid(2);
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  Layout layout(m, field, no_singularity);
  Layout::Path p;
  p.vertices = {V(0), V(8)};
  p.directions = {Vector_3(1, 0, 0)};
  BOOST_CHECK_THROW(layout.add_path(p), std::invalid_argument);
  BOOST_CHECK_THROW(layout.remove_path(3), std::invalid_argument);
}

// The local update of a candidate (preview + add) must give the same patches as a full rebuild, and the
// incrementally updated graph G the same traces as a graph built from scratch.
BOOST_AUTO_TEST_CASE(local_updates_match_a_full_rebuild)
{
  Mesh m;
  BOOST_REQUIRE(CGAL::IO::read_OFF(qr_test::data_file("fandisk.off"), m));
  auto feature = sharp_edges(m);
  auto field = stand_in_field(m);
  Layout layout(m, field, no_singularity);
  layout.add_feature_paths(feature);
  std::vector<Layout::Node> ends;
  auto boundary_ends = [&] {
    ends.clear();
    for(V v : m.vertices()) if(layout.is_on_cut(v)) for(int k = 0; k < 4; ++k) ends.push_back(Layout::Node{v, k});
  };
  boundary_ends();
  std::size_t added = 0, compared = 0;
  for(V v : m.vertices()) {
    if(added == 12) break;
    if(std::size_t(v) % 97 != 0 || layout.is_on_cut(v)) continue;
    auto c = layout.trace(Layout::Node{v, 0}, ends);
    if(!c || layout.crosses_paths_tangentially(*c)) continue;
    const std::size_t before = layout.number_of_patches();
    auto change = layout.preview_add_path(*c);
    BOOST_TEST(layout.number_of_patches() == before); // a preview changes nothing
    layout.add_path(*c, std::move(change));
    ++added;
    // the same layout rebuilt from scratch
    Layout fresh(m, field, no_singularity);
    for(std::size_t id : layout.path_ids()) fresh.add_path(layout.path(id));
    BOOST_REQUIRE(fresh.number_of_patches() == layout.number_of_patches());
    std::map<std::vector<std::size_t>, Layout::Condition> a, b;
    for(std::size_t p = 0; p < layout.number_of_patches(); ++p) {
      std::vector<std::size_t> fa, fb;
      for(F f : layout.patch(p).faces) fa.push_back(std::size_t(f));
      for(F f : fresh.patch(p).faces) fb.push_back(std::size_t(f));
      a[fa] = layout.quality(p);
      b[fb] = fresh.quality(p);
    }
    BOOST_TEST((a == b));
    // traces on the incrementally updated G and on a fresh G agree; after every third path G is released
    // (release_direction_graph()): the next trace builds it whole, and the local updates go on from that
    if(added % 3 == 0) layout.release_direction_graph();
    boundary_ends();
    for(V w : m.vertices()) {
      if(std::size_t(w) % 211 != 0 || layout.is_on_cut(w)) continue;
      auto t1 = layout.trace(Layout::Node{w, 1}, ends);
      auto t2 = fresh.trace(Layout::Node{w, 1}, ends);
      BOOST_TEST(bool(t1) == bool(t2));
      if(t1 && t2) { BOOST_TEST((t1->vertices == t2->vertices)); ++compared; }
    }
  }
  BOOST_TEST(added == 12u);
  BOOST_TEST(compared > 20u);
  // removing paths through the local update gives back the feature layout
  const auto ids = layout.path_ids();
  for(auto it = ids.rbegin(); it != ids.rbegin() + 12; ++it) layout.remove_path(*it, layout.preview_remove_path(*it));
  Layout features_only(m, field, no_singularity);
  features_only.add_feature_paths(feature);
  BOOST_TEST(layout.number_of_patches() == features_only.number_of_patches());
}

// Two feature lines meeting at 6 degrees cut off a sliver whose tip no path can enter: the tip is a corner
// (a right turn), so the sliver is a valid triangle patch. The same lines as traced paths, which the tracer
// may remove, leave the tip a U-turn; on the other side of the tip (a patch angle of 354 degrees, where a
// path can continue the lines) the turn stays a U-turn.
BOOST_AUTO_TEST_CASE(feature_tip_is_a_corner)
{
  const int n = 4;
  Mesh m = fan_disk(n);
  auto field = m.add_property_map<F, Vector_3>("f:field", Vector_3(1, 0, 0)).first;
  const V O(0);
  // the two rays, one feature chain through O (feature degree two there)
  Layout::Path lines;
  for(int r = n; r >= 1; --r) lines.vertices.push_back(V(1 + (r - 1) * 13 + 1));
  lines.vertices.push_back(O);
  for(int r = 1; r <= n; ++r) lines.vertices.push_back(V(1 + (r - 1) * 13));
  for(std::size_t i = 0; i + 1 < lines.vertices.size(); ++i) {
    const Vector_3 d = m.point(lines.vertices[i + 1]) - m.point(lines.vertices[i]);
    lines.directions.push_back(d / std::sqrt(d * d));
  }
  auto sliver_of = [&](const Layout& layout) {
    const F f = m.face(m.halfedge(O, V(1)));
    BOOST_REQUIRE(m.target(m.next(m.halfedge(O, V(1)))) == V(2)); // the face O, ray 0, ray 6 degrees
    return layout.patch_id(f);
  };
  auto turn_at_O = [&](const Layout& layout, std::size_t patch) {
    for(const Passage& q : passages(layout, O)) if(q.patch == patch) return q.turn;
    BOOST_FAIL("O is not on patch " << patch);
    return Layout::STRAIGHT;
  };
  for(bool feature : {true, false}) {
    BOOST_TEST_CONTEXT("feature lines: " << feature)
    {
      Layout layout(m, field, no_singularity);
      Layout::Path p = lines;
      p.is_feature = feature;
      // the preview sees the same turns as the layout once the path is added
      const auto change = layout.preview_add_path(p);
      layout.add_path(p);
      BOOST_REQUIRE(layout.number_of_patches() == 2u);
      BOOST_REQUIRE(change.new_patches.size() == 2u);
      const std::size_t sliver = sliver_of(layout), other = 1 - sliver;
      BOOST_TEST(layout.patch(sliver).faces.size() == std::size_t(2 * n - 1));
      BOOST_TEST(turn_at_O(layout, sliver) == (feature ? Layout::RIGHT_TURN : Layout::U_TURN));
      BOOST_TEST(turn_at_O(layout, other) == Layout::U_TURN);
      BOOST_TEST(layout.validity(sliver) == (feature ? Layout::SATISFIED : Layout::NOT_CONVEX));
      for(const Layout::Patch& P : change.new_patches)
        if(P.faces.size() == layout.patch(sliver).faces.size()) BOOST_TEST(layout.validity(P) == layout.validity(sliver));
      if(feature) {
        BOOST_TEST(layout.patch(sliver).corners.size() == 3u);
        BOOST_TEST(layout.patches()[sliver].sides.size() == 3u);
      }
    }
  }
  // the rounds keep the feature lines and make every patch valid
  auto is_feature = m.add_property_map<E, bool>("e:feature", false).first;
  for(std::size_t i = 0; i + 1 < lines.vertices.size(); ++i) is_feature[m.edge(m.halfedge(lines.vertices[i], lines.vertices[i + 1]))] = true;
  Layout layout(m, field, no_singularity);
  const auto s = CGAL::Quad_remeshing::trace_patch_layout(m, is_feature, layout);
  BOOST_TEST(s.layout.valid_patches == s.layout.patches);
  for(E e : m.edges()) if(is_feature[e]) BOOST_TEST(layout.is_cut(e));
}

// A lens of feature lines too small for any path: on the border of a flat 4 x 4 square, the border edge
// a-b and the feature lines a-c-b (c 0.35 above the middle of a-b) bound 3 triangles around O. Its tips
// a and b (19 degrees) are its only corners, c is straight, so it has 2 corners; no cut through O helps
// (the piece around O turns left). The round `corners` makes c a corner of the lens only: the lens is a
// valid triangle, and c stays a point of the square's bottom side.
BOOST_AUTO_TEST_CASE(feature_lens_gets_a_third_corner)
{
  Mesh m;
  std::map<std::pair<int, int>, V> g; // the grid vertices, x and y in 0..4 (no (1,0) to (3,0) inside the lens)
  for(int j = 0; j <= 4; ++j)
    for(int i = 0; i <= 4; ++i)
      if(j > 0 || i != 2) g[{i, j}] = m.add_vertex(Point_3(i, j, 0));
  const V a = g[{1, 0}], b = g[{3, 0}];
  const V c = m.add_vertex(Point_3(2, 0.35, 0)), O = m.add_vertex(Point_3(2, 0.15, 0));
  auto face = [&](V x, V y, V z) { BOOST_REQUIRE(m.add_face(x, y, z) != Mesh::null_face()); };
  face(a, b, O); face(b, c, O); face(c, a, O);
  face(g[{0, 0}], a, g[{1, 1}]); face(g[{0, 0}], g[{1, 1}], g[{0, 1}]);
  face(a, c, g[{1, 1}]); face(g[{1, 1}], c, g[{2, 1}]); face(c, b, g[{3, 1}]); face(c, g[{3, 1}], g[{2, 1}]);
  face(b, g[{4, 0}], g[{4, 1}]); face(b, g[{4, 1}], g[{3, 1}]);
  for(int j = 1; j < 4; ++j)
    for(int i = 0; i < 4; ++i) {
      face(g[{i, j}], g[{i + 1, j}], g[{i + 1, j + 1}]);
      face(g[{i, j}], g[{i + 1, j + 1}], g[{i, j + 1}]);
    }
  BOOST_REQUIRE(CGAL::is_valid_polygon_mesh(m));
  auto feature = m.add_property_map<E, bool>("e:lens", false).first;
  feature[m.edge(m.halfedge(a, c))] = feature[m.edge(m.halfedge(c, b))] = true;
  auto field = stand_in_field(m);
  const Mesh::Halfedge_index bc = m.halfedge(b, c); // in the lens, c its target
  auto corners_at_c = [&](const Layout& layout, std::size_t p) {
    const auto& C = layout.patch(p).corners;
    return std::count(C.begin(), C.end(), c);
  };

  Layout layout(m, field, no_singularity);
  layout.add_feature_paths(feature);
  const std::size_t lens = layout.patch_id(m.face(bc)), square = layout.patch_id(m.face(m.opposite(bc)));
  BOOST_TEST(layout.patch(lens).corners.size() == 2u);
  BOOST_TEST(layout.validity(lens) == Layout::BAD_VALENCE);
  BOOST_TEST(layout.validity(square) == Layout::SATISFIED);
  const std::size_t square_corners = layout.patch(square).corners.size();
  layout.add_corner(bc);
  BOOST_TEST(layout.patch(layout.patch_id(m.face(bc))).corners.size() == 3u);
  BOOST_TEST(corners_at_c(layout, layout.patch_id(m.face(bc))) == 1);
  BOOST_TEST(layout.validity(layout.patch_id(m.face(bc))) == Layout::SATISFIED);
  BOOST_TEST(layout.patch(layout.patch_id(m.face(m.opposite(bc)))).corners.size() == square_corners);
  BOOST_TEST(corners_at_c(layout, layout.patch_id(m.face(m.opposite(bc)))) == 0);
  BOOST_CHECK_THROW(layout.add_corner(m.halfedge(O, c)), std::invalid_argument); // not on a path

  // the rounds: the lens keeps its three faces and gets c as its third corner
  Layout traced(m, field, no_singularity);
  const auto s = CGAL::Quad_remeshing::trace_patch_layout(m, feature, traced);
  BOOST_TEST(s.rounds.back().name == "corners");
  BOOST_TEST(s.added_corners == 1u);
  BOOST_TEST(s.report()["added_corners"].number() == 1.);
  const std::size_t p = traced.patch_id(m.face(bc));
  BOOST_TEST(traced.patch(p).faces.size() == 3u);
  BOOST_TEST(traced.patch(p).corners.size() == 3u);
  BOOST_TEST(corners_at_c(traced, p) == 1);
  BOOST_TEST(s.layout.valid_patches == s.layout.patches);
}

// A closed mesh with no feature line: the looped-paths round (and, if needed, the last resort) must cut it
// into disks; every feature-free patch is valid or at worst not convex, never a sphere or an annulus.
BOOST_AUTO_TEST_CASE(closed_featureless_mesh_is_cut_into_disks)
{
  Mesh m;
  BOOST_REQUIRE(CGAL::IO::read_OFF(qr_test::data_file("spot.off"), m));
  auto feature = m.add_property_map<E, bool>("e:none", false).first;
  auto field = stand_in_field(m);
  Layout layout(m, field, no_singularity);
  const auto s = CGAL::Quad_remeshing::trace_patch_layout(m, feature, layout);
  BOOST_TEST(s.rounds[2].name == "loops");
  BOOST_TEST(s.rounds[2].paths > 0u);
  BOOST_TEST(s.layout.patches > 10u);
  for(std::size_t p = 0; p < layout.number_of_patches(); ++p) BOOST_TEST(layout.validity(p) != Layout::NOT_A_DISK);
  BOOST_TEST(s.layout.valid_patches * 10 >= s.layout.patches * 9);
}

// The fewest equal arc-length chords that follow a quarter circle of radius 1 within a tolerance: the
// sagitta of n chords is 1 - cos(pi / (4 n)), so 0.01 needs 6 chords (5 leave 0.0123) and 0.05 needs
// 3 (2 leave 0.076); a straight line needs 1, and the cap bounds the count.
BOOST_AUTO_TEST_CASE(chord_minimum_of_a_quarter_circle)
{
  namespace QRI = CGAL::Quad_remeshing::internal;
  std::vector<Point_3> arc, line;
  for(int i = 0; i <= 360; ++i) {
    const double a = 0.5 * CGAL_PI * i / 360.;
    arc.emplace_back(std::cos(a), std::sin(a), 0.);
    line.emplace_back(i / 360., 2. * i / 360., 0.);
  }
  BOOST_CHECK_EQUAL(QRI::chord_minimum(arc, 0.01, 100), 6);
  BOOST_CHECK_EQUAL(QRI::chord_minimum(arc, 0.05, 100), 3);
  BOOST_CHECK_EQUAL(QRI::chord_minimum(arc, 0.5, 100), 1);
  BOOST_CHECK_EQUAL(QRI::chord_minimum(arc, 0.01, 4), 4);
  BOOST_CHECK_EQUAL(QRI::chord_minimum(line, 1e-9, 100), 1);
  BOOST_CHECK_EQUAL(QRI::chord_minimum(std::vector<Point_3>{Point_3(0, 0, 0), Point_3(1, 0, 0)}, 1e-9, 100), 1);
}

// With normals, only the distance along them counts: a quarter circle on a cylinder (normals radial)
// needs as many chords as without them (its sagitta is along the normal), a zigzag in a plane (normals
// out of the plane: an edge path across a flat region) needs one where the full distance needs many.
BOOST_AUTO_TEST_CASE(chord_minimum_along_normals)
{
  namespace QRI = CGAL::Quad_remeshing::internal;
  typedef Point_3::R::Vector_3 Vector_3;
  std::vector<Point_3> arc, zigzag;
  std::vector<Vector_3> radial, up;
  for(int i = 0; i <= 360; ++i) {
    const double a = 0.5 * CGAL_PI * i / 360.;
    arc.emplace_back(std::cos(a), 0., std::sin(a));
    radial.emplace_back(std::cos(a), 0., std::sin(a));
    zigzag.emplace_back(i / 360., (i % 2) * 0.05, 0.);
    up.emplace_back(0., 0., 1.);
  }
  BOOST_CHECK_EQUAL(QRI::chord_minimum(arc, 0.01, 100, radial), 6);
  BOOST_CHECK_EQUAL(QRI::chord_minimum(arc, 0.05, 100, radial), 3);
  BOOST_CHECK_EQUAL(QRI::chord_minimum(zigzag, 0.01, 100, up), 1);
  BOOST_CHECK_GT(QRI::chord_minimum(zigzag, 0.01, 100), 10);
}

BOOST_AUTO_TEST_SUITE_END()
