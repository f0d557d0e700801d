// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Takayama, Panozzo and Sorkine-Hornung's pattern-based quadrangulation of N-sided patches
// (SGP 2014): a small base quad mesh per topological pattern, edge loops inserted in fixed quad
// strips of it, and quad strips ("padding") appended along its sides.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUADRANGULATE_POLYGON_PATTERNS_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUADRANGULATE_POLYGON_PATTERNS_H

#include <CGAL/Quad_remeshing/internal/quadrangulate_polygon/constructions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// A quad mesh under construction: the same storage as Quad_connectivity, but its boundary vertices
// are not yet numbered first; the boundary is the set of edges with one incident quad.
using Work_mesh = Quad_connectivity;

inline unsigned long long edge_key(std::size_t u, std::size_t v)
{
  if(u > v) std::swap(u, v);
  return (static_cast<unsigned long long>(u) << 32) | static_cast<unsigned long long>(v);
}

// undirected edge -> incident quads (one for a boundary edge)
inline std::unordered_map<unsigned long long, std::vector<std::size_t>> edge_faces(const Work_mesh& m)
{
  std::unordered_map<unsigned long long, std::vector<std::size_t>> ef;
  ef.reserve(4 * m.quads.size());
  for(std::size_t f = 0; f < m.quads.size(); ++f)
    for(int k = 0; k < 4; ++k) ef[edge_key(m.quads[f][k], m.quads[f][(k + 1) % 4])].push_back(f);
  return ef;
}

// boundary edges u -> v in face order (the counterclockwise boundary loop)
inline std::unordered_map<std::size_t, std::size_t> boundary_next(const Work_mesh& m)
{
  const auto ef = edge_faces(m);
  std::unordered_map<std::size_t, std::size_t> next;
  for(const auto& q : m.quads)
    for(int k = 0; k < 4; ++k)
      if(ef.at(edge_key(q[k], q[(k + 1) % 4])).size() == 1) next[q[k]] = q[(k + 1) % 4];
  return next;
}

inline int position_in(const std::array<std::size_t, 4>& q, std::size_t v)
{
  for(int k = 0; k < 4; ++k) if(q[k] == v) return k;
  return -1;
}

// Inserts `count` parallel edge loops into the quad strip that starts at the boundary edge {u0, v0}
// and runs, quad by quad through opposite edges, to another boundary edge.
inline void insert_edge_loops(Work_mesh& m, std::size_t u0, std::size_t v0, int count)
{
  if(count <= 0) return;
  const auto ef = edge_faces(m);
  std::vector<std::pair<std::size_t, std::size_t>> rails{{u0, v0}};
  std::vector<std::size_t> strip;
  std::size_t f = ef.at(edge_key(u0, v0)).front();
  for(;;)
  {
    if(std::find(strip.begin(), strip.end(), f) != strip.end())
      throw std::logic_error("quadrangulate_polygon: a pattern strip crosses itself");
    strip.push_back(f);
    const auto& q = m.quads[f];
    const std::size_t u = rails.back().first, v = rails.back().second;
    const int iu = position_in(q, u), iv = position_in(q, v);
    // the neighbours of u and v in the quad away from the edge {u, v}
    const std::size_t u1 = q[(iv == (iu + 1) % 4) ? (iu + 3) % 4 : (iu + 1) % 4];
    const std::size_t v1 = q[(iu == (iv + 1) % 4) ? (iv + 3) % 4 : (iv + 1) % 4];
    rails.emplace_back(u1, v1);
    const auto& across = ef.at(edge_key(u1, v1));
    if(across.size() == 1) break;
    f = across[0] == f ? across[1] : across[0];
  }
  // split every crossed edge into count + 1 pieces
  const std::size_t k = std::size_t(count);
  std::vector<std::vector<std::size_t>> s(rails.size());
  for(std::size_t j = 0; j < rails.size(); ++j)
  {
    s[j].push_back(rails[j].first);
    for(std::size_t t = 0; t < k; ++t) s[j].push_back(m.number_of_vertices++);
    s[j].push_back(rails[j].second);
  }
  for(std::size_t j = 0; j < strip.size(); ++j)
  {
    const auto q = m.quads[strip[j]];
    const bool forward = q[(position_in(q, rails[j].first) + 1) % 4] == rails[j].second;
    for(std::size_t t = 0; t <= k; ++t)
    {
      std::array<std::size_t, 4> nq = forward
        ? std::array<std::size_t, 4>{s[j][t], s[j][t + 1], s[j + 1][t + 1], s[j + 1][t]}
        : std::array<std::size_t, 4>{s[j][t], s[j + 1][t], s[j + 1][t + 1], s[j][t + 1]};
      if(t == 0) m.quads[strip[j]] = nq;
      else m.quads.push_back(nq);
    }
  }
}

