// Side quantization: known optima, brute force on small problems, parity on generated layouts,
// the fallback alone, clusters, threads, time limit, bad input.
#include <CGAL/Quad_remeshing/quantize_patch_sides.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>

namespace {

namespace QR = CGAL::Quad_remeshing;
namespace P = CGAL::Quad_remeshing::parameters;
using QR::Side_quantization_problem;
typedef std::vector<std::size_t> Side;

// A grid of nx x ny cells; arcs: horizontal h(i,j) (i in [0,nx), j in [0,ny]) and vertical v(i,j)
// (i in [0,nx], j in [0,ny)). Some horizontally adjacent cell pairs are merged into one patch with
// T-junctions on its top and bottom sides; some merged pairs become pentagons (bottom side split at
// the T-junction), some single cells become triangles (left and top sides joined).
Side_quantization_problem make_grid(int nx, int ny, std::mt19937& rng, bool fractional,
                                   double merge_prob = 0.2, double odd_prob = 0.1)
{
  Side_quantization_problem pb;
  std::uniform_real_distribution<double> len(1.0, 8.0);
  std::uniform_real_distribution<double> u(0., 1.);
  std::vector<double> wx(nx), wy(ny);
  for(auto& x : wx) x = fractional ? len(rng) : std::round(len(rng));
  for(auto& y : wy) y = fractional ? len(rng) : std::round(len(rng));
  auto h = [&](int i, int j) { return std::size_t(j * nx + i); };
  auto v = [&](int i, int j) { return std::size_t((ny + 1) * nx + j * (nx + 1) + i); };
  pb.arcs.resize(std::size_t((ny + 1) * nx + ny * (nx + 1)));
  for(int j = 0; j <= ny; ++j) for(int i = 0; i < nx; ++i) pb.arcs[h(i, j)].target = wx[i];
  for(int j = 0; j < ny; ++j) for(int i = 0; i <= nx; ++i) pb.arcs[v(i, j)].target = wy[j];
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i) {
      if(i + 1 < nx && u(rng) < merge_prob) {
        std::vector<Side> sides{{h(i, j), h(i + 1, j)}, {v(i + 2, j)}, {h(i + 1, j + 1), h(i, j + 1)}, {v(i, j)}};
        if(u(rng) < odd_prob * 2) sides = {{h(i, j)}, {h(i + 1, j)}, {v(i + 2, j)}, {h(i + 1, j + 1), h(i, j + 1)}, {v(i, j)}};
        pb.patches.push_back(sides);
        ++i;
      } else if(u(rng) < odd_prob) {
        pb.patches.push_back({{h(i, j)}, {v(i + 1, j)}, {h(i, j + 1), v(i, j)}});
      } else {
        pb.patches.push_back({{h(i, j)}, {v(i + 1, j)}, {h(i, j + 1)}, {v(i, j)}});
      }
    }
  return pb;
}

std::size_t odd_or_small(const Side_quantization_problem& pb, const std::vector<int>& s)
{
  std::size_t bad = 0;
  for(int x : s) if(x < 1) ++bad;
  for(const auto& p : pb.patches) {
    long per = 0;
    for(const auto& side : p) for(std::size_t a : side) per += s[a];
    if(per % 2 != 0 || per < 4) ++bad;
  }
  return bad;
}

// Arcs bounding no patch (a merged cell's inner edge) are not part of the program.
std::vector<bool> used_arcs(const Side_quantization_problem& pb)
{
  std::vector<bool> used(pb.arcs.size(), false);
  for(const auto& p : pb.patches) for(const auto& side : p) for(std::size_t a : side) used[a] = true;
  return used;
}

// Twice the sub-sides (up: start corner to separatrix, down: separatrix to end corner) of side j of a
// 3, 5 or 6-sided patch with side counts E, written out per patch size (Tarini's closed forms).
void up_down(const std::vector<int>& e, int j, int& up, int& down)
{
  const int n = int(e.size());
  auto E = [&](int k) { return e[((k % n) + n) % n]; };
  if(n == 3) { down = E(j) + E(j + 2) - E(j + 1); up = E(j) + E(j + 1) - E(j + 2); }
  if(n == 5) { down = E(j) + E(j + 1) + E(j + 2) - E(j + 3) - E(j + 4); up = E(j + 3) + E(j + 4) + E(j) - E(j + 1) - E(j + 2); }
  if(n == 6) { down = E(j) + E(j + 2) - E(j + 4); up = E(j + 4) + E(j) - E(j + 2); }
}

std::vector<int> side_counts(const Side_quantization_problem& pb, std::size_t p, const std::vector<int>& s)
{
  std::vector<int> e(pb.patches[p].size(), 0);
  for(std::size_t i = 0; i < e.size(); ++i) for(std::size_t a : pb.patches[p][i]) e[i] += s[a];
  return e;
}

