// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_PROBLEM_HELPERS_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_PROBLEM_HELPERS_H

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {

/// \ingroup PkgQuadRemeshingRef
/// The input of `quantize_patch_sides()`: a patch layout reduced to what side quantization needs.
///
/// An *arc* is a piece of patch boundary between two consecutive points that are a corner or a
/// T-junction of one of the (at most two) patches it bounds; its edge count is the unknown.
/// A patch is the cyclic list of its sides in counterclockwise order, each side the ordered list of
/// the ids (indices in `arcs`) of the arcs it is made of. An arc listed by one patch only is a
/// boundary arc. The patches adjacent across an arc are deduced from these lists.
///
/// A layout fills it by numbering its arcs, setting `target` to the arc's length measured along the
/// field divided by the quad edge length, and listing the sides of every patch.
struct Side_quantization_problem
{
  /// One arc.
  struct Arc
  {
    /// The desired real edge count (> 0): field-measured length / quad edge length.
    double target = 1.;
    /// If > 0, the edge count is fixed to this value (e.g. already decided elsewhere); 0 means free.
    int fixed = 0;
  };
  /// The arcs.
  std::vector<Arc> arcs;
  /// `patches[p][i]` is side `i` of patch `p` (counterclockwise), the ordered list of its arc ids.
  std::vector<std::vector<std::vector<std::size_t> > > patches;
};

namespace internal {

// Derived adjacency and the current fixed values (the clusters add fixed arcs).
struct Quantization_view
{
  const Side_quantization_problem* problem = nullptr;
  std::vector<int> fixed;                              // per arc, 0 = free
  std::vector<std::vector<std::size_t> > arc_patches;  // one or two patches per arc
  std::vector<std::vector<std::size_t> > patch_arcs;   // distinct arcs of each patch
};

// Checks the preconditions (cheaply) and builds the view; throws std::invalid_argument.
inline Quantization_view make_view(const Side_quantization_problem& pb)
{
  Quantization_view v;
  v.problem = &pb;
  const std::size_t na = pb.arcs.size();
  v.fixed.resize(na);
  v.arc_patches.resize(na);
  v.patch_arcs.resize(pb.patches.size());
  for(std::size_t a = 0; a < na; ++a) {
    const double t = pb.arcs[a].target;
    if(!(t > 0) || !std::isfinite(t) || t > 1e6)
      throw std::invalid_argument("quantize_patch_sides: arc " + std::to_string(a) + " has a target that is not in (0, 1e6]");
    if(pb.arcs[a].fixed < 0)
      throw std::invalid_argument("quantize_patch_sides: arc " + std::to_string(a) + " has a negative fixed value");
    v.fixed[a] = pb.arcs[a].fixed;
  }
  for(std::size_t p = 0; p < pb.patches.size(); ++p) {
    const auto& sides = pb.patches[p];
    if(sides.size() < 3 || sides.size() > 6)
      throw std::invalid_argument("quantize_patch_sides: patch " + std::to_string(p) + " has " +
                                  std::to_string(sides.size()) + " sides (3 to 6 are supported)");
    for(const auto& side : sides) {
      if(side.empty())
        throw std::invalid_argument("quantize_patch_sides: patch " + std::to_string(p) + " has an empty side");
      for(std::size_t a : side) {
        if(a >= na)
          throw std::invalid_argument("quantize_patch_sides: patch " + std::to_string(p) + " refers to arc " +
                                      std::to_string(a) + " that does not exist");
        auto& ap = v.arc_patches[a];
        bool seen = false;
        for(std::size_t q : v.patch_arcs[p]) if(q == a) seen = true;
        if(seen) {
          // An arc may bound the same patch twice (a cut inside the patch), never more.
          if(ap.size() == 2)
            throw std::invalid_argument("quantize_patch_sides: arc " + std::to_string(a) + " is used more than twice");
          ap.push_back(p);
          continue;
        }
        if(ap.size() == 2)
          throw std::invalid_argument("quantize_patch_sides: arc " + std::to_string(a) + " bounds more than two patches");
        ap.push_back(p);
        v.patch_arcs[p].push_back(a);
      }
    }
  }
  return v;
}

inline int side_count(const Quantization_view& v, std::size_t p, std::size_t i, const std::vector<int>& s)
{
  int e = 0;
  for(std::size_t a : v.problem->patches[p][i]) e += s[a];
  return e;
}

inline long perimeter(const Quantization_view& v, std::size_t p, const std::vector<int>& s)
{
  long e = 0;
  for(std::size_t i = 0; i < v.problem->patches[p].size(); ++i) e += side_count(v, p, i, s);
  return e;
}

// The left-hand sides of Tarini's validity inequalities (each must be >= 2, i.e. every separatrix
// length s_i >= 1) for a 3, 5 or 6-sided patch with side counts e; empty for quads.
inline std::vector<std::vector<int> > tarini_rows(std::size_t n)
{
  std::vector<std::vector<int> > rows;
  for(std::size_t i = 0; i < n && n != 4; ++i) {
    std::vector<int> c(n, 0);
    auto at = [&](long k) -> int& { return c[std::size_t(((k % long(n)) + long(n)) % long(n))]; };
    const long j = long(i);
    if(n == 3) { at(j - 1) += 1; at(j + 1) += 1; at(j) -= 1; }                                  // 2 s_i
    else if(n == 5) { at(j - 1) += 1; at(j) += 1; at(j + 1) += 1; at(j + 2) -= 1; at(j - 2) -= 1; }
    else if(n == 6) { at(j - 1) += 1; at(j + 1) += 1; at(j + 3) -= 1; }
    rows.push_back(c);
  }
  return rows;
}

// The unweighted regularity violation of patch p: |e0 - e2| + |e1 - e3| for a quad; otherwise the
// violations of Tarini's inequalities (+ 1 for an odd e0 + e2 + e4 of a hexagon), divided by n.
inline double patch_violation(const Quantization_view& v, std::size_t p, const std::vector<int>& s)
{
  const std::size_t n = v.problem->patches[p].size();
  int e[6] = {0, 0, 0, 0, 0, 0};
  for(std::size_t i = 0; i < n; ++i) e[i] = side_count(v, p, i, s);
  if(n == 4) return std::abs(e[0] - e[2]) + std::abs(e[1] - e[3]);
  double viol = 0;
  for(const auto& r : tarini_rows(n)) {
    int x = 0;
    for(std::size_t i = 0; i < n; ++i) x += r[i] * e[i];
    viol += (std::max)(0, 2 - x);
  }
  if(n == 6 && (e[0] + e[2] + e[4]) % 2 != 0) viol += 1;
  return viol / double(n);
}

// Whether Tarini's simple strategy applies to patch p with counts s (n = 4: opposite sides equal).
inline bool is_simple_patch(const Quantization_view& v, std::size_t p, const std::vector<int>& s)
{
  const std::size_t n = v.problem->patches[p].size();
  std::vector<int> e(n);
  for(std::size_t i = 0; i < n; ++i) e[i] = side_count(v, p, i, s);
  if(n == 4) return e[0] == e[2] && e[1] == e[3];
  if(perimeter(v, p, s) % 2 != 0) return false;
  if(n == 6 && (e[0] + e[2] + e[4]) % 2 != 0) return false;
  for(const auto& r : tarini_rows(n)) {
    int x = 0;
    for(std::size_t i = 0; i < n; ++i) x += r[i] * e[i];
    if(x < 2) return false;
  }
  return true;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
