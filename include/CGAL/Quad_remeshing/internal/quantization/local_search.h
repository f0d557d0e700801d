// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_LOCAL_SEARCH_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_LOCAL_SEARCH_H

#include <CGAL/Quad_remeshing/internal/quantization/problem_helpers.h>
#include <CGAL/Quad_remeshing/internal/quantization/mip_model.h>

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

// Deterministic first-improvement local search on the integer program, keeping every perimeter even
// and >= 4 and every s >= 1 (moves keep s in the window of arc_window()); only arcs with v.fixed == 0 change. A move changes by the same delta
// (+-1, +-2) the arcs of a strip: from an arc, on each side, through 4-sided patches from a side to the
// opposite one (on a side of several arcs, the one whose deviation from its target grows least) until
// a patch with another number of sides, the boundary, or the start again. Strips keep the
// opposite-side differences of the quads they cross; a half strip (one direction only) with delta +-2
// changes the one quad or polygon it starts from and keeps every parity. A move is taken if it lowers
// the objective and leaves every parity even. Sweeps the arcs in id order until no move improves or
// max_sweeps is reached. The objective includes the alignment terms of `pairs`. Returns the
// objective decrease.
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
  for(std::size_t a = 0; a < na; ++a) arc_window(pb.arcs[a].target, lo[a], hi[a]);
  auto allowed = [&](std::size_t a, int x) { return x >= lo[a] && x <= hi[a]; };
  auto iso = [&](std::size_t a, int x) { const double d = x - pb.arcs[a].target; return w.isometry * d * d; };

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
    gain += sweep_gain;
    if(!(sweep_gain > 1e-9)) break;
  }
  return gain;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