// One topological pattern (N, K) as in Takayama et al.: base quads over the corners C_i = i and
// the extra vertices V_j = N + j, and its loop insertion sites, each a boundary edge {C/V, C/V} of
// the base mesh (named after the paper's variables: x, y, z, w, q_i).
struct Quad_pattern
{
  int sides = 0;
  int id = 0;
  std::size_t base_vertices = 0;
  std::vector<std::array<std::size_t, 4>> faces;
  std::vector<std::pair<std::size_t, std::size_t>> loop_sites;
  std::vector<std::string> loop_names;
  // derived from the base mesh: edges per side, and the sides each loop adds one edge to
  std::vector<int> base_counts;
  std::vector<std::array<int, 2>> loop_sides;
};

// Boundary of a mesh split into sides at the given corner vertices: side i runs from corner i to
// corner i+1 counterclockwise, both included.
inline std::vector<std::vector<std::size_t>> boundary_sides(const Work_mesh& m,
                                                            const std::vector<std::size_t>& corners)
{
  const auto next = boundary_next(m);
  const std::size_t n = corners.size();
  std::vector<std::vector<std::size_t>> sides(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    std::size_t v = corners[i];
    sides[i].push_back(v);
    do
    {
      v = next.at(v);
      sides[i].push_back(v);
      if(sides[i].size() > next.size() + 1)
        throw std::logic_error("quadrangulate_polygon: pattern corners out of boundary order");
    } while(v != corners[(i + 1) % n]);
  }
  return sides;
}

inline Quad_pattern make_pattern(int n, int id, std::size_t extra,
                                 std::vector<std::array<std::size_t, 4>> faces,
                                 std::vector<std::pair<std::size_t, std::size_t>> sites,
                                 std::vector<std::string> names)
{
  Quad_pattern p;
  p.sides = n;
  p.id = id;
  p.base_vertices = std::size_t(n) + extra;
  p.faces = std::move(faces);
  p.loop_sites = std::move(sites);
  p.loop_names = std::move(names);
  Work_mesh m{p.base_vertices, p.faces};
  std::vector<std::size_t> corners(std::size_t(n), 0);
  for(int i = 0; i < n; ++i) corners[std::size_t(i)] = std::size_t(i);
  const auto sides = boundary_sides(m, corners);
  std::map<unsigned long long, int> side_of_edge;
  for(std::size_t i = 0; i < sides.size(); ++i)
  {
    p.base_counts.push_back(int(sides[i].size()) - 1);
    for(std::size_t k = 0; k + 1 < sides[i].size(); ++k) side_of_edge[edge_key(sides[i][k], sides[i][k + 1])] = int(i);
  }
  // the end sides of a strip: insert one loop and see which sides grew
  for(const auto& site : p.loop_sites)
  {
    Work_mesh one = m;
    insert_edge_loops(one, site.first, site.second, 1);
    const auto grown = boundary_sides(one, corners);
    std::array<int, 2> ends{-1, -1};
    int c = 0;
    for(std::size_t i = 0; i < grown.size(); ++i)
      for(int g = int(grown[i].size()) - 1 - p.base_counts[i]; g > 0; --g) ends[std::size_t(c++ % 2)] = int(i);
    if(c != 2) throw std::logic_error("quadrangulate_polygon: a pattern strip does not join two boundary edges");
    p.loop_sides.push_back(ends);
  }
  return p;
}

