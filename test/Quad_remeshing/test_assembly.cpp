// Assembly of patch quadrangulations into one conforming quad mesh on the surface.
#include "test_support.h"

#include <CGAL/Quad_remeshing/assemble_quad_mesh.h>
#include <CGAL/Quad_remeshing/quadrangulate_polygon.h>
#include <CGAL/Quad_remeshing/internal/assembly/parameterize_patch.h>
#include <CGAL/Quad_remeshing/internal/quality/soup_figures.h>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace {

namespace QR = CGAL::Quad_remeshing;
using qr_test::Mesh;
using qr_test::Point_3;
typedef Mesh::Vertex_index V;

// A regular a x b grid on the unit square as a patch quadrangulation (sides: bottom a, right b, top a, left b).
struct Grid_pattern
{
  std::vector<std::array<double, 2>> positions;
  std::vector<std::array<std::size_t, 4>> quads;
  std::vector<std::size_t> boundary;

  Grid_pattern(int a, int b)
  {
    auto id = [&](int i, int j) { return std::size_t(j * (a + 1) + i); };
    for(int j = 0; j <= b; ++j)
      for(int i = 0; i <= a; ++i) positions.push_back({{double(i) / a, double(j) / b}});
    for(int j = 0; j < b; ++j)
      for(int i = 0; i < a; ++i) quads.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}});
    for(int i = 0; i < a; ++i) boundary.push_back(id(i, 0));
    for(int j = 0; j < b; ++j) boundary.push_back(id(a, j));
    for(int i = a; i > 0; --i) boundary.push_back(id(i, b));
    for(int j = b; j > 0; --j) boundary.push_back(id(0, j));
  }
};

// An axis-aligned box [0,2]x[0,1]x[0,1], each face an n x n grid of triangle pairs, and its layout:
// the six faces as patches, the twelve box edges as arcs.
struct Box
{
  Mesh mesh;
  QR::Patch_layout_description<Mesh> layout;
  std::map<std::array<int, 3>, V> vertex; // integer grid coordinates (scaled by n)
  int n;

  V at(int x, int y, int z)
  {
    auto it = vertex.find({{x, y, z}});
    if(it != vertex.end()) return it->second;
    V v = mesh.add_vertex(Point_3(2. * x / n, double(y) / n, double(z) / n));
    vertex[{{x, y, z}}] = v;
    return v;
  }

  explicit Box(int n_) : n(n_)
  {
    // each face: origin corner o, directions u and v (outward normal u x v)
    struct Face_def { std::array<int, 3> o, u, v; };
    const std::vector<Face_def> defs = {
      {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}, // z = 0
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, // z = 1
      {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, // y = 0
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, // y = 1
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}}, // x = 0
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, // x = 1
    };
    std::map<std::pair<V, V>, std::size_t> arc_of; // sorted end points -> arc
    for(const Face_def& d : defs)
    {
      auto P = [&](int i, int j) {
        return at(n * d.o[0] + i * d.u[0] + j * d.v[0], n * d.o[1] + i * d.u[1] + j * d.v[1],
                  n * d.o[2] + i * d.u[2] + j * d.v[2]);
      };
      QR::Patch_layout_description<Mesh>::Patch patch;
      for(int j = 0; j < n; ++j)
        for(int i = 0; i < n; ++i)
        {
          patch.faces.push_back(mesh.add_face(P(i, j), P(i + 1, j), P(i + 1, j + 1)));
          patch.faces.push_back(mesh.add_face(P(i, j), P(i + 1, j + 1), P(i, j + 1)));
        }
      // sides: (0,0)->(n,0)->(n,n)->(0,n)->(0,0)
      const std::array<std::array<int, 4>, 4> sides = {{{0, 0, 1, 0}, {n, 0, 0, 1}, {n, n, -1, 0}, {0, n, 0, -1}}};
      for(const auto& s : sides)
      {
        std::vector<V> chain;
        for(int k = 0; k <= n; ++k) chain.push_back(P(s[0] + k * s[2], s[1] + k * s[3]));
        auto key = std::minmax(chain.front(), chain.back());
        QR::Patch_layout_description<Mesh>::Side_arc sa;
        auto it = arc_of.find({key.first, key.second});
        if(it == arc_of.end())
        {
          QR::Patch_layout_description<Mesh>::Arc arc;
          arc.vertices = chain;
          arc.on_feature = true;
          sa.arc = layout.arcs.size();
          arc_of[{key.first, key.second}] = sa.arc;
          layout.arcs.push_back(arc);
          sa.reversed = false;
        }
        else
        {
          sa.arc = it->second;
          sa.reversed = (layout.arcs[sa.arc].vertices.front() != chain.front());
        }
        patch.sides.push_back({sa});
      }
      layout.patches.push_back(patch);
    }
  }
};

