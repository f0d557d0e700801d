// Feature-constrained quad smoothing: stays on the surface and on the feature lines, never inverts.
#include "test_support.h"

#include <CGAL/Quad_remeshing/smooth_quad_mesh.h>
#include <CGAL/Quad_remeshing/IO.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/test/unit_test.hpp>

#include <map>
#include <vector>

namespace {

namespace QR = CGAL::Quad_remeshing;
namespace PMP = CGAL::Polygon_mesh_processing;
using qr_test::Mesh;
using qr_test::Point_3;
typedef qr_test::Kernel::Vector_3 Vector_3;

double min_sj(const Mesh& q)
{
  double m = 1.;
  for(auto f : faces(q))
  {
    std::array<Point_3, 4> p;
    int i = 0;
    for(auto v : vertices_around_face(halfedge(f, q), q)) p[i++] = q.point(v);
    m = std::min(m, QR::internal::quality::quad_scaled_jacobian(p));
  }
  return m;
}

// Splits every triangle into three quads (centroid + edge midpoints); the quad edges that halve a
// feature edge are marked in `qfeature`.
template <typename FeatureMap, typename QFeatureMap>
void split_into_quads(const Mesh& t, FeatureMap tf, Mesh& q, QFeatureMap& qfeature)
{
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> vmap;
  std::map<Mesh::Edge_index, Mesh::Vertex_index> emap;
  for(auto v : vertices(t)) vmap[v] = q.add_vertex(t.point(v));
  for(auto e : edges(t))
    emap[e] = q.add_vertex(CGAL::midpoint(t.point(source(e, t)), t.point(target(e, t))));
  for(auto f : faces(t))
  {
    auto h = halfedge(f, t);
    const Point_3 c = CGAL::centroid(t.point(source(h, t)), t.point(target(h, t)), t.point(target(next(h, t), t)));
    auto vc = q.add_vertex(c);
    for(int i = 0; i < 3; ++i, h = next(h, t))
    {
      // quad at target(h): midpoint(h), target(h), midpoint(next(h)), centroid
      q.add_face(emap[edge(h, t)], vmap[target(h, t)], emap[edge(next(h, t), t)], vc);
    }
  }
  qfeature = get(CGAL::dynamic_edge_property_t<bool>(), q);
  for(auto e : edges(q)) put(qfeature, e, false);
  for(auto e : edges(t))
    if(get(tf, e))
    {
      auto m = emap[e];
      for(auto end : {vmap[source(e, t)], vmap[target(e, t)]})
      {
        auto hq = halfedge(m, end, q);
        BOOST_REQUIRE(hq.second);
        put(qfeature, edge(hq.first, q), true);
      }
    }
}

// The unit square as two triangles (its border as the features) and an n x n quad grid on it; `jitter`
// may move a grid point before it is added.
struct Grid_on_square
{
  Mesh t, q;
  decltype(get(CGAL::dynamic_edge_property_t<bool>(), t)) tf;
  std::vector<Mesh::Vertex_index> grid;

  template <typename Jitter>
  Grid_on_square(int n, Jitter jitter)
  {
    auto a = t.add_vertex(Point_3(0, 0, 0)), b = t.add_vertex(Point_3(1, 0, 0)), c = t.add_vertex(Point_3(1, 1, 0)),
         d = t.add_vertex(Point_3(0, 1, 0));
    t.add_face(a, b, c);
    t.add_face(a, c, d);
    tf = get(CGAL::dynamic_edge_property_t<bool>(), t);
    for(auto e : edges(t)) put(tf, e, is_border(e, t));
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i)
      {
        double x = double(i) / n, y = double(j) / n;
        jitter(i, j, x, y);
        grid.push_back(q.add_vertex(Point_3(x, y, 0)));
      }
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
        q.add_face(grid[j * (n + 1) + i], grid[j * (n + 1) + i + 1], grid[(j + 1) * (n + 1) + i + 1],
                   grid[(j + 1) * (n + 1) + i]);
  }
};

// An 8 x 8 quad grid on the flat unit square in which two inner vertices were pushed across their
// neighbours, which folds several quads over.
struct Folded_grid_on_square : Grid_on_square
{
  Folded_grid_on_square()
    : Grid_on_square(8, [](int i, int j, double& x, double& y) {
        if(i == 2 && j == 2) { x = 3.6 / 8; y = 3.5 / 8; }
        if(i == 6 && j == 5) { x = 4.4 / 8; y = 5.3 / 8; }
      })
  {}
};

} // namespace

