// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_FALLBACK_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_FALLBACK_H

#include <CGAL/Quad_remeshing/internal/quantization/problem_helpers.h>
#include <CGAL/Quad_remeshing/internal/quantization/mip_model.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// Strips of arcs: two free arcs are in one strip when they are the opposite sides of a 4-sided patch,
// each side being that one arc (appearing once on the patch). Equal values on a strip leave every quad
// it crosses with equal opposite sides; changing the whole strip by +-1 flips the parity of its two
// ends only (the patches where it stops, or the outside at a boundary).
//
// The strip graph: its nodes are the patches and the outside (node np), its edges the strips with
// exactly two ends. A strip is named by its smallest arc id (its root).
struct Strip_graph
{
  std::vector<std::size_t> root;                          // per arc: the root of its strip (itself if fixed)
  std::vector<std::vector<std::size_t> > members;         // per root: its free arcs that bound a patch
  std::vector<double> mean_target;                        // per root: the mean target of its members
  std::vector<std::pair<std::size_t, std::size_t> > ends; // per root: its two ends (np + 1 twice if not two)
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > adjacent; // per node: (strip, other end)
};

inline Strip_graph make_strip_graph(const Quantization_view& v)
{
  const auto& pb = *v.problem;
  const std::size_t na = pb.arcs.size(), np = pb.patches.size(), outside = np;
  Strip_graph g;
  auto& root = g.root;
  root.resize(na);
  for(std::size_t a = 0; a < na; ++a) root[a] = a;
  auto find = [&](std::size_t a) {
    while(root[a] != a) { root[a] = root[root[a]]; a = root[a]; }
    return a;
  };
  for(std::size_t p = 0; p < np; ++p) {
    if(pb.patches[p].size() != 4) continue;
    for(std::size_t i = 0; i < 2; ++i) {
      if(pb.patches[p][i].size() != 1 || pb.patches[p][i + 2].size() != 1) continue;
      const std::size_t a = pb.patches[p][i][0], b = pb.patches[p][i + 2][0];
      if(a == b || v.fixed[a] != 0 || v.fixed[b] != 0) continue;
      if(single_arc_side(v, p, a) != long(i) || single_arc_side(v, p, b) != long(i + 2)) continue;
      const std::size_t ra = find(a), rb = find(b);
      if(ra != rb) root[(std::max)(ra, rb)] = (std::min)(ra, rb); // the smaller id stays the root
    }
  }
  for(std::size_t a = 0; a < na; ++a) root[a] = find(a);
  g.members.resize(na);
  g.mean_target.assign(na, 0.);
  for(std::size_t a = 0; a < na; ++a)
    if(v.fixed[a] == 0 && !v.arc_patches[a].empty()) {
      g.members[root[a]].push_back(a);
      g.mean_target[root[a]] += pb.arcs[a].target;
    }
  g.ends.assign(na, {outside + 1, outside + 1});
  g.adjacent.resize(np + 1);
  std::vector<char> flip(np + 1, 0);
  std::vector<std::size_t> seen, odd_nodes;
  for(std::size_t r = 0; r < na; ++r) {
    if(g.members[r].empty()) continue;
    g.mean_target[r] /= double(g.members[r].size());
    seen.clear(); odd_nodes.clear();
    for(std::size_t a : g.members[r]) {
      const auto& inc = v.arc_patches[a];
      const std::size_t nodes[2] = {inc[0], inc.size() > 1 ? inc[1] : outside};
      for(std::size_t q : nodes) {
        if(std::find(seen.begin(), seen.end(), q) == seen.end()) seen.push_back(q);
        flip[q] ^= 1;
      }
    }
    for(std::size_t q : seen) { if(flip[q]) odd_nodes.push_back(q); flip[q] = 0; }
    if(odd_nodes.size() != 2) continue;
    g.ends[r] = {odd_nodes[0], odd_nodes[1]};
    g.adjacent[odd_nodes[0]].emplace_back(r, odd_nodes[1]);
    g.adjacent[odd_nodes[1]].emplace_back(r, odd_nodes[0]);
  }
  return g;
}

// Breadth-first search over nodes 0..n-1 from `start`: `edges(p)` lists the (edge, node) steps out of
// p in a fixed order, `skip(edge)` leaves an edge out. Stops at the first node reached for which
// `goal(q)` holds and returns it (-1: none, or max_expanded nodes expanded first); prev_node /
// prev_edge then give the path back to start.
template <typename Edges, typename Skip, typename Goal>
long breadth_first(std::size_t n, std::size_t start, const Edges& edges, const Skip& skip, const Goal& goal,
                   std::vector<long>& prev_node, std::vector<long>& prev_edge,
                   std::size_t max_expanded = (std::numeric_limits<std::size_t>::max)())
{
  prev_node.assign(n, -2);
  prev_edge.assign(n, -1);
  std::deque<std::size_t> queue{start};
  prev_node[start] = -1;
  for(std::size_t expanded = 0; !queue.empty() && expanded < max_expanded; ++expanded) {
    const std::size_t p = queue.front(); queue.pop_front();
    for(const auto& e : edges(p)) {
      if(skip(e.first) || prev_node[e.second] != -2) continue;
      prev_node[e.second] = long(p); prev_edge[e.second] = long(e.first);
      if(goal(e.second)) return long(e.second);
      queue.push_back(e.second);
    }
  }
  return -1;
}

