// quadrangulate_polygon: exhaustive validity over small side counts, strategy choice, closed forms.
#include <CGAL/Quad_remeshing/quadrangulate_polygon.h>

#include <boost/test/unit_test.hpp>

#include <chrono>
#include <algorithm>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace QR = CGAL::Quad_remeshing;

namespace {

// Returns an empty string if q is a valid quad disk with the prescribed sides, else the first problem.
std::string check_quad_disk(const QR::Polygon_quadrangulation& q, const std::vector<int>& e)
{
  std::ostringstream err;
  const std::size_t n = e.size();
  std::size_t N = 0;
  for(int x : e) N += std::size_t(x);
  const std::size_t V = q.positions.size();
  if(q.boundary.size() != N) return "boundary length";
  if(q.corners.size() != n || q.side_start.size() != n + 1) return "corner/side indexing sizes";
  // per-side counts: boundary vertices from corner i to corner i+1
  for(std::size_t i = 0; i < n; ++i)
  {
    if(q.side_start[i + 1] - q.side_start[i] != std::size_t(e[i])) return "side count";
    if(q.corners[i] != q.side_start[i] || q.index_along_side[q.corners[i]] != 0) return "corner index";
    for(int k = 0; k < e[i]; ++k)
    {
      const std::size_t v = q.side_vertex(i, std::size_t(k));
      if(q.side_of_boundary_vertex[v] != int(i) || q.index_along_side[v] != k) return "side labels";
    }
    if(q.side_vertex(i, std::size_t(e[i])) != q.corners[(i + 1) % n]) return "side end corner";
  }
  // faces: 4 distinct valid vertices; undirected and directed edge counts
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const auto& f : q.quads)
  {
    std::set<std::size_t> s(f.begin(), f.end());
    if(s.size() != 4) return "quad with repeated vertex";
    for(std::size_t v : f) if(v >= V) return "vertex index out of range";
    for(int k = 0; k < 4; ++k)
      if(++directed[{f[k], f[(k + 1) % 4]}] > 1) return "directed edge used twice (non-manifold or misoriented)";
  }
  std::size_t E = 0, boundary_edges = 0;
  std::map<std::size_t, std::size_t> next_on_boundary;
  for(const auto& d : directed)
  {
    const bool has_twin = directed.count({d.first.second, d.first.first}) > 0;
    if(has_twin) { if(d.first.first < d.first.second) ++E; }
    else
    {
      ++E; ++boundary_edges;
      // a boundary edge u->v of a ccw face: the loop must run u->v, i.e. v = u+1 (mod N)
      if(d.first.first >= N || d.first.second != (d.first.first + 1) % N) return "boundary edge not on the loop";
      next_on_boundary[d.first.first] = d.first.second;
    }
  }
  if(boundary_edges != N || next_on_boundary.size() != N) return "boundary edges";
  // one loop
  std::size_t v = 0, steps = 0;
  do { v = next_on_boundary[v]; ++steps; } while(v != 0 && steps <= N);
  if(steps != N) return "more than one boundary loop";
  const long long chi = (long long)V - (long long)E + (long long)q.quads.size();
  if(chi != 1) { err << "Euler characteristic " << chi; return err.str(); }
  // every vertex used
  std::vector<bool> used(V, false);
  for(const auto& f : q.quads) for(std::size_t w : f) used[w] = true;
  for(std::size_t w = 0; w < V; ++w) if(!used[w]) return "isolated vertex";
  // strictly positive orientation at all four corners of every quad
  for(const auto& f : q.quads)
    for(int k = 0; k < 4; ++k)
    {
      const auto& a = q.positions[f[(k + 3) % 4]];
      const auto& b = q.positions[f[k]];
      const auto& c = q.positions[f[(k + 1) % 4]];
      const double cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
      if(!(cross > 1e-12)) { err << "inverted or degenerate quad corner (cross " << cross << ")"; return err.str(); }
    }
  return "";
}

// Reference: does e = s_{i-1} + s_{i+1} have an integer solution with every s_i >= 1 ?  (brute force)
bool brute_force_simple(const std::vector<int>& e)
{
  const std::size_t n = e.size();
  if(n == 4) return e[0] == e[2] && e[1] == e[3];
  if(n == 2) return false;
  // s_0 and s_1 determine the rest through s_{i+1} = e_i - s_{i-1}; try them all, check every equation
  int bound = 0;
  for(int x : e) bound = std::max(bound, x);
  std::vector<int> s(n);
  for(s[0] = 1; s[0] <= bound; ++s[0])
    for(s[1] = 1; s[1] <= bound; ++s[1])
    {
      bool ok = true;
      for(std::size_t i = 1; i + 1 < n && ok; ++i)
      {
        s[i + 1] = e[i] - s[i - 1];
        ok = s[i + 1] >= 1;
      }
      for(std::size_t j = 0; j < n && ok; ++j)
        ok = e[j] == s[(j + n - 1) % n] + s[(j + 1) % n];
      if(ok) return true;
    }
  return false;
}

