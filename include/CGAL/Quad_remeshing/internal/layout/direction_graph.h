// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The graph G of paper section 5.3: four nodes per non-singular vertex (one per field direction),
// field-aligned arcs weighted by drift, two-hop virtual arcs, and shortest paths with Boost.Graph's
// Dijkstra stopped at the first end node reached.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_LAYOUT_DIRECTION_GRAPH_H
#define CGAL_QUAD_REMESHING_INTERNAL_LAYOUT_DIRECTION_GRAPH_H

#include <CGAL/Quad_remeshing/internal/layout/field_directions.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/iterator/transform_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/// A path found in G: the mesh vertices (by index) and, at each, the index of the field direction followed
/// (in that vertex's frame).
struct Graph_path
{
  std::vector<std::size_t> vertices;
  std::vector<int> directions;
  double cost = 0.;
};

/// An arc of G, stored in the out-arc list of its source node: 16 bytes, in place (Boost's adjacency_list
/// keeps a bundled edge property on the heap, one allocation per arc).
struct Direction_arc
{
  std::uint32_t to = 0;
  std::int32_t middle = -1; // the middle node of a two-hop arc, -1 for a mesh-edge arc
  double weight = 0.;
};

/// An arc as Boost.Graph sees it (the `edge_descriptor` of `Direction_arcs`).
struct Direction_arc_ref
{
  std::size_t from = 0;
  const Direction_arc* arc = nullptr;
  bool operator==(const Direction_arc_ref& o) const { return from == o.from && arc == o.arc; }
  bool operator!=(const Direction_arc_ref& o) const { return !(*this == o); }
};

/// The nodes of G with their out-arc lists: a model of Boost.Graph's `IncidenceGraph`, for its Dijkstra.
struct Direction_arcs
{
  std::vector<std::vector<Direction_arc>> out;

  struct Make_ref
  {
    std::size_t from = 0;
    Direction_arc_ref operator()(const Direction_arc& a) const { return Direction_arc_ref{from, &a}; }
  };
  typedef boost::transform_iterator<Make_ref, std::vector<Direction_arc>::const_iterator, Direction_arc_ref,
                                    Direction_arc_ref> Out_iterator;
};

inline std::pair<Direction_arcs::Out_iterator, Direction_arcs::Out_iterator> out_edges(std::size_t u, const Direction_arcs& g)
{
  const Direction_arcs::Make_ref f{u};
  return {Direction_arcs::Out_iterator(g.out[u].begin(), f), Direction_arcs::Out_iterator(g.out[u].end(), f)};
}
inline std::size_t out_degree(std::size_t u, const Direction_arcs& g) { return g.out[u].size(); }
inline std::size_t source(const Direction_arc_ref& e, const Direction_arcs&) { return e.from; }
inline std::size_t target(const Direction_arc_ref& e, const Direction_arcs&) { return e.arc->to; }

/// The weight of an arc, as a readable property map.
struct Direction_arc_weight_map
{
  typedef Direction_arc_ref key_type;
  typedef double value_type;
  typedef double reference;
  typedef boost::readable_property_map_tag category;
  friend double get(const Direction_arc_weight_map&, const Direction_arc_ref& e) { return e.arc->weight; }
};

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

namespace boost {
template <>
struct graph_traits<CGAL::Quad_remeshing::internal::Direction_arcs>
{
  typedef std::size_t vertex_descriptor;
  typedef CGAL::Quad_remeshing::internal::Direction_arc_ref edge_descriptor;
  typedef directed_tag directed_category;
  typedef allow_parallel_edge_tag edge_parallel_category;
  typedef incidence_graph_tag traversal_category;
  typedef CGAL::Quad_remeshing::internal::Direction_arcs::Out_iterator out_edge_iterator;
  typedef std::size_t degree_size_type;
  typedef std::size_t vertices_size_type;
  typedef std::size_t edges_size_type;
  static vertex_descriptor null_vertex() { return vertex_descriptor(-1); }
};
} // namespace boost

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/// Thrown by the visitor to stop Dijkstra at the first end node whose distance is final.
struct Dijkstra_end_reached
{
  std::size_t node;
};

