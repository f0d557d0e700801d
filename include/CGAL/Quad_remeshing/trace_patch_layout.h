// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Rounds of path insertion (paper sections 5.2 and 5.4) on a Patch_layout.

#ifndef CGAL_QUAD_REMESHING_TRACE_PATCH_LAYOUT_H
#define CGAL_QUAD_REMESHING_TRACE_PATCH_LAYOUT_H

#include <CGAL/Quad_remeshing/Patch_layout.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <deque>
#include <iostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `trace_patch_layout()`: the layout's figures and, per round, the candidates traced, the
  paths kept and the time.
*/
struct Trace_patch_layout_statistics
{
  struct Round
  {
    std::string name;
    std::size_t candidates = 0;
    std::size_t paths = 0;
    double seconds = 0.;
  };
  Patch_layout_statistics layout; ///< figures of the final layout
  std::vector<Round> rounds;      ///< in the order they ran
  std::size_t removed_paths = 0;  ///< paths removed by the clean-up
  double seconds = 0.;            ///< total time

  /// the figures as a report record
  Report report() const
  {
    Report r = layout.report();
    Report a = Report::array();
    for(const Round& x : rounds) {
      Report o = Report::object();
      o["name"] = x.name;
      o["candidates"] = x.candidates;
      o["paths"] = x.paths;
      o["seconds"] = x.seconds;
      a.push_back(o);
    }
    r["rounds"] = a;
    r["removed_paths"] = removed_paths;
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {

template <typename Layout>
class Layout_tracer
{
public:
  typedef typename Layout::Path Path;
  typedef typename Layout::Node Node;
  typedef typename Layout::vertex_descriptor vertex_descriptor;

  explicit Layout_tracer(Layout& layout) : layout_(layout) {}

  std::size_t invalid_patches() const
  {
    const auto s = layout_.statistics();
    return s.patches - s.valid_patches;
  }

  // The acceptance rule, in one place: a candidate that crosses no path of the layout tangentially is
  // kept when it directly helps (fewer patches failing a validity condition, or more meeting the quality
  // conditions without losing a valid one) or when it splits a patch that still fails a condition.
  bool accept(const Path& candidate, std::size_t target_patch)
  {
    for(std::size_t id : layout_.path_ids())
      if(layout_.cross_tangentially(layout_.path(id), candidate)) return false;
    const auto before = layout_.statistics();
    const bool target_fails = layout_.quality(target_patch) != Layout::SATISFIED;
    const std::size_t id = layout_.add_path(candidate);
    const auto after = layout_.statistics();
    const bool helps = (after.patches - after.valid_patches < before.patches - before.valid_patches) ||
                       (after.valid_patches >= before.valid_patches && after.quality_patches > before.quality_patches);
    const bool splits = target_fails && after.patches > before.patches && after.valid_patches >= before.valid_patches;
    if(helps || splits) { inserted_.push_back(id); return true; }
    layout_.remove_path(id);
    return false;
  }

  // nodes at every vertex on a path or on the border, except `exclude` (a null vertex excludes none)
  std::vector<Node> boundary_ends(vertex_descriptor exclude) const
  {
    std::vector<Node> ends;
    for(vertex_descriptor v : vertices(layout_.mesh())) {
      if(v == exclude) continue;
      bool cut = false;
      for(auto h : halfedges_around_target(v, layout_.mesh())) cut = cut || layout_.is_cut(edge(h, layout_.mesh()));
      if(cut) for(int k = 0; k < 4; ++k) ends.push_back(Node{v, k});
    }
    return ends;
  }

  // Candidates from the boundary vertices of patch `p` whose turn is in `turns`, in every direction that
  // enters the patch, to the first boundary node reached.
  std::size_t round_from_boundary(const std::vector<typename Layout::Turn>& turns, bool only_invalid,
                                  std::size_t max_starts_per_patch, Trace_patch_layout_statistics::Round& round)
  {
    std::size_t kept = 0;
    std::vector<Node> ends = boundary_ends(typename Layout::vertex_descriptor());
    for(std::size_t p = 0; p < layout_.patches().size(); ++p) {
      const auto condition = only_invalid ? layout_.validity(p) : layout_.quality(p);
      if(condition == Layout::SATISFIED) continue;
      std::vector<vertex_descriptor> starts;
      const auto& P = layout_.patches()[p];
      for(std::size_t l = 0; l < P.loops.size(); ++l)
        for(std::size_t i = 0; i < P.loops[l].size(); ++i)
          if(std::find(turns.begin(), turns.end(), P.turns[l][i]) != turns.end())
            starts.push_back(target(P.loops[l][i], layout_.mesh()));
      // spread the starts along the boundary when there are many
      if(starts.size() > max_starts_per_patch) {
        std::vector<vertex_descriptor> spread;
        for(std::size_t i = 0; i < max_starts_per_patch; ++i) spread.push_back(starts[i * starts.size() / max_starts_per_patch]);
        starts.swap(spread);
      }
      // patch ids change when a path is kept: the next patch is looked at in the next repetition
      bool accepted = false;
      for(vertex_descriptor v : starts) {
        for(int k = 0; k < 4; ++k) {
          auto c = layout_.trace(Node{v, k}, ends);
          ++round.candidates;
          if(!c || c->vertices.size() < 2 || c->vertices.front() == c->vertices.back()) continue;
          // the candidate must start into patch p
          const auto e = edge(c->vertices[0], c->vertices[1], layout_.mesh()).first;
          const auto h = halfedge(e, layout_.mesh());
          if(is_border(h, layout_.mesh()) || layout_.patch_id(face(h, layout_.mesh())) != p) continue;
          if(accept(*c, p)) { ++kept; accepted = true; break; }
        }
        if(accepted) break;
      }
      if(accepted) ends = boundary_ends(typename Layout::vertex_descriptor());
    }
    round.paths += kept;
    return kept;
  }

  // Removes inserted paths in reverse insertion order when no validity or quality count drops.
  std::size_t clean_up()
  {
    std::size_t removed = 0;
    for(auto it = inserted_.rbegin(); it != inserted_.rend(); ++it) {
      const auto before = layout_.statistics();
      const Path p = layout_.path(*it);
      layout_.remove_path(*it);
      const auto after = layout_.statistics();
      if(after.valid_patches == after.patches && after.quality_patches >= before.quality_patches &&
         before.valid_patches == before.patches)
        ++removed;
      else
        layout_.add_path(p);
    }
    return removed;
  }

private:
  Layout& layout_;
  std::vector<std::size_t> inserted_;
};

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Builds the patch layout: the feature edges become the first paths, then rounds of traced paths are
  inserted (paper section 5.2): convexity enforcement from left turns and U-turns, repeated while it
  inserts paths; then, for patches still failing a condition, paths from their straight boundary vertices
  to the first boundary node reached (T-junctions), repeated while it inserts paths (the recursion on
  invalid patches, bounded by `number_of_iterations`); finally a clean-up removes inserted paths in
  reverse insertion order when that breaks no condition that holds.

  Not done: the looped paths from a blue-noise sample of interior vertices and the farthest-first
  ordering of candidates; candidates are taken per failing patch in boundary order. There is no
  last-resort split: a patch no traced path can repair stays invalid and is counted in the figures.

  \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` with triangle faces
  \tparam EdgeIsFeatureMap a readable property map, key `edge_descriptor`, value `bool`
  \tparam GeomTraits the traits of the layout
  \tparam NamedParameters a sequence of named parameters

  \param tmesh the mesh the layout was built on
  \param edge_is_feature_map the feature edges, added as paths
  \param layout a layout built on `tmesh` with the cross field and its singularities, with no path yet
  \param np optional named parameters among the ones listed below

  \pre `&layout.mesh() == &tmesh`

  \cgalNamedParamsBegin
    \cgalParamNBegin{number_of_iterations}
      \cgalParamDescription{maximal number of repetitions of each round}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`8`}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether to print the rounds to `std::cerr`, prefixed by `[layout]`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the figures of the layout and of each round
*/
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename GeomTraits,
          typename NamedParameters = parameters::Default_named_parameters>
Trace_patch_layout_statistics trace_patch_layout(const TriangleMesh& tmesh, EdgeIsFeatureMap edge_is_feature_map,
                                                 Patch_layout<TriangleMesh, GeomTraits>& layout,
                                                 const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef Patch_layout<TriangleMesh, GeomTraits> Layout;
  if(&layout.mesh() != &tmesh) throw std::invalid_argument("trace_patch_layout: the layout is not built on this mesh");
  const unsigned iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 8u);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);

  Trace_patch_layout_statistics stats;
  CGAL::Real_timer total;
  total.start();
  internal::Layout_tracer<Layout> tracer(layout);

  auto run = [&](const std::string& name, auto&& body) {
    CGAL::Real_timer t;
    t.start();
    Trace_patch_layout_statistics::Round r;
    r.name = name;
    body(r);
    r.seconds = t.time();
    if(verbose)
      std::cerr << "[layout] " << name << ": " << r.candidates << " candidates, " << r.paths << " paths, "
                << layout.statistics().valid_patches << "/" << layout.patches().size() << " valid patches, "
                << r.seconds << " s\n";
    stats.rounds.push_back(r);
  };

  run("features", [&](Trace_patch_layout_statistics::Round& r) { r.paths = layout.add_feature_paths(edge_is_feature_map); });
  run("convexity", [&](Trace_patch_layout_statistics::Round& r) {
    for(unsigned i = 0; i < iterations; ++i)
      if(tracer.round_from_boundary({Layout::LEFT_TURN, Layout::U_TURN}, true, 64, r) == 0) break;
  });
  run("split_invalid", [&](Trace_patch_layout_statistics::Round& r) {
    for(unsigned i = 0; i < iterations && tracer.invalid_patches() > 0; ++i)
      if(tracer.round_from_boundary({Layout::STRAIGHT, Layout::LEFT_TURN, Layout::U_TURN}, true, 16, r) == 0) break;
  });
  run("quality", [&](Trace_patch_layout_statistics::Round& r) {
    for(unsigned i = 0; i < iterations; ++i)
      if(tracer.round_from_boundary({Layout::STRAIGHT}, false, 8, r) == 0) break;
  });
  stats.removed_paths = tracer.clean_up();
  stats.layout = layout.statistics();
  stats.seconds = total.time();
  if(verbose)
    std::cerr << "[layout] " << stats.layout.valid_patches << "/" << stats.layout.patches << " valid, "
              << stats.layout.quality_patches << " quality, " << stats.layout.paths << " paths, "
              << stats.removed_paths << " removed by clean-up, " << stats.seconds << " s\n";
  return stats;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_TRACE_PATCH_LAYOUT_H
