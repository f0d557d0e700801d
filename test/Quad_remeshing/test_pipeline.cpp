// The whole pipeline in one call, on real meshes: a valid pure-quad mesh that keeps the features.
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <CGAL/Quad_remeshing/IO.h>
#include <CGAL/Quad_remeshing/quad_mesh_quality.h>
#include <CGAL/Quad_remeshing/quad_remesh.h>
#include <CGAL/Quad_remeshing/internal/pipeline/tip_snapping.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>

#include <boost/test/unit_test.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace {
namespace QR = CGAL::Quad_remeshing;
using qr_test::Mesh;

// The Hausdorff distance and feature coverage of the quad mesh q, made from the triangle mesh t.
QR::Feature_fidelity fidelity_to_input(const Mesh& t, const Mesh& q)
{
  auto features = get(CGAL::dynamic_edge_property_t<bool>(), t);
  QR::detect_evaluation_feature_edges(t, features);
  return QR::feature_fidelity(t, features, q);
}

// The input of the tip tests: a grid of spacing 0.5 on [0, n]^2, each square split along one diagonal,
// the height of grid vertex (i, j) given by `height(i, j)`.
template <typename Height>
Mesh plane_with_spikes(int n, const Height& height)
{
  Mesh input;
  std::vector<Mesh::Vertex_index> iv;
  for(int j = 0; j <= 2 * n; ++j)
    for(int i = 0; i <= 2 * n; ++i) iv.push_back(input.add_vertex(qr_test::Point_3(0.5 * i, 0.5 * j, height(i, j))));
  auto at = [&](int i, int j) { return iv[std::size_t(j * (2 * n + 1) + i)]; };
  for(int j = 0; j < 2 * n; ++j)
    for(int i = 0; i < 2 * n; ++i) {
      input.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      input.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return input;
}

// Puts the quads onto the tips of `input` (tolerance 0.1, 10 smoothing iterations), calling
// `before(m, held)` before each smoothing; the quads kept go to `result`.
template <typename InputFeature, typename QuadFeature, typename Before>
QR::internal::Tip_snapping_statistics snap_tips(const Mesh& input, const InputFeature& input_feature, const Mesh& quads,
                                                const QuadFeature& qfeature, const Before& before, Mesh& result)
{
  auto smooth = [&](Mesh& m, const auto& m_feature, const auto& held) {
    before(m, held);
    QR::smooth_quad_mesh(m, input, input_feature, CGAL::parameters::edge_is_constrained_map(m_feature)
                                                    .vertex_is_constrained_map(held).number_of_iterations(10));
  };
  auto keep = [&](Mesh& m, const auto&) { result = m; };
  return QR::internal::snap_quads_to_input_tips(input, quads, qfeature, 0.1, smooth, keep, false);
}

// an edge map of `m` that is true on its border edges (the constrained edges of the tip tests)
auto border_edge_map(const Mesh& m)
{
  auto map = get(CGAL::dynamic_edge_property_t<bool>(), m);
  for(auto e : m.edges()) put(map, e, m.is_border(e));
  return map;
}

// n x n unit quads on the plane z = 0, the grid vertex (i, j) at `place(i, j)`
template <typename Place>
Mesh quad_grid(int n, const Place& place)
{
  Mesh quads;
  std::vector<Mesh::Vertex_index> qv;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) qv.push_back(quads.add_vertex(place(i, j)));
  auto at = [&](int i, int j) { return qv[std::size_t(j * (n + 1) + i)]; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) quads.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return quads;
}
}

BOOST_AUTO_TEST_SUITE(pipeline)

BOOST_AUTO_TEST_CASE(fandisk_end_to_end)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("fandisk.off"), t);
  std::vector<std::string> stages;
  const std::function<void(const std::string&)> cb = [&](const std::string& s) { stages.push_back(s); };
  const QR::Report r = QR::quad_remesh(t, q, CGAL::parameters::callback(cb));
  BOOST_TEST(stages.size() == 8u);
  BOOST_TEST(r.find("layout") != nullptr);

  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(quality.components == 1u);
  BOOST_TEST(quality.euler_characteristic == 2);
  BOOST_TEST(quality.faces > 500u);
  // a layout patch with three corners is quadrangulated as a triangle; when a fourth corner was added in
  // the middle of its longest side, fandisk's smallest scaled Jacobian was 0.016
  BOOST_TEST(quality.min_scaled_jacobian > 0.1);

  auto features = get(CGAL::dynamic_edge_property_t<bool>(), t);
  QR::detect_evaluation_feature_edges(t, features);
  const QR::Feature_fidelity f = QR::feature_fidelity(t, features, q);
  BOOST_TEST_MESSAGE("fandisk: " << quality.faces << " quads, I=" << quality.irregular_vertices << " SJ mean "
                     << quality.mean_scaled_jacobian << " min " << quality.min_scaled_jacobian << " Hausdorff "
                     << f.hausdorff_max << " coverage " << f.feature_coverage);
  BOOST_TEST(f.feature_coverage >= 0.98);
  BOOST_TEST(f.hausdorff_max <= 0.02);
}