// The patterns PatchGen tries by default, per number of sides, in its order (increasing
// irregularity). Pattern (2,0)'s loop x is omitted: it does what padding p1 does.
inline const std::vector<Quad_pattern>& patterns_for(std::size_t n)
{
  static const std::vector<std::vector<Quad_pattern>> all = [] {
    using F = std::vector<std::array<std::size_t, 4>>;
    using S = std::vector<std::pair<std::size_t, std::size_t>>;
    using Nm = std::vector<std::string>;
    std::vector<std::vector<Quad_pattern>> a(7);
    // vertex names: corners 0..n-1, V_j = n + j
    {
      const std::size_t C0 = 0, C1 = 1, V0 = 2, V1 = 3;
      a[2].push_back(make_pattern(2, 0, 2, F{{C0, V0, V1, C1}}, S{{V1, V0}}, Nm{"y"}));
      a[2].push_back(make_pattern(2, 1, 2, F{{C0, V0, C1, V1}}, S{{V0, C0}, {C1, V0}}, Nm{"x", "y"}));
    }
    {
      const std::size_t C0 = 0, C1 = 1, C2 = 2, V0 = 3, V1 = 4, V2 = 5, V3 = 6, V4 = 7;
      a[3].push_back(make_pattern(3, 0, 1, F{{C0, V0, C1, C2}}, S{}, Nm{}));
      a[3].push_back(make_pattern(3, 1, 4, F{{C0, V0, V3, C2}, {V0, V1, V2, V3}, {C2, V3, V2, C1}},
                                  S{{V2, V1}, {V1, V0}, {V0, C0}}, Nm{"q1", "q2", "x"}));
      a[3].push_back(make_pattern(3, 2, 5, F{{C0, V0, V3, C2}, {V0, V1, V4, V3}, {C1, V2, V4, V1}, {C2, V3, V4, V2}},
                                  S{{V0, C0}, {V1, V0}}, Nm{"x", "q2"}));
    }
    {
      const std::size_t C0 = 0, C1 = 1, C2 = 2, C3 = 3, V0 = 4, V1 = 5, V2 = 6, V3 = 7, V4 = 8, V5 = 9, V6 = 10;
      a[4].push_back(make_pattern(4, 0, 0, F{{C0, C1, C2, C3}}, S{}, Nm{}));
      a[4].push_back(make_pattern(4, 1, 3, F{{C0, V0, V2, C3}, {V0, C1, V1, V2}, {V1, C2, C3, V2}},
                                  S{{V0, C0}}, Nm{"x"}));
      a[4].push_back(make_pattern(4, 2, 2, F{{C0, V0, C2, C3}, {V0, V1, C1, C2}}, S{{V1, V0}, {C1, V1}}, Nm{"x", "y"}));
      a[4].push_back(make_pattern(4, 3, 4, F{{C0, V0, V3, C3}, {V0, V1, V2, V3}, {V1, C1, C2, V2}, {C2, C3, V3, V2}},
                                  S{{V0, C0}, {V1, V0}}, Nm{"x", "q1"}));
      a[4].push_back(make_pattern(4, 4, 7, F{{C0, V0, V6, C3}, {V0, V1, V5, V6}, {V1, V2, V4, V5}, {V2, C1, V3, V4},
                                             {V3, C2, V5, V4}, {C2, C3, V6, V5}},
                                  S{{V0, C0}, {V2, V1}, {V1, V0}}, Nm{"x", "y", "q1"}));
    }
    {
      const std::size_t C0 = 0, C1 = 1, C2 = 2, C3 = 3, C4 = 4;
      const std::size_t V0 = 5, V1 = 6, V2 = 7, V3 = 8, V4 = 9, V5 = 10, V6 = 11, V7 = 12, V8 = 13;
      a[5].push_back(make_pattern(5, 0, 1, F{{V0, C3, C4, C0}, {V0, C1, C2, C3}}, S{}, Nm{}));
      a[5].push_back(make_pattern(5, 1, 1, F{{C0, V0, C1, C2}, {C0, C2, C3, C4}}, S{{V0, C0}, {C1, V0}}, Nm{"x", "q4"}));
      a[5].push_back(make_pattern(5, 2, 5, F{{C0, V0, V3, V4}, {C1, V4, V3, V2}, {V0, V1, V2, V3}, {V4, C3, C4, C0},
                                             {V4, C1, C2, C3}},
                                  S{{V0, C0}, {C0, C4}, {V1, V0}, {V2, V1}}, Nm{"x", "q0", "q1", "q4"}));
      a[5].push_back(make_pattern(5, 3, 9, F{{C0, V0, V5, C4}, {V0, V1, V6, V5}, {V1, V2, V7, V6}, {V2, V3, V8, V7},
                                             {V3, C1, V4, V8}, {V4, C2, V7, V8}, {C2, C3, V6, V7}, {C3, C4, V5, V6}},
                                  S{{V0, C0}, {V3, V2}, {V2, V1}, {V1, V0}}, Nm{"x", "y", "q1", "q4"}));
    }
    {
      const std::size_t C0 = 0, C1 = 1, C2 = 2, C3 = 3, C4 = 4, C5 = 5;
      const std::size_t V0 = 6, V1 = 7, V2 = 8, V3 = 9, V4 = 10, V5 = 11, V6 = 12, V7 = 13, V8 = 14;
      a[6].push_back(make_pattern(6, 0, 0, F{{C0, C1, C2, C5}, {C2, C3, C4, C5}}, S{{C1, C0}}, Nm{"x"}));
      a[6].push_back(make_pattern(6, 1, 4, F{{C0, V0, V2, V3}, {C1, V1, V2, V0}, {V1, C2, V3, V2}, {C2, C3, C4, V3},
                                             {C4, C5, C0, V3}},
                                  S{{V0, C0}, {C1, V0}, {V1, C1}, {C3, C2}}, Nm{"x", "y", "z", "w"}));
      a[6].push_back(make_pattern(6, 2, 6, F{{C0, V0, V2, V4}, {V0, V1, V3, V2}, {V1, C1, V5, V3}, {C1, C2, C3, V5},
                                             {C3, C4, V4, V5}, {C4, C5, C0, V4}, {V2, V3, V5, V4}},
                                  S{{V0, C0}, {V1, V0}, {C0, C5}, {C3, C2}}, Nm{"x", "y", "q0", "q3"}));
      a[6].push_back(make_pattern(6, 3, 9, F{{C0, V0, V6, C5}, {V0, V1, V5, V6}, {V1, V2, V4, V5}, {V2, C1, V3, V4},
                                             {V3, C2, V5, V4}, {C2, C3, V8, V5}, {C3, C4, V7, V8}, {C4, C5, V6, V7},
                                             {V5, V8, V7, V6}},
                                  S{{V0, C0}, {V2, V1}, {V1, V0}, {C3, C2}}, Nm{"x", "y", "z", "q3"}));
    }
    return a;
  }();
  return all[n];
}