BOOST_AUTO_TEST_SUITE(smoothing)

BOOST_AUTO_TEST_CASE(square_fit_of_a_square_is_itself)
{
  std::array<Point_3, 4> p = {Point_3(0, 0, 0), Point_3(2, 0, 0), Point_3(2, 2, 0), Point_3(0, 2, 0)};
  auto q = QR::internal::best_fit_square<Vector_3>(p);
  for(int i = 0; i < 4; ++i) BOOST_TEST(CGAL::squared_distance(p[i], q[i]) < 1e-24);
  BOOST_TEST(QR::internal::quality::quad_scaled_jacobian(p) == 1., boost::test_tools::tolerance(1e-12));
  std::array<Point_3, 4> bowtie = {Point_3(0, 0, 0), Point_3(2, 0, 0), Point_3(0, 2, 0), Point_3(2, 2, 0)};
  BOOST_TEST(QR::internal::quality::quad_scaled_jacobian(bowtie) <= 0.);
}

BOOST_AUTO_TEST_CASE(fandisk_split_quads_improve_and_stay_on_features)
{
  Mesh t;
  QR::read_and_repair(qr_test::data_file("fandisk.off"), t);
  auto tf = get(CGAL::dynamic_edge_property_t<bool>(), t);
  PMP::detect_sharp_edges(t, 35., tf);
  std::size_t nfeat = 0;
  for(auto e : edges(t)) nfeat += get(tf, e) ? 1 : 0;
  BOOST_TEST_REQUIRE(nfeat > 100u);

  Mesh q;
  decltype(get(CGAL::dynamic_edge_property_t<bool>(), q)) qf;
  split_into_quads(t, tf, q, qf);
  const double before = min_sj(q);
  BOOST_TEST_REQUIRE(before > 0.);

  // corners of the feature network must not move: remember the feature-degree != 2 vertices
  std::vector<std::pair<Mesh::Vertex_index, Point_3>> corners;
  for(auto v : vertices(q))
  {
    int d = 0;
    for(auto h : halfedges_around_target(halfedge(v, q), q)) d += get(qf, edge(h, q)) ? 1 : 0;
    if(d != 0 && d != 2) corners.emplace_back(v, q.point(v));
  }
  BOOST_TEST_REQUIRE(!corners.empty());

  const QR::Quad_smoothing_statistics s =
    QR::smooth_quad_mesh(q, t, tf, CGAL::parameters::edge_is_constrained_map(qf).number_of_iterations(10));
  BOOST_TEST(s.iterations == 10u);
  BOOST_TEST(s.feature_vertices > 0u);
  BOOST_TEST(s.min_scaled_jacobian_after > 0.);
  BOOST_TEST(min_sj(q) > 0.);
  BOOST_TEST(s.mean_scaled_jacobian_after > s.mean_scaled_jacobian_before + 0.02);
  for(const auto& c : corners) BOOST_TEST(CGAL::squared_distance(q.point(c.first), c.second) == 0.);

  // still on the surface: every quad vertex within 1e-6 of the diagonal of the triangle mesh
  CGAL::Bbox_3 bb = PMP::bbox(t);
  const double diag = std::sqrt(CGAL::square(bb.xmax() - bb.xmin()) + CGAL::square(bb.ymax() - bb.ymin())
                                + CGAL::square(bb.zmax() - bb.zmin()));
  std::vector<Point_3> qpoints;
  for(auto v : vertices(q)) qpoints.push_back(q.point(v));
  const double d = PMP::max_distance_to_triangle_mesh<CGAL::Sequential_tag>(qpoints, t);
  BOOST_TEST(d < 1e-6 * diag);

  // feature quad edges still lie on feature edges: their midpoints are within 0.5% of the diagonal
  // of the original feature polylines, and feature vertices exactly on them
  std::vector<qr_test::Kernel::Segment_3> fsegs;
  for(auto e : edges(t))
    if(get(tf, e)) fsegs.emplace_back(t.point(source(e, t)), t.point(target(e, t)));
  for(auto e : edges(q))
    if(get(qf, e))
    {
      const Point_3 a = q.point(source(e, q));
      double best = 1e300;
      for(const auto& sg : fsegs) best = std::min(best, CGAL::squared_distance(a, sg));
      BOOST_TEST(std::sqrt(best) < 1e-9 * diag);
    }
}