// A time limit far too short for the stages that always run: the stages that can stop early give up what
// they can, say so in the report, and the output is still a valid quad mesh without inverted quads.
// Without a limit nothing is given up.
BOOST_AUTO_TEST_CASE(time_limit_degrades_and_stays_valid)
{
  Mesh t, q, q0;
  QR::read_and_repair(qr_test::data_file("fandisk.off"), t);
  const QR::Report r = QR::quad_remesh(t, q, CGAL::parameters::maximum_running_time(1e-3));
  const QR::Report* tl = r.find("time_limit");
  BOOST_TEST_REQUIRE(tl != nullptr);
  BOOST_TEST(tl->find("seconds")->number() == 1e-3);
  BOOST_TEST(!tl->find("met")->boolean());
  std::vector<std::string> stages;
  for(const QR::Report& d : tl->find("degraded")->elements()) stages.push_back(d.find("stage")->string());
  // the quantization gives up its solves too when the time left is gone before they start (a solve
  // started with a sliver of time may still return the first incumbent)
  BOOST_TEST_REQUIRE(stages.size() >= 2u);
  BOOST_TEST(stages.front() == "layout");
  // the smoothing gives up iterations, and the fidelity refinement, which would assemble and smooth again,
  // is skipped
  BOOST_TEST(std::count(stages.begin(), stages.end(), std::string("smooth")) == 1);
  BOOST_TEST(stages.back() == "fidelity");
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(quality.euler_characteristic == 2);

  const QR::Report r0 = QR::quad_remesh(t, q0);
  BOOST_TEST(r0.find("time_limit")->find("seconds")->number() == 0.);
  BOOST_TEST(r0.find("time_limit")->find("degraded") == nullptr);
  BOOST_TEST(!r0.find("layout")->find("stopped_early")->boolean());
  BOOST_TEST(num_faces(q0) > num_faces(q)); // the full layout has more patches
}

// Same input, same quad mesh: on every run and with any number of threads. The quantization of
// draco_test_nm stops at its node limit; with the former 10 s limit it changed with the machine's load.
BOOST_AUTO_TEST_CASE(draco_deterministic_with_threads)
{
  Mesh t;
  QR::read_and_repair(qr_test::data_file("draco_test_nm.off"), t);
  auto run = [&](unsigned threads) {
    Mesh q;
    QR::quad_remesh(t, q, QR::parameters::number_of_threads(threads));
    std::ostringstream out;
    out.precision(17);
    out << q;
    return out.str();
  };
  const std::string first = run(1);
  BOOST_TEST(first.size() > 1000u);
  BOOST_TEST(first == run(2));
  // draco_test_nm had a quad with an angle of 180 degrees at a border vertex of valence 2 (smallest scaled
  // Jacobian 3.6e-10), at the corner added in the middle of the longest side of a three-cornered patch;
  // such patches are now quadrangulated as triangles. (0.24 at the symmetric isometry term, 0.077 since
  // too few edges on an arc cost 4 times more: a thin quad elsewhere.)
  Mesh q;
  std::istringstream in(first);
  in >> q;
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.min_scaled_jacobian > 0.05);
  // The untangling of the smoothing mended two bow-tie quads of draco by flipping them over (convex, so
  // their scaled Jacobian was positive); it now judges a quad against the orientation of its neighbourhood.
  BOOST_TEST(qr_test::flipped_over_quads(q) == 0u);
  BOOST_TEST(quality.flipped_quads == 0u); // (the package's own count, computed on the polygons)
}

// No absolute constant: the same mesh scaled by 1024 (exact in floating point) gives exactly 1024 times the
// quads (but for coordinates under 1e-300), the same connectivity. abc_00000008 (with faces 5e8 times smaller than others) gave 2954 quads
// instead of 3029 while its default length was not exactly scaled.
BOOST_AUTO_TEST_CASE(scaled_by_a_power_of_two_gives_the_scaled_quads)
{
  Mesh t;
  QR::read_and_repair(qr_test::data_file("abc_00000008.off"), t);
  Mesh big = t;
  for(auto v : big.vertices())
  {
    const auto& p = big.point(v);
    big.point(v) = qr_test::Point_3(1024. * p.x(), 1024. * p.y(), 1024. * p.z());
  }
  Mesh q, qbig;
  QR::quad_remesh(t, q);
  QR::quad_remesh(big, qbig);
  BOOST_TEST(q.number_of_faces() > 1000u);
  BOOST_REQUIRE_EQUAL(q.number_of_faces(), qbig.number_of_faces());
  BOOST_REQUIRE_EQUAL(q.number_of_vertices(), qbig.number_of_vertices());
  // exact but for values near zero, where a subnormal number (under 2.2e-308) loses bits
  std::size_t moved = 0, other_faces = 0;
  for(auto v : q.vertices())
    for(int i = 0; i < 3; ++i)
      if(!(std::abs(qbig.point(v)[i] - 1024. * q.point(v)[i]) < 1e-300)) { ++moved; break; }
  for(auto f : q.faces())
  {
    std::vector<Mesh::Vertex_index> a, b;
    for(auto v : vertices_around_face(q.halfedge(f), q)) a.push_back(v);
    for(auto v : vertices_around_face(qbig.halfedge(f), qbig)) b.push_back(v);
    if(a != b) ++other_faces;
  }
  BOOST_TEST(moved == 0u);
  BOOST_TEST(other_faces == 0u);
}

// quad_remesh() takes other models of the graph concepts: a Polyhedron_3 (without ids) in and out gives
// the quads of the Surface_mesh run (the stages run on a Surface_mesh copy; they did not compile with a
// Polyhedron_3, which has no point() member and whose descriptors are not indices).
BOOST_AUTO_TEST_CASE(polyhedron_in_and_out)
{
  typedef CGAL::Polyhedron_3<qr_test::Kernel> Polyhedron;
  Mesh t;
  Polyhedron pt;
  BOOST_REQUIRE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(qr_test::data_file("lego.off"), t));
  BOOST_REQUIRE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(qr_test::data_file("lego.off"), pt));
  Mesh q;
  Polyhedron pq;
  QR::quad_remesh(t, q);
  QR::quad_remesh(pt, pq);
  BOOST_TEST(q.number_of_faces() > 500u);
  BOOST_TEST(num_faces(pq) == num_faces(q));
  BOOST_TEST(num_vertices(pq) == num_vertices(q));
  std::vector<qr_test::Point_3> a, b;
  for(auto v : q.vertices()) a.push_back(q.point(v));
  for(auto v : vertices(pq)) b.push_back(v->point());
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  BOOST_TEST((a == b));
  std::size_t not_quads = 0;
  for(auto f : faces(pq))
    if(CGAL::halfedges_around_face(halfedge(f, pq), pq).size() != 4u) ++not_quads;
  BOOST_TEST(not_quads == 0u);
}