template <typename EndFlags>
struct Stop_at_end_visitor : public boost::default_dijkstra_visitor
{
  const EndFlags* is_end;
  std::size_t skip_vertex; // its four nodes are no ends: one end list serves searches that skip their own start
  std::vector<std::size_t>* touched; // every node the search reached, to reset the search arrays
  template <typename G>
  void discover_vertex(std::size_t u, const G&) const { touched->push_back(u); }
  template <typename G>
  void examine_vertex(std::size_t u, const G&) const
  {
    if((*is_end)[u] && u / 4 != skip_vertex) throw Dijkstra_end_reached{u};
  }
};

/*
  G over a triangle mesh. Node `4*v + k` is direction `k` of the frame of vertex `v`. Nodes of singular
  vertices have no arcs. Existing paths block arcs that would run along them: a path edge carries no arc,
  and at a path vertex the directions parallel to the path (the "tangential" class, k mod 2) neither enter
  nor leave, so a new path can only cross a path orthogonally (Figure 11) or end on it (T-junction).
  Crossing needs no explicit zero-weight arc here because G is built on the uncut mesh: the two sides of a
  path share the vertex, and entering and leaving it in the same orthogonal direction is free.

  Weight of an arc: |drift| + length_weight * advance, where drift = (v_j - v_i) . f_perp is the deviation
  orthogonal to the averaged field direction f (Tarini et al. 2011) and advance = (v_j - v_i) . f. The small
  advance term only breaks ties between drift-free paths in favour of the shorter one. The original
  tracer uses length * (1 + 100 (angle / max_angle)^2) instead; both vanish-or-grow with the deviation,
  but the drift form lets the two-hop arcs below cancel opposite deviations, which the angle form cannot.

  Two-hop virtual arcs (v_i -> v_j -> v_l with drifts of opposite sign) carry the modulus of the summed
  signed drift so that a zig-zag that follows the field on average is not over-penalised; the middle node
  is recorded and put back in the path.
*/
template <typename Vector_3>
class Direction_graph
{
public:
  typedef Direction_arc Arc;
  typedef Direction_arcs Graph;

  /// `frames[v]`: the four directions at vertex `v`; `nbrs[v]`: its neighbours (ascending order for
  /// determinism); `points[v]`: its position; `singular[v]`: excluded; `blocked_edges`: set of
  /// (min,max) vertex pairs on paths; `tangent_mask[v]`: bit c set when directions of class c (k mod 2)
  /// are tangential to a path at v.
  /// an arc along one mesh edge
  struct Hop { std::size_t to; double drift, advance; };

  /// The arcs leaving node (i, k) along mesh edges. At a start node (`at_start`) the rule at i is relaxed:
  /// a search may leave a path vertex parallel to a path but away from it (continuing a path through a
  /// concave corner); it may not leave in the direction of a path edge leaving i. Elsewhere an edge whose
  /// direction class at i is tangential to a path is refused.
  std::vector<Hop> direct_hops(std::size_t i, int k, bool at_start) const
  {
    std::vector<Hop> out;
    const auto& frames = *frames_;
    const auto& mask = *mask_;
    if((*singular_)[i]) return out;
    for(std::size_t j : (*nbrs_)[i]) {
      if((*singular_)[j] || is_blocked(*blocked_, i, j)) continue;
      const Vector_3 e = positions_[j] - positions_[i];
      const double el = std::sqrt(CGAL::to_double(e * e));
      if(el == 0.) continue;
      const int ei = closest_direction(frames[i], e);
      if(!at_start && (mask[i] & (1u << (ei % 2)))) continue;
      if(at_start && leaves_along_path(i, ei)) continue;
      // an edge parallel to a path at its far end would run along it (same rule as the tangential test)
      if(mask[j] & (1u << (closest_direction(frames[j], Vector_3(-e)) % 2))) continue;
      const int m = closest_direction(frames[j], frames[i][k]);
      if(mask[j] & (1u << (m % 2))) continue;
      Vector_3 f = frames[i][k] + frames[j][m];
      const double fl = std::sqrt(CGAL::to_double(f * f));
      if(fl == 0.) continue;
      f = f / fl;
      const double advance = CGAL::to_double(e * f);
      if(advance <= el * std::cos(CGAL_PI / 4.)) continue; // not within 45 degrees of the field
      const Vector_3 n = CGAL::cross_product(frames[i][0], frames[i][1]);
      const double drift = CGAL::to_double(e * CGAL::cross_product(n, f));
      out.push_back(Hop{4 * j + std::size_t(m), drift, advance});
    }
    return out;
  }