// A pattern instance: the pattern, how its sides map to the input's, and its variables.
struct Pattern_choice
{
  const Quad_pattern* pattern = nullptr;
  int rotation = 0;       // pattern side j is input side j + rotation ...
  bool reflected = false; // ... or rotation - j, the pattern mirrored
  std::vector<int> loops; // one count per loop site
  std::vector<int> padding; // per pattern side
};

inline std::size_t input_side(std::size_t j, std::size_t n, int rotation, bool reflected)
{
  return reflected ? (std::size_t(rotation) + n - j) % n : (j + std::size_t(rotation)) % n;
}

// The paddings p >= 0 with p_{i-1} + p_{i+1} = r_i (for two sides: 2 p_{1-i} = r_i), at most a
// few candidates when the system is singular (four sides: balanced splits first, then extremes).
inline std::vector<std::vector<int>> solve_padding(const std::vector<int>& r)
{
  const std::size_t n = r.size();
  std::vector<std::vector<int>> out;
  if(n == 2)
  {
    if(r[0] % 2 == 0 && r[1] % 2 == 0) out.push_back({r[1] / 2, r[0] / 2});
    return out;
  }
  if(n == 4)
  {
    if(r[0] != r[2] || r[1] != r[3]) return out;
    std::vector<int> a{r[1] / 2, (r[1] + 1) / 2, 0, r[1]}, b{r[0] / 2, (r[0] + 1) / 2, 0, r[0]};
    for(int p0 : a)
      for(int p1 : b)
      {
        std::vector<int> p{p0, p1, r[1] - p0, r[0] - p1};
        if(std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
      }
    return out;
  }
  std::vector<int> p(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    int twice = 0;
    if(n == 6) twice = r[(i + 5) % 6] + r[(i + 1) % 6] - r[(i + 3) % 6];
    else
      for(std::size_t k = 0; k < n; ++k) twice += (k % 2 == 0 ? 1 : -1) * r[(i + 1 + 2 * k) % n];
    if(twice < 0 || twice % 2 != 0) return out;
    p[i] = twice / 2;
  }
  for(std::size_t i = 0; i < n; ++i)
    if(p[(i + n - 1) % n] + p[(i + 1) % n] != r[i]) return out;
  out.push_back(p);
  return out;
}

// All parameter choices of one pattern under one side permutation, best first: loop counts within
// one of the middle of their feasible range (the core centred), then maximal padding (equivalently
// fewest loops: both add two boundary edges each), then closest to the middle, then balanced
// padding, then lexicographic (deterministic).
inline std::vector<Pattern_choice> pattern_choices(const Quad_pattern& pat, const std::vector<int>& e,
                                                   int rotation, bool reflected,
                                                   std::size_t max_choices = std::size_t(-1))
{
  const std::size_t n = e.size();
  std::vector<int> r(n);
  for(std::size_t j = 0; j < n; ++j)
  {
    r[j] = e[input_side(j, n, rotation, reflected)] - pat.base_counts[j];
    if(r[j] < 0) return {};
  }
  const std::size_t L = pat.loop_sites.size();
  std::vector<int> x(L, 0);
  // depth-first over the loop counts, the residual r kept non-negative; visit(x, p) per solution
  auto enumerate = [&](const auto& visit) {
    auto recurse = [&](auto&& self, std::size_t k) -> void {
      if(k == L)
      {
        for(auto& p : solve_padding(r)) visit(x, p);
        return;
      }
      const auto& sd = pat.loop_sides[k];
      for(x[k] = 0;; ++x[k])
      {
        if(r[std::size_t(sd[0])] < 0 || r[std::size_t(sd[1])] < 0) break;
        self(self, k + 1);
        --r[std::size_t(sd[0])];
        --r[std::size_t(sd[1])];
      }
      r[std::size_t(sd[0])] += x[k];
      r[std::size_t(sd[1])] += x[k];
      x[k] = 0;
    };
    recurse(recurse, 0);
  };
  // first the range of each loop count, then the best max_choices solutions by key (two passes
  // instead of storing every solution: long sides and four loop sites give tens of thousands)
  std::vector<int> lo(L, 1 << 30), hi(L, -1);
  bool any = false;
  enumerate([&](const std::vector<int>& xs, const std::vector<int>&) {
    any = true;
    for(std::size_t k = 0; k < L; ++k) { lo[k] = std::min(lo[k], xs[k]); hi[k] = std::max(hi[k], xs[k]); }
  });
  if(!any) return {};
  using Key = std::tuple<int, int, int, int, std::size_t>;
  std::vector<std::pair<Key, Pattern_choice>> best;
  std::size_t counter = 0; // enumeration order: lexicographic in the loop counts
  enumerate([&](const std::vector<int>& xs, const std::vector<int>& p) {
    int outside = 0, deviation = 0, loops = 0, imbalance = 0;
    for(std::size_t k = 0; k < L; ++k)
    {
      const int d = std::abs(xs[k] - (lo[k] + hi[k]) / 2);
      outside += std::max(0, d - 1);
      deviation += d;
      loops += xs[k];
    }
    for(std::size_t i = 0; i < n; ++i) imbalance += std::abs(p[i] - p[(i + 2) % n]);
    const Key key(outside, loops, deviation, imbalance, counter++);
    if(best.size() == max_choices && !(key < best.back().first)) return;
    auto at = std::upper_bound(best.begin(), best.end(), key,
                               [](const Key& k, const auto& b) { return k < b.first; });
    best.insert(at, {key, Pattern_choice{&pat, rotation, reflected, xs, p}});
    if(best.size() > max_choices) best.pop_back();
  });
  std::vector<Pattern_choice> out;
  out.reserve(best.size());
  for(auto& b : best) out.push_back(std::move(b.second));
  return out;
}

// Builds a pattern instance: base mesh, loops, padding (sides n-1 down to 0, as PatchGen), then
// maps the pattern sides to the input sides (mirroring if needed) and numbers the boundary
// counterclockwise from input corner 0 as Quad_connectivity requires.
inline Quad_connectivity build_pattern(const Pattern_choice& c)
{
  const Quad_pattern& pat = *c.pattern;
  const std::size_t n = std::size_t(pat.sides);
  Work_mesh m{pat.base_vertices, pat.faces};
  std::vector<std::size_t> corners(n);
  for(std::size_t i = 0; i < n; ++i) corners[i] = i;
  for(std::size_t k = 0; k < pat.loop_sites.size(); ++k)
  {
    if(c.loops[k] == 0) continue;
    // the site's boundary edge may have been split by earlier loops: take its piece at the first end
    const std::size_t a = pat.loop_sites[k].first, b = pat.loop_sites[k].second;
    const auto next = boundary_next(m);
    std::size_t v = next.at(a);
    while(v >= pat.base_vertices) v = next.at(v);
    std::size_t start_b = next.at(a);
    if(v != b)
    {
      // the edge runs b -> a along the boundary: take the piece ending at a
      for(const auto& kv : next) if(kv.second == a) start_b = kv.first;
    }
    insert_edge_loops(m, a, start_b, c.loops[k]);
  }
  auto sides = boundary_sides(m, corners);
  for(std::size_t i = n; i-- > 0;)
    for(int t = 0; t < c.padding[i]; ++t)
    {
      std::vector<std::size_t>& s = sides[i];
      std::vector<std::size_t> w(s.size());
      for(auto& x : w) x = m.number_of_vertices++;
      for(std::size_t k = 0; k + 1 < s.size(); ++k) m.quads.push_back({w[k], w[k + 1], s[k + 1], s[k]});
      sides[(i + n - 1) % n].push_back(w.front());
      auto& after = sides[(i + 1) % n];
      after.insert(after.begin(), w.back());
      s = std::move(w);
    }
  // input side i, as a vertex list from input corner i to corner i+1
  std::vector<std::vector<std::size_t>> in(n);
  for(std::size_t j = 0; j < n; ++j)
  {
    std::vector<std::size_t> s = sides[j];
    if(c.reflected) std::reverse(s.begin(), s.end());
    in[input_side(j, n, c.rotation, c.reflected)] = std::move(s);
  }
  std::vector<std::size_t> id(m.number_of_vertices, std::size_t(-1));
  std::size_t next_id = 0;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = 0; k + 1 < in[i].size(); ++k) id[in[i][k]] = next_id++;
  for(auto& v : id) if(v == std::size_t(-1)) v = next_id++;
  Quad_connectivity out;
  out.number_of_vertices = next_id;
  out.quads.reserve(m.quads.size());
  for(const auto& q : m.quads)
  {
    std::array<std::size_t, 4> nq{id[q[0]], id[q[1]], id[q[2]], id[q[3]]};
    if(c.reflected) std::swap(nq[1], nq[3]);
    out.quads.push_back(nq);
  }
  return out;
}