// spot: the smoothing left one interior quad folded onto itself (two opposite corners 1e-4 apart, scaled
// Jacobian -0.001) that no single vertex move could open; the relaxation of its region does. And no quad
// lies flipped over.
BOOST_AUTO_TEST_CASE(spot_has_no_folded_quad)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("spot.off"), t);
  const QR::Report r = QR::quad_remesh(t, q);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(quality.min_scaled_jacobian > 0.);
  BOOST_TEST(r.find("smooth")->find("inverted_after")->number() == 0.);
  // An inset of a later smoothing (the fidelity refinement's) left a thin quad flipped over among its
  // neighbours, with a positive scaled Jacobian; the last step of the smoothing turns it back.
  BOOST_TEST(quality.flipped_quads == 0u);
  BOOST_TEST(qr_test::flipped_over_quads(q) == 0u);
}

// bunny and `layout_refinement` (on by default): the one invalid patch of its layout (a left turn beside a
// held crease's tip) is cut after the refinement, the layout stage says so, and the quads are valid
BOOST_AUTO_TEST_CASE(bunny_layout_refinement)
{
  Mesh t, q, q_default;
  QR::read_and_repair(qr_test::data_file("bunny.off"), t);
  const QR::Report r = QR::quad_remesh(t, q); // (on by default)
  const QR::Report& layout = *r.find("layout");
  BOOST_TEST_REQUIRE(layout.find("refinement") != nullptr);
  const QR::Report& refinement = *layout.find("refinement");
  BOOST_TEST(refinement.find("invalid_before")->number() == 1.);
  BOOST_TEST(refinement.find("split_edges")->number() >= 1.);
  BOOST_TEST(refinement.find("invalid_after")->number() == 0.);
  BOOST_TEST(layout.find("valid_patches")->number() == layout.find("patches")->number());
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(q.is_valid(false));
  // turned off: no refinement record, and the patch stays invalid
  const QR::Report d = QR::quad_remesh(t, q_default, QR::parameters::layout_refinement(false));
  BOOST_TEST(d.find("layout")->find("refinement") == nullptr);
  BOOST_TEST(d.find("layout")->find("valid_patches")->number() + 1. == d.find("layout")->find("patches")->number());
}

// elephant: a quad at a held vertex (a spur of two short feature edges where three lines meet) kept a
// corner past 180 degrees that no move could mend, and both chords through it wind over most of the
// surface (too long to split); the smoothing insets it, which gives that vertex an edge into the quad.
// (That quad is made with the sharp edges that are not features left free in the remeshing and no bend of
// a feature line held, a remeshing tolerance as large as the mesh, and no layout refinement: each of them
// changes the layout there.)
BOOST_AUTO_TEST_CASE(elephant_quad_at_a_held_spur_is_inset)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("elephant.off"), t);
  const QR::Report r = QR::quad_remesh(t, q, QR::parameters::combine(QR::parameters::hold_sharp_edges(false),
                                                                      QR::parameters::remeshing_tolerance(1.),
                                                                      QR::parameters::layout_refinement(false)));
  const QR::Report& smooth = *r.find("smooth");
  BOOST_TEST(smooth.find("inset_quads")->number() >= 1.);
  BOOST_TEST(smooth.find("inverted_after")->number() == 0.);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(quality.min_scaled_jacobian > 0.);
  BOOST_TEST(q.is_valid(false));
  BOOST_TEST(!q.has_garbage());
}

// elephant at 500 quads, with the smoothest field (no curvature pull) and no features: a patch whose
// boundary meets itself (an inner loop bridged to the outer one) gets a pattern with a chord between two
// boundary points that the gluing makes the two ends of a one-edge arc, and the two quads on that edge
// would have it in the same direction. The assembly must give the patches involved more edges and
// solve the counts again, instead of failing.
BOOST_AUTO_TEST_CASE(conflicting_patterns_get_more_edges)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("elephant.off"), t);
  const QR::Report r = QR::quad_remesh(t, q, QR::parameters::combine(QR::parameters::number_of_quads(500),
    QR::parameters::feature_angle(180.), QR::parameters::curvature_alignment_weight(0.),
    QR::parameters::number_of_threads(2u)));
  const QR::Report& quadrangulate = *r.find("quadrangulate");
  BOOST_TEST(quadrangulate.find("count_repairs")->number() >= 1.);
  BOOST_TEST(quadrangulate.find("repaired_patches")->number() >= 2.);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(q.is_valid(false));
  BOOST_TEST(CGAL::is_closed(q));
}

// teapot: the spout and the handle are separate components that pass through the body. The smoothing
// projected body vertices next to the spout onto the spout's surface, inside the body, whose normal is close
// to the body's there (qmeval: 1.7% of the diagonal off the input); a vertex keeps to its own component.
BOOST_AUTO_TEST_CASE(teapot_vertices_keep_to_their_component)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("teapot.off"), t);
  QR::quad_remesh(t, q);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  const QR::Feature_fidelity f = fidelity_to_input(t, q);
  BOOST_TEST_MESSAGE("teapot: Hausdorff " << f.hausdorff_max << " coverage " << f.feature_coverage);
  BOOST_TEST(f.hausdorff_max <= 0.008);
}

