// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_FALLBACK_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_FALLBACK_H

#include <CGAL/Quad_remeshing/internal/quantization/problem_helpers.h>

#include <cmath>
#include <deque>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// Solver-free assignment: every free arc is rounded to max(1, round(target)); then odd patches are
// paired along shortest paths (BFS, lowest ids first, so deterministic) of the patch adjacency graph
// whose steps cross free arcs, or ended at a free boundary arc; every arc crossed changes by +-1
// (towards its target when that keeps it >= 1), which flips the parity of the two path ends only.
// Finally a patch with perimeter 2 gets +2 on one free arc (parity unchanged everywhere).
// Throws std::invalid_argument if the fixed arcs make parity impossible.
inline void fallback_assignment(const Quantization_view& v, std::vector<int>& s)
{
  const std::size_t na = v.problem->arcs.size(), np = v.problem->patches.size();
  for(std::size_t a = 0; a < na; ++a)
    if(v.fixed[a] > 0) s[a] = v.fixed[a];
    else s[a] = (std::max)(1, static_cast<int>(std::lround(v.problem->arcs[a].target)));

  auto bump = [&](std::size_t a) {
    const double t = v.problem->arcs[a].target;
    if(s[a] > 1 && double(s[a]) > t) --s[a]; else ++s[a];
  };
  std::vector<char> odd(np, 0);
  for(std::size_t p = 0; p < np; ++p) odd[p] = char(perimeter(v, p, s) % 2);

  // Node np is the outside, reached through free boundary arcs.
  const std::size_t outside = np;
  std::vector<long> prev_node(np + 1), prev_arc(np + 1);
  for(std::size_t start = 0; start < np; ++start) {
    if(!odd[start]) continue;
    std::fill(prev_node.begin(), prev_node.end(), -2);
    std::deque<std::size_t> queue{start};
    prev_node[start] = -1;
    long found = -1;
    while(!queue.empty() && found < 0) {
      const std::size_t p = queue.front(); queue.pop_front();
      for(std::size_t a : v.patch_arcs[p]) {
        if(v.fixed[a] > 0) continue;
        const auto& inc = v.arc_patches[a];
        // An arc bounding the same patch twice changes its perimeter by 2: useless for parity.
        std::size_t q;
        if(inc.size() == 1) q = outside;
        else if(inc[0] == inc[1]) continue;
        else q = (inc[0] == p) ? inc[1] : inc[0];
        if(prev_node[q] != -2) continue;
        prev_node[q] = long(p); prev_arc[q] = long(a);
        if(q == outside || odd[q]) { found = long(q); break; }
        queue.push_back(q);
      }
    }
    if(found < 0)
      throw std::invalid_argument("quantize_patch_sides: the fixed arc values make an even perimeter impossible "
                                  "for patch " + std::to_string(start));
    for(long q = found; q != long(start); q = prev_node[q]) bump(std::size_t(prev_arc[q]));
    odd[start] = 0;
    if(found != long(outside)) odd[found] = 0;
  }
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
