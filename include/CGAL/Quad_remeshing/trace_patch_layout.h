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
#include <chrono>

#include <functional>
#include <limits>
#include <queue>
#include <type_traits>
#include <utility>

#include <algorithm>
#include <deque>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

/// fraction of the vertices used as seeds of the looped-paths round (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(loop_sample_ratio_t, loop_sample_ratio, loop_sample_ratio)

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
  std::size_t added_corners = 0;  ///< corners added by the round `corners` (see `trace_patch_layout()`)
  double seconds = 0.;            ///< total time
  /// the round that reached `maximum_running_time` (the rounds after it did not run), or empty
  std::string stopped_in_round;

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
    r["added_corners"] = added_corners;
    r["stopped_early"] = !stopped_in_round.empty();
    if(!stopped_in_round.empty()) r["stopped_in_round"] = stopped_in_round;
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {

/*
  The rounds of paper section 5.2/5.4 over a Patch_layout. Every round traces its candidates on the current
  layout, then inserts them farthest-first (`insert_farthest_first()`), each through the acceptance rule
  (`accept()`); the patches a candidate touches are rebuilt locally (Patch_layout::preview_add_path()), so a
  candidate costs time in the size of those patches.
*/
template <typename Layout>
class Layout_tracer
{
public:
  typedef typename Layout::Path Path;
  typedef typename Layout::Node Node;
  typedef typename Layout::Patch Patch;
  typedef typename Layout::Patch_change Patch_change;
  typedef typename Layout::Trace_job Trace_job;
  typedef typename Layout::vertex_descriptor vertex_descriptor;
  typedef typename Layout::halfedge_descriptor halfedge_descriptor;
  typedef typename Layout::face_descriptor face_descriptor;
  typedef typename Layout::Turn Turn;
  typedef Trace_patch_layout_statistics::Round Round;

  struct Candidate
  {
    Path path;
    double score = 0.;
  };

  explicit Layout_tracer(Layout& layout) : layout_(layout), tm_(layout.mesh())
  {
    for(vertex_descriptor v : vertices(tm_)) verts_.push_back(v);
    std::sort(verts_.begin(), verts_.end(), [&](vertex_descriptor a, vertex_descriptor b) {
      return layout_.vertex_index(a) < layout_.vertex_index(b);
    });
  }

  std::size_t invalid_patches() const
  {
    std::size_t n = 0;
    for(std::size_t p = 0; p < layout_.number_of_patches(); ++p) n += layout_.validity(p) != Layout::SATISFIED;
    return n;
  }
  const std::vector<std::size_t>& inserted() const { return inserted_; }

  // The time limit: once it is reached, the candidate generation returns what it has traced and the
  // insertion tries no more candidates (the rounds then end; see trace_patch_layout()).
  void set_time_limit(double seconds)
  {
    limited_ = seconds > 0.;
    if(limited_)
      deadline_ = std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
  }
  bool out_of_time() const { return limited_ && std::chrono::steady_clock::now() >= deadline_; }
  // the candidate searches of a round run in up to this many threads (the same candidates for any number)
  void set_threads(unsigned threads) { threads_ = (std::max)(1u, threads); }

  // The acceptance rule, in one place (paper section 5.2). A candidate that crosses no path of the layout
  // tangentially is kept when
  //  - it directly helps: fewer of the patches it touches fail a validity condition, or more meet the
  //    quality conditions and none becomes invalid; or
  //  - it splits a patch that still fails a condition, without making a valid patch invalid.
  // invalid and quality patches among the old and the new patches of a change
  struct Change_counts
  {
    std::size_t invalid_before = 0, quality_before = 0, invalid_after = 0, quality_after = 0;
  };
  Change_counts count(const Patch_change& c) const
  {
    Change_counts n;
    for(std::size_t p : c.old_patches) {
      n.invalid_before += layout_.validity(p) != Layout::SATISFIED;
      n.quality_before += layout_.quality(p) == Layout::SATISFIED;
    }
    for(const Patch& P : c.new_patches) {
      n.invalid_after += layout_.validity(P) != Layout::SATISFIED;
      n.quality_after += layout_.quality(P) == Layout::SATISFIED;
    }
    return n;
  }

  bool accept(const Path& candidate)
  {
    if(candidate.vertices.size() < 2 || layout_.crosses_paths_tangentially(candidate)) return false;
    Patch_change c = layout_.preview_add_path(candidate);
    if(separating_singularities) return accept_separation(std::move(c), candidate);
    const Change_counts n = count(c);
    const std::size_t invalid_before = n.invalid_before, quality_before = n.quality_before;
    const std::size_t invalid_after = n.invalid_after, quality_after = n.quality_after;
    const bool some_fails = split_quality_failing ? quality_before < c.old_patches.size() : invalid_before > 0;
    // paths running within an edge of another one cut off slivers: unless every patch it makes is valid,
    // refuse a candidate that makes new U-turns or tiny patches
    if(invalid_after > 0) {
      if(u_turns(c.new_patches) > u_turns_of(c.old_patches)) return false;
      for(const Patch& P : c.new_patches) if(P.faces.size() < min_patch_faces) return false;
    }
    const std::size_t valid_before = c.old_patches.size() - invalid_before;
    const std::size_t valid_after = c.new_patches.size() - invalid_after;
    const bool breaks_validity = invalid_before == 0 && invalid_after > 0;
    const bool helps = invalid_after < invalid_before ||
                       (!breaks_validity && valid_after >= valid_before && quality_after > quality_before);
    const bool splits = !breaks_validity && some_fails && c.new_patches.size() > c.old_patches.size() &&
                        valid_after >= valid_before;
    if(!helps && !splits) return false;
    insert(candidate, std::move(c));
    return true;
  }

  // adds an accepted candidate to the layout and to the distances of the farthest-first order
  void insert(const Path& candidate, Patch_change c)
  {
    inserted_.push_back(layout_.add_path(candidate, std::move(c)));
    add_to_distances(inserted_.back());
  }

  // The rule of the `singularity_separation` round: a candidate inside one valid patch with several
  // singularities is kept when every patch it makes is valid, has fewer of them, and at least
  // `min_patch_faces` faces.
  bool accept_separation(Patch_change c, const Path& candidate)
  {
    if(c.old_patches.size() != 1 || c.new_patches.size() < 2) return false;
    const std::size_t before = layout_.patch(c.old_patches[0]).singularities.size();
    for(const Patch& P : c.new_patches)
      if(layout_.validity(P) != Layout::SATISFIED || P.singularities.size() >= before || P.faces.size() < min_patch_faces)
        return false;
    insert(candidate, std::move(c));
    return true;
  }

  static constexpr std::size_t min_patch_faces = 4;
  // whether accept() applies the rule of the singularity separation instead (see accept_separation())
  bool separating_singularities = false;
  // whether a split of a valid patch failing a quality condition is accepted for that reason alone
  bool split_quality_failing = true;
  static std::size_t u_turns(const Patch& P)
  {
    std::size_t n = 0;
    for(const auto& T : P.turns) n += std::size_t(std::count(T.begin(), T.end(), Layout::U_TURN));
    return n;
  }
  std::size_t u_turns(const std::vector<Patch>& ps) const
  {
    std::size_t n = 0;
    for(const Patch& P : ps) n += u_turns(P);
    return n;
  }
  std::size_t u_turns_of(const std::vector<std::size_t>& ids) const
  {
    std::size_t n = 0;
    for(std::size_t p : ids) n += u_turns(layout_.patch(p));
    return n;
  }

  // ---- distances to the paths, for the farthest-first order (paper's "Candidate Sorting")

  // the length of the edge between the vertices of indices `a` and `b`
  double distance(std::size_t a, std::size_t b) const
  {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(layout_.point(verts_[a]), layout_.point(verts_[b]))));
  }

  // graph distance (along mesh edges) of every vertex to the nearest path or border vertex
  void reset_distances()
  {
    dist_.assign(verts_.size(), std::numeric_limits<double>::infinity());
    std::vector<std::size_t> seeds;
    for(vertex_descriptor v : verts_) if(layout_.is_on_cut(v)) seeds.push_back(layout_.vertex_index(v));
    relax_distances(seeds);
  }
  void add_to_distances(std::size_t path_id)
  {
    if(dist_.empty()) return;
    std::vector<std::size_t> seeds;
    for(vertex_descriptor v : layout_.path(path_id).vertices) seeds.push_back(layout_.vertex_index(v));
    relax_distances(seeds);
  }
  void relax_distances(const std::vector<std::size_t>& seeds)
  {
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
    for(std::size_t s : seeds) { dist_[s] = 0.; q.push({0., s}); }
    while(!q.empty()) {
      const Item it = q.top();
      q.pop();
      if(it.first > dist_[it.second]) continue;
      const vertex_descriptor v = verts_[it.second];
      for(halfedge_descriptor h : halfedges_around_target(v, tm_)) {
        const std::size_t w = layout_.vertex_index(source(h, tm_));
        const double d = it.first + distance(it.second, w);
        if(d < dist_[w]) { dist_[w] = d; q.push({d, w}); }
      }
    }
  }
  // our reading of "the largest distance from the closest edge in any picked path": the mean distance of
  // the candidate's vertices to the paths (a minimum would be zero for every path ending on a path)
  double score(const Path& p) const
  {
    double s = 0.;
    for(vertex_descriptor v : p.vertices) s += dist_[layout_.vertex_index(v)];
    return s / double(p.vertices.size());
  }

  // Inserts the candidates farthest-first: the candidate farthest from the paths is tried next; scores only
  // drop as paths are inserted, so a lazily re-scored max-heap gives the exact order.
  std::size_t insert_farthest_first(std::vector<Candidate>& candidates, Round& round)
  {
    round.candidates += candidates.size();
    if(dist_.empty()) reset_distances();
    typedef std::pair<double, std::size_t> Item; // (score, -index) ordering by score then first traced
    auto cmp = [](const Item& a, const Item& b) { return a.first < b.first || (a.first == b.first && a.second > b.second); };
    std::priority_queue<Item, std::vector<Item>, decltype(cmp)> heap(cmp);
    for(std::size_t i = 0; i < candidates.size(); ++i) heap.push({score(candidates[i].path), i});
    std::size_t kept = 0;
    while(!heap.empty() && !out_of_time()) {
      Item top = heap.top();
      heap.pop();
      const double now = score(candidates[top.second].path);
      if(now < top.first && !heap.empty() && now < heap.top().first) { heap.push({now, top.second}); continue; }
      if(accept(candidates[top.second].path)) ++kept;
    }
    round.paths += kept;
    return kept;
  }

  // ---- candidate generation

  // whether the first edge of `p` enters patch `patch` (any patch when `patch` is -1)
  bool enters(const Path& p, std::size_t patch) const
  {
    if(patch == std::size_t(-1)) return true;
    const auto e = edge(p.vertices[0], p.vertices[1], tm_).first;
    for(halfedge_descriptor h : {halfedge(e, tm_), opposite(halfedge(e, tm_), tm_)})
      if(!is_border(h, tm_) && layout_.patch_id(face(h, tm_)) == patch) return true;
    return false;
  }

  // nodes at the boundary vertices of the patches `ps` (all patches when `ps` is empty), every direction
  std::vector<Node> boundary_nodes(const std::vector<std::size_t>& ps) const
  {
    std::vector<Node> ends;
    if(ps.empty()) {
      for(vertex_descriptor v : verts_)
        if(layout_.is_on_cut(v)) for(int k = 0; k < 4; ++k) ends.push_back(Node{v, k});
      return ends;
    }
    for(std::size_t p : ps)
      for(const auto& loop : layout_.patch(p).loops)
        for(halfedge_descriptor h : loop) for(int k = 0; k < 4; ++k) ends.push_back(Node{target(h, tm_), k});
    return ends;
  }

  // a start: a boundary vertex of a patch and the patch its candidates must enter
  struct Start { vertex_descriptor v; std::size_t patch; };

  // boundary vertices with a turn in `turns` of the patches failing (validity when `only_invalid`, else
  // quality); `patch` restricts to one patch; at most `per_patch` per patch, spread along the loops
  std::vector<Start> boundary_starts(const std::vector<Turn>& turns, bool only_invalid, std::size_t per_patch,
                                     std::size_t patch = std::size_t(-1)) const
  {
    std::vector<Start> starts;
    for(std::size_t p = 0; p < layout_.number_of_patches(); ++p) {
      if(patch != std::size_t(-1) && p != patch) continue;
      const auto condition = only_invalid ? layout_.validity(p) : layout_.quality(p);
      if(condition == Layout::SATISFIED) continue;
      std::vector<vertex_descriptor> vs;
      for(std::size_t l = 0; l < layout_.patch(p).loops.size(); ++l)
        for(std::size_t i = 0; i < layout_.patch(p).loops[l].size(); ++i)
          if(std::find(turns.begin(), turns.end(), layout_.patch(p).turns[l][i]) != turns.end())
            vs.push_back(target(layout_.patch(p).loops[l][i], tm_));
      const std::size_t n = (std::min)(vs.size(), per_patch);
      for(std::size_t i = 0; i < n; ++i) starts.push_back(Start{vs[i * vs.size() / n], p});
    }
    return starts;
  }

  // traces from every direction of every start that enters its patch, to the first node of `ends`
  // (`opposite_ends`: to the nodes of the other starts' vertices instead, every direction)
  std::vector<Candidate> trace_from(const std::vector<Start>& starts, const std::vector<Node>& ends, bool opposite_ends)
  {
    // one list of the nodes of all starts, each search skipping its own start's vertex: O(S) memory, not O(S^2)
    std::vector<Node> start_nodes;
    if(opposite_ends)
      for(const Start& t : starts) for(int k = 0; k < 4; ++k) start_nodes.push_back(Node{t.v, k});
    std::vector<Trace_job> jobs;
    for(const Start& s : starts)
      for(int k = 0; k < 4; ++k)
        jobs.push_back(Trace_job{Node{s.v, k}, opposite_ends ? &start_nodes : &ends, false, opposite_ends});
    auto paths = layout_.trace_all(jobs, threads_, [this]() { return out_of_time(); });
    std::vector<Candidate> out;
    for(std::size_t j = 0; j < jobs.size(); ++j) {
      auto& c = paths[j];
      if(!c || c->vertices.size() < 2 || c->vertices.front() == c->vertices.back() || !enters(*c, starts[j / 4].patch))
        continue;
      out.push_back(Candidate{std::move(*c), 0.});
    }
    return out;
  }

  // Interior vertices spread evenly (farthest-point sampling on the distance to the paths, which gives a
  // blue-noise sample away from the paths), `count` of them, inside patch `patch` (any when -1).
  std::vector<vertex_descriptor> interior_samples(std::size_t count, std::size_t patch)
  {
    std::vector<vertex_descriptor> samples;
    if(dist_.empty()) reset_distances();
    std::vector<double> d = dist_;
    for(std::size_t n = 0; n < count && !out_of_time(); ++n) {
      std::size_t best = std::size_t(-1);
      for(std::size_t i = 0; i < verts_.size(); ++i) {
        const vertex_descriptor v = verts_[i];
        if(d[i] <= 0. || layout_.is_singular(v) || layout_.is_on_cut(v)) continue;
        if(patch != std::size_t(-1) && layout_.patch_id(face(halfedge(v, tm_), tm_)) != patch) continue;
        if(best == std::size_t(-1) || d[i] > d[best]) best = i;
      }
      if(best == std::size_t(-1)) break;
      samples.push_back(verts_[best]);
      std::swap(d, dist_);
      relax_distances({best}); // on the copy: the samples are not paths
      std::swap(d, dist_);
    }
    return samples;
  }

  // two loops per sample (the two field directions; the other two trace the same loops backwards), each
  // ending at its start or at the first node of `extra_ends` reached
  std::vector<Candidate> trace_loops(const std::vector<vertex_descriptor>& samples, const std::vector<Node>& extra_ends)
  {
    std::vector<Trace_job> jobs;
    for(vertex_descriptor v : samples)
      for(int k = 0; k < 2; ++k) jobs.push_back(Trace_job{Node{v, k}, &extra_ends, true});
    auto paths = layout_.trace_all(jobs, threads_, [this]() { return out_of_time(); });
    std::vector<Candidate> out;
    for(auto& c : paths)
      if(c && c->vertices.size() >= 3) out.push_back(Candidate{std::move(*c), 0.});
    return out;
  }

  // ---- last resort: cuts that are not traced along the field, for patches no traced path can make disks

  typedef decltype(std::declval<typename Layout::Point_3>() - std::declval<typename Layout::Point_3>()) Vector;

  // the straight path (internal::straight_path()) from the source of a search to vertex index `end`, along
  // the predecessors `pred`
  Path straight_path_to(std::size_t end, const std::vector<std::size_t>& pred) const
  {
    std::vector<vertex_descriptor> vs;
    for(std::size_t v = end; v != std::size_t(-1); v = pred[v]) vs.push_back(verts_[v]);
    std::reverse(vs.begin(), vs.end());
    return internal::straight_path(layout_, std::move(vs));
  }

  // Adds the edges between `region` faces and the other faces of patch `p` as one-edge paths.
  void cut_between(std::size_t p, const std::vector<char>& in_region, const std::vector<face_descriptor>& faces,
                   std::size_t& added)
  {
    auto findex = CGAL::get_initialized_face_index_map(tm_);
    std::vector<std::pair<vertex_descriptor, vertex_descriptor>> cut;
    for(face_descriptor f : faces)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm_), tm_)) {
        const halfedge_descriptor o = opposite(h, tm_);
        if(is_border(o, tm_) || layout_.is_cut(edge(h, tm_))) continue;
        if(layout_.patch_id(face(o, tm_)) != p) continue;
        if(in_region[get(findex, f)] && !in_region[get(findex, face(o, tm_))]) cut.push_back({source(h, tm_), target(h, tm_)});
      }
    for(const auto& e : cut) {
      Path q = internal::straight_path(layout_, {e.first, e.second});
      auto c = layout_.preview_add_path(q);
      layout_.add_path(std::move(q), std::move(c));
      ++added;
    }
  }

  // Joins two boundary loops of patch `p` by a path traced along the field (from up to
  // `max_starts_per_loop` vertices spread along each loop, every direction, each search ending at the first
  // boundary node of the patch it reaches), so that the disk it makes has field-aligned sides: a cut that
  // does not follow the field makes turns wherever it leaves it, and the disk is then not convex (teapot: an
  // annulus around the body, cut so, became a patch of 861 faces with left turns that no later cut
  // mended). Of the traces that reach another loop, the one leaving the fewest invalid patches is
  // inserted, then the lowest total `badness()`, then the shortest. Returns whether one was.
  bool traced_split(std::size_t p, const Patch& P, const std::vector<int>& loop_of)
  {
    constexpr std::size_t max_starts_per_loop = 16;
    std::vector<Start> starts;
    for(const auto& loop : P.loops) {
      const std::size_t n = (std::min)(loop.size(), max_starts_per_loop);
      for(std::size_t i = 0; i < n; ++i) starts.push_back(Start{target(loop[i * loop.size() / n], tm_), p});
    }
    std::vector<Candidate> candidates = trace_from(starts, boundary_nodes({p}), false);
    bool found = false;
    std::tuple<std::size_t, std::size_t, std::size_t> best;
    std::size_t best_index = 0;
    Patch_change best_change;
    for(std::size_t i = 0; i < candidates.size(); ++i) {
      const Path& c = candidates[i].path;
      const int start_loop = loop_of[layout_.vertex_index(c.vertices.front())];
      const int end_loop = loop_of[layout_.vertex_index(c.vertices.back())];
      if(end_loop < 0 || end_loop == start_loop) continue; // back on its own loop (or outside the patch)
      Patch_change change = layout_.preview_add_path(c);
      const auto counts = invalid_and_badness(change);
      const auto key = std::make_tuple(counts.first, counts.second, c.vertices.size());
      if(!found || key < best) {
        found = true;
        best = key;
        best_index = i;
        best_change = std::move(change);
      }
    }
    if(!found) return false;
    layout_.add_path(std::move(candidates[best_index].path), std::move(best_change));
    return true;
  }

  // Splits a patch that is not a disk: a patch with several boundary loops is cut along a path traced along
  // the field between two of its loops (traced_split()), else along the shortest edge path (Euclidean
  // lengths, inside the patch) from its first loop to another loop, which joins the two; any
  // other (closed, or with a handle) is cut along the border of the ball of half its faces grown (by face
  // adjacency) from its first face. Returns the number of one-edge paths added.
  std::size_t last_resort_split(std::size_t p)
  {
    const Patch P = layout_.patch(p);
    auto findex = CGAL::get_initialized_face_index_map(tm_);
    std::vector<char> in_region(num_faces(tm_), 0);
    std::size_t added = 0;
    if(P.loops.size() > 1) {
      std::vector<int> loop_of(verts_.size(), -1);
      for(std::size_t l = 0; l < P.loops.size(); ++l)
        for(halfedge_descriptor h : P.loops[l]) {
          int& x = loop_of[layout_.vertex_index(target(h, tm_))];
          if(x == -1 || x > int(l)) x = int(l);
        }
      if(traced_split(p, P, loop_of)) return 1;
      std::vector<char> in_patch(verts_.size(), 0);
      for(face_descriptor f : P.faces) for(vertex_descriptor v : vertices_around_face(halfedge(f, tm_), tm_)) in_patch[layout_.vertex_index(v)] = 1;
      std::vector<double> d(verts_.size(), std::numeric_limits<double>::infinity());
      std::vector<std::size_t> pred(verts_.size(), std::size_t(-1));
      typedef std::pair<double, std::size_t> Item;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
      for(std::size_t i = 0; i < verts_.size(); ++i) if(loop_of[i] == 0) { d[i] = 0.; q.push({0., i}); }
      std::size_t reached = std::size_t(-1);
      while(!q.empty()) {
        const Item it = q.top();
        q.pop();
        if(it.first > d[it.second]) continue;
        if(loop_of[it.second] > 0) { reached = it.second; break; }
        if(it.first > 0. && loop_of[it.second] == 0) continue; // back on the first loop: no way through
        for(halfedge_descriptor h : halfedges_around_target(verts_[it.second], tm_)) {
          const std::size_t w = layout_.vertex_index(source(h, tm_));
          if(!in_patch[w] || layout_.is_cut(edge(h, tm_))) continue;
          // the edge must be inside the patch
          const halfedge_descriptor o = opposite(h, tm_);
          const bool inside = (!is_border(h, tm_) && layout_.patch_id(face(h, tm_)) == p) ||
                              (!is_border(o, tm_) && layout_.patch_id(face(o, tm_)) == p);
          if(!inside) continue;
          const double nd = it.first + distance(it.second, w);
          if(nd < d[w]) { d[w] = nd; pred[w] = it.second; q.push({nd, w}); }
        }
      }
      if(reached != std::size_t(-1)) {
        Path q2 = straight_path_to(reached, pred);
        if(q2.vertices.size() >= 2) {
          auto c = layout_.preview_add_path(q2);
          layout_.add_path(std::move(q2), std::move(c));
          return 1;
        }
      }
    }
    // the ball of half the faces around the first face
    std::vector<face_descriptor> ball{P.faces.front()};
    in_region[get(findex, P.faces.front())] = 1;
    for(std::size_t i = 0; i < ball.size() && 2 * ball.size() < P.faces.size(); ++i)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(ball[i], tm_), tm_)) {
        const halfedge_descriptor o = opposite(h, tm_);
        if(is_border(o, tm_) || layout_.is_cut(edge(h, tm_))) continue;
        const face_descriptor g = face(o, tm_);
        if(in_region[get(findex, g)] || 2 * ball.size() >= P.faces.size()) continue;
        in_region[get(findex, g)] = 1;
        ball.push_back(g);
      }
    cut_between(p, in_region, P.faces, added);
    return added;
  }

  // How far a disk patch is from valid: its left turns, twice its U-turns, and the number of corners it
  // lacks or has too many (0 for a valid patch). A patch that is not a disk counts more than any disk.
  std::size_t badness(const Patch& P) const
  {
    if(layout_.validity(P) == Layout::NOT_A_DISK) return std::numeric_limits<std::size_t>::max() / 4;
    std::size_t b = 0;
    for(Turn t : P.turns[0]) b += t == Layout::LEFT_TURN ? 1 : (t == Layout::U_TURN ? 2 : 0);
    const std::size_t c = P.corners.size();
    return b + (c < 3 ? 3 - c : (c > 6 ? c - 6 : 0));
  }

  // the number of invalid patches among the patches change `c` makes, and the sum of their badness()
  std::pair<std::size_t, std::size_t> invalid_and_badness(const Patch_change& c) const
  {
    std::pair<std::size_t, std::size_t> r(0, 0);
    for(const Patch& N : c.new_patches) {
      r.first += layout_.validity(N) != Layout::SATISFIED;
      r.second += badness(N);
    }
    return r;
  }

  std::size_t cuts_made = 0; // paths inserted by last_resort_cut() and kept

  // Cuts a disk patch that is not convex or has fewer than 3 or more than 6 corners along a shortest edge
  // path through its interior (Euclidean lengths; interior vertices and edges of the patch only) between
  // two of its boundary vertices, which need not follow the field, or along a path traced along the field
  // from the same starts to the first boundary node it reaches. The path starts at a left turn or
  // U-turn of a non-convex patch, at any boundary vertex otherwise (at most `max_starts` of them, spread
  // along the loop), and ends at any other boundary vertex (at most `max_ends` per start). Of the
  // candidates, the one leaving the fewest invalid patches is taken, then the lowest total `badness()`,
  // then one making no patch of fewer than `min_patch_faces` faces, then the shortest, its edges weighted
  // by how far they leave the field. It is inserted only when it lowers the badness and leaves at most
  // one invalid patch, so the number of invalid patches never grows and repeated cuts end. Returns 1 if a
  // path was inserted.
  std::size_t last_resort_cut(std::size_t p)
  {
    const Patch P = layout_.patch(p);
    const auto condition = layout_.validity(P);
    if(condition != Layout::NOT_CONVEX && condition != Layout::BAD_VALENCE) return 0;
    constexpr std::size_t max_starts = 12, max_ends = 16;
    const std::vector<halfedge_descriptor>& loop = P.loops[0];
    std::vector<char> on_loop(verts_.size(), 0);
    for(halfedge_descriptor h : loop) on_loop[layout_.vertex_index(target(h, tm_))] = 1;
    std::vector<std::size_t> starts;
    for(std::size_t i = 0; i < loop.size(); ++i)
      if(condition == Layout::BAD_VALENCE || P.turns[0][i] == Layout::LEFT_TURN || P.turns[0][i] == Layout::U_TURN)
        starts.push_back(layout_.vertex_index(target(loop[i], tm_)));
    if(starts.size() > max_starts) {
      std::vector<std::size_t> spread;
      for(std::size_t i = 0; i < max_starts; ++i) spread.push_back(starts[i * starts.size() / max_starts]);
      starts.swap(spread);
    }
    // the candidates: shortest paths through the patch interior from the starts to boundary vertices (the
    // paths traced along the field were tried by the recursion)
    std::vector<Path> candidates;
    std::vector<double> d(verts_.size(), std::numeric_limits<double>::infinity());
    std::vector<std::size_t> pred(verts_.size(), std::size_t(-1)), touched;
    typedef std::pair<double, std::size_t> Item;
    for(std::size_t s : starts) {
      // Dijkstra from s through the patch interior; boundary vertices end a path
      std::vector<std::size_t> ends;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
      d[s] = 0.;
      touched.push_back(s);
      q.push({0., s});
      while(!q.empty()) {
        const Item it = q.top();
        q.pop();
        if(it.first > d[it.second]) continue;
        if(it.second != s && on_loop[it.second]) { ends.push_back(it.second); continue; }
        for(halfedge_descriptor h : halfedges_around_target(verts_[it.second], tm_)) {
          if(layout_.is_cut(edge(h, tm_)) || is_border(h, tm_) || layout_.patch_id(face(h, tm_)) != p) continue;
          const std::size_t w = layout_.vertex_index(source(h, tm_));
          if(w == s) continue;
          const double nd = it.first + distance(it.second, w);
          if(nd < d[w]) {
            if(d[w] == std::numeric_limits<double>::infinity()) touched.push_back(w);
            d[w] = nd;
            pred[w] = it.second;
            q.push({nd, w});
          }
        }
      }
      const std::size_t n_ends = (std::min)(ends.size(), max_ends);
      for(std::size_t k = 0; k < n_ends; ++k) candidates.push_back(straight_path_to(ends[k * ends.size() / n_ends], pred));
      for(std::size_t v : touched) { d[v] = std::numeric_limits<double>::infinity(); pred[v] = std::size_t(-1); }
      touched.clear();
    }
    // and the paths traced along the field from the same starts to the patch's boundary: the patch may be
    // a merge of the clean-up that the recursion never saw
    {
      std::vector<Start> traced_starts;
      for(std::size_t s : starts) traced_starts.push_back(Start{verts_[s], p});
      for(Candidate& c : trace_from(traced_starts, boundary_nodes({p}), false))
        if(on_loop[layout_.vertex_index(c.path.vertices.back())]) candidates.push_back(std::move(c.path));
    }

    struct Key
    {
      std::size_t invalid, badness;
      bool tiny;
      double cost;
      bool operator<(const Key& o) const
      {
        if(invalid != o.invalid) return invalid < o.invalid;
        if(badness != o.badness) return badness < o.badness;
        if(tiny != o.tiny) return !tiny;
        return cost < o.cost;
      }
    };
    const std::size_t before = badness(P);
    bool found = false;
    Key best{0, 0, false, 0.};
    std::size_t best_index = 0;
    Patch_change best_change;
    for(std::size_t i = 0; i < candidates.size(); ++i) {
      const Path& c = candidates[i]; // at least one edge: the ends are other vertices than the start
      Patch_change change = layout_.preview_add_path(c);
      // the length, each edge weighted up to 3 times as it leaves the field directions (45 degrees)
      double cost = 0.;
      for(std::size_t j = 0; j + 1 < c.vertices.size(); ++j) {
        const Vector u = layout_.point(c.vertices[j + 1]) - layout_.point(c.vertices[j]);
        const double l = std::sqrt(CGAL::to_double(u * u));
        const Node n = layout_.closest_node(c.vertices[j], u);
        const double cosine = l > 0. ? std::abs(CGAL::to_double(u * layout_.direction(n.vertex, n.direction))) / l : 1.;
        cost += l * (1. + 2. * (1. - cosine) / (1. - std::sqrt(0.5)));
      }
      const auto counts = invalid_and_badness(change);
      Key key{counts.first, counts.second, false, cost};
      for(const Patch& N : change.new_patches) key.tiny = key.tiny || N.faces.size() < min_patch_faces;
      if(key.invalid <= 1 && key.badness < before && (!found || key < best)) {
        found = true;
        best = key;
        best_index = i;
        best_change = std::move(change);
      }
    }
    if(!found) return 0;
    layout_.add_path(std::move(candidates[best_index]), std::move(best_change));
    ++cuts_made;
    return 1;
  }

  // Merges an invalid patch with a neighbour by removing a part of a path on its boundary: a chain of
  // boundary edges between two junctions (vertices with at least three cut edges; they keep two, so no
  // path is left dangling), each edge on exactly one path and that path not a feature. A sliver between
  // two close paths goes back into the patch on the other side of one of them, which the whole path could
  // not do (it also bounds valid patches elsewhere). The removal must lower the number of invalid patches
  // among the patches it merges; of those that do, the one leaving the fewest invalid patches is taken,
  // then the lowest `badness()`, then the shortest part. If none does and `recut` is set, each part in
  // turn is removed and the merged patch cut again by `last_resort_cut()` (the path is moved); that is
  // kept if the number of invalid patches of the layout went down, and undone otherwise (the cuts removed,
  // the part put back as a path of its own). Returns 1 if a part was removed.
  struct Part { std::size_t id, i, j; }; // the vertices i..j of the path id
  std::size_t merge_across_path_part(std::size_t p, bool recut)
  {
    const Patch P = layout_.patch(p);
    if(layout_.validity(P) == Layout::SATISFIED) return 0;
    auto cut_degree = [&](vertex_descriptor v) {
      int n = 0;
      for(halfedge_descriptor h : halfedges_around_target(v, tm_)) n += layout_.is_cut(edge(h, tm_));
      return n;
    };
    auto removable = [&](halfedge_descriptor h) {
      const auto e = edge(h, tm_);
      return !is_border(e, tm_) && layout_.number_of_paths(e) == 1 && !layout_.is_on_feature_path(e);
    };
    // where each edge of a path that is not a feature is: path id and index of its first vertex
    std::map<std::pair<vertex_descriptor, vertex_descriptor>, std::pair<std::size_t, std::size_t>> where;
    auto locate = [&](halfedge_descriptor h) -> std::optional<std::pair<std::size_t, std::size_t>> {
      if(where.empty())
        for(std::size_t id : layout_.path_ids()) {
          const Path& q = layout_.path(id);
          if(q.is_feature) continue;
          for(std::size_t i = 0; i + 1 < q.vertices.size(); ++i) where[{q.vertices[i], q.vertices[i + 1]}] = {id, i};
        }
      auto it = where.find({source(h, tm_), target(h, tm_)});
      if(it != where.end()) return it->second;
      return std::nullopt;
    };
    // the part of one path that a chain of halfedges is, if it is one
    auto as_part = [&](const std::vector<halfedge_descriptor>& chain) -> std::optional<Part> {
      const auto fw = locate(chain.front());
      const auto bw = locate(opposite(chain.back(), tm_)); // the path may run against the loop
      for(int side = 0; side < 2; ++side) {
        const auto& at = side == 0 ? fw : bw;
        if(!at) continue;
        const bool forward = side == 0;
        const Path& q = layout_.path(at->first);
        const std::size_t i = at->second, j = i + chain.size();
        if(j >= q.vertices.size()) continue;
        bool same = true;
        for(std::size_t k = 0; k < chain.size() && same; ++k) {
          const halfedge_descriptor h = forward ? chain[k] : opposite(chain[chain.size() - 1 - k], tm_);
          same = q.vertices[i + k] == source(h, tm_) && q.vertices[i + k + 1] == target(h, tm_);
        }
        if(same) return Part{at->first, i, j};
      }
      return std::nullopt;
    };

    // the chains of boundary edges between junctions whose edges could all be removed
    std::vector<std::vector<halfedge_descriptor>> chains;
    for(const auto& L : P.loops) {
      std::size_t k0 = L.size();
      for(std::size_t k = 0; k < L.size() && k0 == L.size(); ++k) if(cut_degree(source(L[k], tm_)) >= 3) k0 = k;
      if(k0 == L.size()) continue;
      std::vector<halfedge_descriptor> chain;
      bool ok = true;
      for(std::size_t n = 0; n < L.size(); ++n) {
        const halfedge_descriptor h = L[(k0 + n) % L.size()];
        chain.push_back(h);
        ok = ok && removable(h);
        if(cut_degree(target(h, tm_)) < 3) continue;
        // a chain from a junction back to itself takes two of its cut edges
        if(target(h, tm_) == source(chain.front(), tm_) && cut_degree(target(h, tm_)) < 4) ok = false;
        if(ok) chains.push_back(chain);
        chain.clear();
        ok = true;
      }
    }

    // a removal that lowers the number of invalid patches by itself
    bool found = false;
    std::tuple<std::size_t, std::size_t, std::size_t> best{0, 0, 0};
    Part best_part{0, 0, 0};
    Patch_change best_change;
    for(const auto& chain : chains) {
      const auto part = as_part(chain);
      if(!part) continue;
      Patch_change change = layout_.preview_remove_path_part(part->id, part->i, part->j);
      const Change_counts c = count(change);
      if(c.invalid_after >= c.invalid_before) continue;
      std::size_t bad = 0;
      for(const Patch& N : change.new_patches) bad += badness(N);
      const std::tuple<std::size_t, std::size_t, std::size_t> key{c.invalid_after, bad, part->j - part->i};
      if(!found || key < best) {
        found = true;
        best = key;
        best_part = *part;
        best_change = std::move(change);
      }
    }
    if(found) {
      remove_part(best_part, std::move(best_change));
      return 1;
    }
    if(!recut) return 0;

    // else a removal followed by last-resort cuts of the merged patch (the path is moved): kept if the
    // number of invalid patches goes down, undone otherwise
    const face_descriptor f0 = P.faces.front();
    for(const auto& chain : chains) {
      where.clear(); // an undone removal leaves the path in three pieces
      const auto part = as_part(chain);
      if(!part) continue;
      const std::size_t invalid_before = invalid_patches();
      const std::size_t patches_before = layout_.number_of_patches();
      Path removed = layout_.path_part(part->id, part->i, part->j);
      remove_part(*part, layout_.preview_remove_path_part(part->id, part->i, part->j));
      // the cuts only add paths, after these (ids grow with insertion)
      const std::size_t paths_after_removal = layout_.path_ids().size();
      const std::size_t merged = layout_.patch_id(f0);
      while(last_resort_cut(merged) > 0) {}
      for(std::size_t k = patches_before - 1; k < layout_.number_of_patches(); ++k)
        while(last_resort_cut(k) > 0) {}
      if(invalid_patches() < invalid_before) return 1;
      // undo: remove the cuts, put the part back
      const std::vector<std::size_t> ids_after = layout_.path_ids();
      for(std::size_t k = ids_after.size(); k > paths_after_removal; --k) {
        layout_.remove_path(ids_after[k - 1], layout_.preview_remove_path(ids_after[k - 1]));
        --cuts_made;
      }
      Patch_change back = layout_.preview_add_path(removed);
      layout_.add_path(std::move(removed), std::move(back));
    }
    return 0;
  }

  // removes a part of a path, keeping the pieces left in the inserted paths
  void remove_part(const Part& part, Patch_change change)
  {
    const std::vector<std::size_t> kept = layout_.remove_path_part(part.id, part.i, part.j, std::move(change));
    auto it = std::find(inserted_.begin(), inserted_.end(), part.id);
    if(it != inserted_.end()) { it = inserted_.erase(it); inserted_.insert(it, kept.begin(), kept.end()); }
  }

  // Dissolves inserted paths on the boundary of invalid patches when that lowers the number of invalid
  // patches among the patches they separate (a sliver cut off by two close paths goes back into its
  // neighbour); the merged patch can then be repaired again by the recursion.
  std::size_t dissolve_around_invalid()
  {
    std::size_t removed = 0;
    std::map<std::pair<vertex_descriptor, vertex_descriptor>, std::size_t> path_of_edge;
    for(std::size_t id : inserted_) {
      const Path& q = layout_.path(id);
      for(std::size_t i = 0; i + 1 < q.vertices.size(); ++i) path_of_edge[std::minmax(q.vertices[i], q.vertices[i + 1])] = id;
    }
    std::vector<char> gone(layout_.path_ids().empty() ? 0 : layout_.path_ids().back() + 1, 0);
    for(std::size_t p = 0; p < layout_.number_of_patches(); ++p) {
      if(layout_.validity(p) == Layout::SATISFIED) continue;
      std::vector<std::size_t> ids;
      for(const auto& loop : layout_.patch(p).loops)
        for(halfedge_descriptor h : loop) {
          auto it = path_of_edge.find(std::minmax(source(h, tm_), target(h, tm_)));
          if(it != path_of_edge.end() && !gone[it->second]) ids.push_back(it->second);
        }
      std::sort(ids.begin(), ids.end());
      ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
      for(std::size_t id : ids) {
        Patch_change c = layout_.preview_remove_path(id);
        const Change_counts n = count(c);
        if(n.invalid_after >= n.invalid_before) continue;
        layout_.remove_path(id, std::move(c));
        gone[id] = 1;
        inserted_.erase(std::find(inserted_.begin(), inserted_.end(), id));
        ++removed;
        break; // patch ids changed
      }
    }
    return removed;
  }

  // ---- clean-up

  // Removes inserted paths in reverse insertion order when that breaks no condition that holds in the
  // patches they separate: the merged patches are valid, and meet the quality conditions when one of the
  // patches they replace did.
  std::size_t clean_up()
  {
    std::size_t removed = 0;
    for(auto it = inserted_.rbegin(); it != inserted_.rend(); ++it) {
      Patch_change c = layout_.preview_remove_path(*it);
      const Change_counts n = count(c);
      // the merged patches must be valid, and meet the quality conditions if one of the old ones did
      if(n.invalid_after > 0 || (n.quality_before > 0 && n.quality_after < c.new_patches.size())) continue;
      layout_.remove_path(*it, std::move(c));
      ++removed;
    }
    return removed;
  }