// Alignment of the pair (p, i) - (q, j): the shared line is walked in opposite directions.
int misalignment(const Side_quantization_problem& pb, const QR::internal::Alignment_pair& ap, const std::vector<int>& s)
{
  int up_p, down_p, up_q, down_q;
  up_down(side_counts(pb, ap.p, s), int(ap.i), up_p, down_p);
  up_down(side_counts(pb, ap.q, s), int(ap.j), up_q, down_q);
  return std::abs(up_p - down_q) + std::abs(down_p - up_q);
}

// The model's objective evaluated independently (squared deviation, 4 times larger below the target,
// quads |e0-e2|+|e1-e3|, Tarini, alignment of the given pairs with weight 9).
double objective(const Side_quantization_problem& pb, const std::vector<int>& s,
                 const std::vector<QR::internal::Alignment_pair>& pairs = {})
{
  double align = 0;
  for(const auto& ap : pairs) align += 0.5 * misalignment(pb, ap, s);
  double iso = 0, quad = 0, poly = 0;
  const auto used = used_arcs(pb);
  for(std::size_t a = 0; a < pb.arcs.size(); ++a)
    if(used[a]) iso += (s[a] < pb.arcs[a].target ? 4. : 1.) * (s[a] - pb.arcs[a].target) * (s[a] - pb.arcs[a].target);
  for(const auto& p : pb.patches) {
    const int n = int(p.size());
    std::vector<int> e(n, 0);
    for(int i = 0; i < n; ++i) for(std::size_t a : p[i]) e[i] += s[a];
    auto E = [&](int k) { return e[((k % n) + n) % n]; };
    if(n == 4) { quad += std::abs(e[0] - e[2]) + std::abs(e[1] - e[3]); continue; }
    double viol = 0;
    for(int i = 0; i < n; ++i) {
      int two_s = 0;
      if(n == 3) two_s = E(i - 1) + E(i + 1) - E(i);
      if(n == 5) two_s = E(i - 1) + E(i) + E(i + 1) - E(i + 2) - E(i - 2);
      if(n == 6) two_s = E(i - 1) + E(i + 1) - E(i + 3);
      viol += std::max(0, 2 - two_s);
    }
    if(n == 6 && (e[0] + e[2] + e[4]) % 2) viol += 1;
    poly += viol / n;
  }
  return iso + 99 * quad + 91 * poly + 9 * align;
}

double brute_force(const Side_quantization_problem& pb, const std::vector<QR::internal::Alignment_pair>& pairs = {})
{
  const std::size_t na = pb.arcs.size();
  std::vector<int> s(na), lo(na), hi(na);
  const auto used = used_arcs(pb);
  for(std::size_t a = 0; a < na; ++a) {
    QR::internal::arc_window(pb.arcs[a], lo[a], hi[a]);
    if(!used[a]) hi[a] = lo[a];
  }
  double best = 1e300;
  std::function<void(std::size_t)> rec = [&](std::size_t a) {
    if(a == na) { if(odd_or_small(pb, s) == 0) best = std::min(best, objective(pb, s, pairs)); return; }
    for(int x = lo[a]; x <= hi[a]; ++x) { s[a] = x; rec(a + 1); }
  };
  rec(0);
  return best;
}

} // namespace

BOOST_AUTO_TEST_SUITE(quantization)

BOOST_AUTO_TEST_CASE(regular_grid_integer_targets_is_exact)
{
  std::mt19937 rng(1);
  const auto pb = make_grid(12, 10, rng, false, 0., 0.);
  std::vector<int> s;
  const auto st = QR::quantize_patch_sides(pb, s);
  for(std::size_t a = 0; a < pb.arcs.size(); ++a) BOOST_CHECK_EQUAL(s[a], int(pb.arcs[a].target));
  BOOST_CHECK_SMALL(st.objective, 1e-9);
  BOOST_CHECK_EQUAL(st.simple_patches, pb.patches.size());
  BOOST_CHECK_EQUAL(st.status.at(0), "optimal");
}