// A small part beside a large one: truck's steering wheel beside fandisk. At fandisk's quad edge length
// (0.09) the wheel's spokes, 0.03 wide, were one quad wide and its quads crossed the holes between them
// (qmeval: 0.77% of the diagonal, and a quad with a negative scaled Jacobian); remeshed and quantized at
// its own length (a quarter), 0.33%.
BOOST_AUTO_TEST_CASE(small_part_keeps_its_shape)
{
  const Mesh t = qr_test::fandisk_and_steering_wheel();
  Mesh q;
  const QR::Report r = QR::quad_remesh(t, q);
  BOOST_TEST(r.find("remesh")->find("small_components")->number() == 1.);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.components == 2u);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  const QR::Feature_fidelity f = fidelity_to_input(t, q);
  BOOST_TEST_MESSAGE("fandisk and steering wheel: Hausdorff " << f.hausdorff_max << ", coverage " << f.feature_coverage);
  BOOST_TEST(f.hausdorff_max <= 0.005);
  BOOST_TEST(f.feature_coverage >= 0.99);
}

// spot: the smoothed quads cut the tips of the horns and ears short (qmeval: 0.78% of the diagonal off
// the input without the refinement); the patches there get more quads, and the closer quads are kept.
// Then the input vertices still farther than the tolerance from the quads (the horn tips, 0.47%) get the
// nearest quad vertex, and the quads smoothed around them are kept, being closer (0.38%; 0.41% when the
// tips taken were two quad edge lengths apart instead of one).
BOOST_AUTO_TEST_CASE(spot_patches_far_from_their_quads_get_more_quads)
{
  Mesh t, coarse, refined;
  QR::read_and_repair(qr_test::data_file("spot.off"), t);
  QR::quad_remesh(t, coarse, QR::parameters::fidelity_tolerance(0.));
  const QR::Report r = QR::quad_remesh(t, refined);
  const QR::Report& fidelity = *r.find("fidelity");
  BOOST_TEST(fidelity.find("kept")->number() >= 1.);
  BOOST_TEST(fidelity.find("refined_patches")->number() >= 1.);
  BOOST_TEST(fidelity.find("distance_after")->number() < 0.9 * fidelity.find("distance_before")->number());
  const QR::Report& tips = *fidelity.find("tips");
  BOOST_TEST(tips.find("snapped")->number() >= 1.);
  BOOST_TEST(tips.find("kept")->boolean());
  BOOST_TEST(tips.find("distance_after")->number() < tips.find("distance_before")->number());
  BOOST_TEST(tips.find("rounds")->number() >= 1.);
  BOOST_TEST(tips.find("distance_after")->number() <= 0.0040);
  const QR::Feature_fidelity before = fidelity_to_input(t, coarse), after = fidelity_to_input(t, refined);
  BOOST_TEST_MESSAGE("spot: Hausdorff " << before.hausdorff_max << " -> " << after.hausdorff_max << ", quads "
                     << num_faces(coarse) << " -> " << num_faces(refined));
  BOOST_TEST(after.hausdorff_max < before.hausdorff_max);
  BOOST_TEST(after.hausdorff_max <= 0.005);
  BOOST_TEST(num_faces(refined) > num_faces(coarse));
  BOOST_TEST(double(num_faces(refined)) < 1.5 * double(num_faces(coarse)));
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(refined);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
}

// A vertex on no face, 1% of the diagonal above fandisk's surface where quads are free to move, is not
// a tip of the surface: no quad vertex goes onto it (the output stays as close to the faces as without it).
BOOST_AUTO_TEST_CASE(isolated_vertex_is_not_a_tip)
{
  Mesh t;
  QR::read_and_repair(qr_test::data_file("fandisk.off"), t);
  const Mesh faces_only = t;
  auto features = get(CGAL::dynamic_edge_property_t<bool>(), t);
  QR::detect_feature_edges(t, features);
  // a vertex two rings away from every feature edge
  Mesh::Vertex_index free_vertex;
  for(auto v : t.vertices())
  {
    bool near_feature = false;
    for(auto w : CGAL::vertices_around_target(v, t))
      for(auto h : CGAL::halfedges_around_target(w, t))
        if(get(features, t.edge(h)) || t.is_border(t.edge(h))) near_feature = true;
    if(!near_feature) { free_vertex = v; break; }
  }
  BOOST_REQUIRE(free_vertex != Mesh::Vertex_index());
  const double diagonal = CGAL::Quad_remeshing::internal::mesh_bbox_diagonal(t);
  const auto normal = CGAL::Polygon_mesh_processing::compute_vertex_normal(free_vertex, t);
  t.add_vertex(t.point(free_vertex) + 0.01 * diagonal * normal);
  Mesh q;
  const QR::Report r = QR::quad_remesh(t, q);
  const QR::Report& tips = *r.find("fidelity")->find("tips");
  BOOST_TEST_MESSAGE("isolated vertex: " << tips.find("candidates")->number() << " tip candidates, "
                     << tips.find("snapped")->number() << " snapped");
  const QR::Feature_fidelity f = fidelity_to_input(faces_only, q);
  BOOST_TEST(f.hausdorff_max <= 0.005);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
}

// Two spikes on a plane, A (height 1) and C (height 0.9) half a quad edge apart, that a flat grid of unit
// quads cuts off. The first round of tips puts a quad vertex onto A (C is within a quad edge of it); the
// quads smoothed around it are still farther than the tolerance from C and from the plane beneath them,
// and the later rounds, with A held, bring them closer: at least two rounds are kept, and A keeps its
// vertex through them.
BOOST_AUTO_TEST_CASE(tips_left_by_a_round_get_the_next)
{
  typedef qr_test::Point_3 P;
  // the input on [0,8]^2 with the two spikes raised; the quads: 8 x 8 unit squares on the plane
  const Mesh input = plane_with_spikes(8, [](int i, int j) { return i == 8 && j == 8 ? 1. : (i == 9 && j == 8 ? 0.9 : 0.); });
  const auto input_feature = border_edge_map(input);
  const Mesh quads = quad_grid(8, [](int i, int j) { return P(i, j, 0.); });
  const auto qfeature = border_edge_map(quads);

  std::size_t smoothings = 0;
  Mesh result;
  const QR::internal::Tip_snapping_statistics st =
    snap_tips(input, input_feature, quads, qfeature, [&](const Mesh&, const auto&) { ++smoothings; }, result);
  BOOST_TEST(st.kept);
  BOOST_TEST(st.rounds >= 2u);
  BOOST_TEST(st.distance_before == 1., boost::test_tools::tolerance(1e-9));
  BOOST_TEST(st.distance_after < 0.3);
  BOOST_TEST(smoothings >= 3u);
  auto has_vertex_at = [&](const P& p) {
    for(auto v : result.vertices()) if(CGAL::squared_distance(result.point(v), p) < 1e-18) return true;
    return false;
  };
  BOOST_TEST(has_vertex_at(P(4., 4., 1.))); // A, taken in the first round and held since
  BOOST_TEST(result.number_of_faces() == quads.number_of_faces());
}