private:
  Layout& layout_;
  const typename std::remove_reference<decltype(std::declval<Layout&>().mesh())>::type& tm_;
  std::vector<vertex_descriptor> verts_;
  std::vector<std::size_t> inserted_;
  std::vector<double> dist_;
  bool limited_ = false;
  std::chrono::steady_clock::time_point deadline_;
  unsigned threads_ = 1;
};

// A runner of the rounds of `trace_patch_layout()` and `repair_patch_layout()`: a round that may stop at
// the time limit is skipped once it is reached, and the first one it stops is named.
template <typename Layout>
auto round_runner(Layout& layout, Layout_tracer<Layout>& tracer, Trace_patch_layout_statistics& stats, bool verbose)
{
  return [&layout, &tracer, &stats, verbose](const std::string& name, auto&& body, bool may_stop = true) {
    if(may_stop && !stats.stopped_in_round.empty()) return;
    CGAL::Real_timer t;
    t.start();
    Trace_patch_layout_statistics::Round r;
    r.name = name;
    body(r);
    r.seconds = t.time();
    if(may_stop && tracer.out_of_time()) stats.stopped_in_round = name;
    if(verbose)
      std::cerr << "[layout] " << name << ": " << r.candidates << " candidates, " << r.paths << " paths, "
                << layout.statistics().valid_patches << "/" << layout.number_of_patches() << " valid patches, "
                << r.seconds << " s\n";
    stats.rounds.push_back(r);
  };
}

