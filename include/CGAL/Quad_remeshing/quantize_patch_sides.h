// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_QUAD_REMESHING_QUANTIZE_PATCH_SIDES_H
#define CGAL_QUAD_REMESHING_QUANTIZE_PATCH_SIDES_H

#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/GLPK_mixed_integer_program_traits_with_limits.h>
#include <CGAL/Quad_remeshing/internal/quantization/problem_helpers.h>
#include <CGAL/Quad_remeshing/internal/quantization/fallback.h>
#include <CGAL/Quad_remeshing/internal/quantization/mip_model.h>
#include <CGAL/Quad_remeshing/internal/quantization/local_search.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <deque>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(isometry_weight_t, isometry_weight, isometry_weight)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(under_subdivision_weight_t, under_subdivision_weight, under_subdivision_weight)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(quad_regularity_weight_t, quad_regularity_weight, quad_regularity_weight)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(polygon_regularity_weight_t, polygon_regularity_weight, polygon_regularity_weight)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(alignment_weight_t, alignment_weight, alignment_weight)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(maximum_cluster_size_t, maximum_cluster_size, maximum_cluster_size)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(relative_mip_gap_t, relative_mip_gap, relative_mip_gap)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(maximum_number_of_nodes_t, maximum_number_of_nodes, maximum_number_of_nodes)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(use_mip_solver_t, use_mip_solver, use_mip_solver)

namespace CGAL {
namespace Quad_remeshing {

/// \ingroup PkgQuadRemeshingRef
/// The figures of one `quantize_patch_sides()` run.
struct Side_quantization_statistics
{
  std::size_t clusters = 0;            ///< number of clusters solved separately
  std::size_t variables = 0;           ///< program variables, summed over clusters
  std::size_t constraints = 0;         ///< program constraints, summed over clusters
  double isometry = 0;                 ///< sum over arcs of (s - target)^2, `under_subdivision_weight` times larger where s < target
  double quad_regularity = 0;          ///< sum over quads of |e0 - e2| + |e1 - e3|
  double polygon_regularity = 0;       ///< sum over 3/5/6-gons of the violations of Tarini's inequalities / n (+ hexagon parity)
  double alignment = 0;                ///< sum over the facing side pairs kept by the second solve of (|up - down'| + |down - up'|) / 2
  double objective = 0;                ///< weighted total of the four terms above
  std::size_t alignment_pairs = 0;     ///< facing sides of non-quad patches (see quantize_patch_sides())
  std::size_t aligned_pairs = 0;       ///< of those, the ones whose singularities are aligned in the result
  std::size_t dropped_pairs = 0;       ///< pairs left out of the second solve because the first could not align them
  std::vector<std::string> status;     ///< per cluster: optimal, feasible_at_limit, ..., or "fallback"
  std::size_t fallback_clusters = 0;   ///< clusters whose values come from the solver-free fallback
  std::size_t simple_patches = 0;      ///< patches admitting Tarini's simple (one-singularity) pattern
  std::size_t odd_perimeters = 0;      ///< patches with an odd perimeter (always 0 on return)
  double seconds = 0;                  ///< wall-clock time