// Valence (number of incident edges) of every vertex of a quad disk whose boundary vertices are
// 0..N-1: its number of quads, plus one on the boundary. Called for every candidate instance.
inline std::vector<int> valences(const Quad_connectivity& c, std::size_t N)
{
  std::vector<int> val(c.number_of_vertices, 0);
  for(std::size_t v = 0; v < N && v < val.size(); ++v) val[v] = 1;
  for(const auto& q : c.quads)
    for(std::size_t v : q) ++val[v];
  return val;
}

// Irregular vertices by valence: corners regular at 2, other boundary vertices at 3, interior at 4.
inline std::map<int, int> irregular_by_valence(const Quad_connectivity& c, const std::vector<int>& e)
{
  const std::vector<std::size_t> off = side_offsets(e);
  std::vector<bool> corner(off.back(), false);
  for(std::size_t i = 0; i + 1 < off.size(); ++i) corner[off[i]] = true;
  std::map<int, int> out;
  const std::vector<int> val = valences(c, off.back());
  for(std::size_t v = 0; v < val.size(); ++v)
  {
    const int regular = v < off.back() ? (corner[v] ? 2 : 3) : 4;
    if(val[v] != regular) ++out[val[v]];
  }
  return out;
}

// Connectivity that no embedding on the straight-sided polygon can realise without a flat or
// inverted quad corner: a non-corner boundary vertex in one quad only (its two boundary edges are
// collinear), an interior vertex of valence 2, or an interior edge joining two vertices of the
// same side. The circular 2-gon domain has no straight side, so only valence 2 inside matters there.
inline bool has_flat_corner(const Quad_connectivity& c, const std::vector<int>& e)
{
  const std::vector<std::size_t> off = side_offsets(e);
  const std::size_t n = e.size(), N = off.back();
  const std::vector<int> val = valences(c, off.back());
  for(std::size_t v = N; v < val.size(); ++v) if(val[v] <= 2) return true;
  if(n == 2) return false;
  // side(s) of boundary vertex v: bit mask
  std::vector<unsigned> mask(N, 0u);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = off[i]; k <= off[i + 1]; ++k) mask[k % N] |= 1u << i;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = off[i] + 1; k < off[i + 1]; ++k) if(val[k] == 2) return true;
  for(const auto& q : c.quads)
    for(int k = 0; k < 4; ++k)
    {
      const std::size_t u = q[k], v = q[(k + 1) % 4];
      if(u >= N || v >= N) continue;
      const bool on_loop = (v == (u + 1) % N) || (u == (v + 1) % N);
      if(!on_loop && (mask[u] & mask[v]) != 0u) return true;
    }
  return false;
}