// A tip whose quads, once it is taken, end farther from the input than it was from the quads is left out,
// and the round is tried again with the other tips (elephant: a quad vertex put onto a toe's rim pulled
// the quads beside it farther off the toe than the rim vertex was from them). Here the smoothing
// hook lifts a neighbour of the vertex put onto spike B by 2 (and holds it there); A is taken alone.
BOOST_AUTO_TEST_CASE(tips_that_pull_their_quads_off_are_dropped)
{
  typedef qr_test::Point_3 P;
  const Mesh input = plane_with_spikes(8, [](int i, int j) { return i == 4 && j == 4 ? 1. : (i == 12 && j == 12 ? 0.8 : 0.); });
  const auto input_feature = border_edge_map(input);
  const Mesh quads = quad_grid(8, [](int i, int j) { return P(i, j, 0.); });
  const auto qfeature = border_edge_map(quads);
  std::size_t pulled = 0;
  auto pull = [&](Mesh& m, const auto& held) {
    for(auto v : m.vertices())
      if(m.point(v) == P(6., 6., 0.8)) {
        const auto w = m.source(m.halfedge(v));
        m.point(w) = P(m.point(w).x(), m.point(w).y(), m.point(w).z() + 2.);
        put(held, w, true);
        ++pulled;
      }
  };
  Mesh result;
  const QR::internal::Tip_snapping_statistics st = snap_tips(input, input_feature, quads, qfeature, pull, result);
  BOOST_TEST(pulled == 1u);
  BOOST_TEST(st.dropped == 1u);
  BOOST_TEST(st.kept);
  BOOST_TEST(st.distance_before == 1., boost::test_tools::tolerance(1e-9));
  BOOST_TEST(st.distance_after < 0.8 + 1e-9); // B is left out (the smoothing may bring quads up its sides)
  bool at_a = false, at_b = false;
  double highest = 0.;
  for(auto v : result.vertices()) {
    at_a = at_a || result.point(v) == P(2., 2., 1.);
    at_b = at_b || result.point(v) == P(6., 6., 0.8);
    highest = (std::max)(highest, result.point(v).z());
  }
  BOOST_TEST(at_a);
  BOOST_TEST(!at_b);
  BOOST_TEST(highest == 1.);
}