  /// The figures as a `Report` record.
  Report report() const
  {
    Report r = Report::object();
    r["clusters"] = clusters;
    r["variables"] = variables;
    r["constraints"] = constraints;
    Report o = Report::object();
    o["isometry"] = isometry;
    o["quad_regularity"] = quad_regularity;
    o["polygon_regularity"] = polygon_regularity;
    o["alignment"] = alignment;
    o["total"] = objective;
    r["objective"] = o;
    Report st = Report::array();
    for(const auto& s : status) st.push_back(s);
    r["status"] = st;
    r["fallback_clusters"] = fallback_clusters;
    r["alignment_pairs"] = alignment_pairs;
    r["aligned_pairs"] = aligned_pairs;
    r["dropped_pairs"] = dropped_pairs;
    r["simple_patches"] = simple_patches;
    r["odd_perimeters"] = odd_perimeters;
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {
// Stands for "no solver available": only the fallback runs.
struct No_mip_traits {};
} // namespace internal

/// \ingroup PkgQuadRemeshingRef
/// The traits used by `quantize_patch_sides()` by default.
#if defined(CGAL_USE_GLPK) || defined(DOXYGEN_RUNNING)
typedef GLPK_mixed_integer_program_traits_with_limits<double> Default_mip_traits;
#else
typedef internal::No_mip_traits Default_mip_traits;
#endif

namespace internal {

// Calls T::release_thread_resources() where the traits have it (the GLPK model: its per-thread
// environment), at the end of a worker thread.
template <typename T>
auto release_thread_resources(int) -> decltype(T::release_thread_resources(), void()) { T::release_thread_resources(); }
template <typename T>
void release_thread_resources(long) {}

// Connected clusters of at most max_size patches: breadth-first growth in ascending patch order.
inline std::vector<std::vector<std::size_t> > make_clusters(const Quantization_view& v, std::size_t max_size)
{
  const std::size_t np = v.problem->patches.size();
  std::vector<long> cluster_of(np, -1);
  std::vector<std::vector<std::size_t> > clusters;
  for(std::size_t seed = 0; seed < np; ++seed) {
    if(cluster_of[seed] >= 0) continue;
    clusters.emplace_back();
    auto& c = clusters.back();
    std::deque<std::size_t> queue{seed};
    cluster_of[seed] = long(clusters.size() - 1);
    while(!queue.empty() && c.size() < max_size) {
      const std::size_t p = queue.front(); queue.pop_front();
      c.push_back(p);
      for(std::size_t a : v.patch_arcs[p])
        for(std::size_t q : v.arc_patches[a])
          if(cluster_of[q] < 0) { cluster_of[q] = cluster_of[seed]; queue.push_back(q); }
    }
    for(std::size_t q : queue) cluster_of[q] = -1; // not reached before the cap: later clusters
    std::sort(c.begin(), c.end());
  }
  return clusters;
}

// The terms of the objective at s; the alignment term sums over `pairs`, and aligned_pairs counts
// the aligned ones among `all_pairs`.
inline void evaluate(const Quantization_view& v, const std::vector<int>& s, const Quantization_weights& w,
                     Side_quantization_statistics& st, const std::vector<Alignment_pair>& pairs = {},
                     const std::vector<Alignment_pair>& all_pairs = {})
{
  const auto& pb = *v.problem;
  st.isometry = st.quad_regularity = st.polygon_regularity = st.alignment = 0;
  st.simple_patches = st.odd_perimeters = st.aligned_pairs = 0;
  for(const Alignment_pair& ap : pairs) st.alignment += 0.5 * alignment_violation(v, ap, s);
  for(const Alignment_pair& ap : all_pairs) if(alignment_violation(v, ap, s) == 0) ++st.aligned_pairs;
  for(std::size_t a = 0; a < pb.arcs.size(); ++a) {
    if(v.problem->arcs[a].fixed > 0 || v.arc_patches[a].empty()) continue;
    st.isometry += isometry_cost(s[a], pb.arcs[a].target, w);
  }
  for(std::size_t p = 0; p < pb.patches.size(); ++p) {
    if(perimeter(v, p, s) % 2 != 0) ++st.odd_perimeters;
    if(is_simple_patch(v, p, s)) ++st.simple_patches;
    if(pb.patches[p].size() == 4) st.quad_regularity += patch_violation(v, p, s);
    else st.polygon_regularity += patch_violation(v, p, s);
  }
  st.objective = w.isometry * st.isometry + w.regularity_quads * st.quad_regularity +
                 w.regularity_others * st.polygon_regularity + w.alignment * st.alignment;
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef

  \brief computes the number of quad edges of every arc of a patch layout (paper, Section 6.1).

  Solves, per cluster of patches, the mixed-integer program: one integer `s >= max(1, minimum)` per arc; every
  patch perimeter even and at least 4 (hard); minimise
  `w_iso * sum c (s - target)^2`, with `c = w_under` (`under_subdivision_weight`, 4 by default) where
  `s < target` and 1 otherwise (exact at integers through secant cuts, within a window of at least 3
  around the target)
  `+ w_quad * sum_quads (|e0 - e2| + |e1 - e3|)`
  `+ w_poly * sum_{3,5,6-gons} (1/n) sum_i max(0, 2 - L_i(e))` where `L_i(e) >= 2` are Tarini's
  inequalities (every separatrix at least one edge; paper Eq. 1), plus, for hexagons, a penalty when
  `e0 + e2 + e4` is odd. Arcs between clusters are first fixed to the one of the two even numbers
  around their target (at least 2 and their minimum) with the lower isometry term. A cluster whose solve ends with no trusted solution (node or time limit before any incumbent,
  solver error, no GLPK) takes its values from a solver-free fallback. The fallback works on *strips*:
  arcs that are opposite single-arc sides of 4-sided patches, chained; every strip takes the rounded
  mean of its targets (so the quads it crosses are regular), then odd patches are paired along
  shortest paths of the graph whose edges are the strips (a strip changed by `+-1` flips the parity of
  its two ends only), and, where no such path exists, along shortest paths of the patch adjacency
  graph (or to the boundary) by `+-1` on single arcs. The fallback values, improved by a local search,
  are the first incumbent of every solve; the merged result is improved again by the local search
  over the whole layout (arcs between clusters included). Its moves change by the same `+-1` or `+-2`
  the arcs of a strip of 4-sided patches (through opposite sides) and keep every parity; its cycle
  moves change one strip by `+-1` and the strips of a shortest path between its two ends by `+-1`
  each (this is what regularises the quads at T-junctions); a move is taken when it lowers the
  objective. Everything is deterministic. With this first incumbent a small node limit suffices: on
  the 22 development meshes the default of 100 nodes gives a lower total objective than 500 nodes did
  from the plain rounding, in a third of the time. The result always has every free arc at least at
  its minimum (fixed values are kept as given) and every perimeter even and `>= 4`.

  `+ w_align * sum_pairs (|up_p - down_q| + |down_p - up_q|) / 2`, the singularity alignment of the
  paper: a pair is a side of a 3, 5 or 6-sided patch `p` and one of another such patch `q` that face
  each other across one arc, directly or through a chain of 4-sided patches entered and left through
  opposite sides (every side on the way one arc: T-junctions, boundaries and slits stop the chain);
  `up` and `down` are twice the two sub-sides into which the separatrix of Tarini's one-singularity
  pattern cuts the side (`2 s_{i-1}` and `2 s_{i+1}`), so a zero term puts both singular vertices on
  one line of quad edges. Pairs are modelled when both patches are in one cluster. After a cluster's
  first solve, the pairs it left unaligned are dropped and the cluster is solved a second time,
  starting from the first solution, with a quarter of the node limit (and, with a time limit, in the
  time the first solve left); the final
  local search and the reported `alignment` term use the pairs kept.

  @tparam MIPTraits a model of `MixedIntegerProgramTraitsWithLimits`, default-constructible;
          `GLPK_mixed_integer_program_traits_with_limits<double>` when `CGAL_USE_GLPK` is defined,
          otherwise `internal::No_mip_traits` (fallback only).
  @tparam NamedParameters a sequence of named parameters

  @param problem the arcs and patches
  @param arc_edge_counts output: resized to `problem.arcs.size()`, the edge count of every arc
  @param np optional named parameters among the ones listed below

  @pre every patch has 3 to 6 non-empty sides; arc ids are valid; every arc bounds at most two
       patch sides; targets are in `(0, 1e6]`, minimums in `[1, 1e6]`. Violations throw `std::invalid_argument`, as do fixed
       arc values that make even perimeters impossible.

  \cgalNamedParamsBegin
    \cgalParamNBegin{isometry_weight}
      \cgalParamDescription{weight of the squared deviation from the targets}
      \cgalParamType{`double`}
      \cgalParamDefault{1}
    \cgalParamNEnd
    \cgalParamNBegin{under_subdivision_weight}
      \cgalParamDescription{factor (at least 1) of the isometry term of an arc given fewer edges than its target:
                            too few edges stretch the quads across the arc and cut corners off the surface,
                            too many only make the quads smaller. At 1 (the paper's symmetric term), the
                            quantization of fertility put one quad where the targets asked for 3 to 4 on a few
                            arcs (a strip of quads 5 times longer than wide, 2.6% of the diagonal away from the
                            input); 4 brought it back to 1.3%, with about 7% more quads over the 22
                            development meshes}
      \cgalParamType{`double`}
      \cgalParamDefault{4}
    \cgalParamNEnd
    \cgalParamNBegin{quad_regularity_weight}
      \cgalParamDescription{weight of the opposite-side differences of 4-sided patches}
      \cgalParamType{`double`}
      \cgalParamDefault{99}
    \cgalParamNEnd
    \cgalParamNBegin{polygon_regularity_weight}
      \cgalParamDescription{weight of the violations of Tarini's conditions on 3, 5 and 6-sided patches}
      \cgalParamType{`double`}
      \cgalParamDefault{91}
    \cgalParamNEnd
    \cgalParamNBegin{alignment_weight}
      \cgalParamDescription{weight of the singularity alignment terms (0: not modelled, one solve per cluster)}
      \cgalParamType{`double`}
      \cgalParamDefault{9}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_cluster_size}
      \cgalParamDescription{maximal number of patches solved in one program}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{300}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_number_of_nodes}
      \cgalParamDescription{branch-and-bound nodes after which each cluster's solve stops with its best
                            solution (0: none); unlike a time limit, it gives the same result on any machine
                            and under any load}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{100}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_running_time}
      \cgalParamDescription{time limit in seconds of the stage (<= 0: none): each cluster's solve gets, when
                            it starts, an even share of the time left (times the number of threads); a
                            cluster that starts with no time left keeps the fallback values (status
                            `fallback (time limit)`); a result a limit stops depends on the speed and
                            load of the machine}
      \cgalParamType{`double`}
      \cgalParamDefault{0}
    \cgalParamNEnd
    \cgalParamNBegin{relative_mip_gap}
      \cgalParamDescription{relative gap at which a solve stops as optimal}
      \cgalParamType{`double`}
      \cgalParamDefault{1e-4}
    \cgalParamNEnd
    \cgalParamNBegin{use_mip_solver}
      \cgalParamDescription{if `false`, only the solver-free fallback runs}
      \cgalParamType{`bool`}
      \cgalParamDefault{`true` if `CGAL_USE_GLPK` is defined or `MIPTraits` is given}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_threads}
      \cgalParamDescription{clusters solved in parallel; the result does not depend on it}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{1}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{prints progress to `std::cerr` with the prefix `[quantization]`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the statistics of the run.
*/
template <typename MIPTraits = Default_mip_traits, typename NamedParameters = parameters::Default_named_parameters>
Side_quantization_statistics
quantize_patch_sides(const Side_quantization_problem& problem,
                     std::vector<int>& arc_edge_counts,
                     const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto t0 = std::chrono::steady_clock::now();

  internal::Quantization_weights w;
  w.isometry = choose_parameter(get_parameter(np, internal_np::isometry_weight), 1.);
  w.under_subdivision = choose_parameter(get_parameter(np, internal_np::under_subdivision_weight), 4.);
  w.regularity_quads = choose_parameter(get_parameter(np, internal_np::quad_regularity_weight), 99.);
  w.regularity_others = choose_parameter(get_parameter(np, internal_np::polygon_regularity_weight), 91.);
  w.alignment = choose_parameter(get_parameter(np, internal_np::alignment_weight), 9.);
  const std::size_t max_cluster = choose_parameter(get_parameter(np, internal_np::maximum_cluster_size), std::size_t(300));
  // a node limit by default, not a time limit: the same input gives the same output whatever the load
  const double time_limit = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  const std::size_t node_limit =
    choose_parameter(get_parameter(np, internal_np::maximum_number_of_nodes), std::size_t(100));
  const double gap = choose_parameter(get_parameter(np, internal_np::relative_mip_gap), 1e-4);
  // The second solve (alignment terms the first left unmet dropped) starts from the first solution and
  // only has to undo what those terms pulled: a quarter of the node budget.
  const std::size_t second_node_limit = node_limit == 0 ? 0 : (std::max)(std::size_t(1), node_limit / 4);
  const bool use_solver = choose_parameter(get_parameter(np, internal_np::use_mip_solver), true);
  const unsigned threads = (std::max)(1u, static_cast<unsigned>(
                             choose_parameter(get_parameter(np, internal_np::number_of_threads), 1u)));
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  if(!(w.under_subdivision >= 1)) throw std::invalid_argument("quantize_patch_sides: under_subdivision_weight must be >= 1");
  if(!(w.isometry >= 0) || !(w.regularity_quads >= 0) || !(w.regularity_others >= 0) || !(w.alignment >= 0))
    throw std::invalid_argument("quantize_patch_sides: weights must be >= 0");
  if(max_cluster == 0) throw std::invalid_argument("quantize_patch_sides: maximum_cluster_size must be > 0");

  internal::Quantization_view v = internal::make_view(problem);
  Side_quantization_statistics st;
  std::vector<int>& s = arc_edge_counts;
  s.assign(problem.arcs.size(), 1);

  const auto clusters = internal::make_clusters(v, max_cluster);
  st.clusters = clusters.size();
  std::vector<std::size_t> cluster_of(problem.patches.size());
  for(std::size_t c = 0; c < clusters.size(); ++c) for(std::size_t p : clusters[c]) cluster_of[p] = c;
  if(clusters.size() > 1) {
    // Even values on arcs between clusters keep each cluster's parity problem independent and solvable:
    // of the two even values around the target (at least 2 and the arc's minimum), the one of lower
    // isometry cost (too few edges cost more, so a target of 2.9 takes 4, not 2).
    for(std::size_t a = 0; a < problem.arcs.size(); ++a) {
      const auto& inc = v.arc_patches[a];
      if(v.fixed[a] == 0 && inc.size() == 2 && cluster_of[inc[0]] != cluster_of[inc[1]]) {
        const double t = problem.arcs[a].target;
        const int low = (std::max)((problem.arcs[a].minimum + 1) / 2 * 2,
                                   (std::max)(2, 2 * static_cast<int>(std::floor(t / 2.))));
        v.fixed[a] = internal::isometry_cost(low + 2, t, w) < internal::isometry_cost(low, t, w) ? low + 2 : low;
      }
    }
  }
  // Facing sides of non-quad patches; a pair is modelled in the program of a cluster holding both.
  const std::vector<internal::Alignment_pair> all_pairs =
    w.alignment > 0 ? internal::alignment_pairs(v) : std::vector<internal::Alignment_pair>();
  std::vector<char> kept(all_pairs.size(), 1);
  std::vector<std::vector<std::size_t> > cluster_pairs(clusters.size());
  std::vector<std::size_t> every_pair(all_pairs.size());
  for(std::size_t k = 0; k < all_pairs.size(); ++k) {
    every_pair[k] = k;
    if(cluster_of[all_pairs[k].p] == cluster_of[all_pairs[k].q]) cluster_pairs[cluster_of[all_pairs[k].p]].push_back(k);
  }
  // the pairs among `ids` that are still kept
  auto kept_pairs = [&](const std::vector<std::size_t>& ids) {
    std::vector<internal::Alignment_pair> out;
    for(std::size_t k : ids) if(kept[k]) out.push_back(all_pairs[k]);
    return out;
  };

  // The fallback gives every arc a value first; a successful solve overwrites its cluster's free arcs.
  internal::fallback_assignment(v, s);
  // Improved by strip moves (clusters kept apart): a better first incumbent of every solve.
  internal::improve_locally(v, s, w, all_pairs);

  std::vector<internal::Cluster_result> results(clusters.size());
  std::vector<char> no_time_left(clusters.size(), 0);
  // the time limit of cluster c's solves, when it starts: 0 without a stage limit, < 0 when none is left
  auto solve_limit = [&](std::size_t c) -> double {
    if(!(time_limit > 0)) return 0.;
    const double left = time_limit - std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if(left <= 0) return -1.;
    return (std::min)(left, left * double(threads) / double(clusters.size() - c));
  };
  if constexpr(!std::is_same<MIPTraits, internal::No_mip_traits>::value) if(use_solver) {
    std::vector<std::vector<int> > local(clusters.size());
    std::atomic<std::size_t> next(0);
    std::exception_ptr failure;
    auto work = [&]() {
      for(std::size_t c; (c = next++) < clusters.size();) {
        try {
          const auto start = std::chrono::steady_clock::now();
          const double limit = solve_limit(c);
          if(limit < 0) { no_time_left[c] = 1; continue; }
          MIPTraits mip;
          local[c] = s;
          results[c] = internal::solve_cluster(v, clusters[c], kept_pairs(cluster_pairs[c]), w, limit,
                                               node_limit, gap, local[c], mip);
          // Second solve without the alignment terms the first could not meet (they only pull the
          // other terms away), started from the first solution.
          if(!results[c].solved) continue;
          bool dropped = false;
          for(std::size_t k : cluster_pairs[c])
            if(internal::alignment_violation(v, all_pairs[k], local[c]) != 0) { kept[k] = 0; dropped = true; }
          const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          if(!dropped || (limit > 0 && spent >= limit)) continue;
          // a failure of the second solve keeps the first solve's result
          try {
            MIPTraits mip2;
            std::vector<int> second = local[c];
            const internal::Cluster_result r2 =
              internal::solve_cluster(v, clusters[c], kept_pairs(cluster_pairs[c]), w,
                                      limit > 0 ? limit - spent : 0., second_node_limit, gap, second, mip2);
            if(r2.solved) { local[c] = second; results[c].status = r2.status; }
          } catch(...) {}
        } catch(...) { results[c] = internal::Cluster_result(); }
      }
    };
    if(threads == 1 || clusters.size() == 1) work();
    else {
      std::vector<std::thread> pool;
      for(unsigned i = 0; i < (std::min<std::size_t>)(threads, clusters.size()); ++i)
        pool.emplace_back([&]() { work(); internal::release_thread_resources<MIPTraits>(0); });
      for(auto& t : pool) t.join();
    }
    // Clusters share no free arc, so the merge order does not matter.
    for(std::size_t c = 0; c < clusters.size(); ++c) {
      if(!results[c].solved) continue;
      for(std::size_t p : clusters[c])
        for(std::size_t a : v.patch_arcs[p]) if(v.fixed[a] == 0) s[a] = local[c][a];
    }
  }
  {
    // Strip moves over the whole layout: they also cross the arcs fixed between clusters.
    internal::Quantization_view whole = v;
    for(std::size_t a = 0; a < problem.arcs.size(); ++a) whole.fixed[a] = problem.arcs[a].fixed;
    internal::improve_locally(whole, s, w, kept_pairs(every_pair));
  }
  for(std::size_t c = 0; c < clusters.size(); ++c) {
    st.variables += results[c].variables;
    st.constraints += results[c].constraints;
    if(results[c].solved) st.status.push_back(to_string(Mip_status(results[c].status)));
    else {
      ++st.fallback_clusters;
      st.status.push_back(no_time_left[c] ? std::string("fallback (time limit)")
                          : results[c].status < 0 ? std::string("fallback")
                                                : std::string("fallback (") + to_string(Mip_status(results[c].status)) + ")");
    }
  }
  internal::evaluate(v, s, w, st, kept_pairs(every_pair), all_pairs);
  st.alignment_pairs = all_pairs.size();
  st.dropped_pairs = std::size_t(std::count(kept.begin(), kept.end(), char(0)));
  if(st.odd_perimeters != 0) throw std::logic_error("quantize_patch_sides: odd perimeter left (bug)");
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if(verbose)
    std::cerr << "[quantization] " << st.clusters << " clusters, " << st.variables << " variables, "
              << st.fallback_clusters << " fallback, objective " << st.objective << ", "
              << st.seconds << " s\n";
  return st;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_QUANTIZE_PATCH_SIDES_H