  template <typename Point_3>
  void build(const std::vector<std::array<Vector_3, 4>>& frames,
             const std::vector<std::vector<std::size_t>>& nbrs,
             const std::vector<Point_3>& points,
             const std::vector<char>& singular,
             const std::vector<std::vector<std::size_t>>& blocked_neighbours,
             const std::vector<unsigned char>& tangent_mask,
             double length_weight)
  {
    const std::size_t nv = frames.size();
    nodes_ = 4 * nv;
    if(nodes_ + 64 > std::size_t((std::numeric_limits<std::int32_t>::max)()))
      throw std::length_error("Direction_graph: too many vertices for 32-bit node indices");
    // the nodes after the 4|V| direction nodes are the spare sources of the searches
    g_.out.assign(nodes_ + 1, {});
    frames_ = &frames;
    nbrs_ = &nbrs;
    singular_ = &singular;
    blocked_ = &blocked_neighbours;
    mask_ = &tangent_mask;
    length_weight_ = length_weight;
    positions_.resize(nv);
    for(std::size_t i = 0; i < nv; ++i) positions_[i] = points[i] - CGAL::ORIGIN;
    for(std::size_t u = 0; u < nodes_; ++u) add_node_arcs(u);
  }

  /// Recomputes the arcs leaving the nodes of the vertices `vs` after the blocked edges or the tangent masks
  /// changed at some vertices: `vs` must hold the closed two-ring of those vertices (an arc depends on the
  /// masks at its ends and, for a two-hop arc, at its middle vertex).
  void rebuild_nodes(const std::vector<std::size_t>& vs)
  {
    for(std::size_t i : vs)
      for(std::size_t k = 0; k < 4; ++k) {
        g_.out[4 * i + k].clear();
        add_node_arcs(4 * i + k);
      }
  }

  std::size_t number_of_nodes() const { return nodes_; }

  /// Makes room for `k` concurrent searches (a spare source node and the search arrays of each slot); not to
  /// be called during a search.
  void reserve_searches(std::size_t k)
  {
    if(g_.out.size() < nodes_ + k) g_.out.resize(nodes_ + k);
    if(searches_.size() < k) searches_.resize(k);
  }
  std::size_t number_of_arcs() const
  {
    std::size_t n = 0;
    for(const auto& o : g_.out) n += o.size();
    return n;
  }