// A flat nx x ny grid of cells of side 0.5 in the plane z = 0, split into triangles, as one patch
// (its sides are left to the test) with helpers to add arcs.
struct Flat_grid
{
  Mesh mesh;
  std::vector<V> g;
  int nx;
  QR::Patch_layout_description<Mesh> layout;
  QR::Patch_layout_description<Mesh>::Patch patch;

  Flat_grid(int nx_, int ny) : nx(nx_)
  {
    for(int j = 0; j <= ny; ++j)
      for(int i = 0; i <= nx; ++i) g.push_back(mesh.add_vertex(Point_3(0.5 * i, 0.5 * j, 0.)));
    for(int j = 0; j < ny; ++j)
      for(int i = 0; i < nx; ++i)
      {
        patch.faces.push_back(mesh.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1)));
        patch.faces.push_back(mesh.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1)));
      }
  }
  V id(int i, int j) const { return g[std::size_t(j * (nx + 1) + i)]; }
  std::size_t add_arc(const std::vector<V>& chain)
  {
    QR::Patch_layout_description<Mesh>::Arc arc;
    arc.vertices = chain;
    arc.on_feature = true;
    layout.arcs.push_back(arc);
    return layout.arcs.size() - 1;
  }
};

// Flat_grid(8, 4) with the arcs of a slit up from (4,0) to (4,2) and of the border: bottom left of
// the slit, bottom right, right, top, left, each counterclockwise.
struct Slit_grid : Flat_grid
{
  std::size_t a_bl, a_slit, a_br, a_r, a_t, a_l;
  Slit_grid() : Flat_grid(8, 4)
  {
    std::vector<V> bottom_left, slit, bottom_right, right, top, left;
    for(int i = 0; i <= 4; ++i) bottom_left.push_back(id(i, 0));
    for(int j = 0; j <= 2; ++j) slit.push_back(id(4, j));
    for(int i = 4; i <= 8; ++i) bottom_right.push_back(id(i, 0));
    for(int j = 0; j <= 4; ++j) right.push_back(id(8, j));
    for(int i = 8; i >= 0; --i) top.push_back(id(i, 4));
    for(int j = 4; j >= 0; --j) left.push_back(id(0, j));
    a_bl = add_arc(bottom_left); a_slit = add_arc(slit); a_br = add_arc(bottom_right);
    a_r = add_arc(right); a_t = add_arc(top); a_l = add_arc(left);
  }
};

} // namespace

BOOST_AUTO_TEST_SUITE(assembly)