// A time limit already reached ends the iterations after the third that always runs.
BOOST_AUTO_TEST_CASE(time_limit_ends_the_iterations_after_a_third)
{
  Mesh t;
  QR::read_and_repair(qr_test::data_file("fandisk.off"), t);
  auto tf = get(CGAL::dynamic_edge_property_t<bool>(), t);
  PMP::detect_sharp_edges(t, 35., tf);
  Mesh q;
  decltype(get(CGAL::dynamic_edge_property_t<bool>(), q)) qf;
  split_into_quads(t, tf, q, qf);
  Mesh q2 = q;
  auto qf2 = get(CGAL::dynamic_edge_property_t<bool>(), q2);
  for(auto e : edges(q)) put(qf2, e, get(qf, e)); // same indices in the copy
  const QR::Quad_smoothing_statistics all =
    QR::smooth_quad_mesh(q, t, tf, CGAL::parameters::edge_is_constrained_map(qf).number_of_iterations(12));
  BOOST_TEST(all.iterations == 12u);
  BOOST_TEST(!all.stopped_early);
  const QR::Quad_smoothing_statistics cut = QR::smooth_quad_mesh(
    q2, t, tf, CGAL::parameters::edge_is_constrained_map(qf2).number_of_iterations(12).maximum_running_time(1e-9));
  BOOST_TEST(cut.iterations == 4u);
  BOOST_TEST(cut.stopped_early);
  BOOST_TEST(cut.report().find("stopped_early")->boolean());
  BOOST_TEST(min_sj(q2) > 0.);
}