// Replaces every quad holding a non-corner boundary vertex of valence 2 (flat in any embedding on
// the straight side) by five quads: an inner quad and a ring of four, which gives the vertex an
// interior neighbour. Returns the number of quads replaced.
inline int split_flat_boundary_quads(Quad_connectivity& c, const std::vector<int>& e)
{
  const std::vector<std::size_t> off = side_offsets(e);
  const std::size_t N = off.back();
  std::vector<bool> corner(N, false);
  for(std::size_t i = 0; i + 1 < off.size(); ++i) corner[off[i]] = true;
  const std::vector<int> val = valences(c, off.back());
  int replaced = 0;
  const std::size_t F = c.quads.size();
  for(std::size_t f = 0; f < F; ++f)
  {
    const auto q = c.quads[f];
    bool flat = false;
    for(std::size_t v : q) flat = flat || (v < N && !corner[v] && val[v] == 2);
    if(!flat) continue;
    std::array<std::size_t, 4> in;
    for(auto& x : in) x = c.number_of_vertices++;
    c.quads[f] = in;
    for(int k = 0; k < 4; ++k) c.quads.push_back({q[k], q[(k + 1) % 4], in[(k + 1) % 4], in[k]});
    ++replaced;
  }
  return replaced;
}

// Every quad corner strictly convex in the embedding (counterclockwise quads).
inline bool embedding_is_valid(const Quad_connectivity& c, const std::vector<std::array<double, 2>>& pos)
{
  for(const auto& q : c.quads)
    for(int k = 0; k < 4; ++k)
    {
      const auto& a = pos[q[(k + 3) % 4]];
      const auto& b = pos[q[k]];
      const auto& d = pos[q[(k + 1) % 4]];
      const double cross = (b[0] - a[0]) * (d[1] - b[1]) - (b[1] - a[1]) * (d[0] - b[0]);
      if(!(cross > 1e-10)) return false;
    }
  return true;
}