// The distance of the quads to the input is measured at their vertices too: a grid of unit quads over a
// plane, one inner vertex raised by 0.5, is 0.5 from it there (its edge midpoints are 0.25 away, its quad
// centres 0.125; the measure took only those and gave 0.25). The vertex goes back down onto the plane.
BOOST_AUTO_TEST_CASE(tips_measure_quad_vertices)
{
  typedef qr_test::Point_3 P;
  const Mesh input = plane_with_spikes(8, [](int, int) { return 0.; });
  const auto input_feature = border_edge_map(input);
  Mesh quads = quad_grid(8, [](int i, int j) { return P(i, j, i == 4 && j == 4 ? 0.5 : 0.); });
  const auto qfeature = border_edge_map(quads);
  Mesh result;
  const QR::internal::Tip_snapping_statistics st =
    snap_tips(input, input_feature, quads, qfeature, [](const Mesh&, const auto&) {}, result);
  BOOST_TEST(st.distance_before == 0.5, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(st.kept);
  BOOST_TEST(st.distance_after < 0.1);
}

// Where the quads stray from the input but no input vertex is far from them (the smoothing projects the
// quads onto the remeshed triangles, which can be off the input where it bends tightly: elephant's toes),
// the quad vertices farther than half the tolerance go onto the input. A grid of unit quads over a plane,
// one inner vertex raised by 0.3: the plane's vertex below it is 0.287 from the tent of quads, under the
// tolerance of 0.29, so there is no tip; the raised vertex is pulled back down.
BOOST_AUTO_TEST_CASE(quad_vertices_far_from_the_input_are_pulled_onto_it)
{
  typedef qr_test::Point_3 P;
  const Mesh input = plane_with_spikes(8, [](int, int) { return 0.; });
  const Mesh quads = quad_grid(8, [](int i, int j) { return P(i, j, i == 4 && j == 4 ? 0.3 : 0.); });
  const auto qfeature = border_edge_map(quads);
  std::size_t smoothings = 0;
  auto smooth = [&](Mesh&, const auto&, const auto&) { ++smoothings; };
  Mesh result;
  auto keep = [&](Mesh& m, const auto&) { result = m; };
  const QR::internal::Tip_snapping_statistics st =
    QR::internal::snap_quads_to_input_tips(input, quads, qfeature, 0.29, smooth, keep, false);
  BOOST_TEST(st.candidates == 0u);
  BOOST_TEST(smoothings == 0u);
  BOOST_TEST(st.distance_before == 0.3, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(st.pulled == 1u);
  BOOST_TEST(st.pulled_kept);
  BOOST_TEST(st.kept);
  BOOST_TEST(st.distance_after < 1e-9);
  double highest = -1.;
  for(auto v : result.vertices()) highest = (std::max)(highest, result.point(v).z());
  BOOST_TEST(result.number_of_vertices() == quads.number_of_vertices());
  BOOST_TEST(highest < 1e-9);

  // with a tolerance over the raised vertex's distance, nothing moves
  Mesh untouched;
  auto keep_untouched = [&](Mesh& m, const auto&) { untouched = m; };
  const QR::internal::Tip_snapping_statistics within =
    QR::internal::snap_quads_to_input_tips(input, quads, qfeature, 0.31, smooth, keep_untouched, false);
  BOOST_TEST(within.pulled == 0u);
  BOOST_TEST(!within.kept);
  BOOST_TEST(untouched.number_of_vertices() == 0u);
}

// A spike in the middle of a plane that a 16 x 16 grid of unit quads cuts off, the grid's inner vertices
// jittered (so that smoothing them would move them). A round of tips smooths only the quads within
// tip_smoothing_rings rings of its tips, every other vertex held (all the quads were smoothed again before,
// and truck, with --refine-layout, got an inverted quad a unit away from its tips, which made the round
// fail); after the last round kept, all the quads are smoothed once more with the tips held.
BOOST_AUTO_TEST_CASE(tips_smooth_the_quads_around_them)
{
  typedef qr_test::Point_3 P;
  const Mesh input = plane_with_spikes(16, [](int i, int j) { return i == 16 && j == 16 ? 1. : 0.; });
  const auto input_feature = border_edge_map(input);
  std::vector<std::pair<P, int>> jittered; // the inner vertices and their grid distance from the spike
  Mesh quads = quad_grid(16, [&](int i, int j) {
    const bool inner = i > 0 && i < 16 && j > 0 && j < 16;
    const P p(i + (inner ? 0.05 * ((i * 7 + j * 3) % 5 - 2) : 0.), j + (inner ? 0.05 * ((i * 3 + j * 5) % 5 - 2) : 0.), 0.);
    if(inner) jittered.emplace_back(p, std::abs(i - 8) + std::abs(j - 8));
    return p;
  });
  const auto qfeature = border_edge_map(quads);
  // the grid distance from the spike of each vertex left free by each smoothing
  std::vector<std::vector<int>> free_distances;
  auto record = [&](const Mesh& m, const auto& held) {
    std::vector<int> d;
    for(auto v : m.vertices())
      if(!get(held, v))
        d.push_back(int(std::abs(std::lround(m.point(v).x()) - 8) + std::abs(std::lround(m.point(v).y()) - 8)));
    free_distances.push_back(d);
  };
  Mesh result;
  const QR::internal::Tip_snapping_statistics st = snap_tips(input, input_feature, quads, qfeature, record, result);
  BOOST_TEST(st.kept);
  BOOST_TEST(st.distance_after < st.distance_before);
  auto has_vertex_at = [&](const P& p) {
    for(auto v : result.vertices()) if(CGAL::squared_distance(result.point(v), p) < 1e-18) return true;
    return false;
  };
  BOOST_TEST(has_vertex_at(P(8., 8., 1.))); // the spike
  // the rounds: only vertices near the spike are free (the tips of later rounds are within two quad
  // edges of the spike's vertex); the last smoothing: all but the tips
  BOOST_REQUIRE(free_distances.size() >= 2u);
  const int near_rings = int(QR::internal::tip_smoothing_rings) + 2;
  for(std::size_t k = 0; k + 1 < free_distances.size(); ++k)
  {
    BOOST_TEST(free_distances[k].size() > 10u);
    BOOST_TEST(*std::max_element(free_distances[k].begin(), free_distances[k].end()) <= near_rings + 1);
  }
  BOOST_TEST(free_distances.back().size() + 8u >= quads.number_of_vertices());
  // unless that last smoothing was kept, the vertices far from the spike are where they were
  std::size_t far = 0, kept_far = 0;
  for(const auto& pd : jittered)
    if(pd.second > near_rings) { ++far; if(has_vertex_at(pd.first)) ++kept_far; }
  BOOST_TEST(far > 50u);
  if(!st.smoothed_all) BOOST_TEST(kept_far == far);
  else BOOST_TEST(kept_far < far);
}

// xyz_cube_20mm without feature lines: one arc of the layout has a minimum edge count far above its
// target (an arc over the embossed letters), in a strip of arcs whose other end is at the top of its
// window, so the quantization's fallback could move the strip neither up nor down; it clamped that arc at
// its minimum instead, which left odd perimeters and made the quantize stage fail.
BOOST_AUTO_TEST_CASE(xyz_cube_without_features_quantizes)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("xyz_cube_20mm.off"), t);
  const QR::Report r = QR::quad_remesh(t, q, QR::parameters::feature_angle(180.));
  BOOST_TEST(r.find("quantize")->find("odd_perimeters")->number() == 0.);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
}

// chair_doublesided (every face twice, in both orientations, many non-manifold edges) repairs into
// thin closed sheets whose layout has patches with slits and bridges (sides that walk an arc there
// and back): the assembly must cut them open, and the result must still be a valid quad mesh.
BOOST_AUTO_TEST_CASE(chair_with_slit_patches)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("chair_doublesided.off"), t);
  const QR::Report r = QR::quad_remesh(t, q);
  BOOST_TEST(r.find("quadrangulate") != nullptr);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  // a sliver patch gave a quad with a flat corner at a held border vertex (scaled Jacobian 1.4e-10);
  // the smoothing insets it
  BOOST_TEST(quality.min_scaled_jacobian > 1e-3);
  BOOST_TEST(quality.faces > 1000u);
  auto features = get(CGAL::dynamic_edge_property_t<bool>(), t);
  QR::detect_evaluation_feature_edges(t, features);
  const QR::Feature_fidelity f = QR::feature_fidelity(t, features, q);
  BOOST_TEST_MESSAGE("chair: " << quality.faces << " quads, SJ min " << quality.min_scaled_jacobian << " Hausdorff "
                     << f.hausdorff_max << " coverage " << f.feature_coverage);
  BOOST_TEST(f.feature_coverage >= 0.99);
  // the smoothing projected free vertices onto the closest point of the surface, which across these thin
  // sheets could be on the other sheet (0.0086 of the diagonal); it now keeps them on their own side.
  // Since the own side is within 75 degrees rather than 90 (see angle_block below; it brings elephant
  // from 1.69% to 1.18% of the diagonal in qmeval), a valence-6 vertex on a tight bend of the sheets
  // lands elsewhere, and the figure went from 0.0049 to 0.0070.
  BOOST_TEST(f.hausdorff_max <= 0.0075);
}