BOOST_AUTO_TEST_CASE(too_few_edges_cost_more_than_too_many)
{
  // One quad whose opposite sides want 2.5 and 1.5 edges: equal counts on opposite sides, so 2 or 3 and
  // 1 or 2. The squared deviation alone is the same either way; too few edges count 4 times more by
  // default, so both sides round up.
  Side_quantization_problem pb;
  pb.arcs = {{2.5}, {1.5}, {2.5}, {1.5}};
  pb.patches = {{{0}, {1}, {2}, {3}}};
  std::vector<int> s;
  const auto st = QR::quantize_patch_sides(pb, s);
  BOOST_TEST((s == std::vector<int>{3, 2, 3, 2}));
  BOOST_CHECK_CLOSE(st.isometry, 4 * 0.25, 1e-9);
  // at 1 (the symmetric term) both roundings cost the same
  std::vector<int> s1;
  const auto st1 = QR::quantize_patch_sides(pb, s1, P::under_subdivision_weight(1.));
  BOOST_CHECK_CLOSE(st1.isometry, 4 * 0.25, 1e-9);
  // a factor that makes the term concave is refused
  BOOST_CHECK_THROW(QR::quantize_patch_sides(pb, s1, P::under_subdivision_weight(0.5)), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(triangle_forces_irregular_vertex)
{
  // One triangle with targets 3,3,3: odd perimeter; the optimum moves one arc by one (cost 1).
  Side_quantization_problem pb;
  pb.arcs = {{3.}, {3.}, {3.}};
  pb.patches = {{{0}, {1}, {2}}};
  std::vector<int> s;
  const auto st = QR::quantize_patch_sides(pb, s);
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  BOOST_CHECK_CLOSE(st.objective, 1., 1e-6);
  BOOST_CHECK_EQUAL(st.simple_patches, 1u);
  // A ring of four quads around a triangle-free hole would be regular; a pentagon among quads:
  Side_quantization_problem pent;
  pent.arcs = {{2.}, {2.}, {2.}, {2.}, {2.}};
  pent.patches = {{{0}, {1}, {2}, {3}, {4}}};
  QR::quantize_patch_sides(pent, s);
  BOOST_CHECK_EQUAL(odd_or_small(pent, s), 0u);
  BOOST_CHECK_CLOSE(objective(pent, s), brute_force(pent), 1e-6);
}

// A ring of three quads around a triangle (a valence-3 vertex inside the triangle is forced): the
// triangle's targets 2, 2, 3 give an odd perimeter, and each quad wants its outer side equal to the
// triangle side it faces. The optimum changes one triangle side and the outer side facing it (cost 2).
BOOST_AUTO_TEST_CASE(ring_around_a_triangle_forces_an_irregular_vertex)
{
  // arcs: 0-2 the triangle's sides c_i, 3-5 the quads' outer sides o_i, 6-8 the spokes r_i between quads
  Side_quantization_problem pb;
  pb.arcs = {{2.}, {2.}, {3.}, {2.}, {2.}, {3.}, {2.}, {2.}, {2.}};
  pb.patches = {{{0}, {1}, {2}},
                {{0}, {6}, {3}, {7}}, {{1}, {7}, {4}, {8}}, {{2}, {8}, {5}, {6}}};
  std::vector<int> s;
  const auto st = QR::quantize_patch_sides(pb, s);
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  BOOST_CHECK_CLOSE(st.objective, 2., 1e-6);
  BOOST_CHECK_CLOSE(objective(pb, s), brute_force(pb), 1e-6);
  for(int i = 0; i < 3; ++i) BOOST_CHECK_EQUAL(s[std::size_t(i)], s[std::size_t(3 + i)]); // every quad regular
  // the same without the solver: the strip fallback and its moves find it too
  std::vector<int> sf;
  const auto stf = QR::quantize_patch_sides(pb, sf, P::use_mip_solver(false));
  BOOST_CHECK_CLOSE(stf.objective, 2., 1e-6);
}

BOOST_AUTO_TEST_CASE(t_junction_case)
{
  // Left: two quads A (bottom) and C (top) of height 2 and 3; right: quad B whose left side is the
  // two arcs shared with A and C (a T-junction). Targets are consistent: optimum 0.
  // arcs: 0 A.bottom, 1 A|B, 2 A.top=C.bottom, 3 A.left, 4 C|B, 5 C.top, 6 C.left, 7 B.bottom, 8 B.right, 9 B.top
  Side_quantization_problem pb;
  pb.arcs = {{4.}, {2.}, {4.}, {2.}, {3.}, {4.}, {3.}, {5.}, {5.}, {5.}};
  pb.patches = {{{0}, {1}, {2}, {3}}, {{2}, {4}, {5}, {6}}, {{7}, {8}, {9}, {4, 1}}};
  std::vector<int> s;
  const auto st = QR::quantize_patch_sides(pb, s);
  BOOST_CHECK_SMALL(st.objective, 1e-9);
  // Make the T-junction inconsistent: B.right wants 4.6: the optimum is a trade-off, checked by brute force.
  pb.arcs[8].target = 4.6;
  pb.arcs[4].target = 2.6;
  QR::quantize_patch_sides(pb, s);
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  BOOST_CHECK_CLOSE(objective(pb, s), brute_force(pb), 1e-6);
}

BOOST_AUTO_TEST_CASE(small_random_problems_match_brute_force)
{
  std::mt19937 rng(7);
  int checked = 0, with_pairs = 0;
  for(int k = 0; k < 40 && checked < 12; ++k) {
    auto pb = make_grid(2, 1, rng, true, 0.5, 0.4);
    if(pb.arcs.size() > 7) continue;
    std::vector<int> s;
    const auto st = QR::quantize_patch_sides(pb, s);
    const auto pairs = QR::internal::alignment_pairs(QR::internal::make_view(pb));
    BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
    if(st.dropped_pairs == 0) {
      // one solve: the optimum of the whole objective, alignment included
      BOOST_CHECK_CLOSE(st.objective, objective(pb, s, pairs), 1e-6);
      BOOST_CHECK_CLOSE(st.objective + 1., brute_force(pb, pairs) + 1., 1e-6);
    }
    std::vector<int> s0;
    const auto st0 = QR::quantize_patch_sides(pb, s0, P::alignment_weight(0.));
    BOOST_CHECK_CLOSE(st0.objective, objective(pb, s0), 1e-6);
    BOOST_CHECK_CLOSE(st0.objective + 1., brute_force(pb) + 1., 1e-6);
    with_pairs += !pairs.empty();
    ++checked;
  }
  BOOST_CHECK_GE(checked, 5);
  BOOST_TEST_MESSAGE("  " << with_pairs << " of " << checked << " problems have an alignment pair");
}

// Two triangles sharing arc 0 (4 edges wanted). A (sides 0, 1, 2) has targets 3 and 3: its separatrix
// lands in the middle of arc 0. B (sides 0, 3, 4) wants 2.4 and 3.6: rounded (2, 4) its separatrix lands
// one edge off A's. Aligned, B takes (3, 3) for 1 more isometry (0.36 + 4 x 0.36 instead of 4 x 0.16 +
// 0.16: too few edges cost 4 times more); misaligned costs 9 * (2 + 2) / 2.
BOOST_AUTO_TEST_CASE(alignment_puts_facing_singularities_on_one_line)
{
  Side_quantization_problem pb;
  pb.arcs = {{4.}, {3.}, {3.}, {2.4}, {3.6}};
  pb.patches = {{{0}, {1}, {2}}, {{0}, {3}, {4}}};
  const auto pairs = QR::internal::alignment_pairs(QR::internal::make_view(pb));
  BOOST_REQUIRE_EQUAL(pairs.size(), 1u);
  BOOST_CHECK(pairs[0].p == 0 && pairs[0].i == 0 && pairs[0].q == 1 && pairs[0].j == 0);
  std::vector<int> s, s0, sf;
  const auto st = QR::quantize_patch_sides(pb, s);
  BOOST_CHECK((s == std::vector<int>{4, 3, 3, 3, 3}));
  BOOST_CHECK_EQUAL(st.alignment_pairs, 1u);
  BOOST_CHECK_EQUAL(st.aligned_pairs, 1u);
  BOOST_CHECK_EQUAL(st.dropped_pairs, 0u);
  BOOST_CHECK_CLOSE(st.objective, brute_force(pb, pairs), 1e-6);
  BOOST_CHECK_CLOSE(st.objective, 1.8, 1e-6);
  const auto st0 = QR::quantize_patch_sides(pb, s0, P::alignment_weight(0.));
  BOOST_CHECK((s0 == std::vector<int>{4, 3, 3, 2, 4}));
  BOOST_CHECK_EQUAL(st0.alignment_pairs, 0u);
  BOOST_CHECK_EQUAL(misalignment(pb, pairs[0], s0), 4);
  // the fallback's local search sees the alignment term too
  QR::quantize_patch_sides(pb, sf, P::use_mip_solver(false));
  BOOST_CHECK_EQUAL(misalignment(pb, pairs[0], sf), 0);
}

// A pentagon and a triangle facing each other through a strip of two quads; a T-junction on the strip
// (one quad side made of two arcs) or a boundary stops the chain.
BOOST_AUTO_TEST_CASE(alignment_pairs_through_quad_strips)
{
  // arcs: 0 T|Q1, 1 Q1|Q2, 2 Q2|P; triangle T = (0, 3, 4); quads Q1 = (0, 5, 1, 6), Q2 = (1, 7, 2, 8);
  // pentagon P = (2, 9, 10, 11, 12).
  Side_quantization_problem pb;
  pb.arcs.assign(13, Side_quantization_problem::Arc());
  for(auto& a : pb.arcs) a.target = 3.;
  pb.patches = {{{0}, {3}, {4}}, {{0}, {5}, {1}, {6}}, {{1}, {7}, {2}, {8}}, {{2}, {9}, {10}, {11}, {12}}};
  auto pairs = QR::internal::alignment_pairs(QR::internal::make_view(pb));
  BOOST_REQUIRE_EQUAL(pairs.size(), 1u);
  BOOST_CHECK(pairs[0].p == 0 && pairs[0].i == 0 && pairs[0].q == 3 && pairs[0].j == 0);
  // Solved with fractional targets: aligned, and the optimum of the whole objective.
  pb.arcs[3].target = 2.6; pb.arcs[4].target = 3.7; pb.arcs[9].target = 2.2; pb.arcs[12].target = 3.4;
  std::vector<int> s;
  const auto st = QR::quantize_patch_sides(pb, s);
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  BOOST_CHECK_EQUAL(misalignment(pb, pairs[0], s), 0);
  BOOST_CHECK_CLOSE(st.objective, objective(pb, s, pairs), 1e-6);
  // Q2's side towards P split in two arcs (a T-junction): no pair.
  Side_quantization_problem t = pb;
  t.arcs.push_back(Side_quantization_problem::Arc());
  t.patches[2][2] = {2, 13};
  t.patches[3] = {{13, 2}, {9}, {10}, {11}, {12}};
  BOOST_CHECK(QR::internal::alignment_pairs(QR::internal::make_view(t)).empty());
  // Q1 without its neighbour Q2 (arc 1 on the boundary): no pair either.
  Side_quantization_problem b = pb;
  b.patches.erase(b.patches.begin() + 2);
  BOOST_CHECK(QR::internal::alignment_pairs(QR::internal::make_view(b)).empty());
}

// A pair that fixed arcs keep misaligned is dropped after the first solve; the second solve then
// optimises the other terms alone and the reported objective is the independent one without the pair.
BOOST_AUTO_TEST_CASE(unmet_alignment_is_dropped_in_the_second_solve)
{
  Side_quantization_problem pb;
  pb.arcs = {{4.}, {3., 3}, {3., 3}, {2., 2}, {4., 4}, {3.3}, {3.3}};
  // Triangles A = (0, 1, 2) and B = (0, 3, 4) share arc 0, with B's other arcs fixed so that its
  // separatrix is one edge off A's whatever arc 0 is; triangle C = (2, 5, 6) shares arc 2 with A and
  // can be aligned with it.
  pb.patches = {{{0}, {1}, {2}}, {{0}, {3}, {4}}, {{2}, {5}, {6}}};
  const auto pairs = QR::internal::alignment_pairs(QR::internal::make_view(pb));
  BOOST_REQUIRE_EQUAL(pairs.size(), 2u);
  std::vector<int> s;
  const auto st = QR::quantize_patch_sides(pb, s);
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  BOOST_CHECK_EQUAL(st.alignment_pairs, 2u);
  BOOST_CHECK_EQUAL(st.dropped_pairs, 1u);
  BOOST_CHECK_EQUAL(st.aligned_pairs, 1u);
  std::vector<QR::internal::Alignment_pair> kept;
  for(const auto& ap : pairs) if(misalignment(pb, ap, s) == 0) kept.push_back(ap);
  BOOST_REQUIRE_EQUAL(kept.size(), 1u);
  BOOST_CHECK_CLOSE(st.objective, objective(pb, s, kept), 1e-6);
  BOOST_CHECK_CLOSE(st.objective + 1., brute_force(pb, kept) + 1., 1e-6);
}

#ifdef CGAL_USE_GLPK
// GLPK traits whose solves after the first one throw, as a solver can (e.g. out of memory)
struct Throws_after_first_solve : QR::GLPK_mixed_integer_program_traits_with_limits<double>
{
  static int& calls() { static int n = 0; return n; }
  bool solve() override
  {
    if(++calls() > 1) throw std::runtime_error("second solve fails");
    return QR::GLPK_mixed_integer_program_traits_with_limits<double>::solve();
  }
};

// A failing second solve (the one without the dropped alignment pairs) keeps the first solve's result
// instead of sending the whole cluster to the fallback.
BOOST_AUTO_TEST_CASE(failing_second_solve_keeps_the_first_result)
{
  Side_quantization_problem pb;
  pb.arcs = {{4.}, {3., 3}, {3., 3}, {2., 2}, {4., 4}, {3.3}, {3.3}};
  pb.patches = {{{0}, {1}, {2}}, {{0}, {3}, {4}}, {{2}, {5}, {6}}}; // as above: one pair is dropped
  Throws_after_first_solve::calls() = 0;
  std::vector<int> s;
  const auto st = QR::quantize_patch_sides<Throws_after_first_solve>(pb, s);
  BOOST_CHECK_EQUAL(Throws_after_first_solve::calls(), 2); // the second solve was tried
  BOOST_CHECK_EQUAL(st.fallback_clusters, 0u);
  BOOST_CHECK_EQUAL(st.dropped_pairs, 1u);
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  BOOST_REQUIRE_EQUAL(st.status.size(), 1u);
  BOOST_CHECK(st.status[0].find("fallback") == std::string::npos);
}
#endif

BOOST_AUTO_TEST_CASE(parity_on_generated_layouts_solver_fallback_threads)
{
  std::mt19937 rng(11);
  for(int sz : {12, 20}) {
    const auto pb = make_grid(sz, sz, rng, true);
    std::vector<int> s1, s2, sf;
    auto t = std::chrono::steady_clock::now();
    // 400 nodes: at the default 100, one cluster of the 20 x 20 grid stops at the node limit (the
    // isometry term weighs too few edges 4 times, and the search there needs more nodes)
    const auto st1 = QR::quantize_patch_sides(pb, s1, P::combine(P::maximum_cluster_size(100), P::maximum_running_time(5.),
                                                                 P::maximum_number_of_nodes(400)));
    const double t_glpk = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    const auto st2 = QR::quantize_patch_sides(pb, s2, P::combine(P::maximum_cluster_size(100), P::maximum_running_time(5.), P::number_of_threads(2),
                                                                 P::maximum_number_of_nodes(400)));
    t = std::chrono::steady_clock::now();
    const auto stf = QR::quantize_patch_sides(pb, sf, QR::parameters::use_mip_solver(false));
    const double t_fb = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    BOOST_CHECK_EQUAL(odd_or_small(pb, s1), 0u);
    BOOST_CHECK_EQUAL(odd_or_small(pb, sf), 0u);
    // A wall-clock limit makes a result time-dependent; proven optima must not depend on threads.
    auto all_optimal = [](const QR::Side_quantization_statistics& st) {
      return std::all_of(st.status.begin(), st.status.end(), [](const std::string& x) { return x == "optimal"; });
    };
    BOOST_CHECK(all_optimal(st1));
    if(all_optimal(st1) && all_optimal(st2)) BOOST_CHECK(s1 == s2);
    BOOST_CHECK_EQUAL(st1.odd_perimeters, 0u);
    BOOST_CHECK_GT(st1.clusters, 1u);
    BOOST_CHECK_LE(st1.objective, stf.objective + 1e-9);
    std::cerr << "[quantization test] " << pb.patches.size() << " patches, " << st1.clusters << " clusters: GLPK "
              << t_glpk << " s objective " << st1.objective << " (simple " << st1.simple_patches
              << "), fallback " << t_fb << " s objective " << stf.objective << " (simple " << stf.simple_patches << ")\n";
  }
}

BOOST_AUTO_TEST_CASE(large_problem_fallback_and_time_limit)
{
  std::mt19937 rng(3);
  const auto pb = make_grid(50, 50, rng, true);
  std::vector<int> s;
  auto stf = QR::quantize_patch_sides(pb, s, QR::parameters::use_mip_solver(false));
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  std::cerr << "[quantization test] fallback on " << pb.patches.size() << " patches: " << stf.seconds << " s\n";
  // One cluster of ~2000 patches with fractional targets and a 2 s limit on the stage: the fallback and
  // the strip moves run first, the solve gets what is left.
  const auto st = QR::quantize_patch_sides(pb, s, P::combine(P::maximum_cluster_size(100000), P::maximum_running_time(2.)));
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  // The limit bounds the stage; the model building comes on top of it. An AddressSanitizer build runs the
  // fallback several times slower, leaving the solve no time at all, so the time and the solve's status
  // are checked in optimised builds only.
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
  BOOST_CHECK_LT(st.seconds, 6.);
  // the fallback is offered as the first incumbent: the limit ends with a solution
  BOOST_CHECK(st.status.at(0) == "feasible_at_limit" || st.status.at(0) == "optimal");
#endif
  // never worse than the fallback alone
  std::vector<int> sf1;
  const auto stf1 = QR::quantize_patch_sides(pb, sf1, P::combine(P::maximum_cluster_size(100000), P::use_mip_solver(false)));
  BOOST_CHECK_LE(st.objective, stf1.objective + 1e-6);
  std::cerr << "[quantization test] one cluster, 2 s limit: " << st.seconds << " s, status " << st.status.at(0)
            << ", objective " << st.objective << " (fallback alone " << stf.objective << ")\n";
}

// The time limit bounds the stage: with none left, no cluster is solved and every cluster keeps the
// solver-free values (fallback and strip moves), exactly as without the solver.
BOOST_AUTO_TEST_CASE(no_time_left_keeps_the_fallback)
{
  std::mt19937 rng(5);
  const auto pb = make_grid(12, 12, rng, true);
  std::vector<int> s, sf;
  const auto st = QR::quantize_patch_sides(pb, s, P::combine(P::maximum_cluster_size(40), P::maximum_running_time(1e-9)));
  const auto stf = QR::quantize_patch_sides(pb, sf, P::combine(P::maximum_cluster_size(40), P::use_mip_solver(false)));
  BOOST_TEST_REQUIRE(st.status.size() > 1u);
  for(const std::string& x : st.status) BOOST_TEST(x == "fallback (time limit)");
  BOOST_TEST(st.fallback_clusters == st.status.size());
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  BOOST_TEST(s == sf);
  // with time to solve, the program does better
  std::vector<int> sm;
  const auto stm = QR::quantize_patch_sides(pb, sm, P::maximum_cluster_size(40));
  BOOST_TEST(stm.fallback_clusters == 0u);
  BOOST_TEST(stm.objective < st.objective);
}

// A node limit, unlike a time limit, stops every run at the same point of the search: the same result
// on every run and with any number of threads, even when the search is cut short.
BOOST_AUTO_TEST_CASE(node_limit_is_deterministic)
{
  std::mt19937 rng(5);
  const auto pb = make_grid(30, 30, rng, true);
  auto run = [&](unsigned threads, std::vector<int>& s) {
    return QR::quantize_patch_sides(pb, s, P::combine(P::maximum_cluster_size(300), P::maximum_number_of_nodes(std::size_t(10)),
                                                      P::number_of_threads(threads)));
  };
  std::vector<int> s1, s2, s3;
  const auto st1 = run(1, s1);
  const auto st2 = run(1, s2);
  const auto st3 = run(2, s3);
  BOOST_CHECK(std::count(st1.status.begin(), st1.status.end(), "feasible_at_limit") > 0); // the limit was hit
  BOOST_CHECK_EQUAL(odd_or_small(pb, s1), 0u);
  BOOST_CHECK(s1 == s2);
  BOOST_CHECK(s1 == s3);
  BOOST_CHECK(st1.status == st2.status);
  BOOST_CHECK(st1.status == st3.status);
  BOOST_CHECK_EQUAL(st1.objective, st3.objective);
}

// The local search (strip moves) never raises the objective, keeps every parity even, leaves the fixed
// arcs alone and is deterministic; on a layout with a quad strip whose rounded sides disagree, it makes
// the strip regular.
BOOST_AUTO_TEST_CASE(local_search_improves_and_keeps_parity)
{
  QR::internal::Quantization_weights w;
  for(unsigned seed = 0; seed < 5; ++seed) {
    std::mt19937 rng(seed);
    auto pb = make_grid(12, 12, rng, true);
    for(std::size_t a = 0; a < pb.arcs.size(); a += 17) pb.arcs[a].fixed = 2;
    auto v = QR::internal::make_view(pb);
    std::vector<int> s(pb.arcs.size(), 1);
    QR::internal::fallback_assignment(v, s);
    QR::Side_quantization_statistics before, after;
    QR::internal::evaluate(v, s, w, before);
    std::vector<int> s1 = s, s2 = s;
    const double gain = QR::internal::improve_locally(v, s1, w);
    QR::internal::improve_locally(v, s2, w);
    QR::internal::evaluate(v, s1, w, after);
    BOOST_CHECK(s1 == s2);
    BOOST_CHECK_EQUAL(odd_or_small(pb, s1), 0u);
    BOOST_CHECK_CLOSE(before.objective - after.objective, gain, 1e-6);
    BOOST_CHECK_LE(after.objective, before.objective + 1e-9);
    for(std::size_t a = 0; a < pb.arcs.size(); ++a) if(pb.arcs[a].fixed > 0) BOOST_CHECK_EQUAL(s1[a], pb.arcs[a].fixed);
  }
  // A row of 3 quads between two boundaries: arcs 0-2 on top, 3-5 at the bottom, 6-9 vertical with
  // targets 2.9 but values 2. Moving one vertical arc alone would make a quad irregular or odd; the
  // strip through the row moves all four together.
  Side_quantization_problem pb;
  pb.arcs.resize(10);
  for(std::size_t a = 0; a < 6; ++a) pb.arcs[a].target = 3;
  for(std::size_t a = 6; a < 10; ++a) pb.arcs[a].target = 2.9;
  for(std::size_t i = 0; i < 3; ++i) pb.patches.push_back({{i}, {7 + i}, {3 + i}, {6 + i}});
  auto v = QR::internal::make_view(pb);
  std::vector<int> s = {3, 3, 3, 3, 3, 3, 2, 2, 2, 2};
  QR::internal::improve_locally(v, s, w);
  BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
  BOOST_CHECK((s == std::vector<int>{3, 3, 3, 3, 3, 3, 3, 3, 3, 3}));
}

// The solver-free heuristic alone (strip rounding, parity repair along strips, strip and cycle moves)
// finds the optimum of layouts whose quads only need consistent strips: a grid with fractional targets
// that vary along every strip (plain rounding makes quads irregular), and the T-junction case of
// t_junction_case() with inconsistent targets (one strip on each side of the T-junction must change).
BOOST_AUTO_TEST_CASE(heuristic_alone_finds_known_optima)
{
  std::mt19937 rng(3);
  auto pb = make_grid(10, 8, rng, true, 0., 0.);
  std::uniform_real_distribution<double> jitter(-0.45, 0.45);
  for(auto& a : pb.arcs) a.target += jitter(rng);
  std::vector<int> sf, sm;
  const auto stf = QR::quantize_patch_sides(pb, sf, P::use_mip_solver(false));
  BOOST_CHECK_EQUAL(odd_or_small(pb, sf), 0u);
  BOOST_CHECK_EQUAL(stf.quad_regularity, 0.);
#if defined(CGAL_USE_GLPK)
  const auto stm = QR::quantize_patch_sides(pb, sm, P::maximum_number_of_nodes(std::size_t(0)));
  BOOST_TEST_MESSAGE("  grid: heuristic " << stf.objective << ", exact " << stm.objective << " (" << stm.status.at(0) << ")");
  BOOST_CHECK_EQUAL(stm.status.at(0), "optimal");
  BOOST_CHECK_CLOSE(stf.objective, stm.objective, 1e-6);
#endif
  Side_quantization_problem t;
  t.arcs = {{4.}, {2.}, {4.}, {2.}, {3.}, {4.}, {3.}, {5.}, {4.6}, {5.}};
  t.arcs[4].target = 2.6;
  t.patches = {{{0}, {1}, {2}, {3}}, {{2}, {4}, {5}, {6}}, {{7}, {8}, {9}, {4, 1}}};
  std::vector<int> st;
  const auto stt = QR::quantize_patch_sides(t, st, P::use_mip_solver(false));
  BOOST_CHECK_EQUAL(odd_or_small(t, st), 0u);
  BOOST_CHECK_CLOSE(stt.objective, brute_force(t), 1e-6);
}

// Arcs with a minimum above their target (a bent feature line needs more edges than its length asks
// for) keep it in the program, in the fallback and across clusters, and the parities still hold.
BOOST_AUTO_TEST_CASE(arc_minimums_are_kept)
{
  std::mt19937 rng(5);
  auto pb = make_grid(16, 16, rng, true);
  std::uniform_real_distribution<double> u(0., 1.);
  std::size_t binding = 0;
  for(auto& a : pb.arcs)
    if(u(rng) < 0.15) {
      a.minimum = static_cast<int>(std::ceil(1.6 * a.target)) + 1;
      ++binding;
    }
  BOOST_REQUIRE_GT(binding, 10u);
  auto check = [&](const std::vector<int>& s) {
    BOOST_CHECK_EQUAL(odd_or_small(pb, s), 0u);
    std::size_t below = 0;
    for(std::size_t a = 0; a < pb.arcs.size(); ++a) if(s[a] < pb.arcs[a].minimum) ++below;
    BOOST_CHECK_EQUAL(below, 0u);
  };
  std::vector<int> s, sf, sc;
  QR::quantize_patch_sides(pb, s);
  check(s);
  QR::quantize_patch_sides(pb, sf, P::use_mip_solver(false));
  check(sf);
  const auto stc = QR::quantize_patch_sides(pb, sc, P::maximum_cluster_size(40));
  BOOST_CHECK_GT(stc.clusters, 1u);
  check(sc);
  // without the minimums the optimum has arcs below them: they did change the result
  auto free_pb = pb;
  for(auto& a : free_pb.arcs) a.minimum = 1;
  std::vector<int> s0;
  QR::quantize_patch_sides(free_pb, s0);
  std::size_t below = 0;
  for(std::size_t a = 0; a < pb.arcs.size(); ++a) if(s0[a] < pb.arcs[a].minimum) ++below;
  BOOST_CHECK_GT(below, binding / 2);
}

BOOST_AUTO_TEST_CASE(bad_input_throws)
{
  std::vector<int> s;
  Side_quantization_problem pb;
  pb.arcs = {{1.}, {1.}};
  pb.patches = {{{0}, {1}}};
  BOOST_CHECK_THROW(QR::quantize_patch_sides(pb, s), std::invalid_argument);
  pb.arcs = {{1.}, {1.}, {-1.}};
  pb.patches = {{{0}, {1}, {2}}};
  BOOST_CHECK_THROW(QR::quantize_patch_sides(pb, s), std::invalid_argument);
  pb.arcs = {{1.}, {1.}, {1.}};
  pb.patches = {{{0}, {1}, {7}}};
  BOOST_CHECK_THROW(QR::quantize_patch_sides(pb, s), std::invalid_argument);
  pb.arcs = {{1.}, {1.}, {1.}};
  pb.arcs[1].minimum = 0;
  pb.patches = {{{0}, {1}, {2}}};
  BOOST_CHECK_THROW(QR::quantize_patch_sides(pb, s), std::invalid_argument);
  // All arcs fixed with an odd perimeter: impossible.
  pb.arcs = {{1., 1}, {1., 1}, {1., 1}};
  pb.patches = {{{0}, {1}, {2}}};
  BOOST_CHECK_THROW(QR::quantize_patch_sides(pb, s), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
