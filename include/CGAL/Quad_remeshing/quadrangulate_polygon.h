// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quadrangulation of an n-sided polygon with prescribed edge counts per side (paper, section 6.2).

#ifndef CGAL_QUAD_REMESHING_QUADRANGULATE_POLYGON_H
#define CGAL_QUAD_REMESHING_QUADRANGULATE_POLYGON_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/quadrangulate_polygon/constructions.h>
#include <CGAL/Quad_remeshing/internal/quadrangulate_polygon/patterns.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  A quad mesh of a disk whose boundary is an n-sided polygon with a prescribed number of edges per
  side, as returned by `quadrangulate_polygon()`.

  Vertices are indexed `0..positions.size()-1`. The boundary vertices come first: vertex `k`,
  `k < boundary.size()`, is the `k`-th vertex of the counterclockwise boundary loop, vertex 0 being
  corner 0. Hence boundary vertex `k` of side `i` (`0 <= k < e_i`, `k` counted from corner `i`) is
  vertex `side_start[i] + k`, and the end of side `i` is corner `i+1`.
*/
struct Polygon_quadrangulation
{
  /// how the polygon was filled
  enum Strategy {
    SIMPLE,       ///< Tarini's single-singularity patch (regular grid for 4 sides)
    GENERAL,      ///< one of Takayama et al.'s topological patterns, with loops and padding
    RING_AND_GRID ///< last resort when no pattern embeds without a flat quad corner: a ring of
                  ///< quads along the boundary around a regular grid (only tiny inputs, see
                  ///< `quadrangulate_polygon()`)
  };

  /// the number of edges of each side, as given
  std::vector<int> side_edge_counts;
  /// 2D embedding: boundary on the regular n-gon inscribed in the unit circle (two half circles for
  /// n = 2), side `i` split uniformly, interior vertices by a harmonic map
  std::vector<std::array<double, 2>> positions;
  /// quads, vertex indices in counterclockwise order in the embedding
  std::vector<std::array<std::size_t, 4>> quads;
  /// the boundary loop, counterclockwise from corner 0 (equal to `0, 1, ..., N-1`)
  std::vector<std::size_t> boundary;
  /// vertex index of corner `i` (start of side `i`), for `i = 0..n-1`
  std::vector<std::size_t> corners;
  /// loop index where side `i` starts; `side_start[n]` is the boundary length
  std::vector<std::size_t> side_start;
  /// for each boundary vertex, the side it starts or lies on
  std::vector<int> side_of_boundary_vertex;
  /// for each boundary vertex, its index along its side (0 for a corner)
  std::vector<int> index_along_side;
  /// the strategy used
  Strategy strategy = GENERAL;
  /// for `SIMPLE` with 3, 5 or 6 sides, Tarini's separatrix lengths `s_i` (else empty)
  std::vector<int> separatrix_lengths;
  /// for `GENERAL`, the pattern `(n, K)` used, named `"n_K"` as in Takayama et al. (else empty)
  std::string pattern;
  /// for `GENERAL`, the number of edge loops inserted at each of the pattern's loop sites
  std::vector<int> pattern_loops;
  /// for `GENERAL`, the padding (quad strips appended) along each side of the pattern, in pattern
  /// side order
  std::vector<int> pattern_padding;
  /// for `GENERAL`, the side map: pattern side `j` is input side `j + pattern_rotation` (mod n), or
  /// `pattern_rotation - j` if `pattern_reflected` (the pattern then mirrored)
  int pattern_rotation = 0;
  /// see `pattern_rotation`
  bool pattern_reflected = false;
  /// for `GENERAL`, the number of pattern quads split into five (an inner quad and a ring of four)
  /// because a lone pattern vertex on an unpadded side would make them flat in the embedding
  int pattern_split_quads = 0;
  /// irregular vertices counted by valence (number of incident edges): interior vertices of
  /// valence != 4, boundary non-corner vertices of valence != 3, corners of valence != 2
  std::map<int, int> irregular_vertices_by_valence;
  /// wall-clock seconds spent
  double seconds = 0.;

