// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_PROBLEM_HELPERS_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUANTIZATION_PROBLEM_HELPERS_H

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
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
    /// The smallest edge count a free arc may take (>= 1), e.g. the number of straight edges a bent
    /// feature line needs to be followed within a tolerance (see `internal::chord_minimum()`).
    int minimum = 1;
  };
  /// The arcs.
  std::vector<Arc> arcs;
  /// `patches[p][i]` is side `i` of patch `p` (counterclockwise), the ordered list of its arc ids.
  std::vector<std::vector<std::vector<std::size_t> > > patches;
};

namespace internal {

// Plain-text form of a problem (the CLI's --dump writes it; benchmarks read it back): the number of
// arcs, one "target fixed minimum" line per arc (targets with 17 significant digits), the number of patches,
// then per patch its number of sides followed, per side, by its number of arcs and their ids.
inline void write_quantization_problem(std::ostream& out, const Side_quantization_problem& pb)
{
  out << std::setprecision(17) << pb.arcs.size() << "\n";
  for(const auto& a : pb.arcs) out << a.target << " " << a.fixed << " " << a.minimum << "\n";
  out << pb.patches.size() << "\n";
  for(const auto& patch : pb.patches) {
    out << patch.size();
    for(const auto& side : patch) {
      out << "  " << side.size();
      for(std::size_t a : side) out << " " << a;
    }
    out << "\n";
  }
}

// Reads what write_quantization_problem() wrote; throws std::runtime_error on malformed input.
inline Side_quantization_problem read_quantization_problem(std::istream& in)
{
  Side_quantization_problem pb;
  std::size_t n = 0;
  if(!(in >> n)) throw std::runtime_error("read_quantization_problem: no arc count");
  pb.arcs.resize(n);
  for(auto& a : pb.arcs) if(!(in >> a.target >> a.fixed >> a.minimum)) throw std::runtime_error("read_quantization_problem: bad arc");
  if(!(in >> n)) throw std::runtime_error("read_quantization_problem: no patch count");
  pb.patches.resize(n);
  for(auto& patch : pb.patches) {
    std::size_t ns = 0;
    if(!(in >> ns) || ns > 64) throw std::runtime_error("read_quantization_problem: bad patch");
    patch.resize(ns);
    for(auto& side : patch) {
      std::size_t k = 0;
      if(!(in >> k) || k > pb.arcs.size()) throw std::runtime_error("read_quantization_problem: bad side");
      side.resize(k);
      for(auto& a : side) if(!(in >> a)) throw std::runtime_error("read_quantization_problem: bad arc id");
    }
  }
  return pb;
}

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
    if(pb.arcs[a].minimum < 1 || pb.arcs[a].minimum > 1000000)
      throw std::invalid_argument("quantize_patch_sides: arc " + std::to_string(a) + " has a minimum that is not in [1, 1e6]");
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

// Two sides of non-quad patches (3, 5 or 6 sides) that face each other: side i of patch p and side j
// of patch q are both one arc, and that arc is shared, directly or through a chain of 4-sided
// patches entered and left through opposite sides that are one arc each (a T-junction, a boundary,
// a side bounding its patch twice or a loop ends the chain). With one singular vertex per patch
// (Tarini's simple pattern), their separatrices meet the shared line at the same point exactly when
// the sub-sides of p's side equal those of q's side in reverse order (see alignment_violation()).
struct Alignment_pair { std::size_t p, i, q, j; };

// The side index of patch q that arc a forms alone, or -1 (a is on no side of q, on several, or
// shares its side with other arcs).
inline long single_arc_side(const Quantization_view& v, std::size_t q, std::size_t a)
{
  long side = -1; int seen = 0;
  const auto& sides = v.problem->patches[q];
  for(std::size_t k = 0; k < sides.size(); ++k)
    for(std::size_t b : sides[k]) if(b == a) { ++seen; side = long(k); }
  if(seen != 1 || sides[std::size_t(side)].size() != 1) return -1;
  return side;
}

// Every facing pair once (p < q, or p == q never), in ascending (p, i) order: deterministic.
inline std::vector<Alignment_pair> alignment_pairs(const Quantization_view& v)
{
  const auto& pb = *v.problem;
  const std::size_t np = pb.patches.size();
  std::vector<Alignment_pair> pairs;
  for(std::size_t p = 0; p < np; ++p) {
    if(pb.patches[p].size() == 4) continue;
    for(std::size_t i = 0; i < pb.patches[p].size(); ++i) {
      if(pb.patches[p][i].size() != 1) continue;
      std::size_t arc = pb.patches[p][i][0], from = p;
      if(single_arc_side(v, p, arc) != long(i)) continue;
      for(std::size_t steps = 0; steps <= np; ++steps) {
        const auto& inc = v.arc_patches[arc];
        if(inc.size() != 2 || inc[0] == inc[1]) break;
        const std::size_t q = inc[0] == from ? inc[1] : inc[0];
        if(q == p) break;
        const long k = single_arc_side(v, q, arc);
        if(k < 0) break;
        if(pb.patches[q].size() != 4) {
          if(p < q) pairs.push_back(Alignment_pair{p, i, q, std::size_t(k)});
          break;
        }
        const auto& opposite = pb.patches[q][(std::size_t(k) + 2) % 4];
        if(opposite.size() != 1 || single_arc_side(v, q, opposite[0]) < 0) break;
        arc = opposite[0]; from = q;
      }
    }
  }
  return pairs;
}

// Twice the sub-sides of side i of a 3, 5 or 6-sided patch with side counts e, as linear forms in e:
// `up` (from the side's start corner to its separatrix) is 2 s_{i-1}, `down` (from the separatrix to
// its end corner) is 2 s_{i+1}, with 2 s_k the k-th row of tarini_rows().
inline void sub_side_rows(std::size_t n, std::size_t i, std::vector<int>& up, std::vector<int>& down)
{
  const auto rows = tarini_rows(n);
  up = rows[(i + n - 1) % n];
  down = rows[(i + 1) % n];
}

inline int dot_sides(const Quantization_view& v, std::size_t p, const std::vector<int>& r, const std::vector<int>& s)
{
  int x = 0;
  for(std::size_t k = 0; k < r.size(); ++k) if(r[k] != 0) x += r[k] * side_count(v, p, k, s);
  return x;
}

// |up_p - down_q| + |down_p - up_q|: 0 when the two singular vertices lie on one line of quad edges
// (the shared line is walked in opposite directions by the two patches, and each quad patch on the way
// keeps the position measured from the corresponding corner).
inline int alignment_violation(const Quantization_view& v, const Alignment_pair& a, const std::vector<int>& s)
{
  std::vector<int> up_p, down_p, up_q, down_q;
  sub_side_rows(v.problem->patches[a.p].size(), a.i, up_p, down_p);
  sub_side_rows(v.problem->patches[a.q].size(), a.j, up_q, down_q);
  return std::abs(dot_sides(v, a.p, up_p, s) - dot_sides(v, a.q, down_q, s)) +
         std::abs(dot_sides(v, a.p, down_p, s) - dot_sides(v, a.q, up_q, s));
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
