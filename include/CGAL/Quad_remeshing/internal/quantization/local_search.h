// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_LOCAL_SEARCH_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_LOCAL_SEARCH_H

#include <CGAL/Quad_remeshing/internal/quantization/problem_helpers.h>
#include <CGAL/Quad_remeshing/internal/quantization/mip_model.h>
#include <CGAL/Quad_remeshing/internal/quantization/fallback.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// The regularity term of patch p (weighted), as in evaluate().
inline double patch_regularity_cost(const Quantization_view& v, std::size_t p, const std::vector<int>& s,
                                    const Quantization_weights& w)
{
  const double weight = v.problem->patches[p].size() == 4 ? w.regularity_quads : w.regularity_others;
  return weight * patch_violation(v, p, s);
}

// Deterministic first-improvement search over cycles of strips (make_strip_graph()): a strip with two ends
// changes by +-1, which makes its two end patches odd, and the strips of a shortest path between
// those ends in the strip graph (nodes: patches and the outside; edges: strips with two ends, the
// moved one left out) change by +-1 each, every one in the direction that costs least when it is
// applied, which makes every parity even again. This is what fixes the quads of a T-junction
// (a side of one arc against a side of two): the strip on one side and a strip on the other change
// together. The move is kept if it lowers the objective (alignment terms of `pairs` included) and
// keeps every arc in its window. One pass over the strips in root-id order; returns the decrease.
inline double improve_strip_cycles(const Quantization_view& v, std::vector<int>& s, const Quantization_weights& w,
                                   const std::vector<Alignment_pair>& pairs = {}, std::size_t max_expanded = 1000)
{
  const auto& pb = *v.problem;
  const std::size_t na = pb.arcs.size(), np = pb.patches.size(), outside = np;
  const Strip_graph g = make_strip_graph(v);
  const auto& members = g.members;
  const auto& ends = g.ends;
  std::vector<std::vector<std::size_t> > pairs_of(np);
  if(w.alignment > 0)
    for(std::size_t k = 0; k < pairs.size(); ++k) { pairs_of[pairs[k].p].push_back(k); pairs_of[pairs[k].q].push_back(k); }
  std::vector<int> lo(na), hi(na);
  for(std::size_t a = 0; a < na; ++a) arc_window(pb.arcs[a], lo[a], hi[a]);
  auto fits = [&](std::size_t r, int d) {
    for(std::size_t a : members[r]) if(s[a] + d < (std::max)(1, lo[a]) || s[a] + d > hi[a]) return false;
    return true;
  };
  // the objective restricted to the arcs of the strips `rs`, the patches they bound and their pairs
  std::vector<char> patch_mark(np, 0), pair_mark(pairs.size(), 0);
  auto local_cost = [&](const std::vector<std::size_t>& rs) {
    double c = 0;
    std::vector<std::size_t> ps, ks;
    for(std::size_t r : rs)
      for(std::size_t a : members[r]) {
        c += w.isometry * isometry_cost(s[a], pb.arcs[a].target, w);
        for(std::size_t p : v.arc_patches[a]) if(!patch_mark[p]) { patch_mark[p] = 1; ps.push_back(p); }
      }
    for(std::size_t p : ps) {
      c += patch_regularity_cost(v, p, s, w);
      for(std::size_t k : pairs_of[p]) if(!pair_mark[k]) { pair_mark[k] = 1; ks.push_back(k); }
    }
    for(std::size_t k : ks) c += 0.5 * w.alignment * alignment_violation(v, pairs[k], s);
    for(std::size_t p : ps) patch_mark[p] = 0;
    for(std::size_t k : ks) pair_mark[k] = 0;
    return c;
  };
  auto shift = [&](std::size_t r, int d) { for(std::size_t a : members[r]) s[a] += d; };

  double gain = 0;
  std::vector<long> prev_node, prev_strip;
  std::vector<std::size_t> path;
  std::vector<int> dirs;
  for(std::size_t r = 0; r < na; ++r) {
    if(ends[r].first > outside) continue;
    for(int d : {1, -1}) {
      if(!fits(r, d)) continue;
      // shortest path between the two ends of r, r left out
      const std::size_t from = ends[r].first, to = ends[r].second;
      auto strip_edges = [&](std::size_t p) -> const std::vector<std::pair<std::size_t, std::size_t> >& { return g.adjacent[p]; };
      auto skip_r = [&](std::size_t e) { return e == r; };
      auto is_to = [&](std::size_t q) { return q == to; };
      // (a cycle through more than max_expanded nodes is rarely an improvement: the search is bounded so
      // that a pass stays linear in the size of the layout)
      if(breadth_first(np + 1, from, strip_edges, skip_r, is_to, prev_node, prev_strip, max_expanded) < 0) continue;
      path.assign(1, r);
      for(long q = long(to); q != long(from); q = prev_node[q]) path.push_back(std::size_t(prev_strip[q]));
      const double before = local_cost(path);
      shift(r, d);
      dirs.assign(1, d);
      bool ok = true;
      for(std::size_t k = 1; k < path.size() && ok; ++k) {
        const std::vector<std::size_t> one(1, path[k]);
        int best = 0; double best_cost = 0;
        for(int e : {1, -1}) {
          if(!fits(path[k], e)) continue;
          shift(path[k], e);
          const double c = local_cost(one);
          shift(path[k], -e);
          if(best == 0 || c < best_cost - 1e-12) { best = e; best_cost = c; }
        }
        if(best == 0) ok = false;
        else { shift(path[k], best); dirs.push_back(best); }
      }
      const double after = ok ? local_cost(path) : 0.;
      if(ok && after < before - 1e-9) { gain += before - after; break; }
      for(std::size_t k = 0; k < dirs.size(); ++k) shift(path[k], -dirs[k]);
    }
  }
  return gain;
}