void for_each_even_vector(std::size_t n, int max_e, const std::function<void(const std::vector<int>&)>& f)
{
  std::vector<int> e(n, 1);
  for(;;)
  {
    int sum = 0;
    for(int x : e) sum += x;
    if(sum % 2 == 0 && sum >= 4) f(e);
    std::size_t i = 0;
    while(i < n && e[i] == max_e) { e[i] = 1; ++i; }
    if(i == n) return;
    ++e[i];
  }
}

std::string to_string(const std::vector<int>& e)
{
  std::ostringstream o;
  for(std::size_t i = 0; i < e.size(); ++i) o << (i ? "," : "(") << e[i];
  o << ")";
  return o.str();
}

} // namespace

BOOST_AUTO_TEST_SUITE(quadrangulate_polygon)

BOOST_AUTO_TEST_CASE(exhaustive_small_side_counts)
{
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t cases = 0, simple = 0, failures = 0;
  double library_seconds = 0.;
  std::map<std::size_t, std::size_t> general_irregular_max;
  for(std::size_t n = 2; n <= 6; ++n)
  {
    const int max_e = n <= 4 ? 8 : 6;
    for_each_even_vector(n, max_e, [&](const std::vector<int>& e) {
      ++cases;
      const QR::Polygon_quadrangulation q = QR::quadrangulate_polygon(e);
      library_seconds += q.seconds;
      const std::string problem = check_quad_disk(q, e);
      const bool expect_simple = brute_force_simple(e);
      bool ok = problem.empty() && QR::admits_simple_quadrangulation(e) == expect_simple &&
                (q.strategy == QR::Polygon_quadrangulation::SIMPLE) == expect_simple;
      if(ok && expect_simple)
      {
        ++simple;
        if(n == 4) ok = q.irregular_vertices_by_valence.empty();
        else
        {
          ok = q.number_of_irregular_vertices() == 1 && q.irregular_vertices_by_valence.count(int(n)) == 1;
          // the centre is interior, the only vertex of valence n
          std::size_t faces = 0;
          const auto& s = q.separatrix_lengths;
          for(std::size_t i = 0; i < n; ++i) faces += std::size_t(s[i] * s[(i + 1) % n]);
          ok = ok && faces == q.quads.size();
        }
      }
      if(ok && !expect_simple)
      {
        std::size_t& m = general_irregular_max[n];
        m = std::max(m, std::size_t(q.number_of_irregular_vertices()));
        ok = std::size_t(q.number_of_irregular_vertices()) <= n + 4;
      }
      if(!ok && ++failures <= 10)
        BOOST_ERROR("case " << to_string(e) << ": " << (problem.empty() ? "strategy/irregularity mismatch" : problem));
    });
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cerr << "[quadrangulate_polygon test] " << cases << " cases (" << simple << " simple), "
            << failures << " failures, " << secs << " s in all, "
            << library_seconds << " s in quadrangulate_polygon\n";
  for(const auto& kv : general_irregular_max)
    std::cerr << "  n=" << kv.first << ": general strategy, at most " << kv.second << " irregular vertices\n";
  BOOST_TEST(failures == 0u);
  // n=2: 32 even vectors minus (1,1); n=3: 256; n=4: 2048; n=5: 3888; n=6: 23328
  BOOST_TEST(cases == 29551u);
}

BOOST_AUTO_TEST_CASE(tarini_worked_examples)
{
  // Tarini's Fig. 1 pentagon
  const auto s = QR::simple_quadrangulation_separatrices({6, 4, 3, 5, 4});
  BOOST_REQUIRE(s);
  BOOST_TEST((*s == std::vector<int>{3, 2, 1, 1, 4}));
  const auto p = QR::quadrangulate_polygon(std::vector<int>{6, 4, 3, 5, 4});
  BOOST_TEST(p.strategy == QR::Polygon_quadrangulation::SIMPLE);
  BOOST_TEST(p.quads.size() == std::size_t(3 * 2 + 2 * 1 + 1 * 1 + 1 * 4 + 4 * 3));
  BOOST_TEST(p.irregular_vertices_by_valence.at(5) == 1);
  // the triangle e = (4,2,4): s = (1,3,1), 7 faces
  const auto t = QR::quadrangulate_polygon(std::vector<int>{4, 2, 4});
  BOOST_TEST(t.strategy == QR::Polygon_quadrangulation::SIMPLE);
  BOOST_TEST((t.separatrix_lengths == std::vector<int>{1, 3, 1}));
  BOOST_TEST(t.quads.size() == 7u);
  BOOST_TEST(check_quad_disk(t, {4, 2, 4}) == "");
  // a single valence-6 hexagon, which QuadWild's pattern 6_0 never builds
  const auto h = QR::quadrangulate_polygon(std::vector<int>{2, 2, 2, 2, 2, 2});
  BOOST_TEST(h.strategy == QR::Polygon_quadrangulation::SIMPLE);
  BOOST_TEST(h.quads.size() == 6u);
  BOOST_TEST(h.irregular_vertices_by_valence.at(6) == 1);
  // report
  const QR::Report r = t.report();
  BOOST_TEST(r.find("strategy")->string() == "simple");
  BOOST_TEST(r.find("quads")->number() == 7.);
}

BOOST_AUTO_TEST_CASE(degenerate_separatrix_goes_general)
{
  // (1,1,2): s = (1,1,0) puts the centre on side 2; the simple strategy refuses s_i = 0
  BOOST_TEST(!QR::admits_simple_quadrangulation({1, 1, 2}));
  const auto q = QR::quadrangulate_polygon(std::vector<int>{1, 1, 2});
  BOOST_TEST(q.strategy == QR::Polygon_quadrangulation::GENERAL);
  BOOST_TEST(check_quad_disk(q, {1, 1, 2}) == "");
  // hexagon with the triangle inequalities but odd alternate sums
  BOOST_TEST(!QR::admits_simple_quadrangulation({2, 1, 2, 1, 2, 2}));
  BOOST_TEST(!QR::admits_simple_quadrangulation({3, 4, 3, 5}));
  BOOST_TEST(QR::admits_simple_quadrangulation({3, 5, 3, 5}));
}

BOOST_AUTO_TEST_CASE(invalid_input_throws)
{
  BOOST_CHECK_THROW(QR::quadrangulate_polygon(std::vector<int>{1, 2, 2}), std::invalid_argument);
  BOOST_CHECK_THROW(QR::quadrangulate_polygon(std::vector<int>{4}), std::invalid_argument);
  BOOST_CHECK_THROW(QR::quadrangulate_polygon(std::vector<int>{}), std::invalid_argument);
  BOOST_CHECK_THROW(QR::quadrangulate_polygon(std::vector<int>{1, 1, 1, 1, 1, 1, 2}), std::invalid_argument);
  BOOST_CHECK_THROW(QR::quadrangulate_polygon(std::vector<int>{0, 2, 2}), std::invalid_argument);
  BOOST_CHECK_THROW(QR::quadrangulate_polygon(std::vector<int>{-1, 3, 2}), std::invalid_argument);
  BOOST_CHECK_THROW(QR::quadrangulate_polygon(std::vector<int>{1, 1}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(deterministic)
{
  const auto a = QR::quadrangulate_polygon(std::vector<int>{5, 2, 7, 3, 1});
  const auto b = QR::quadrangulate_polygon(std::vector<int>{5, 2, 7, 3, 1}, CGAL::parameters::verbose(true));
  BOOST_TEST((a.quads == b.quads));
  BOOST_TEST((a.positions == b.positions));
}

BOOST_AUTO_TEST_CASE(larger_side_counts_sample)
{
  // a deterministic sample with sides up to 40 edges: validity of the embedding beyond the exhaustive range
  std::size_t failures = 0, cases = 0;
  unsigned state = 12345u;
  auto next = [&state](int m) { state = state * 1103515245u + 12345u; return int((state >> 16) % unsigned(m)); };
  for(int t = 0; t < 600; ++t)
  {
    const std::size_t n = 2 + std::size_t(next(5));
    std::vector<int> e(n);
    for(int& x : e) x = 1 + next(40);
    int sum = 0;
    for(int x : e) sum += x;
    if(sum % 2 != 0) ++e[0];
    ++cases;
    const auto q = QR::quadrangulate_polygon(e);
    const std::string problem = check_quad_disk(q, e);
    const bool strategy_ok = (q.strategy == QR::Polygon_quadrangulation::SIMPLE) == brute_force_simple(e);
    if((!problem.empty() || !strategy_ok) && ++failures <= 10)
      BOOST_ERROR("case " << to_string(e) << ": " << (problem.empty() ? "strategy mismatch" : problem));
  }
  BOOST_TEST(failures == 0u);
  BOOST_TEST(cases == 600u);
}

BOOST_AUTO_TEST_SUITE_END()