  /// Shortest path from `start` to the first end node reached. The ends are the nodes `ends` and, when `loop`,
  /// `start` itself (the path is then a loop), but no node of the vertex `skip_vertex` (-1: none). The search
  /// uses the spare source and the arrays of `slot` (< the `k` of `reserve_searches()`): searches in distinct
  /// slots may run in parallel threads, as long as the graph does not change.
  std::optional<Graph_path> shortest_path(std::size_t start, const std::vector<std::size_t>& ends, bool loop,
                                          std::size_t skip_vertex, std::size_t slot)
  {
    const std::size_t n = g_.out.size();
    const std::size_t spare = nodes_ + slot;
    if(spare >= n || slot >= searches_.size())
      throw std::logic_error("Direction_graph: no spare node for this search slot (bug)");
    Search& s = searches_[slot];
    auto& dist_ = s.dist;
    auto& pred_ = s.pred;
    auto& color_ = s.color;
    auto& is_end_ = s.is_end;
    auto& touched_ = s.touched;
    // the search starts from a spare copy of the start node: the start node itself may then be an end (a loop),
    // and a start on a path vertex may leave it in a direction parallel to that path (into the patch)
    const std::size_t source = spare;
    for(const Hop& h : direct_hops(start / 4, int(start % 4), true))
      g_.out[spare].push_back(Arc{std::uint32_t(h.to), -1, std::abs(h.drift) + length_weight_ * h.advance});
    // Searches stopped at a patch's boundary reach few nodes: the search arrays persist between searches
    // and only the nodes a search reached are reset, instead of initialising all 4|V| nodes every time.
    const double infinity = (std::numeric_limits<double>::max)();
    if(dist_.size() != n) {
      dist_.assign(n, infinity);
      pred_.resize(n);
      for(std::size_t u = 0; u < n; ++u) pred_[u] = u;
      color_.assign(n, boost::white_color);
      is_end_.assign(n, 0);
      s.heap_index.assign(n, 0);
    }
    for(std::size_t e : ends) is_end_[e] = 1;
    if(loop) is_end_[start] = 1;
    touched_.clear();
    Stop_at_end_visitor<std::vector<char>> vis;
    vis.is_end = &is_end_;
    vis.skip_vertex = skip_vertex;
    vis.touched = &touched_;
    dist_[source] = 0.;
    std::optional<std::size_t> reached;
    const boost::typed_identity_property_map<std::size_t> index;
    try {
      // boost::dijkstra_shortest_paths_no_init(), whose body this is, allocates and fills a heap-index array
      // of all 4|V| nodes for every search (its memset was 12% of truck's layout time): the slot keeps one. Its
      // entries need no reset, the heap sets a node's entry when it pushes the node.
      typedef typename boost::graph_traits<Graph>::vertex_descriptor Graph_node;
      const auto pred_map = boost::make_iterator_property_map(pred_.begin(), index);
      const auto dist_map = boost::make_iterator_property_map(dist_.begin(), index);
      const auto heap_index_map = boost::make_iterator_property_map(s.heap_index.begin(), index);
      const Direction_arc_weight_map weight_map;
      typedef boost::d_ary_heap_indirect<Graph_node, 4, std::remove_const_t<decltype(heap_index_map)>,
                                         std::remove_const_t<decltype(dist_map)>, std::less<double>> Queue;
      Queue queue(dist_map, heap_index_map, std::less<double>());
      boost::detail::dijkstra_bfs_visitor<Stop_at_end_visitor<std::vector<char>>, Queue,
                                          std::remove_const_t<decltype(weight_map)>,
                                          std::remove_const_t<decltype(pred_map)>,
                                          std::remove_const_t<decltype(dist_map)>, boost::closed_plus<double>,
                                          std::less<double>>
        bfs_vis(vis, queue, weight_map, pred_map, dist_map, boost::closed_plus<double>(infinity), std::less<double>(), 0.);
      const Graph_node from = source;
      boost::breadth_first_visit(g_, &from, &from + 1, queue, bfs_vis,
                                 boost::make_iterator_property_map(color_.begin(), index));
    } catch(const Dijkstra_end_reached& r) {
      reached = r.node;
    } catch(...) {
      // the arrays persist: left dirty, they are initialised again by the next search of this slot
      s.dist.clear();
      g_.out[spare].clear();
      throw;
    }
    g_.out[spare].clear();
    std::vector<std::size_t> nodes;
    double cost = 0.;
    if(reached) {
      cost = dist_[*reached];
      for(std::size_t u = *reached;; u = pred_[u]) {
        nodes.push_back(u);
        if(u == source) break;
      }
    }
    // the search discovers the source first, so this resets it too
    for(std::size_t u : touched_) {
      dist_[u] = infinity;
      pred_[u] = u;
      color_[u] = boost::white_color;
    }
    for(std::size_t e : ends) is_end_[e] = 0;
    is_end_[start] = 0;
    if(!reached) return std::nullopt;

    nodes.back() = start;
    std::reverse(nodes.begin(), nodes.end());
    Graph_path p;
    p.cost = cost;
    for(std::size_t i = 0; i < nodes.size(); ++i) {
      if(i > 0) {
        // recover the middle node of a two-hop arc (the lightest arc between the two nodes); the first step
        // comes from the spare node and is always a mesh edge
        std::ptrdiff_t middle = -1;
        double best = (std::numeric_limits<double>::max)();
        if(i > 1)
          for(const Arc& a : g_.out[nodes[i - 1]])
            if(a.to == nodes[i] && a.weight < best) { best = a.weight; middle = a.middle; }
        if(middle >= 0) push(p, std::size_t(middle));
      }
      push(p, nodes[i]);
    }
    return p;
  }

private:
  // The arrays of the searches of one slot, kept between searches (only the nodes a search reached are reset
  // after it).
  struct Search
  {
    std::vector<double> dist;
    std::vector<std::size_t> pred;
    std::vector<boost::default_color_type> color;
    std::vector<char> is_end;
    std::vector<std::size_t> touched;
    std::vector<std::size_t> heap_index; // position of each node in the search's heap (see shortest_path())
  };