// Deterministic first-improvement local search on the integer program, keeping every perimeter even
// and >= 4 and every s >= 1 (moves keep s in the window of arc_window()); only arcs with v.fixed == 0 change. A move changes by the same delta
// (+-1, +-2) the arcs of a strip: from an arc, on each side, through 4-sided patches from a side to the
// opposite one (on a side of several arcs, the one whose deviation from its target grows least) until
// a patch with another number of sides, the boundary, or the start again. Strips keep the
// opposite-side differences of the quads they cross; a half strip (one direction only) with delta +-2
// changes the one quad or polygon it starts from and keeps every parity. A move is taken if it lowers
// the objective and leaves every parity even. Sweeps the arcs in id order, each sweep followed by a
// pass of improve_strip_cycles(), until no move improves or max_sweeps is reached. The objective
// includes the alignment terms of `pairs`. Returns the objective decrease.
inline double improve_locally(const Quantization_view& v, std::vector<int>& s, const Quantization_weights& w,
                              const std::vector<Alignment_pair>& pairs = {}, std::size_t max_sweeps = 100)
{
  const auto& pb = *v.problem;
  const std::size_t na = pb.arcs.size(), np = pb.patches.size();
  std::vector<std::vector<std::size_t> > pairs_of(np);
  if(w.alignment > 0)
    for(std::size_t k = 0; k < pairs.size(); ++k) { pairs_of[pairs[k].p].push_back(k); pairs_of[pairs[k].q].push_back(k); }
  std::vector<char> pair_seen(pairs.size(), 0);
  std::vector<std::size_t> touched_pairs;
  // side_of[p] lists (arc, side index) pairs of patch p
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > side_of(np);
  for(std::size_t p = 0; p < np; ++p)
    for(std::size_t i = 0; i < pb.patches[p].size(); ++i)
      for(std::size_t a : pb.patches[p][i]) side_of[p].emplace_back(a, i);
  // values stay in the windows of the program (arc_window), so that a result is a valid starting point
  std::vector<int> lo(na), hi(na);
  for(std::size_t a = 0; a < na; ++a) arc_window(pb.arcs[a], lo[a], hi[a]);
  auto allowed = [&](std::size_t a, int x) { return x >= lo[a] && x <= hi[a]; };
  auto iso = [&](std::size_t a, int x) { return w.isometry * isometry_cost(x, pb.arcs[a].target, w); };

  std::vector<char> in_move(na, 0), touched(np, 0);
  std::vector<std::size_t> arcs, patches;
  // Extends the strip from arc a into patch q (a is on one of q's sides); appends the arcs.
  auto trace = [&](std::size_t a, std::size_t q, int delta) {
    for(std::size_t steps = 0; steps < np; ++steps) {
      if(pb.patches[q].size() != 4) return;
      long side = -1; int count = 0;
      for(const auto& as : side_of[q]) if(as.first == a) { side = long(as.second); ++count; }
      if(count != 1) return; // an arc bounding q twice: stop
      const std::size_t opp = (std::size_t(side) + 2) % 4;
      long best = -1; double best_cost = 0;
      for(std::size_t b : pb.patches[q][opp]) {
        if(v.fixed[b] != 0 || in_move[b] || !allowed(b, s[b] + delta)) continue;
        const double c = iso(b, s[b] + delta) - iso(b, s[b]);
        if(best < 0 || c < best_cost) { best = long(b); best_cost = c; }
      }
      if(best < 0) return;
      const std::size_t b = std::size_t(best);
      in_move[b] = 1; arcs.push_back(b);
      const auto& inc = v.arc_patches[b];
      if(inc.size() != 2 || inc[0] == inc[1]) return;
      const std::size_t next = (inc[0] == q) ? inc[1] : inc[0];
      a = b; q = next;
    }
  };
  // Applies s += delta on the current arcs if it improves and keeps parity; otherwise leaves s as is.
  auto try_move = [&](int delta) -> double {
    patches.clear();
    for(std::size_t a : arcs)
      for(std::size_t p : v.arc_patches[a]) if(!touched[p]) { touched[p] = 1; patches.push_back(p); }
    touched_pairs.clear();
    for(std::size_t p : patches)
      for(std::size_t k : pairs_of[p]) if(!pair_seen[k]) { pair_seen[k] = 1; touched_pairs.push_back(k); }
    auto alignment = [&]() {
      double c = 0;
      for(std::size_t k : touched_pairs) c += 0.5 * w.alignment * alignment_violation(v, pairs[k], s);
      return c;
    };
    double before = alignment(), after = 0;
    for(std::size_t a : arcs) before += iso(a, s[a]);
    for(std::size_t p : patches) before += patch_regularity_cost(v, p, s, w);
    for(std::size_t a : arcs) s[a] += delta;
    bool ok = true;
    after += alignment();
    for(std::size_t a : arcs) after += iso(a, s[a]);
    for(std::size_t p : patches) {
      const long per = perimeter(v, p, s);
      if(per % 2 != 0 || per < 4) ok = false;
      after += patch_regularity_cost(v, p, s, w);
    }
    for(std::size_t p : patches) touched[p] = 0;
    for(std::size_t k : touched_pairs) pair_seen[k] = 0;
    if(ok && after < before - 1e-9) return before - after;
    for(std::size_t a : arcs) s[a] -= delta;
    return 0;
  };

  double gain = 0;
  for(std::size_t sweep = 0; sweep < max_sweeps; ++sweep) {
    double sweep_gain = 0;
    for(std::size_t a = 0; a < na; ++a) {
      if(v.fixed[a] != 0 || v.arc_patches[a].empty()) continue;
      for(int delta : {-1, 1, -2, 2}) {
        const auto& inc = v.arc_patches[a];
        // 0: both directions; 1, 2: half strip into inc[0] or inc[1] (only with delta +-2)
        for(int mode = 0; mode < 3; ++mode) {
          if(mode > 0 && (std::abs(delta) != 2 || std::size_t(mode) > inc.size())) continue;
          if(!allowed(a, s[a] + delta)) continue;
          arcs.assign(1, a); in_move[a] = 1;
          if(mode == 0 || mode == 1) trace(a, inc[0], delta);
          if((mode == 0 && inc.size() == 2 && inc[0] != inc[1]) || mode == 2) trace(a, inc[1], delta);
          const double g = try_move(delta);
          for(std::size_t b : arcs) in_move[b] = 0;
          sweep_gain += g;
        }
      }
    }
    sweep_gain += improve_strip_cycles(v, s, w, pairs);
    gain += sweep_gain;
    if(!(sweep_gain > 1e-9)) break;
  }
  return gain;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