BOOST_AUTO_TEST_CASE(box_faces_as_grids)
{
  Box box(4);
  BOOST_TEST_REQUIRE(box.mesh.is_valid());
  BOOST_TEST_REQUIRE(CGAL::is_closed(box.mesh));
  BOOST_TEST_REQUIRE(box.layout.arcs.size() == 12u);

  // x edges (length 2) get 6 quad edges, the others 3
  std::vector<int> counts;
  for(const auto& arc : box.layout.arcs)
  {
    const Point_3 a = box.mesh.point(arc.vertices.front()), b = box.mesh.point(arc.vertices.back());
    counts.push_back(std::abs(a.x() - b.x()) > 0.5 ? 6 : 3);
  }
  std::vector<Grid_pattern> patterns;
  for(const auto& patch : box.layout.patches)
  {
    const int a = counts[patch.sides[0][0].arc], b = counts[patch.sides[1][0].arc];
    patterns.emplace_back(a, b);
  }
  Mesh q;
  auto qf = get(CGAL::dynamic_edge_property_t<bool>(), q);
  const QR::Quad_assembly_statistics s = QR::assemble_quad_mesh(box.mesh, box.layout, counts, patterns, q, qf);

  // 2 faces 6x3... : faces z=0,z=1,y=0,y=1 are 6x3 = 18 quads, x faces 3x3 = 9: 4*18 + 2*9 = 90
  BOOST_TEST(s.faces == 90u);
  BOOST_TEST(num_faces(q) == 90u);
  BOOST_TEST(q.is_valid());
  BOOST_TEST(CGAL::is_closed(q));
  BOOST_TEST(int(num_vertices(q)) - int(num_edges(q)) + int(num_faces(q)) == 2);
  BOOST_TEST(s.feature_edges == 4u * 6u + 8u * 3u);
  std::size_t marked = 0;
  for(auto e : edges(q)) marked += get(qf, e) ? 1 : 0;
  BOOST_TEST(marked == s.feature_edges);

  // every quad vertex lies on the box and quads are planar squares/rectangles of the right size
  for(auto v : vertices(q))
  {
    const Point_3 p = q.point(v);
    const bool on = std::abs(p.x()) < 1e-12 || std::abs(p.x() - 2) < 1e-12 || std::abs(p.y()) < 1e-12
                    || std::abs(p.y() - 1) < 1e-12 || std::abs(p.z()) < 1e-12 || std::abs(p.z() - 1) < 1e-12;
    BOOST_TEST(on);
  }
  for(auto e : edges(q))
  {
    const double l = std::sqrt(CGAL::squared_distance(q.point(source(e, q)), q.point(target(e, q))));
    BOOST_TEST(l == 1. / 3., boost::test_tools::tolerance(1e-9));
  }
  // outward orientation is kept: the signed volume is positive
  double volume = 0;
  for(auto f : faces(q))
  {
    std::vector<Point_3> p;
    for(auto v : vertices_around_face(halfedge(f, q), q)) p.push_back(q.point(v));
    for(int k : {1, 2})
      volume += CGAL::to_double(CGAL::determinant(p[0] - CGAL::ORIGIN, p[k] - CGAL::ORIGIN, p[k + 1] - CGAL::ORIGIN)) / 6.;
  }
  BOOST_TEST(volume == 2., boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(mismatched_counts_are_refused)
{
  Box box(2);
  std::vector<int> counts(box.layout.arcs.size(), 2);
  std::vector<Grid_pattern> patterns(box.layout.patches.size(), Grid_pattern(3, 2)); // 3 != 2
  Mesh q;
  auto qf = get(CGAL::dynamic_edge_property_t<bool>(), q);
  BOOST_CHECK_THROW(QR::assemble_quad_mesh(box.mesh, box.layout, counts, patterns, q, qf), std::invalid_argument);
  counts.pop_back();
  BOOST_CHECK_THROW(QR::assemble_quad_mesh(box.mesh, box.layout, counts, patterns, q, qf), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(patch_with_a_slit_is_cut_open)
{
  // A flat 4 x 2 rectangle of 8 x 4 cells; one patch whose bottom side walks up a slit from (2,0) to
  // (2,1) and back down. Without cutting the patch open along the slit, both sides of the slit
  // would share their map positions and the quads there would fold.
  Slit_grid grid;
  Mesh& t = grid.mesh;
  QR::Patch_layout_description<Mesh>& layout = grid.layout;
  QR::Patch_layout_description<Mesh>::Patch& patch = grid.patch;
  auto id = [&](int i, int j) { return grid.id(i, j); };
  const std::size_t a_bl = grid.a_bl, a_slit = grid.a_slit, a_br = grid.a_br, a_r = grid.a_r, a_t = grid.a_t,
                    a_l = grid.a_l;
  typedef QR::Patch_layout_description<Mesh>::Side_arc SA;
  patch.sides = {{SA{a_bl, false}, SA{a_slit, false}, SA{a_slit, true}, SA{a_br, false}},
                 {SA{a_r, false}}, {SA{a_t, false}}, {SA{a_l, false}}};
  layout.patches.push_back(patch);
  // bottom side 4 + 2 + 2 + 4 = 12 edges, as the top
  std::vector<int> counts(layout.arcs.size(), 0);
  counts[a_bl] = 4; counts[a_slit] = 2; counts[a_br] = 4; counts[a_r] = 4; counts[a_t] = 12; counts[a_l] = 4;
  const std::vector<Grid_pattern> patterns(1, Grid_pattern(12, 4));

  // cut open along the slit, the slit's base and middle vertices have two copies, its tip one
  typedef QR::internal::Cut_open_patch<Mesh> Cut;
  const Cut::Edge_set cut_edges = Cut::edges_along(t, patch.sides, layout.arcs);
  BOOST_TEST(cut_edges.size() == 26u); // the rectangle's 24 boundary edges and the slit's 2
  const Cut cut(t, patch.faces, cut_edges);
  BOOST_TEST(cut.vertex_of.size() == num_vertices(t) + 2u);
  std::size_t left_u, left_w, right_u, right_w;
  BOOST_TEST_REQUIRE(cut.left_of(id(4, 0), id(4, 1), left_u, left_w));
  BOOST_TEST_REQUIRE(cut.left_of(id(4, 1), id(4, 0), right_w, right_u));
  BOOST_TEST(left_u != right_u);
  BOOST_TEST(left_w != right_w);

  Mesh q;
  auto qf = get(CGAL::dynamic_edge_property_t<bool>(), q);
  const QR::Quad_assembly_statistics s = QR::assemble_quad_mesh(t, layout, counts, patterns, q, qf);
  BOOST_TEST(q.is_valid());
  // The grid's column over the slit tip has no inner edge at the tip: its two quads merge into one.
  BOOST_TEST(s.merged_quads == 1u);
  BOOST_TEST(s.folded_quads == 0u);
  BOOST_TEST(num_faces(q) == 12u * 4u - 1u);
  // still a disk with one boundary cycle
  BOOST_TEST(int(num_vertices(q)) - int(num_edges(q)) + int(num_faces(q)) == 1);
  // every quad lies flat in the rectangle and keeps its orientation
  for(auto f : faces(q))
  {
    std::array<Point_3, 4> p;
    int i = 0;
    for(auto v : vertices_around_face(halfedge(f, q), q)) p[std::size_t(i++)] = q.point(v);
    BOOST_TEST(QR::internal::quality::quad_scaled_jacobian(p) > 0.);
    const auto n = CGAL::cross_product(p[2] - p[0], p[3] - p[1]);
    BOOST_TEST(n.z() > 0.);
  }
  // no quad edge crosses the slit (which would mean that the two sides of the slit got mixed up)
  std::size_t crossing = 0;
  for(auto e : edges(q))
  {
    const Point_3 a = q.point(source(e, q)), b = q.point(target(e, q));
    if((a.x() - 2.) * (b.x() - 2.) >= 0.) continue;
    const double y = a.y() + (b.y() - a.y()) * (2. - a.x()) / (b.x() - a.x());
    if(y > 0. && y < 1. - 1e-9) ++crossing;
  }
  BOOST_TEST(crossing == 0u);
  // the slit is inside the mesh: its base and middle vertices have quads on both sides
  std::size_t inner_on_slit = 0;
  for(auto v : vertices(q))
  {
    const Point_3 p = q.point(v);
    if(std::abs(p.x() - 2.) < 1e-12 && p.y() > 0.25 && p.y() < 0.75) inner_on_slit += is_border(v, q) ? 0 : 1;
  }
  BOOST_TEST(inner_on_slit == 1u);

}

// On rocker_arm with a sizing tolerance, a triangular patch has its corner 0 at the tip of a slit and
// side counts 5, 1, 6, which quadrangulate_polygon() fills with pattern 3_2: two of its quads fold over
// the slit (opposite corners on one vertex), and the two quads behind them then lie on the same four
// vertices, facing each other. Kept, they would close a sphere and make the slit's base non-manifold
// (the assembly used to throw); all four go, and the patch is the strip of the three others.
BOOST_AUTO_TEST_CASE(pattern_closing_a_slit_at_a_corner)
{
  Slit_grid grid;
  QR::Patch_layout_description<Mesh>& layout = grid.layout;
  const std::size_t a_slit = grid.a_slit, a_br = grid.a_br, a_r = grid.a_r, a_t = grid.a_t, a_l = grid.a_l,
                    a_bl = grid.a_bl;
  // the patch goes down the slit from its tip (4,2) to its base (4,0) on the bottom border, around the
  // rectangle and back up
  typedef QR::Patch_layout_description<Mesh>::Side_arc SA;
  // corner 0 at the tip, corner 1 at (8,0), corner 2 at (8,4)
  grid.patch.sides = {{SA{a_slit, true}, SA{a_br, false}}, {SA{a_r, false}},
                      {SA{a_t, false}, SA{a_l, false}, SA{a_bl, false}, SA{a_slit, false}}};
  layout.patches.push_back(grid.patch);
  std::vector<int> counts(layout.arcs.size(), 0);
  counts[a_slit] = 2; counts[a_br] = 3; counts[a_r] = 1; counts[a_t] = 1; counts[a_l] = 1; counts[a_bl] = 2;
  const std::vector<QR::Polygon_quadrangulation> patterns(1, QR::quadrangulate_polygon({5, 1, 6}));
  BOOST_TEST_REQUIRE(patterns[0].pattern == "3_2");
  BOOST_TEST_REQUIRE(patterns[0].quads.size() == 7u);

  Mesh q;
  auto qf = get(CGAL::dynamic_edge_property_t<bool>(), q);
  QR::Quad_assembly_statistics s;
  BOOST_REQUIRE_NO_THROW(s = QR::assemble_quad_mesh(grid.mesh, layout, counts, patterns, q, qf));
  BOOST_TEST(q.is_valid());
  BOOST_TEST(s.folded_quads == 2u);
  BOOST_TEST(s.closed_quads == 2u);
  BOOST_TEST(s.report()["closed_quads"].number() == 2.);
  BOOST_TEST(num_faces(q) == 3u);
  // a manifold disk: one boundary cycle, no vertex with two fans
  BOOST_TEST(int(num_vertices(q)) - int(num_edges(q)) + int(num_faces(q)) == 1);
  for(auto v : vertices(q))
  {
    std::size_t border_halfedges = 0;
    for(auto h : halfedges_around_target(v, q)) border_halfedges += is_border(h, q);
    BOOST_TEST(border_halfedges <= 1u);
  }
}

// A patch of truck remeshed with the adaptive pass: its free vertex 2 lies at the midpoint of the fixed
// vertices 1 and 4 and on the fixed vertex 3. The angle at 2 towards 3 used to be atan2(0, -0) = pi, its
// mean-value weight infinite, and the map NaN (the smoothing then crashed on a NaN point). Coincident
// vertices give no weight; the map is then the weighted average of 0, 1 and 4.
BOOST_AUTO_TEST_CASE(mean_value_map_with_a_vertex_on_another)
{
  QR::internal::Patch_map m;
  m.points = {{{0.705449, 0.0930744, 0.213573}},
              {{0.684256, 0.0705907, 0.230798}},
              {{0.6957005, 0.07376135, 0.2315395}},
              {{0.6957005, 0.07376135, 0.2315395}},
              {{0.707145, 0.076932, 0.232281}}};
  m.triangles = {{{0, 1, 2}}, {{3, 4, 2}}, {{2, 4, 0}}, {{2, 1, 3}}};
  m.fixed = {true, true, false, true, true};
  const double s = std::sqrt(0.75);
  m.uv = {{{0., 1.}}, {{-s, -0.5}}, {{0., 0.}}, {{-s / 3., -0.5}}, {{s, -0.5}}};
  QR::internal::solve_mean_value_map(m);
  const std::array<double, 2> uv = m.uv[2];
  BOOST_TEST_REQUIRE(std::isfinite(uv[0]));
  BOOST_TEST_REQUIRE(std::isfinite(uv[1]));
  // mean-value weights tan(alpha / 2) / length from the triangles (0, 1, 2) and (2, 4, 0)
  auto angle = [&](std::size_t a, std::size_t b, std::size_t c) {
    const Point_3 pa(m.points[a][0], m.points[a][1], m.points[a][2]), pb(m.points[b][0], m.points[b][1], m.points[b][2]),
      pc(m.points[c][0], m.points[c][1], m.points[c][2]);
    return std::acos(((pb - pa) * (pc - pa)) / std::sqrt((pb - pa).squared_length() * (pc - pa).squared_length()));
  };
  auto length = [&](std::size_t a, std::size_t b) {
    return std::sqrt(CGAL::squared_distance(Point_3(m.points[a][0], m.points[a][1], m.points[a][2]),
                                            Point_3(m.points[b][0], m.points[b][1], m.points[b][2])));
  };
  const double t1 = std::tan(angle(2, 0, 1) / 2.), t2 = std::tan(angle(2, 4, 0) / 2.);
  const double w0 = t1 / length(2, 0) + t2 / length(2, 0), w1 = t1 / length(2, 1), w4 = t2 / length(2, 4);
  const double u = (w1 * -s + w4 * s) / (w0 + w1 + w4), v = (w0 * 1. + (w1 + w4) * -0.5) / (w0 + w1 + w4);
  BOOST_TEST(uv[0] == u, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(uv[1] == v, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_SUITE_END()