struct Pattern_result
{
  Pattern_choice choice;
  int split_quads = 0; // pattern quads replaced by split_flat_boundary_quads()
  Quad_connectivity connectivity;
  std::vector<std::array<double, 2>> positions;
};

// Takayama et al.'s default selection, by enumeration instead of an ILP: the patterns of n sides
// in order of increasing irregularity, the first one that has an embeddable instance wins. Within
// it, each of the 2n side permutations contributes its best parameter choice (pattern_choices())
// whose connectivity has no forced flat corner; among those, the fewest irregular vertices, then
// the first permutation.
// Takayama et al. accept a pattern vertex alone in one quad on an unpadded side; on our straight
// sided domain its quad would be flat there. If no pattern avoids that (small inputs such as
// (4,1,1) or (4,1,1,1,1)), a second pass allows such instances with their flat quads split in five
// (split_flat_boundary_quads()). Returns nothing if that fails too.
inline std::optional<Pattern_result> best_pattern(const std::vector<int>& e)
{
  const std::size_t n = e.size();
  // a few choices per permutation: the flat-corner test rejects structural defects (an unpadded
  // side under a lone pattern vertex), which the next choices in the order do not repair
  const std::size_t tries_per_permutation = 8;
  const std::vector<std::array<double, 2>> boundary = polygon_boundary_positions(e);
  for(int pass = 0; pass < 2; ++pass)
    for(const Quad_pattern& pat : patterns_for(n))
    {
      std::vector<std::vector<Pattern_choice>> choices;
      for(int reflected = 0; reflected < 2; ++reflected)
        for(int rotation = 0; rotation < int(n); ++rotation)
          choices.push_back(pattern_choices(pat, e, rotation, reflected != 0, tries_per_permutation));
      // round 0: the first choice of each permutation without a flat corner; round 1, only if none
      // of those embeds (the harmonic map can still fold a quad): all the other tried choices
      for(int round = 0; round < 2; ++round)
      {
        std::vector<std::pair<int, Pattern_result>> candidates;
        for(const auto& list : choices)
        {
          bool first = true;
          for(std::size_t t = 0; t < list.size() && t < tries_per_permutation; ++t)
          {
            Quad_connectivity c = build_pattern(list[t]);
            const int split = pass == 0 ? 0 : split_flat_boundary_quads(c, e);
            if(has_flat_corner(c, e)) continue;
            if(first == (round == 0))
            {
              int irregular = 0;
              for(const auto& kv : irregular_by_valence(c, e)) irregular += kv.second;
              candidates.emplace_back(irregular, Pattern_result{list[t], split, std::move(c), {}});
            }
            if(round == 0) break;
            first = false;
          }
        }
        std::stable_sort(candidates.begin(), candidates.end(),
                         [](const auto& a, const auto& b) { return a.first < b.first; });
        for(auto& cand : candidates)
        {
          cand.second.positions = harmonic_positions(cand.second.connectivity, boundary);
          if(embedding_is_valid(cand.second.connectivity, cand.second.positions)) return std::move(cand.second);
        }
      }
    }
  return std::nullopt;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_QUADRANGULATE_POLYGON_PATTERNS_H