// truck: a cap triangle next to a window (three feature edges, 0.0018 wide) became a patch of its own
// whose corner at the window was dropped, and a quad with four collinear corners filled it. On the
// same configuration (qr_test::cap_plate) the quads near the cap must keep a proper shape.
BOOST_AUTO_TEST_CASE(cap_with_three_feature_edges_gives_no_flat_quad)
{
  const Mesh t = qr_test::cap_plate();
  Mesh q;
  QR::quad_remesh(t, q);
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST_MESSAGE("cap plate: " << quality.faces << " quads, SJ min " << quality.min_scaled_jacobian);
  BOOST_TEST(quality.pure_quad);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  BOOST_TEST(quality.min_scaled_jacobian > 0.3);
  auto features = get(CGAL::dynamic_edge_property_t<bool>(), t);
  QR::detect_evaluation_feature_edges(t, features);
  BOOST_TEST(QR::feature_fidelity(t, features, q).feature_coverage >= 0.99);
}

// With a sizing tolerance (the default) the quads shrink where draco's surface bends: more of them, closer to
// the input than with the uniform size.
BOOST_AUTO_TEST_CASE(sizing_tolerance_brings_draco_closer)
{
  Mesh t;
  QR::read_and_repair(qr_test::data_file("draco_test_nm.off"), t);
  auto features = get(CGAL::dynamic_edge_property_t<bool>(), t);
  QR::detect_evaluation_feature_edges(t, features);
  auto run = [&](double tolerance, std::size_t& faces) {
    Mesh q;
    // (no surface tolerance, which refines draco's bends too)
    const QR::Report r = QR::quad_remesh(t, q, QR::parameters::sizing_tolerance(QR::parameters::surface_tolerance(QR::parameters::fidelity_tolerance(0.), 0.), tolerance));
    BOOST_TEST((r.find("quantize")->find("smallest_local_quad_edge_length") != nullptr) == (tolerance > 0.));
    const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
    BOOST_TEST(quality.valid);
    faces = quality.faces;
    const QR::Feature_fidelity f = QR::feature_fidelity(t, features, q);
    BOOST_TEST_MESSAGE("draco, sizing tolerance " << tolerance << ": " << faces << " quads, Hausdorff " << f.hausdorff_max);
    return f.hausdorff_max;
  };
  std::size_t uniform_faces = 0, sized_faces = 0;
  const double uniform = run(0., uniform_faces);
  const double sized = run(0.002, sized_faces);
  BOOST_TEST(sized_faces > uniform_faces);
  BOOST_TEST(sized < 0.8 * uniform);
  // 0.002 is the default
  Mesh q;
  QR::quad_remesh(t, q, QR::parameters::surface_tolerance(QR::parameters::fidelity_tolerance(0.), 0.));
  BOOST_TEST(num_faces(q) == sized_faces);
}

// number_of_quads(n): the remeshing is made for the length from the area, and the quantization's length
// grows until its counts give at most 10% more quads than n (the length from the area alone gave fandisk
// 1810 quads for 1000).
BOOST_AUTO_TEST_CASE(number_of_quads_is_approximate)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("fandisk.off"), t);
  const QR::Report r = QR::quad_remesh(t, q, QR::parameters::number_of_quads(std::size_t(1000)));
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.valid);
  BOOST_TEST_MESSAGE("fandisk, 1000 quads asked for: " << quality.faces << " in "
                     << r.find("quantize")->find("face_count_solves")->number() << " solves");
  BOOST_TEST(quality.faces >= 850u);
  BOOST_TEST(quality.faces < 1150u);
  BOOST_TEST(r.find("quantize")->find("face_count_solves")->number() >= 2.);
  const double predicted = r.find("quantize")->find("face_count_predicted_quads")->number();
  BOOST_TEST(std::abs(predicted - double(quality.faces)) <= 0.02 * predicted);
}

// The cube's embossed letters have rounded feature lines: without a feature tolerance the quantization
// gives some of their bends so few edges that the quad edges cut them (qmeval: feature coverage 0.9975,
// Hausdorff 0.76% of the diagonal); with the default one they follow them.
BOOST_AUTO_TEST_CASE(feature_tolerance_keeps_xyz_cube_letters)
{
  Mesh t;
  QR::read_and_repair(qr_test::data_file("xyz_cube_20mm.off"), t);
  auto features = get(CGAL::dynamic_edge_property_t<bool>(), t);
  QR::detect_evaluation_feature_edges(t, features);
  auto run = [&](double tolerance, std::size_t& bent) {
    Mesh q;
    // (the uniform size: the sizing tolerance would shrink the quads along the bent lines too)
    const QR::Report r = QR::quad_remesh(t, q, QR::parameters::sizing_tolerance(QR::parameters::feature_tolerance(QR::parameters::fidelity_tolerance(0.), tolerance), 0.));
    bent = std::size_t(r.find("quantize")->find("bent_feature_arcs")->number());
    BOOST_TEST(QR::quad_mesh_quality(q).valid);
    const QR::Feature_fidelity f = QR::feature_fidelity(t, features, q);
    BOOST_TEST_MESSAGE("xyz cube, feature tolerance " << tolerance << ": " << bent << " bent arcs, Hausdorff "
                       << f.hausdorff_max << ", feature max " << f.feature_max_distance << ", coverage " << f.feature_coverage);
    return f;
  };
  std::size_t bent_none = 0, bent_default = 0;
  const QR::Feature_fidelity none = run(0., bent_none);
  const QR::Feature_fidelity bounded = run(0.002, bent_default);
  BOOST_TEST(bent_none == 0u);
  BOOST_TEST(bent_default > 0u);
  BOOST_TEST(bounded.feature_coverage == 1.);
  // 0.0033 against 0.0055 (the ratio moves with the layout: 0.60 since the last-resort cuts)
  BOOST_TEST(bounded.feature_max_distance < 0.67 * none.feature_max_distance);
  BOOST_TEST(bounded.hausdorff_max < 0.005);
}