// Solver-free assignment, deterministic (everything in ascending id order):
// 1. every strip of free arcs (make_strip_graph()) takes the rounded mean of its targets (at least 1),
//    so that the quads it crosses are regular; an arc whose window (arc_window()) does not hold that
//    value takes the nearest value of its window;
// 2. patches with an odd perimeter are paired along shortest paths of the strip graph, or to the
//    outside; every strip on a path changes by +-1 (towards its mean target unless that takes an arc
//    out of its window), which flips the parity of the two path ends only and keeps the quads on the
//    way regular;
// 3. an odd patch left (no such path) is paired likewise along a shortest path of the patch adjacency
//    graph whose steps cross single free arcs, or ended at a free boundary arc, each arc changed by +-1;
// 4. a patch with perimeter 2 gets +2 on one free arc (parity unchanged everywhere).
// Throws std::invalid_argument if the fixed arcs make parity impossible.
inline void fallback_assignment(const Quantization_view& v, std::vector<int>& s)
{
  const std::size_t na = v.problem->arcs.size(), np = v.problem->patches.size();
  const std::size_t outside = np;
  const Strip_graph g = make_strip_graph(v);
  std::vector<int> lo(na), hi(na);
  for(std::size_t a = 0; a < na; ++a) arc_window(v.problem->arcs[a], lo[a], hi[a]);
  // Step 1.
  for(std::size_t a = 0; a < na; ++a) {
    if(v.fixed[a] > 0) { s[a] = v.fixed[a]; continue; }
    const double t = v.arc_patches[a].empty() ? v.problem->arcs[a].target : g.mean_target[g.root[a]];
    s[a] = (std::min)(hi[a], (std::max)(lo[a], (std::max)(1, static_cast<int>(std::lround(t)))));
  }
  std::vector<char> odd(np + 1, 0);
  for(std::size_t p = 0; p < np; ++p) odd[p] = char(perimeter(v, p, s) % 2);
  auto goal = [&](std::size_t q) { return q == outside || odd[q] != 0; };
  auto no_skip = [](std::size_t) { return false; };
  std::vector<long> prev_node, prev_edge;

  // Step 2.
  auto bump_strip = [&](std::size_t r) {
    const auto& m = g.members[r];
    auto fits = [&](int d) {
      for(std::size_t a : m) if(s[a] + d < (std::max)(1, lo[a]) || s[a] + d > hi[a]) return false;
      return true;
    };
    int d = g.mean_target[r] < double(s[m[0]]) ? -1 : 1;
    if(!fits(d)) d = -d;
    // Neither fits when one arc of the strip is at the low end of its window and another at the high
    // end (a minimum far above the target raises the low end): +1 then, above a window rather than
    // below a minimum. Every arc of the strip must change, or the parities on the way break.
    if(!fits(d)) d = 1;
    for(std::size_t a : m) s[a] += d;
  };
  auto strip_edges = [&](std::size_t p) -> const std::vector<std::pair<std::size_t, std::size_t> >& { return g.adjacent[p]; };
  for(std::size_t start = 0; start < np; ++start) {
    if(!odd[start]) continue;
    odd[start] = 0; // not a goal of its own search
    const long found = breadth_first(np + 1, start, strip_edges, no_skip, goal, prev_node, prev_edge);
    if(found < 0) { odd[start] = 1; continue; } // left to step 3
    for(long q = found; q != long(start); q = prev_node[q]) bump_strip(std::size_t(prev_edge[q]));
    if(found != long(outside)) odd[found] = 0;
  }

  // Step 3.
  std::vector<std::pair<std::size_t, std::size_t> > steps;
  auto arc_edges = [&](std::size_t p) -> const std::vector<std::pair<std::size_t, std::size_t> >& {
    steps.clear();
    if(p == outside) return steps; // the outside is a goal, never expanded
    for(std::size_t a : v.patch_arcs[p]) {
      if(v.fixed[a] > 0) continue;
      const auto& inc = v.arc_patches[a];
      // An arc bounding the same patch twice changes its perimeter by 2: useless for parity.
      if(inc.size() == 1) steps.emplace_back(a, outside);
      else if(inc[0] != inc[1]) steps.emplace_back(a, inc[0] == p ? inc[1] : inc[0]);
    }
    return steps;
  };
  auto bump = [&](std::size_t a) {
    const double t = v.problem->arcs[a].target;
    if(s[a] > v.problem->arcs[a].minimum && double(s[a]) > t) --s[a]; else ++s[a];
  };
  for(std::size_t start = 0; start < np; ++start) {
    if(!odd[start]) continue;
    odd[start] = 0;
    const long found = breadth_first(np + 1, start, arc_edges, no_skip, goal, prev_node, prev_edge);
    if(found < 0)
      throw std::invalid_argument("quantize_patch_sides: the fixed arc values make an even perimeter impossible "
                                  "for patch " + std::to_string(start));
    for(long q = found; q != long(start); q = prev_node[q]) bump(std::size_t(prev_edge[q]));
    if(found != long(outside)) odd[found] = 0;
  }
  // Step 4.
  for(std::size_t p = 0; p < np; ++p) {
    if(perimeter(v, p, s) >= 4) continue;
    bool done = false;
    for(std::size_t a : v.patch_arcs[p])
      if(v.fixed[a] == 0) { s[a] += 2; done = true; break; }
    if(!done)
      throw std::invalid_argument("quantize_patch_sides: patch " + std::to_string(p) +
                                  " has only fixed arcs and a perimeter below 4");
  }
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