  /// number of sides
  std::size_t number_of_sides() const { return side_edge_counts.size(); }
  /// vertex index of the `k`-th subdivision point of side `i` (`k = 0..e_i`, `k = e_i` is corner `i+1`)
  std::size_t side_vertex(std::size_t i, std::size_t k) const
  {
    return (side_start[i] + k) % side_start.back();
  }
  /// total number of irregular vertices
  int number_of_irregular_vertices() const
  {
    int c = 0;
    for(const auto& kv : irregular_vertices_by_valence) c += kv.second;
    return c;
  }
  /// the figures of this patch: strategy, counts, irregular vertices by valence, seconds
  Report report() const
  {
    Report r = Report::object();
    r["sides"] = number_of_sides();
    r["strategy"] = strategy == SIMPLE ? "simple" : strategy == GENERAL ? "general" : "ring_and_grid";
    if(strategy == GENERAL)
    {
      r["pattern"] = pattern;
      r["pattern_split_quads"] = pattern_split_quads;
    }
    r["vertices"] = positions.size();
    r["quads"] = quads.size();
    r["irregular_vertices"] = number_of_irregular_vertices();
    Report& by = r["irregular_vertices_by_valence"];
    by = Report::object();
    for(const auto& kv : irregular_vertices_by_valence) by[std::to_string(kv.first)] = kv.second;
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {

inline void check_side_edge_counts(const std::vector<int>& e)
{
  if(e.size() < 2 || e.size() > 6)
    throw std::invalid_argument("quadrangulate_polygon: the polygon must have 2 to 6 sides, got " +
                                std::to_string(e.size()));
  long long sum = 0;
  for(int x : e)
  {
    if(x < 1) throw std::invalid_argument("quadrangulate_polygon: every side needs at least one edge");
    sum += x;
  }
  if(sum % 2 != 0)
    throw std::invalid_argument("quadrangulate_polygon: the total number of boundary edges must be even");
  // a 2-gon with one edge per side would have two coincident straight edges
  if(sum < 4)
    throw std::invalid_argument("quadrangulate_polygon: the boundary needs at least 4 edges");
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Returns Tarini's separatrix lengths `s` of the single-singularity quadrangulation of the polygon with
  `e[i]` edges on side `i`, i.e. the solution of `e[i] = s[i-1] + s[i+1]` (indices mod n) with every
  `s[i] >= 1`, or `std::nullopt` if there is none. Region `i`, at the corner between sides `i` and
  `i+1`, is then an `s[i+1] x s[i]` grid and the separatrix `i` lands on side `i` after `s[i-1]` edges.

  Only 3, 5 and 6 sides have such a patch with a singular centre (for 4 sides see
  `admits_simple_quadrangulation()`); `s[i] = 0` (the centre on the boundary) is refused on purpose,
  since the centre would then be a boundary vertex, and such inputs go to the general strategy.
  Closed forms: for odd n, `2 s[i] = sum_k (-1)^k e[i+1+2k]`; for n = 6, `2 s[i] = e[i-1] + e[i+1] - e[i+3]`.

  @param e number of edges of each side
*/
inline std::optional<std::vector<int>> simple_quadrangulation_separatrices(const std::vector<int>& e)
{
  const std::size_t n = e.size();
  if(n != 3 && n != 5 && n != 6) return std::nullopt;
  std::vector<int> s(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    long long twice = 0;
    if(n == 6)
      twice = (long long)e[(i + 5) % 6] + e[(i + 1) % 6] - e[(i + 3) % 6];
    else
      for(std::size_t k = 0; k < n; ++k)
        twice += (k % 2 == 0 ? 1 : -1) * (long long)e[(i + 1 + 2 * k) % n];
    if(twice < 2 || twice % 2 != 0) return std::nullopt;
    s[i] = int(twice / 2);
  }
  // the hexagon formula does not imply the equations (alternate-side parity), so verify them all
  for(std::size_t i = 0; i < n; ++i)
    if(e[i] != s[(i + n - 1) % n] + s[(i + 1) % n]) return std::nullopt;
  return s;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Tells whether `quadrangulate_polygon()` uses the simple strategy for these side counts: for 4 sides
  when `e[0] == e[2]` and `e[1] == e[3]` (regular grid, no irregular vertex), for 3, 5 and 6 sides when
  `simple_quadrangulation_separatrices(e)` has a solution (one interior vertex of valence n).
  Never true for 2 sides.

  @param e number of edges of each side
*/
inline bool admits_simple_quadrangulation(const std::vector<int>& e)
{
  for(int x : e) if(x < 1) return false;
  if(e.size() == 4) return e[0] == e[2] && e[1] == e[3];
  return bool(simple_quadrangulation_separatrices(e));
}

/*!
  \ingroup PkgQuadRemeshingRef
  Builds a quad mesh of a disk bounded by a polygon with `side_edge_counts[i]` edges on side `i`, and
  a 2D embedding of it usable as a parameter domain.

  Strategy: the simple one (Tarini 2021) whenever `admits_simple_quadrangulation()` holds: the
  regular grid for 4 sides, otherwise one interior vertex of valence n whose n separatrices cut the
  patch into n regular grids.

  Otherwise the general one, the pattern-based quadrangulation of Takayama, Panozzo and
  Sorkine-Hornung (SGP 2014), with the patterns of their PatchGen code: for n sides, patterns
  `n_0, n_1, ...` (2_0-2_1, 3_0-3_2, 4_0-4_4, 5_0-5_3, 6_0-6_3), each a small quad mesh whose
  side counts grow with edge loops inserted in fixed quad strips (`pattern_loops`) and with padding
  strips appended along its sides (`pattern_padding`), placed on the polygon in any of the 2n
  rotations and mirror images. Parameters are found by enumerating the loop counts (bounded by the
  side counts), the paddings following from a linear system; no ILP solver is needed. Selection, as
  PatchGen's default: the first pattern, in order of increasing irregularity, that has an instance;
  for each side permutation the parameters with the loop counts centred in their feasible range
  (within one of the middle), then the maximal padding, then balanced padding; then, where PatchGen
  takes the first feasible permutation, the permutation with the fewest irregular vertices (ties:
  the first, rotations before mirror images). Instances are only accepted if the embedding below has
  every quad corner strictly convex; in particular a pattern vertex alone in one quad on an unpadded
  side (which PatchGen accepts, its quad being flat on our straight sides) is refused. Every
  input with 2 to 6 sides of at most 8 edges (4 sides or fewer) or 6 edges (5 and 6 sides) is served
  this way; for a few small inputs, such as (4,1,1) or (4,1,1,1,1), only after the flat quads of a
  pattern are split in five (an inner quad and a ring; `pattern_split_quads`). Should no pattern
  instance embed (seen only for extreme inputs such as (80,1,1,1,1,2)), the last resort
  `Polygon_quadrangulation::RING_AND_GRID` is a ring of quads along the whole boundary around a
  regular grid, with n + 4 irregular vertices of valence 3.

  Positions: boundary on the regular n-gon, interior by a uniform-weight harmonic (Tutte) map,
  solved with Eigen's sparse Cholesky factorization. Deterministic.

  @tparam NamedParameters a sequence of named parameters

  @param side_edge_counts number of edges of each side, sides in counterclockwise order
  @param np an optional sequence of named parameters among the ones listed below

  @pre `2 <= side_edge_counts.size() <= 6`, every count `>= 1`, the sum even and `>= 4`
       (checked: `std::invalid_argument`)

  \cgalNamedParamsBegin
    \cgalParamNBegin{verbose}
      \cgalParamDescription{print the strategy (and pattern) and the counts to `std::cerr`, prefixed by `[quadrangulate-polygon]`}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the quadrangulation with its embedding, boundary indexing, irregular-vertex counts and,
          for the general strategy, the pattern and its parameters
*/
template <typename NamedParameters = parameters::Default_named_parameters>
Polygon_quadrangulation quadrangulate_polygon(const std::vector<int>& side_edge_counts,
                                              const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  CGAL::Real_timer timer;
  timer.start();

  const std::vector<int>& e = side_edge_counts;
  internal::check_side_edge_counts(e);
  const std::size_t n = e.size();

  Polygon_quadrangulation out;
  out.side_edge_counts = e;
  out.side_start = internal::side_offsets(e);
  const std::size_t N = out.side_start[n];

  internal::Quad_connectivity c;
  if(admits_simple_quadrangulation(e))
  {
    out.strategy = Polygon_quadrangulation::SIMPLE;
    if(n == 4)
      c = internal::build_regular_grid(e);
    else
    {
      out.separatrix_lengths = *simple_quadrangulation_separatrices(e);
      c = internal::build_single_singularity(e, out.separatrix_lengths);
    }
    out.positions = internal::harmonic_positions(c, internal::polygon_boundary_positions(e));
  }
  else if(auto general = internal::best_pattern(e))
  {
    out.strategy = Polygon_quadrangulation::GENERAL;
    const internal::Pattern_choice& pc = general->choice;
    out.pattern = std::to_string(pc.pattern->sides) + "_" + std::to_string(pc.pattern->id);
    out.pattern_loops = pc.loops;
    out.pattern_padding = pc.padding;
    out.pattern_rotation = pc.rotation;
    out.pattern_reflected = pc.reflected;
    out.pattern_split_quads = general->split_quads;
    c = std::move(general->connectivity);
    out.positions = std::move(general->positions);
  }
  else
  {
    out.strategy = Polygon_quadrangulation::RING_AND_GRID;
    c = internal::build_ring_and_grid(N);
    out.positions = internal::harmonic_positions(c, internal::polygon_boundary_positions(e));
  }

  out.irregular_vertices_by_valence = internal::irregular_by_valence(c, e);
  out.quads = std::move(c.quads);
  out.boundary.resize(N);
  out.side_of_boundary_vertex.resize(N);
  out.index_along_side.resize(N);
  for(std::size_t i = 0; i < n; ++i)
  {
    out.corners.push_back(out.side_start[i]);
    for(int k = 0; k < e[i]; ++k)
    {
      const std::size_t v = out.side_start[i] + std::size_t(k);
      out.boundary[v] = v;
      out.side_of_boundary_vertex[v] = int(i);
      out.index_along_side[v] = k;
    }
  }

  out.seconds = timer.time();
  if(verbose)
    std::cerr << "[quadrangulate-polygon] " << n << " sides, " << N << " boundary edges: "
              << out.report()["strategy"].string() << (out.pattern.empty() ? "" : " " + out.pattern) << ", "
              << out.quads.size() << " quads, " << out.number_of_irregular_vertices()
              << " irregular vertices\n";
  return out;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_QUADRANGULATE_POLYGON_H