// The rounds after the clean-up and the singularity separation: `last_resort_cuts`, `path_part_removal`
// and `corners` (see `trace_patch_layout()`).
template <typename TriangleMesh, typename Layout, typename Run>
void run_final_layout_rounds(const TriangleMesh& tmesh, Layout& layout, Layout_tracer<Layout>& tracer,
                             unsigned iterations, Trace_patch_layout_statistics& stats, Run& run)
{
  typedef Trace_patch_layout_statistics::Round Round;
  // after the clean-up, which then leaves the same paths as without them: disks that are not convex or have
  // a bad number of corners are cut. A cut changes its own patch only (the second part is appended to the
  // patches), so one pass over the growing list tries every patch until no cut helps it; every cut lowers
  // the badness, so the pass ends.
  run("last_resort_cuts", [&](Round& r) {
    const std::size_t cuts_before = tracer.cuts_made;
    for(std::size_t p = 0; p < layout.number_of_patches(); ++p)
      while(tracer.last_resort_cut(p) > 0) {}
    r.paths = tracer.cuts_made - cuts_before;
  }, false);
  // then invalid patches are merged into a neighbour across a part of a path, and the merged patches cut
  // again; every step lowers the number of invalid patches or keeps it, so a few passes end it
  // (the round's `candidates` are the path parts removed, its `paths` the cuts kept)
  run("path_part_removal", [&](Round& r) {
    const std::size_t cuts_before = tracer.cuts_made;
    for(unsigned pass = 0; pass < iterations; ++pass) {
      const std::size_t before = tracer.invalid_patches();
      std::size_t removed = 0;
      for(std::size_t p = 0; p < layout.number_of_patches(); ++p) removed += tracer.merge_across_path_part(p, true);
      for(std::size_t p = 0; p < layout.number_of_patches(); ++p)
        while(tracer.last_resort_cut(p) > 0) {}
      r.candidates += removed;
      if(removed == 0 || tracer.invalid_patches() >= before) break;
    }
    r.paths = tracer.cuts_made - cuts_before;
  }, false);
  // Last, a convex disk with fewer than 3 corners, which no path or cut could split (typically a loop of
  // feature lines meeting at two tips, a few triangles wide), gets corners in the middle of its longest
  // sides, where the quadrangulation would put them (internal::middle_of_longest_side()): it is then a
  // valid triangle. The patch on the other side of such a corner sees a point of its side.
  run("corners", [&](Round& r) {
    typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
    std::vector<halfedge_descriptor> corners;
    for(std::size_t p = 0; p < layout.number_of_patches(); ++p) {
      const auto& P = layout.patch(p);
      if(layout.validity(P) != Layout::BAD_VALENCE || P.corners.size() >= 3) continue;
      ++r.candidates;
      const auto& L = P.loops[0];
      const std::size_t m = L.size();
      std::vector<double> cum(m + 1, 0.);
      std::vector<std::size_t> positions;
      for(std::size_t i = 0; i < m; ++i) {
        cum[i + 1] = cum[i] + std::sqrt(CGAL::to_double(CGAL::squared_distance(layout.point(source(L[i], tmesh)),
                                                                                 layout.point(target(L[i], tmesh)))));
        if(P.turns[0][i] != Layout::STRAIGHT) positions.push_back(i);
      }
      while(positions.size() < 3) {
        const std::size_t i = internal::middle_of_longest_side(cum, positions);
        if(i == m) break;
        positions.insert(std::upper_bound(positions.begin(), positions.end(), i), i);
        corners.push_back(L[i]);
      }
    }
    // added once the patches are all looked at: adding rebuilds the patches, whose ids may then change
    for(halfedge_descriptor h : corners) layout.add_corner(h);
    stats.added_corners = corners.size();
  }, false);
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Builds the patch layout (paper sections 5.2 and 5.4). The feature edges become the first paths; then
  rounds of candidate paths are traced in G (`Patch_layout::trace()`) and inserted:
  - `convexity`: from the left turns and U-turns of invalid patches, first to the opposite nodes of the
    other bad vertices, then to any boundary node (T-junctions); repeated while it inserts paths;
  - `loops`: two looped paths (the two field directions) from each of `loop_sample_ratio` times the number
    of vertices interior vertices, sampled farthest-first from the paths (a blue-noise sample);
  - `border_to_border`: from straight boundary vertices of patches failing a condition to any boundary node;
  - `recursion`: the same rounds restricted to each patch still invalid (its bad vertices, interior loops
    for a patch that is not a disk, its straight vertices), every candidate stopped at the patch boundary,
    repeated while it helps; when nothing can be inserted, inserted paths on the boundary of invalid
    patches are dissolved when that lowers the number of invalid patches (slivers between close paths);
  - `last_resort`: a patch that is still not a disk is cut: along a path traced along the field that
    joins two of its boundary loops (the best of those traced from vertices of every loop), else, without
    following the field, along the shortest edge path joining two of them, or, for a closed patch or one
    with a handle, along the border of the ball of half its faces; repeated (at most 64 times) until every
    patch is a disk;
  - `singularity_separation` (after the clean-up, which would merge the parts again when neither meets
    the quality conditions): a valid patch with several field singularities inside is split from its
    straight boundary vertices to its boundary, a candidate kept when every patch it makes is valid, has
    fewer singularities and at least 4 faces; repeated while it inserts paths (at most
    `number_of_iterations` times). A patch's quads follow its boundary only, so where the surface inside
    bulges out (a protrusion, around which the field turns at several singularities) they are stretched
    over it: on elephant moved by ten diagonals, a three-sided patch of 878 triangles around 9
    singularities left a quad mesh 6.3% of the diagonal from the input, 0.47% once split;
  - `last_resort_cuts` (after the clean-up, so that the other paths are the ones it keeps): a disk patch
    that is not convex or has fewer than 3 or more than 6 corners is cut along a shortest edge path
    through its interior, which need not follow the field, or along a path traced along the field, from
    one of its left turns or U-turns (from any boundary vertex when it is convex) to another boundary
    vertex (the patch may be a merge of the clean-up that the recursion never saw). The cut taken leaves the fewest
    invalid patches, then the smallest sum of left turns, twice the U-turns and missing or extra corners,
    and it must lower that sum and leave at most one invalid patch, so the number of invalid patches
    never grows; a patch is cut again while a cut helps;
  - `path_part_removal`: an invalid patch is merged with a neighbour by removing a part of a path on its
    boundary, between two junctions that keep at least two cut edges each (path or border edges, so no
    path is left dangling; feature paths are never touched), when that lowers the number of invalid patches; else a
    part is removed and the merged patch cut again as above, kept only if the number of invalid patches
    of the layout goes down. Slivers between two close paths, which no cut of their own improves, mostly
    go this way. Then the last-resort cuts run again; repeated while the number of invalid patches falls
    (at most `number_of_iterations` times).
  - `corners`: a convex disk patch that still has fewer than 3 corners (a loop of feature lines meeting
    at two tips, too narrow for any path) gets corners (`Patch_layout::add_corner()`) in the middle of its
    longest sides until it has 3; `added_corners` of the result counts them.

  In every round the candidates are tried farthest-first (the next one is the one whose vertices are, on
  average, farthest from the paths already inserted, features included) and kept by one acceptance rule:
  no tangential crossing, and it either lowers the number of invalid patches among those it touches, raises
  the number meeting the quality conditions without making a valid one invalid, or splits a patch that
  still fails a condition (in the border-to-border round: a validity condition). A candidate that leaves
  an invalid patch behind may not create a U-turn or a patch of fewer than four faces. Candidates are
  evaluated on the patches they touch only (`Patch_layout::preview_add_path()`), and G is updated around
  the new path only. A clean-up finally removes inserted paths in reverse insertion order when the patches
  they separate, merged, are valid, and meet the quality conditions if one of them did.

  Not guaranteed: convexity, and at most 6 sides. The last resort makes every patch a disk and the round
  `corners` gives every convex one at least 3 corners; a disk patch that neither a cut nor a path-part
  removal improves (typically a sliver between two close paths that both cross other paths there, or two
  feature lines one triangle apart) is left non-convex or with more than 6 corners and counted in the
  figures (the pipeline then chooses corners for it, see `quad_remesh()`).

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
    \cgalParamNBegin{loop_sample_ratio}
      \cgalParamDescription{number of seeds of the looped-paths round, as a fraction of the number of vertices}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.01`, as the original (at most 200 seeds)}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_running_time}
      \cgalParamDescription{a time limit in seconds for the rounds: once reached, the round running stops
                            (no more candidates are traced or tried) and the later rounds are skipped. The
                            features and convexity rounds (most patches convex), the last resort (every
                            patch a disk), the clean-up and the last-resort cuts always run to their end.
                            `stopped_in_round` of the result names the round that stopped}
      \cgalParamType{`double`}
      \cgalParamDefault{`0` (no limit)}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_threads}
      \cgalParamDescription{the candidate paths of a round are traced in up to this many threads (the
                            layout does not depend on it)}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{`1`}
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
  const double loop_ratio = choose_parameter(get_parameter(np, internal_np::loop_sample_ratio), 0.01);
  const double time_limit = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.);
  const unsigned threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 1u);

  Trace_patch_layout_statistics stats;
  CGAL::Real_timer total;
  total.start();
  internal::Layout_tracer<Layout> tracer(layout);
  tracer.set_threads(threads);

  typedef Trace_patch_layout_statistics::Round Round;
  auto run = internal::round_runner(layout, tracer, stats, verbose);

  run("features", [&](Round& r) { r.paths = layout.add_feature_paths(edge_is_feature_map); }, false);
  // convexity enforcement: from left turns and U-turns, first to the opposite nodes of other bad vertices,
  // then to any boundary node (T-junctions)
  run("convexity", [&](Round& r) {
    for(unsigned i = 0; i < iterations; ++i) {
      auto starts = tracer.boundary_starts({Layout::LEFT_TURN, Layout::U_TURN}, true, 64);
      if(starts.empty()) break;
      auto c1 = tracer.trace_from(starts, {}, true);
      std::size_t kept = tracer.insert_farthest_first(c1, r);
      starts = tracer.boundary_starts({Layout::LEFT_TURN, Layout::U_TURN}, true, 64);
      auto c2 = tracer.trace_from(starts, tracer.boundary_nodes({}), false);
      kept += tracer.insert_farthest_first(c2, r);
      if(kept == 0) break;
    }
  }, false);
  // The time limit applies from here: the rounds above make most patches convex (the quad patterns of a
  // non-convex patch may fold), the ones below mostly improve the regularity.
  if(time_limit > 0.) tracer.set_time_limit((std::max)(1e-9, time_limit - total.time()));
  run("loops", [&](Round& r) {
    // at most 200 seeds: every loop is a Dijkstra search over much of G
    const std::size_t n = (std::min)(std::size_t(200), (std::max)(std::size_t(1), std::size_t(loop_ratio * double(num_vertices(tmesh)))));
    auto c = tracer.trace_loops(tracer.interior_samples(n, std::size_t(-1)), {});
    tracer.insert_farthest_first(c, r);
  });
  run("border_to_border", [&](Round& r) {
    tracer.split_quality_failing = false; // here a split must make a patch valid or improve quality directly
    for(unsigned i = 0; i < iterations; ++i) {
      auto starts = tracer.boundary_starts({Layout::STRAIGHT}, false, 16);
      auto c = tracer.trace_from(starts, tracer.boundary_nodes({}), false);
      if(tracer.insert_farthest_first(c, r) == 0) break;
    }
  });
  // recursion: rounds restricted to each patch still invalid, the candidates stopped at its boundary;
  // between two passes, slivers are dissolved into their neighbours
  run("recursion", [&](Round& r) {
    for(unsigned depth = 0; depth < 4 * iterations && tracer.invalid_patches() > 0 && !tracer.out_of_time(); ++depth) {
      std::size_t kept = 0;
      std::vector<std::size_t> invalid;
      for(std::size_t p = 0; p < layout.number_of_patches(); ++p)
        if(layout.validity(p) != Layout::SATISFIED) invalid.push_back(p);
      for(std::size_t p : invalid) {
        if(p >= layout.number_of_patches() || layout.validity(p) == Layout::SATISFIED) continue;
        const auto ends = tracer.boundary_nodes({p});
        auto c1 = tracer.trace_from(tracer.boundary_starts({Layout::LEFT_TURN, Layout::U_TURN}, true, 64, p), ends, false);
        kept += tracer.insert_farthest_first(c1, r);
        if(layout.validity(p) == Layout::NOT_A_DISK) {
          auto c2 = tracer.trace_loops(tracer.interior_samples(4, p), ends);
          kept += tracer.insert_farthest_first(c2, r);
        }
        if(layout.validity(p) != Layout::SATISFIED) {
          auto c3 = tracer.trace_from(tracer.boundary_starts({Layout::STRAIGHT}, true, 32, p), ends, false);
          kept += tracer.insert_farthest_first(c3, r);
        }
      }
      if(kept == 0 && tracer.dissolve_around_invalid() == 0) break;
    }
  });
  // last resort: patches that are still not disks are cut without following the field (see above)
  run("last_resort", [&](Round& r) {
    for(unsigned k = 0; k < 64; ++k) {
      std::size_t added = 0;
      for(std::size_t p = 0; p < layout.number_of_patches(); ++p)
        if(layout.validity(p) == Layout::NOT_A_DISK) added += tracer.last_resort_split(p);
      r.paths += added;
      if(added == 0) break;
    }
  }, false);
  stats.removed_paths = tracer.clean_up();
  // A valid patch with several singularities inside is split between them, from its straight boundary
  // nodes to its boundary, each part valid and with fewer singularities (after the clean-up, which would
  // merge the parts again when neither meets the quality conditions). The quads of a patch follow its
  // boundary only: where the surface inside bulges out (the field turns around singularities), they are
  // stretched over it.
  run("singularity_separation", [&](Round& r) {
    tracer.separating_singularities = true;
    // (patch ids change as paths go in: a patch is looked at again before its turn)
    auto has_several = [&](std::size_t p) {
      return p < layout.number_of_patches() && layout.patch(p).singularities.size() > 1 &&
             layout.validity(p) == Layout::SATISFIED;
    };
    for(unsigned pass = 0; pass < iterations && !tracer.out_of_time(); ++pass) {
      std::vector<std::size_t> several;
      for(std::size_t p = 0; p < layout.number_of_patches(); ++p)
        if(has_several(p)) several.push_back(p);
      std::size_t kept = 0;
      for(std::size_t p : several) {
        if(!has_several(p)) continue;
        auto c = tracer.trace_from(tracer.boundary_starts({Layout::STRAIGHT}, false, 32, p), tracer.boundary_nodes({p}), false);
        kept += tracer.insert_farthest_first(c, r);
      }
      if(kept == 0) break;
    }
    tracer.separating_singularities = false;
  });
  internal::run_final_layout_rounds(tmesh, layout, tracer, iterations, stats, run);
  stats.layout = layout.statistics();
  stats.seconds = total.time();
  if(verbose)
    std::cerr << "[layout] " << stats.layout.valid_patches << "/" << stats.layout.patches << " valid, "
              << stats.layout.quality_patches << " quality, " << stats.layout.paths << " paths, "
              << stats.removed_paths << " removed by clean-up, " << stats.seconds << " s\n";
  if(verbose) {
    std::map<int, std::size_t> failing;
    for(std::size_t p = 0; p < layout.number_of_patches(); ++p) ++failing[int(layout.validity(p))];
    std::cerr << "[layout] validity:";
    for(auto& f : failing) std::cerr << " " << f.first << ":" << f.second;
    std::cerr << "\n";
  }
  return stats;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Runs the rounds of `trace_patch_layout()` that come after its clean-up, `last_resort_cuts`,
  `path_part_removal` and `corners`, on a layout that already has its paths: typically a layout traced by
  `trace_patch_layout()` whose paths were copied onto a refined mesh (see `refine_patch_layout()`),
  so that the patches the refinement touched get their cuts. A patch that was valid stays valid: every cut
  and every removal lowers the number of invalid patches or keeps it.

  \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` with triangle faces
  \tparam GeomTraits the traits of the layout
  \tparam NamedParameters a sequence of named parameters

  \param tmesh the mesh the layout was built on
  \param layout a layout built on `tmesh`, with its paths
  \param np optional named parameters: `number_of_iterations` (default `8`), `number_of_threads` (default
            `1`) and `verbose` (default `false`), as for `trace_patch_layout()`

  \pre `&layout.mesh() == &tmesh`
*/
template <typename TriangleMesh, typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
Trace_patch_layout_statistics repair_patch_layout(const TriangleMesh& tmesh, Patch_layout<TriangleMesh, GeomTraits>& layout,
                                                  const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef Patch_layout<TriangleMesh, GeomTraits> Layout;
  if(&layout.mesh() != &tmesh) throw std::invalid_argument("repair_patch_layout: the layout is not built on this mesh");
  const unsigned iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 8u);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const unsigned threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 1u);
  Trace_patch_layout_statistics stats;
  CGAL::Real_timer total;
  total.start();
  internal::Layout_tracer<Layout> tracer(layout);
  tracer.set_threads(threads);
  auto run = internal::round_runner(layout, tracer, stats, verbose);
  internal::run_final_layout_rounds(tmesh, layout, tracer, iterations, stats, run);
  stats.layout = layout.statistics();
  stats.seconds = total.time();
  return stats;
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_TRACE_PATCH_LAYOUT_H