BOOST_AUTO_TEST_CASE(perturbed_grid_on_a_plane_is_untangled_towards_squares)
{
  // A 10 x 10 quad grid on the flat unit square with interior noise.
  const int n = 10;
  CGAL::Random rng(7);
  Grid_on_square g(n, [&](int i, int j, double& x, double& y) {
    if(i > 0 && i < n && j > 0 && j < n) { x += rng.get_double(-0.03, 0.03); y += rng.get_double(-0.03, 0.03); }
  });
  Mesh& q = g.q;
  const QR::Quad_smoothing_statistics s = QR::smooth_quad_mesh(q, g.t, g.tf);
  BOOST_TEST(s.fixed_vertices == 4u); // the four corners of the square
  BOOST_TEST(s.min_scaled_jacobian_after > s.min_scaled_jacobian_before);
  BOOST_TEST(s.mean_scaled_jacobian_after > 0.99);
  for(auto v : vertices(q))
  {
    BOOST_TEST(std::abs(q.point(v).z()) < 1e-12);
    BOOST_TEST(q.point(v).x() >= -1e-12);
    BOOST_TEST(q.point(v).x() <= 1 + 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(folded_grid_is_untangled_without_smoothing_iterations)
{
  Folded_grid_on_square g;
  Mesh& q = g.q;
  BOOST_TEST_REQUIRE(min_sj(q) <= 0.);

  const QR::Quad_smoothing_statistics s = QR::smooth_quad_mesh(q, g.t, g.tf, CGAL::parameters::number_of_iterations(0));
  BOOST_TEST(s.iterations == 0u);
  BOOST_TEST(s.inverted_before >= 4u);
  BOOST_TEST(s.inverted_after == 0u);
  BOOST_TEST(s.untangling_moves > 0u);
  BOOST_TEST(min_sj(q) > 0.);
  for(auto v : vertices(q)) BOOST_TEST(std::abs(q.point(v).z()) < 1e-12);
}

BOOST_AUTO_TEST_CASE(a_held_dart_is_mended_by_splitting_its_chords)
{
  // A 4 x 4 grid on the flat unit square whose central quad is a dart (a corner at about 240 degrees)
  // with all four corners held: no move of a vertex can mend it, splitting the two chords through it
  // (their quads cut in two, in four where they cross) and moving the new vertices can.
  const int n = 4;
  Grid_on_square g(n, [&](int i, int j, double& x, double& y) {
    if(i == 2 && j == 2) { x = 0.3; y = 0.3; }
  });
  Mesh& q = g.q;
  auto held = get(CGAL::dynamic_vertex_property_t<bool>(), q);
  for(auto v : vertices(q)) put(held, v, false);
  for(int j : {1, 2})
    for(int i : {1, 2}) put(held, g.grid[j * (n + 1) + i], true);
  auto qf = get(CGAL::dynamic_edge_property_t<bool>(), q);
  for(auto e : edges(q)) put(qf, e, is_border(e, q));
  BOOST_TEST_REQUIRE(min_sj(q) <= 0.);
  const std::size_t border_edges_before = std::size_t(std::count_if(edges(q).begin(), edges(q).end(),
                                                                     [&](auto e) { return is_border(e, q); }));

  const QR::Quad_smoothing_statistics s = QR::smooth_quad_mesh(
    q, g.t, g.tf, CGAL::parameters::vertex_is_constrained_map(held).edge_is_constrained_map(qf));
  BOOST_TEST(s.inverted_before >= 1u);
  BOOST_TEST(s.inverted_after == 0u);
  BOOST_TEST(s.refined_chords >= 1u);
  BOOST_TEST(min_sj(q) > 0.);
  // still a conforming, pure-quad disk on the square, held vertices where they were
  BOOST_TEST(q.is_valid(false));
  BOOST_TEST(num_faces(q) == 16u + s.refinement_quads);
  for(auto f : faces(q)) BOOST_TEST(CGAL::halfedges_around_face(halfedge(f, q), q).size() == 4u);
  for(auto v : vertices(q))
  {
    BOOST_TEST(std::abs(q.point(v).z()) < 1e-12);
    BOOST_TEST((q.point(v).x() > -1e-12 && q.point(v).x() < 1 + 1e-12 && q.point(v).y() > -1e-12 && q.point(v).y() < 1 + 1e-12));
  }
  BOOST_TEST(q.point(g.grid[2 * (n + 1) + 2]) == Point_3(0.3, 0.3, 0));
  // the split border edges' halves are constrained, and they are the whole border
  std::size_t border_edges = 0;
  for(auto e : edges(q))
  {
    BOOST_TEST(get(qf, e) == is_border(e, q));
    if(is_border(e, q)) ++border_edges;
  }
  BOOST_TEST(border_edges > border_edges_before);
}

BOOST_AUTO_TEST_CASE(untangling_never_slides_a_vertex_onto_a_corner)
{
  // A 3 x 3 grid whose inner vertex (1, 1) is held fixed just outside the square, at (-0.05, 0.1): the
  // corner quad is then inverted wherever the boundary vertex (1, 0) slides on the bottom line, except
  // when it reaches the square's corner and the quad collapses. A collapsed quad is not a repair.
  const int n = 3;
  Grid_on_square g(n, [&](int i, int j, double& x, double& y) {
    if(i == 1 && j == 1) { x = -0.05; y = 0.1; }
  });
  Mesh& q = g.q;
  auto fixed = get(CGAL::dynamic_vertex_property_t<bool>(), q);
  for(auto v : vertices(q)) put(fixed, v, !is_border(v, q));
  BOOST_TEST_REQUIRE(min_sj(q) <= 0.);

  const QR::Quad_smoothing_statistics s = QR::smooth_quad_mesh(
    q, g.t, g.tf, CGAL::parameters::number_of_iterations(0).vertex_is_constrained_map(fixed));
  BOOST_TEST(s.inverted_after <= s.inverted_before);
  for(auto e : edges(q))
    BOOST_TEST(CGAL::squared_distance(q.point(source(e, q)), q.point(target(e, q))) > 1e-12);
}

BOOST_AUTO_TEST_CASE(a_vertex_keeps_to_its_sheet_over_another_facing_the_same_way)
{
  // One component folded twice (a Z): the unit square at z = 0 facing up, a wall down along x = 1, a
  // floor at z = -1 facing down, a wall up along x = -0.5, and a sheet at z = -0.04 facing up again,
  // under the square. The quads of a folded 8 x 8 grid on the square try moves a quarter or half of
  // their edge length (0.125) off it, whose closest point is on the lower sheet: its normal and
  // component are those of the square's, so only the connection through the surface tells them apart
  // (truck's hood, 0.017 above a sheet of its own component that faces up too after the repair).
  Folded_grid_on_square g;
  Mesh& t = g.t;
  const double gap = 0.04;
  auto corner = [&](double x, double y, double z) {
    for(auto v : vertices(t))
      if(t.point(v) == Point_3(x, y, z)) return v;
    return t.add_vertex(Point_3(x, y, z));
  };
  auto b = corner(1, 0, 0), c = corner(1, 1, 0), b1 = corner(1, 0, -1), c1 = corner(1, 1, -1);
  auto a2 = corner(-0.5, 0, -1), d2 = corner(-0.5, 1, -1), a3 = corner(-0.5, 0, -gap), d3 = corner(-0.5, 1, -gap);
  auto e = corner(0.9, 0, -gap), f = corner(0.9, 1, -gap);
  for(std::array<Mesh::Vertex_index, 3> tri : {std::array<Mesh::Vertex_index, 3>{c, b, b1}, {c, b1, c1}, {c1, b1, a2},
                                                {c1, a2, d2}, {d2, a2, a3}, {d2, a3, d3}, {d3, a3, e}, {d3, e, f}})
    BOOST_TEST_REQUIRE(t.add_face(tri[0], tri[1], tri[2]) != Mesh::null_face());
  BOOST_TEST_REQUIRE(t.is_valid(false));
  // the features: the border and the folds
  g.tf = get(CGAL::dynamic_edge_property_t<bool>(), t);
  for(auto ed : edges(t))
  {
    const auto h = halfedge(ed, t);
    put(g.tf, ed, is_border(ed, t) || CGAL::scalar_product(PMP::compute_face_normal(face(h, t), t),
                                                            PMP::compute_face_normal(face(opposite(h, t), t), t)) < 0.5);
  }
  Mesh& q = g.q;
  BOOST_TEST_REQUIRE(min_sj(q) <= 0.);

  const QR::Quad_smoothing_statistics s = QR::smooth_quad_mesh(q, t, g.tf);
  BOOST_TEST(s.inverted_after == 0u);
  for(auto v : vertices(q))
    BOOST_TEST(std::abs(q.point(v).z()) < 1e-12, "vertex at " << q.point(v) << " left the square's sheet");
}

// The smoothing's closest-point search gives what the tree's own query gives, point and face, ties
// included: on fandisk's vertices (queries on the surface, where many faces tie), edge midpoints, and
// points off the surface on both sides and far away.
BOOST_AUTO_TEST_CASE(closest_point_search_matches_the_tree)
{
  Mesh t;
  BOOST_TEST_REQUIRE(CGAL::IO::read_polygon_mesh(qr_test::data_file("fandisk.off"), t));
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh, CGAL::Default, CGAL::Tag_true, CGAL::Tag_true> Primitive;
  typedef CGAL::AABB_traits<qr_test::Kernel, Primitive> Traits;
  CGAL::AABB_tree<Traits> tree(faces(t).first, faces(t).second, t);
  tree.accelerate_distance_queries();
  std::vector<Point_3> queries;
  CGAL::Random rng(7);
  for(auto v : vertices(t)) queries.push_back(t.point(v));
  for(auto e : edges(t))
  {
    const Point_3 m = CGAL::midpoint(t.point(source(e, t)), t.point(target(e, t)));
    queries.push_back(m);
    const Vector_3 n = PMP::compute_face_normal(face(halfedge(e, t), t), t);
    const double off = rng.get_double(-0.05, 0.05);
    queries.push_back(m + off * n);
  }
  for(int i = 0; i < 1000; ++i)
    queries.emplace_back(rng.get_double(-3., 3.), rng.get_double(-3., 3.), rng.get_double(-3., 3.));
  std::size_t same = 0;
  for(const Point_3& p : queries)
  {
    const auto a = tree.closest_point_and_primitive(p);
    const auto b = QR::internal::closest_point_and_primitive(tree, p);
    if(a.first == b.first && a.second == b.second) ++same;
    else BOOST_TEST_MESSAGE("query " << p << ": tree " << a.first << " on face " << a.second << ", search " << b.first << " on face " << b.second);
  }
  BOOST_TEST(same == queries.size());
  BOOST_TEST(queries.size() > 20000u);
}

BOOST_AUTO_TEST_SUITE_END()