// draco_test_nm's rounded body is crossed by arcs that the quantization gave too few edges (quads cut the
// bend); a surface tolerance gives them more, only there: the result follows the surface more closely
// (qmeval: 0.73% -> 0.45% of the diagonal) and covers the sharp edges at least as well.
BOOST_AUTO_TEST_CASE(surface_tolerance_follows_bends)
{
  Mesh t;
  QR::read_and_repair(qr_test::data_file("draco_test_nm.off"), t);
  auto features = get(CGAL::dynamic_edge_property_t<bool>(), t);
  QR::detect_evaluation_feature_edges(t, features);
  auto run = [&](double tolerance, std::size_t& bent, std::size_t& quads) {
    Mesh q;
    // (the uniform size: the sizing tolerance would shrink the quads over the bends too)
    // (a negative tolerance: the default)
    const QR::Report r = tolerance < 0.
                           ? QR::quad_remesh(t, q, QR::parameters::sizing_tolerance(QR::parameters::fidelity_tolerance(0.), 0.))
                           : QR::quad_remesh(t, q, QR::parameters::sizing_tolerance(QR::parameters::surface_tolerance(QR::parameters::fidelity_tolerance(0.), tolerance), 0.));
    bent = std::size_t(r.find("quantize")->find("bent_surface_arcs")->number());
    quads = num_faces(q);
    BOOST_TEST(QR::quad_mesh_quality(q).valid);
    const QR::Feature_fidelity f = QR::feature_fidelity(t, features, q);
    BOOST_TEST_MESSAGE("draco, surface tolerance " << tolerance << ": " << bent << " bent arcs, " << quads
                       << " quads, Hausdorff " << f.hausdorff_max << ", coverage " << f.feature_coverage);
    return f;
  };
  std::size_t bent_none = 0, bent = 0, quads_none = 0, quads = 0;
  const QR::Feature_fidelity none = run(0., bent_none, quads_none);
  const QR::Feature_fidelity bounded = run(0.002, bent, quads);
  BOOST_TEST(bent_none == 0u);
  BOOST_TEST(bent > 0u);
  BOOST_TEST(quads > quads_none);
  BOOST_TEST(quads < 2 * quads_none);
  BOOST_TEST(bounded.hausdorff_max < 0.8 * none.hausdorff_max);
  BOOST_TEST(bounded.feature_coverage >= none.feature_coverage);
  // 0.002 is the default
  std::size_t bent_default = 0, quads_default = 0;
  run(-1., bent_default, quads_default);
  BOOST_TEST(bent_default == bent);
  BOOST_TEST(quads_default == quads);
}

// angle_block has a crack: a boundary loop of four edges whose two middle vertices share a position.
// Its two sides are arcs with the same ends; given one edge each they became one edge (the crack zipped,
// one boundary loop and the Euler characteristic lost). The output keeps the repaired input's topology.
BOOST_AUTO_TEST_CASE(angle_block_crack_stays_open)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("angle_block.off"), t);
  const QR::Quad_mesh_quality input = QR::quad_mesh_quality(t);
  QR::quad_remesh(t, q);
  const QR::Quad_mesh_quality output = QR::quad_mesh_quality(q);
  BOOST_TEST(output.valid);
  BOOST_TEST(output.pure_quad);
  BOOST_TEST(input.boundary_loops == 4u);
  BOOST_TEST(output.boundary_loops == input.boundary_loops);
  BOOST_TEST(output.components == input.components);
  BOOST_TEST(output.euler_characteristic == input.euler_characteristic);
}

// With the adaptive pass, a free vertex of angle_block's floor was smoothed up the curved wall next to it,
// across a 90-degree crease: the wall leans by about 2 degrees towards the floor there, so the sign of
// the dot product with the floor's normal took it for the vertex's own side (Hausdorff 0.022 of the
// diagonal, 0.005 before the adaptive pass). The smoothing now wants the normals within 75 degrees.
// (0.0108 since the sizing tolerance is on by default: a bent quad on the floor, not a vertex on the wall.)
BOOST_AUTO_TEST_CASE(angle_block_adaptive_vertices_stay_on_their_side)
{
  Mesh t, q;
  QR::read_and_repair(qr_test::data_file("angle_block.off"), t);
  QR::quad_remesh(t, q, QR::parameters::adaptive_remeshing(true));
  const QR::Quad_mesh_quality quality = QR::quad_mesh_quality(q);
  BOOST_TEST(quality.valid);
  BOOST_TEST(quality.non_positive_scaled_jacobian == 0u);
  const QR::Feature_fidelity f = fidelity_to_input(t, q);
  BOOST_TEST_MESSAGE("angle_block adaptive: " << quality.faces << " quads, Hausdorff " << f.hausdorff_max
                     << ", coverage " << f.feature_coverage);
  BOOST_TEST(f.feature_coverage >= 0.99);
  BOOST_TEST(f.hausdorff_max <= 0.015);
}

BOOST_AUTO_TEST_SUITE_END()
