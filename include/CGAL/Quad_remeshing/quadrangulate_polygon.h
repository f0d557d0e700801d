// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quadrangulation of an n-sided polygon with prescribed edge counts per side (paper, section 6.2).

#ifndef CGAL_QUAD_REMESHING_QUADRANGULATE_POLYGON_H
#define CGAL_QUAD_REMESHING_QUADRANGULATE_POLYGON_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/quadrangulate_polygon/constructions.h>

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
    SIMPLE,  ///< Tarini's single-singularity patch (regular grid for 4 sides)
    GENERAL  ///< the general construction (boundary ring around a regular grid)
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
    r["strategy"] = strategy == SIMPLE ? "simple" : "general";
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
  patch into n regular grids. Otherwise the general construction, complete for every valid input: a
  ring of quads along the whole boundary (each boundary vertex joined to one ring vertex) enclosing a
  regular `a x b` grid with `a + b = N/2` (N the boundary length, `a = floor(N/4)`), its corners
  joined to ring vertices `0, a, a+b, 2a+b`. It creates no more than n + 4 irregular vertices
  (the corners, of valence 3, and the four grid corners, of valence 3). Takayama's minimal-irregularity
  patterns are not implemented.

  Positions: boundary on the regular n-gon, interior by a uniform-weight harmonic (Tutte) map,
  solved with Eigen's sparse Cholesky factorization. Deterministic.

  @tparam NamedParameters a sequence of named parameters

  @param side_edge_counts number of edges of each side, sides in counterclockwise order
  @param np an optional sequence of named parameters among the ones listed below

  @pre `2 <= side_edge_counts.size() <= 6`, every count `>= 1`, the sum even and `>= 4`
       (checked: `std::invalid_argument`)

  \cgalNamedParamsBegin
    \cgalParamNBegin{verbose}
      \cgalParamDescription{print the strategy and the counts to `std::cerr`, prefixed by `[quadrangulate-polygon]`}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the quadrangulation with its embedding, boundary indexing and irregular-vertex counts
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
  }
  else
  {
    out.strategy = Polygon_quadrangulation::GENERAL;
    c = internal::build_ring_and_grid(N);
  }

  out.positions = internal::harmonic_positions(c, internal::polygon_boundary_positions(e));
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

  // valence = number of distinct neighbours
  std::vector<std::vector<std::size_t>> nb(out.positions.size());
  for(const auto& q : out.quads)
    for(int k = 0; k < 4; ++k)
    {
      nb[q[k]].push_back(q[(k + 1) % 4]);
      nb[q[(k + 1) % 4]].push_back(q[k]);
    }
  for(std::size_t v = 0; v < nb.size(); ++v)
  {
    std::sort(nb[v].begin(), nb[v].end());
    const int valence = int(std::unique(nb[v].begin(), nb[v].end()) - nb[v].begin());
    int regular = 4;
    if(v < N) regular = (out.index_along_side[v] == 0) ? 2 : 3;
    if(valence != regular) ++out.irregular_vertices_by_valence[valence];
  }

  out.seconds = timer.time();
  if(verbose)
    std::cerr << "[quadrangulate-polygon] " << n << " sides, " << N << " boundary edges: "
              << (out.strategy == Polygon_quadrangulation::SIMPLE ? "simple" : "general") << ", "
              << out.quads.size() << " quads, " << out.number_of_irregular_vertices()
              << " irregular vertices\n";
  return out;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_QUADRANGULATE_POLYGON_H