  std::vector<Hop> hops_of(std::size_t u) const
  {
    const std::size_t i = u / 4;
    const int k = int(u % 4);
    if((*mask_)[i] & (1u << (k % 2))) return {};
    return direct_hops(i, k, false);
  }

  // the arcs leaving node `u`: one per mesh edge within 45 degrees of the field, and two-hop zig-zags,
  // keeping the lightest arc per target node
  void add_node_arcs(std::size_t u)
  {
    const std::vector<Hop> first = hops_of(u);
    std::map<std::size_t, Arc> out; // ordered: deterministic insertion
    for(const Hop& h : first) {
      const double w = std::abs(h.drift) + length_weight_ * h.advance;
      auto it = out.find(h.to);
      if(it == out.end() || w < it->second.weight) out[h.to] = Arc{std::uint32_t(h.to), -1, w};
    }
    for(const Hop& h1 : first)
      for(const Hop& h2 : hops_of(h1.to)) {
        if(h2.to / 4 == u / 4 || h1.drift * h2.drift >= 0.) continue; // only zig-zags gain
        const double w = std::abs(h1.drift + h2.drift) + length_weight_ * (h1.advance + h2.advance);
        auto it = out.find(h2.to);
        if(it == out.end() || w < it->second.weight) out[h2.to] = Arc{std::uint32_t(h2.to), std::int32_t(h1.to), w};
      }
    std::vector<Arc>& arcs = g_.out[u];
    arcs.reserve(out.size());
    for(const auto& a : out) arcs.push_back(a.second);
  }

  bool leaves_along_path(std::size_t i, int dir) const
  {
    for(std::size_t b : (*blocked_)[i])
      if(closest_direction((*frames_)[i], Vector_3(positions_[b] - positions_[i])) == dir) return true;
    return false;
  }
  static bool is_blocked(const std::vector<std::vector<std::size_t>>& blocked, std::size_t i, std::size_t j)
  {
    for(std::size_t b : blocked[i]) if(b == j) return true;
    return false;
  }
  static void push(Graph_path& p, std::size_t node)
  {
    p.vertices.push_back(node / 4);
    p.directions.push_back(int(node % 4));
  }

  Graph g_;
  std::size_t nodes_ = 0; // the direction nodes 0 .. nodes_ - 1; the spare sources follow
  std::vector<Search> searches_; // one per search slot
  const std::vector<std::array<Vector_3, 4>>* frames_ = nullptr;
  const std::vector<std::vector<std::size_t>>* nbrs_ = nullptr;
  const std::vector<char>* singular_ = nullptr;
  const std::vector<std::vector<std::size_t>>* blocked_ = nullptr;
  const std::vector<unsigned char>* mask_ = nullptr;
  std::vector<Vector_3> positions_;
  double length_weight_ = 0.;
};

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
