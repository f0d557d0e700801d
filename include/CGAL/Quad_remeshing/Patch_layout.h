// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The patch layout of paper section 5: paths on a triangle mesh, the patches they cut it into, the
// classification of the patch boundary vertices, validity and quality conditions, and field-aligned tracing.

#ifndef CGAL_QUAD_REMESHING_PATCH_LAYOUT_H
#define CGAL_QUAD_REMESHING_PATCH_LAYOUT_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/layout/direction_graph.h>
#include <CGAL/Quad_remeshing/internal/layout/field_directions.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <exception>
#include <iomanip>
#include <map>
#include <mutex>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <thread>
#include <vector>

/// weight of the advance along the field in the tracing cost, relative to the drift (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(tracing_length_weight_t, tracing_length_weight, tracing_length_weight)

namespace CGAL {
namespace Quad_remeshing {

namespace internal {

// The length of side `c` of a loop, from its corner `corners[c]` to the next one, cyclically: `cum` holds
// the cumulated edge lengths of the loop (its m edges: m + 1 values from 0), `corners` the sorted
// positions of its corners (a corner at position i is at the target of the i-th edge).
inline double loop_side_length(const std::vector<double>& cum, const std::vector<std::size_t>& corners, std::size_t c)
{
  const std::size_t m = cum.size() - 1;
  const std::size_t i = corners[c], j = corners[(c + 1) % corners.size()];
  return j > i ? cum[j] - cum[i] : cum[m] - cum[i] + cum[j];
}

// The position of a loop (see loop_side_length()) nearest the middle of its longest side (with no
// corner, the whole loop is the side). Returns m when that side has no position left between its corners.
inline std::size_t middle_of_longest_side(const std::vector<double>& cum, const std::vector<std::size_t>& corners)
{
  const std::size_t m = cum.size() - 1;
  std::size_t from = 0;
  double len = cum[m];
  if(!corners.empty()) {
    double l_best = -1.;
    for(std::size_t c = 0; c < corners.size(); ++c) {
      const double l = loop_side_length(cum, corners, c);
      if(l > l_best) { l_best = l; from = corners[c]; }
    }
    len = l_best;
  }
  const double target_len = (corners.empty() ? 0. : cum[from]) + 0.5 * len;
  std::size_t best_i = m;
  double best_d = 1e300;
  for(std::size_t step = 1; step < m; ++step) {
    const std::size_t i = corners.empty() ? step - 1 : (from + step) % m;
    if(std::find(corners.begin(), corners.end(), i) != corners.end()) break; // reached the next corner
    double pos = cum[i + 1];
    if(!corners.empty() && i < from) pos += cum[m];
    const double d = std::abs(pos - target_len);
    if(d < best_d) { best_d = d; best_i = i; }
  }
  return best_i;
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of a patch layout (see `Patch_layout::statistics()`).
*/
struct Patch_layout_statistics
{
  std::size_t patches = 0;         ///< number of patches
  std::size_t valid_patches = 0;   ///< patches meeting the validity conditions
  std::size_t quality_patches = 0; ///< valid patches also meeting the quality conditions
  std::map<std::size_t, std::size_t> patches_by_valence; ///< number of patches per number of corners
  std::size_t paths = 0;           ///< number of paths (feature paths included)
  std::size_t t_junctions = 0;     ///< vertices where a path ends on another one
  double seconds = 0.;             ///< time of the last rebuild

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["patches"] = patches;
    r["valid_patches"] = valid_patches;
    r["quality_patches"] = quality_patches;
    Report v = Report::object();
    for(const auto& p : patches_by_valence) v[std::to_string(p.first)] = p.second;
    r["patches_by_valence"] = v;
    r["paths"] = paths;
    r["t_junctions"] = t_junctions;
    r["seconds"] = seconds;
    return r;
  }
};

/*!
  \ingroup PkgQuadRemeshingRef
  A patch layout over a triangle mesh (paper section 5): a set of paths, chains of mesh edges each
  following a direction of a cross field, and the patches they cut the mesh into.

  For every patch the layout gives its faces, its boundary loops as halfedges of its faces (so the patch
  lies on the left of each halfedge), the turn at every boundary vertex, its corners, its sides, and the
  arcs of each side. An arc is a maximal chain of path edges with no corner of any patch and no junction of
  paths inside it; it has a length measured along the field (sum of |edge . field direction|) and the
  patches on both of its sides, so that the two patches sharing it see the same arc id.

  Adding or removing a path marks the layout dirty; the patches are rebuilt on the next query by a cheap
  rebuild (one flood fill and one walk of the boundaries, linear in the mesh size), not incrementally.
  The direction graph G used for tracing is rebuilt the same way when paths have changed.

  Turns are named as in the paper, whose boundaries run with the patch on their right: a right turn is
  a convex corner, a left turn a concave one, a U-turn a dangling path end or a spike. They are found by
  carrying the field direction of the incoming boundary edge across the faces of the fan to the outgoing
  edge (the matchings), which fixes the turn modulo a full turn, and choosing among those turns the one
  closest to the turn measured by the angle of the fan. One exception: a sharp tip between two feature
  paths or border edges, where the turn found is a U-turn but the angle of the patch is below
  `max_tip_angle`, is a right turn (a corner no path can remove, see `max_tip_angle`).

  \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` with triangle faces
  \tparam GeomTraits a kernel; the default is the kernel of the mesh's points
*/
template <typename TriangleMesh,
          typename GeomTraits = typename Kernel_traits<
              typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel>
class Patch_layout
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  /// turn of a patch boundary at a vertex (paper Figure 6)
  enum Turn { STRAIGHT = 0, RIGHT_TURN, LEFT_TURN, U_TURN };

  /// A boundary vertex whose turn is two or more quarter turns toward the patch (a U-turn by the field),
  /// whose angle inside the patch is below this one (a right angle) and whose two boundary edges are both
  /// on feature paths or on the mesh border, is a right turn: the tip between two feature lines meeting at
  /// a small angle. No path fits into the tip and neither line may be removed, so every quad mesh keeping
  /// both lines has a quad corner there. (A U-turn paths can fix stays one: a dangling path end, whose
  /// patch angle is near 360 degrees, or a tip cut by a traced path.)
  static constexpr double max_tip_angle = CGAL_PI / 2.;

  /// the first condition a patch fails, in the order they are checked
  enum Condition {
    SATISFIED = 0,
    NOT_A_DISK,        ///< more than one boundary loop or a handle
    NOT_CONVEX,        ///< a left turn or a U-turn on the boundary
    BAD_VALENCE,       ///< fewer than 3 or more than 6 corners
    SIDE_LENGTHS,      ///< side lengths violate Equation 1 by more than the shortest side
    SINGULARITIES      ///< singularities inside do not match the number of sides
  };

  /// a path: its vertices and, for each of its edges, the unit field direction it follows
  struct Path
  {
    std::vector<vertex_descriptor> vertices;
    std::vector<Vector_3> directions; ///< `directions[i]` for the edge `vertices[i]`-`vertices[i+1]`
    bool is_feature = false;
  };

  /// a node of the direction graph: direction `direction` (0..3) of the frame at `vertex`
  struct Node
  {
    vertex_descriptor vertex;
    int direction;
  };

  /// a patch of the layout
  struct Patch
  {
    std::vector<face_descriptor> faces;
    std::vector<std::vector<halfedge_descriptor>> loops; ///< boundary loops, patch on the left
    std::vector<std::vector<Turn>> turns; ///< `turns[l][i]`: turn at the target of `loops[l][i]`
    std::vector<vertex_descriptor> corners; ///< vertices of non-straight turns, in loop order
    std::vector<std::vector<std::size_t>> sides; ///< arc ids of each side, from one corner to the next
    std::vector<double> side_lengths;
    std::vector<vertex_descriptor> singularities; ///< singular vertices inside the patch
    int euler_characteristic = 0;
  };

  /// an arc: a maximal chain of path edges between corners and junctions
  struct Arc
  {
    std::vector<halfedge_descriptor> halfedges;
    double length = 0.;                     ///< sum of |edge . field direction|
    std::array<std::ptrdiff_t, 2> patches{{-1, -1}}; ///< patch on the left of `halfedges`, then on the right (-1: none)
  };

  /*!
    builds a layout with no path (one patch per connected component; call `add_feature_paths()` next).

    \tparam FaceFieldMap a readable property map, key `face_descriptor`, value `Vector_3`: one direction of
            the cross of every face (projected into the face plane here)
    \tparam VertexSingularityMap a readable property map, key `vertex_descriptor`, value `int`: the
            singularity index in quarter turns (0 regular, +1 for a valence-3 singularity, -1 for valence 5)
    \tparam NamedParameters a sequence of named parameters

    \param tm the triangle mesh; it must outlive the layout and stay unchanged
    \param field the cross field
    \param singularities the singularity indices
    \param np optional named parameters among the ones listed below

    \pre `CGAL::is_triangle_mesh(tm)`

    \cgalNamedParamsBegin
      \cgalParamNBegin{vertex_point_map}
        \cgalParamDescription{a property map associating points to the vertices of `tm`}
        \cgalParamType{a readable property map, key `vertex_descriptor`, value `Point_3`}
        \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
      \cgalParamNEnd
      \cgalParamNBegin{geom_traits}
        \cgalParamDescription{an instance of a geometric traits class}
        \cgalParamType{`GeomTraits`}
        \cgalParamDefault{a default-constructed `GeomTraits`}
      \cgalParamNEnd
      \cgalParamNBegin{tracing_length_weight}
        \cgalParamDescription{weight of the advance along the field in an arc cost of the direction graph,
          added to the drift; it breaks ties between drift-free paths in favour of the shortest}
        \cgalParamType{`double`}
        \cgalParamDefault{`0.01`}
      \cgalParamNEnd
    \cgalNamedParamsEnd
  */
  template <typename FaceFieldMap, typename VertexSingularityMap,
            typename NamedParameters = parameters::Default_named_parameters>
  Patch_layout(const TriangleMesh& tm, FaceFieldMap field, VertexSingularityMap singularities,
               const NamedParameters& np = parameters::default_values())
    : tm_(tm),
      vindex_{CGAL::get_initialized_vertex_index_map(tm)},
      findex_{CGAL::get_initialized_face_index_map(tm)},
      eindex_{CGAL::get_initialized_edge_index_map(tm)},
      hindex_{CGAL::get_initialized_halfedge_index_map(tm)}
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    if(!CGAL::is_triangle_mesh(tm)) throw std::invalid_argument("Patch_layout: the mesh must be a triangle mesh");
    gt_ = choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
    length_weight_ = choose_parameter(get_parameter(np, internal_np::tracing_length_weight), 0.01);

    verts_.resize(num_vertices(tm));
    points_.resize(num_vertices(tm));
    faces_.resize(num_faces(tm));
    edges_.resize(num_edges(tm));
    for(vertex_descriptor v : vertices(tm)) { verts_.at(vindex_[v]) = v; points_[vindex_[v]] = get(vpm, v); }
    for(face_descriptor f : faces(tm)) faces_.at(findex_[f]) = f;
    for(edge_descriptor e : edges(tm)) edges_.at(eindex_[e]) = e;

    frames_.build(tm, findex_.map, vpm, field, gt_);
    singular_.assign(verts_.size(), 0);
    singularity_index_.assign(verts_.size(), 0);
    for(vertex_descriptor v : vertices(tm)) {
      const int s = get(singularities, v);
      singularity_index_[vindex_[v]] = s;
      singular_[vindex_[v]] = (s != 0);
    }
    build_vertex_frames();
    edge_paths_.assign(edges_.size(), 0);
    edge_features_.assign(edges_.size(), 0);
    dirty_ = true;
    graph_dirty_ = true;
  }

  // the direction graph refers to the layout's own arrays
  Patch_layout(const Patch_layout&) = delete;
  Patch_layout& operator=(const Patch_layout&) = delete;

  /// the mesh
  const TriangleMesh& mesh() const { return tm_; }

  /*!
    adds one path per maximal chain of feature edges (chains stop at vertices where the number of incident
    feature edges is not two; a sharp turn inside a chain is a corner through the turn classification, not
    a chain end).
    \tparam EdgeIsFeatureMap a readable property map, key `edge_descriptor`, value `bool`
    \return the number of paths added
  */
  template <typename EdgeIsFeatureMap>
  std::size_t add_feature_paths(EdgeIsFeatureMap is_feature)
  {
    std::vector<char> feat(edges_.size(), 0), used(edges_.size(), 0);
    std::vector<int> degree(verts_.size(), 0);
    for(std::size_t i = 0; i < edges_.size(); ++i)
      if(get(is_feature, edges_[i])) {
        feat[i] = 1;
        ++degree[vindex_[source(edges_[i], tm_)]];
        ++degree[vindex_[target(edges_[i], tm_)]];
      }
    // a feature chain goes on through a vertex of feature degree two
    auto next_feature = [&](halfedge_descriptor h) -> std::optional<halfedge_descriptor> {
      if(degree[vindex_[target(h, tm_)]] != 2) return std::nullopt;
      for(halfedge_descriptor g : halfedges_around_source(target(h, tm_), tm_)) {
        const std::size_t ei = eindex_.at(edge(g, tm_));
        if(feat[ei] && !used[ei] && g != opposite(h, tm_)) return g;
      }
      return std::nullopt;
    };
    std::size_t added = 0;
    for(std::size_t i = 0; i < edges_.size(); ++i) {
      if(!feat[i] || used[i]) continue;
      used[i] = 1;
      halfedge_descriptor h0 = halfedge(edges_[i], tm_);
      std::vector<halfedge_descriptor> chain{h0};
      for(auto g = next_feature(h0); g; g = next_feature(*g)) { used[eindex_.at(edge(*g, tm_))] = 1; chain.push_back(*g); }
      std::vector<halfedge_descriptor> back;
      for(auto g = next_feature(opposite(h0, tm_)); g; g = next_feature(*g)) { used[eindex_.at(edge(*g, tm_))] = 1; back.push_back(opposite(*g, tm_)); }
      std::reverse(back.begin(), back.end());
      back.insert(back.end(), chain.begin(), chain.end());
      Path p;
      p.is_feature = true;
      p.vertices.push_back(source(back.front(), tm_));
      for(halfedge_descriptor h : back) {
        p.vertices.push_back(target(h, tm_));
        Vector_3 d = points_[vindex_[target(h, tm_)]] - points_[vindex_[source(h, tm_)]];
        const double l = std::sqrt(CGAL::to_double(d * d));
        p.directions.push_back(l > 0. ? d / l : d);
      }
      add_path(std::move(p));
      ++added;
    }
    return added;
  }

  /// adds a path (its consecutive vertices must be adjacent) and returns its id
  std::size_t add_path(Path p)
  {
    for(std::size_t i = 0; i + 1 < p.vertices.size(); ++i) {
      auto e = edge(p.vertices[i], p.vertices[i + 1], tm_);
      if(!e.second) throw std::invalid_argument("Patch_layout::add_path: consecutive vertices are not adjacent");
      ++edge_paths_[eindex_.at(e.first)];
      if(p.is_feature) ++edge_features_[eindex_.at(e.first)];
    }
    paths_.push_back(std::move(p));
    alive_.push_back(1);
    dirty_ = graph_dirty_ = true;
    return paths_.size() - 1;
  }

  /// removes the path `id` (its id is not reused)
  void remove_path(std::size_t id)
  {
    if(id >= paths_.size() || !alive_[id]) throw std::invalid_argument("Patch_layout::remove_path: no such path");
    const Path& p = paths_[id];
    for(std::size_t i = 0; i + 1 < p.vertices.size(); ++i) {
      const std::size_t e = eindex_.at(edge(p.vertices[i], p.vertices[i + 1], tm_).first);
      --edge_paths_[e];
      if(p.is_feature) --edge_features_[e];
    }
    alive_[id] = 0;
    dirty_ = graph_dirty_ = true;
  }

  /*!
    makes the target of `h` a corner of the patch on the left of `h`: a straight turn there becomes a
    right turn. The patch on the other side does not change. Meant for a convex patch that no path can
    split but that has fewer than three corners (see `trace_patch_layout()`); the corner holds while `h`
    is on the boundary of a patch.
    \pre `h` is on a path and is not a border halfedge
  */
  void add_corner(halfedge_descriptor h)
  {
    if(is_border(h, tm_) || !is_cut(edge(h, tm_)))
      throw std::invalid_argument("Patch_layout::add_corner: the halfedge is not on a patch boundary");
    if(added_corner_.empty()) added_corner_.assign(num_halfedges(tm_), 0);
    added_corner_[hindex_[h]] = 1;
    dirty_ = graph_dirty_ = true;
  }

  /// the halfedges given to `add_corner()`, in the order of their indices
  std::vector<halfedge_descriptor> added_corners() const
  {
    std::vector<halfedge_descriptor> r;
    if(added_corner_.empty()) return r;
    for(halfedge_descriptor h : halfedges(tm_))
      if(added_corner_[hindex_[h]]) r.push_back(h);
    return r;
  }

  /// The patches that replace some patches of the layout when paths are added or removed (see
  /// `preview_add_path()`): `old_patches` are the ids of the patches that change, `new_patches` what they
  /// become. Only those patches are rebuilt, so trying a candidate path costs time in the size of the
  /// patches it touches, not of the mesh.
  struct Patch_change
  {
    std::vector<std::size_t> old_patches;
    std::vector<Patch> new_patches;
  };

  /// the change the path `p` would make if it were added (the layout is left as it is)
  Patch_change preview_add_path(const Path& p) { return preview(edge_ids(p), +1, p.is_feature); }

  /// the change removing the path `id` would make (the layout is left as it is)
  Patch_change preview_remove_path(std::size_t id)
  {
    if(id >= paths_.size() || !alive_[id]) throw std::invalid_argument("Patch_layout::preview_remove_path: no such path");
    return preview(edge_ids(paths_[id]), -1, paths_[id].is_feature);
  }

  /// adds the path `p` whose change `c` was computed by `preview_add_path(p)` on the current layout, updating
  /// only the patches it touches; returns the path id. The first new patches take the ids of the old ones.
  std::size_t add_path(Path p, Patch_change c)
  {
    update();
    const std::size_t id = add_path(std::move(p));
    apply(std::move(c));
    return id;
  }

  /// removes the path `id` whose change `c` was computed by `preview_remove_path(id)` on the current layout
  void remove_path(std::size_t id, Patch_change c)
  {
    update();
    remove_path(id);
    apply(std::move(c));
  }

  /// the change removing the edges of the path `id` from its vertex `i` to its vertex `j` (`i < j`) would
  /// make (the layout is left as it is)
  Patch_change preview_remove_path_part(std::size_t id, std::size_t i, std::size_t j)
  {
    if(id >= paths_.size() || !alive_[id] || !(i < j) || j >= paths_[id].vertices.size())
      throw std::invalid_argument("Patch_layout::preview_remove_path_part: no such path part");
    const std::vector<std::size_t> ids = edge_ids(paths_[id]);
    return preview(std::vector<std::size_t>(ids.begin() + std::ptrdiff_t(i), ids.begin() + std::ptrdiff_t(j)), -1,
                   paths_[id].is_feature);
  }

  /// the part of the path `id` from its vertex `i` to its vertex `j` (`i <= j`), with the directions of its edges
  Path path_part(std::size_t id, std::size_t i, std::size_t j) const
  {
    const Path& p = paths_.at(id);
    Path q;
    q.is_feature = p.is_feature;
    q.vertices.assign(p.vertices.begin() + std::ptrdiff_t(i), p.vertices.begin() + std::ptrdiff_t(j) + 1);
    if(p.directions.size() + 1 == p.vertices.size())
      q.directions.assign(p.directions.begin() + std::ptrdiff_t(i), p.directions.begin() + std::ptrdiff_t(j));
    return q;
  }

  /// removes the edges of the path `id` from its vertex `i` to its vertex `j`, with the change `c` computed by
  /// `preview_remove_path_part(id, i, j)` on the current layout: the path is replaced by its parts before `i`
  /// and after `j` (those with at least one edge), whose ids are returned in that order
  std::vector<std::size_t> remove_path_part(std::size_t id, std::size_t i, std::size_t j, Patch_change c)
  {
    update();
    const std::size_t last = paths_.at(id).vertices.size() - 1;
    // copies of the pieces, taken before adding any path (an addition may reallocate the path list)
    std::vector<Path> pieces;
    if(i > 0) pieces.push_back(path_part(id, 0, i));
    if(j < last) pieces.push_back(path_part(id, j, last));
    remove_path(id);
    std::vector<std::size_t> kept;
    for(Path& q : pieces) kept.push_back(add_path(std::move(q)));
    apply(std::move(c));
    return kept;
  }

  /// the number of paths through the edge `e`, feature paths included
  int number_of_paths(edge_descriptor e) const { return edge_paths_[eindex_.at(e)]; }
  /// whether a feature path passes through the edge `e`
  bool is_on_feature_path(edge_descriptor e) const { return edge_features_[eindex_.at(e)] > 0; }

  /// ids of the paths in the layout, in insertion order
  std::vector<std::size_t> path_ids() const
  {
    std::vector<std::size_t> ids;
    for(std::size_t i = 0; i < paths_.size(); ++i) if(alive_[i]) ids.push_back(i);
    return ids;
  }
  /// the path `id`
  const Path& path(std::size_t id) const { return paths_.at(id); }

  /// whether the edge `e` is on a path or on the mesh border (a patch boundary)
  bool is_cut(edge_descriptor e) const { return edge_paths_[eindex_.at(e)] > 0 || is_border(e, tm_); }

  /// the patches
  const std::vector<Patch>& patches() const { update_arcs(); return patches_; }
  /// the patch `p`, without its `sides` (filled by `patches()` only: they need the arcs, which are global)
  const Patch& patch(std::size_t p) const { update(); return patches_.at(p); }
  /// the number of patches
  std::size_t number_of_patches() const { update(); return patches_.size(); }
  /// the arcs
  const std::vector<Arc>& arcs() const { update_arcs(); return arcs_; }
  /// the patch of `f`
  std::size_t patch_id(face_descriptor f) const { update(); return face_patch_[findex_.at(f)]; }

  /// writes the patch id of every face into `face_patch_map` (writable, key `face_descriptor`, value `std::size_t`)
  template <typename FacePatchMap>
  void fill_face_patch_map(FacePatchMap face_patch_map) const
  {
    update();
    for(std::size_t i = 0; i < faces_.size(); ++i) put(face_patch_map, faces_[i], face_patch_[i]);
  }

  /// the first validity condition (disk, convex, 3 to 6 corners) the patch `p` fails, `SATISFIED` if none
  Condition validity(std::size_t p) const
  {
    update();
    return validity(patches_.at(p));
  }

  /// the first validity condition the patch `P` (of this layout or of a `Patch_change`) fails
  Condition validity(const Patch& P) const
  {
    if(P.loops.size() != 1 || P.euler_characteristic != 1) return NOT_A_DISK;
    for(Turn t : P.turns[0]) if(t == LEFT_TURN || t == U_TURN) return NOT_CONVEX;
    if(P.corners.size() < 3 || P.corners.size() > 6) return BAD_VALENCE;
    return SATISFIED;
  }

  /// the first quality condition (Equation 1 within the shortest side; singularities matching the number of
  /// sides, at most one, none in a 4-sided patch) the valid patch `p` fails, `SATISFIED` if none
  Condition quality(std::size_t p) const
  {
    update();
    return quality(patches_.at(p));
  }

  /// the first quality condition the patch `P` (of this layout or of a `Patch_change`) fails
  Condition quality(const Patch& P) const
  {
    const Condition v = validity(P);
    if(v != SATISFIED) return v;
    const std::vector<double>& e = P.side_lengths;
    const std::size_t n = e.size();
    const double tol = *std::min_element(e.begin(), e.end());
    auto E = [&](std::size_t i) { return e[i % n]; };
    for(std::size_t i = 0; i < n; ++i) {
      bool ok = true;
      if(n == 3) ok = E(i) <= E(i + 1) + E(i + 2) + tol;
      else if(n == 4) ok = std::abs(E(i) - E(i + 2)) <= tol;
      else if(n == 5) ok = E(i) + E(i + 1) + E(i + 4) + tol >= E(i + 2) + E(i + 3);
      else ok = E(i) <= E(i + 2) + E(i + 4) + tol;
      if(!ok) return SIDE_LENGTHS;
    }
    if(n == 4 && !P.singularities.empty()) return SINGULARITIES;
    if(P.singularities.size() > 1) return SINGULARITIES;
    if(P.singularities.size() == 1 && 4 - singularity_index_[vindex_.at(P.singularities[0])] != int(n))
      return SINGULARITIES;
    return SATISFIED;
  }

  /// the unit direction `k` (0..3) of the field frame at `v` (in the vertex tangent plane)
  Vector_3 direction(vertex_descriptor v, int k) const { return vframes_[vindex_.at(v)][k & 3]; }

  /// the node of `v` whose direction is closest to `d`
  Node closest_node(vertex_descriptor v, const Vector_3& d) const
  {
    return Node{v, internal::closest_direction(vframes_[vindex_.at(v)], d)};
  }

  /// number of nodes and arcs of the direction graph G (built if needed)
  std::pair<std::size_t, std::size_t> direction_graph_size() { update_graph(); return {graph_.number_of_nodes(), graph_.number_of_arcs()}; }

  /*!
    frees the direction graph G and the arrays of its searches, the largest part of the layout's memory.
    The layout itself does not change; the next `trace()` or `trace_all()` builds G again, whole.
    `quad_remesh()` calls it once the layout is traced, so that the quantization's solvers, in their own
    threads, do not add to it: the peak memory of a whole run fell on every development mesh (rocker_arm
    47 -> 37 MiB, truck 76 -> 62, plate_holes 57 -> 47, fandisk 28 -> 27), with the same outputs.
  */
  void release_direction_graph()
  {
    graph_ = internal::Direction_graph<Vector_3>();
    std::vector<std::vector<std::size_t>>().swap(graph_blocked_);
    std::vector<unsigned char>().swap(graph_mask_);
    std::vector<char>().swap(graph_excluded_);
    std::vector<char>().swap(graph_cut_); // (empty: update_graph() builds G whole)
    graph_dirty_ = true;
  }

  /*!
    traces the cheapest path in G from `start` to the first node of `ends` reached (Boost.Graph's Dijkstra
    stopped at that node); a loop when `start` is one of `ends`. Existing paths are crossed only
    orthogonally. Nodes of singular vertices are not in G. Returns no path when no end can be reached.
    The path is not added to the layout.
  */
  std::optional<Path> trace(const Node& start, const std::vector<Node>& ends)
  {
    return std::move(trace_all({Trace_job{start, &ends}}, 1, []() { return false; }).front());
  }

  /// A search of `trace_all()`: from `start` to the first end node reached. The ends are the nodes of `*ends`
  /// and, when `loop`, `start` itself, but none of the nodes of `start.vertex` when `skip_start_vertex`. Jobs
  /// may share one list `*ends`.
  struct Trace_job
  {
    Node start;
    const std::vector<Node>* ends;
    bool loop = false;              ///< `start` is an end too: the path is then a loop
    bool skip_start_vertex = false; ///< the nodes of `start.vertex` in `*ends` are not ends
  };

  /*!
    traces every job as `trace()` does, in up to `threads` threads (the searches are independent and their
    results do not depend on the number of threads). `stop()` is asked before each search; once it returns
    true, the remaining jobs get no path. Returns the paths in the order of `jobs`.
  */
  template <typename Stop>
  std::vector<std::optional<Path> > trace_all(const std::vector<Trace_job>& jobs, unsigned threads, const Stop& stop)
  {
    update_graph();
    std::vector<std::optional<Path> > out(jobs.size());
    threads = (std::max)(1u, (std::min)(threads, unsigned(jobs.size())));
    graph_.reserve_searches(threads);
    std::atomic<std::size_t> next(0);
    std::atomic<bool> stopped(false);
    // every slot searches with the arrays G keeps for it between calls (reset where the last search went)
    auto work = [&](std::size_t slot) {
      std::vector<std::size_t> end_nodes;
      for(std::size_t j; (j = next++) < jobs.size();) {
        if(stopped || stop()) { stopped = true; break; }
        const Trace_job& job = jobs[j];
        end_nodes.clear();
        for(const Node& n : *job.ends) end_nodes.push_back(node_index(n));
        const std::size_t skip = job.skip_start_vertex ? vindex_.at(job.start.vertex) : std::size_t(-1);
        out[j] = to_path(graph_.shortest_path(node_index(job.start), end_nodes, job.loop, skip, slot));
      }
    };
    if(threads == 1) work(0);
    else {
      std::vector<std::thread> pool;
      std::exception_ptr failure;
      std::mutex failure_mutex;
      for(unsigned t = 0; t < threads; ++t)
        pool.emplace_back([&, t]() {
          try { work(t); } catch(...) {
            std::lock_guard<std::mutex> lock(failure_mutex);
            if(!failure) failure = std::current_exception();
            stopped = true;
          }
        });
      for(auto& th : pool) th.join();
      if(failure) std::rethrow_exception(failure);
    }
    return out;
  }

  /*!
    whether the paths `a` and `b` cross tangentially: they share an edge, or at a shared vertex an edge of
    `a` and an edge of `b` leave it in the same field direction (closest direction in the vertex frame), i.e.
    one runs along the other. A path continuing another one through its end (opposite directions) or
    crossing it orthogonally is not tangential. G refuses every arc that would make a traced path cross
    the layout's paths tangentially.
  */
  bool cross_tangentially(const Path& a, const Path& b) const
  {
    std::map<vertex_descriptor, unsigned> leaving; // bit d: an edge of a leaves the vertex in direction d
    std::map<std::pair<vertex_descriptor, vertex_descriptor>, char> edges_a;
    auto dir = [&](vertex_descriptor v, vertex_descriptor w) {
      const std::size_t i = vindex_.at(v);
      return 1u << internal::closest_direction(vframes_[i], Vector_3(points_[vindex_.at(w)] - points_[i]));
    };
    for(std::size_t i = 0; i + 1 < a.vertices.size(); ++i) {
      const vertex_descriptor x = a.vertices[i], y = a.vertices[i + 1];
      edges_a[std::minmax(x, y)] = 1;
      leaving[x] |= dir(x, y);
      leaving[y] |= dir(y, x);
    }
    for(std::size_t i = 0; i + 1 < b.vertices.size(); ++i) {
      const vertex_descriptor x = b.vertices[i], y = b.vertices[i + 1];
      if(edges_a.count(std::minmax(x, y))) return true;
      auto lx = leaving.find(x), ly = leaving.find(y);
      if(lx != leaving.end() && (lx->second & dir(x, y))) return true;
      if(ly != leaving.end() && (ly->second & dir(y, x))) return true;
    }
    return false;
  }

  /// whether the path `c` crosses a path of the layout tangentially (see `cross_tangentially()`): the same
  /// test against every path at once, in time linear in the length of `c`
  bool crosses_paths_tangentially(const Path& c) const
  {
    auto dir = [&](std::size_t v, std::size_t w) {
      return 1u << internal::closest_direction(vframes_[v], Vector_3(points_[w] - points_[v]));
    };
    auto leaving = [&](std::size_t v) {
      unsigned bits = 0;
      for(halfedge_descriptor h : halfedges_around_source(verts_[v], tm_))
        if(edge_paths_[eindex_.at(edge(h, tm_))] > 0) bits |= dir(v, vindex_.at(target(h, tm_)));
      return bits;
    };
    for(std::size_t i = 0; i + 1 < c.vertices.size(); ++i) {
      const auto e = edge(c.vertices[i], c.vertices[i + 1], tm_);
      if(!e.second || edge_paths_[eindex_.at(e.first)] > 0) return true;
      const std::size_t x = vindex_.at(c.vertices[i]), y = vindex_.at(c.vertices[i + 1]);
      if(leaving(x) & dir(x, y)) return true;
      if(leaving(y) & dir(y, x)) return true;
    }
    return false;
  }

  /// the position of `v`
  const Point_3& point(vertex_descriptor v) const { return points_[vindex_.at(v)]; }
  /// the index of `v` (0 .. number of vertices - 1)
  std::size_t vertex_index(vertex_descriptor v) const { return vindex_.at(v); }
  /// whether `v` is a singularity of the field (it has no node in G)
  bool is_singular(vertex_descriptor v) const { return singular_[vindex_.at(v)] != 0; }
  /// whether a path or the mesh border passes through `v`
  bool is_on_cut(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : halfedges_around_target(v, tm_)) if(is_cut(edge(h, tm_))) return true;
    return false;
  }

  /// the quantization problem in neutral form: per patch its sides as ordered arc ids (cyclic order);
  /// the arc lengths are `arcs()[id].length`
  std::vector<std::vector<std::vector<std::size_t>>> quantization_sides() const
  {
    std::vector<std::vector<std::vector<std::size_t>>> r;
    for(const Patch& P : patches()) r.push_back(P.sides);
    return r;
  }

  /// the figures of the layout
  Patch_layout_statistics statistics() const
  {
    update_arcs();
    Patch_layout_statistics s;
    s.patches = patches_.size();
    for(std::size_t p = 0; p < patches_.size(); ++p) {
      if(validity(p) == SATISFIED) ++s.valid_patches;
      if(quality(p) == SATISFIED) ++s.quality_patches;
      ++s.patches_by_valence[patches_[p].corners.size()];
    }
    s.paths = path_ids().size();
    s.t_junctions = t_junctions_;
    s.seconds = rebuild_seconds_;
    return s;
  }

  /// writes the mesh as an ASCII PLY with one colour per patch (coordinates with 17 significant digits)
  void write_ply(std::ostream& os) const
  {
    update();
    os << std::setprecision(17) << "ply\nformat ascii 1.0\nelement vertex " << verts_.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
       << "element face " << faces_.size() << "\nproperty list uchar int vertex_indices\n"
       << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for(const Point_3& p : points_) os << p.x() << " " << p.y() << " " << p.z() << "\n";
    for(std::size_t i = 0; i < faces_.size(); ++i) {
      os << "3";
      for(vertex_descriptor v : vertices_around_face(halfedge(faces_[i], tm_), tm_)) os << " " << vindex_.at(v);
      const std::size_t c = face_patch_[i] * 2654435761u;
      os << " " << (64 + c % 192) << " " << (64 + (c >> 8) % 192) << " " << (64 + (c >> 16) % 192) << "\n";
    }
  }

  /// writes the paths as CGAL polylines (one line per path: number of points, then the coordinates, with
  /// 17 significant digits)
  void write_polylines(std::ostream& os) const
  {
    os << std::setprecision(17);
    for(std::size_t id : path_ids()) {
      os << paths_[id].vertices.size();
      for(vertex_descriptor v : paths_[id].vertices) { const Point_3& p = points_[vindex_.at(v)]; os << " " << p.x() << " " << p.y() << " " << p.z(); }
      os << "\n";
    }
  }

private:
  std::vector<std::size_t> edge_ids(const Path& p) const
  {
    std::vector<std::size_t> ids;
    for(std::size_t i = 0; i + 1 < p.vertices.size(); ++i) {
      auto e = edge(p.vertices[i], p.vertices[i + 1], tm_);
      if(!e.second) throw std::invalid_argument("Patch_layout: consecutive path vertices are not adjacent");
      ids.push_back(eindex_.at(e.first));
    }
    return ids;
  }

  // Patches touched by changing the path count of `ids` by `delta` (and their feature path count if
  // `feature`), rebuilt with that change applied: a flood fill over the faces of the touched patches only
  // (added cuts only split them, removed cuts only join them, so no other face can be reached).
  Patch_change preview(const std::vector<std::size_t>& ids, int delta, bool feature)
  {
    update();
    Patch_change c;
    for(std::size_t e : ids)
      for(halfedge_descriptor h : {halfedge(edges_[e], tm_), opposite(halfedge(edges_[e], tm_), tm_)})
        if(!is_border(h, tm_)) c.old_patches.push_back(face_patch_[findex_.at(face(h, tm_))]);
    std::sort(c.old_patches.begin(), c.old_patches.end());
    c.old_patches.erase(std::unique(c.old_patches.begin(), c.old_patches.end()), c.old_patches.end());
    for(std::size_t e : ids) { edge_paths_[e] += delta; if(feature) edge_features_[e] += delta; }
    scratch_label_.resize(faces_.size(), std::size_t(-1));
    std::vector<std::size_t> seeds;
    for(std::size_t p : c.old_patches) for(face_descriptor f : patches_[p].faces) seeds.push_back(findex_.at(f));
    std::sort(seeds.begin(), seeds.end());
    for(std::size_t s : seeds) {
      if(scratch_label_[s] != std::size_t(-1)) continue;
      c.new_patches.emplace_back();
      c.new_patches.back().faces = flood(s, c.new_patches.size() - 1, scratch_label_);
    }
    for(Patch& P : c.new_patches) build_boundary(P);
    for(std::size_t s : seeds) scratch_label_[s] = std::size_t(-1);
    for(std::size_t e : ids) { edge_paths_[e] -= delta; if(feature) edge_features_[e] -= delta; }
    return c;
  }

  // replaces the old patches of `c` by its new ones; ids stay 0..n-1 (a patch left without a slot moves
  // into a freed one)
  void apply(Patch_change c)
  {
    std::vector<std::size_t> slots = c.old_patches;
    for(std::size_t k = 0; k < c.new_patches.size(); ++k) {
      std::size_t id;
      if(k < slots.size()) id = slots[k];
      else { id = patches_.size(); patches_.emplace_back(); }
      for(face_descriptor f : c.new_patches[k].faces) face_patch_[findex_.at(f)] = id;
      patches_[id] = std::move(c.new_patches[k]);
    }
    // free the slots left over (fewer patches after a removal), filling them from the end
    std::vector<std::size_t> freed(slots.begin() + std::min(slots.size(), c.new_patches.size()), slots.end());
    std::sort(freed.begin(), freed.end());
    while(!freed.empty()) {
      const std::size_t last = patches_.size() - 1;
      if(freed.back() == last) { patches_.pop_back(); freed.pop_back(); continue; }
      const std::size_t hole = freed.front();
      freed.erase(freed.begin());
      for(face_descriptor f : patches_[last].faces) face_patch_[findex_.at(f)] = hole;
      patches_[hole] = std::move(patches_[last]);
      patches_.pop_back();
    }
    dirty_ = false;
    arcs_dirty_ = true;
  }

  void build_vertex_frames()
  {
    vframes_.assign(verts_.size(), std::array<Vector_3, 4>());
    nbrs_.assign(verts_.size(), {});
    for(std::size_t i = 0; i < verts_.size(); ++i) {
      const vertex_descriptor v = verts_[i];
      Vector_3 n(0, 0, 0);
      std::optional<face_descriptor> ref;
      for(face_descriptor f : faces_around_target(halfedge(v, tm_), tm_)) {
        if(f == GT::null_face()) continue;
        n = n + frames_.normals[findex_.at(f)];
        if(!ref || findex_.at(f) < findex_.at(*ref)) ref = f; // the lowest-index face: deterministic
      }
      for(vertex_descriptor w : vertices_around_target(halfedge(v, tm_), tm_)) nbrs_[i].push_back(vindex_.at(w));
      std::sort(nbrs_[i].begin(), nbrs_[i].end());
      const double nl = std::sqrt(CGAL::to_double(n * n));
      if(!ref || nl == 0.) continue;
      n = n / nl;
      Vector_3 d = frames_.dirs[findex_.at(*ref)][0];
      d = d - n * CGAL::to_double(d * n);
      const double dl = std::sqrt(CGAL::to_double(d * d));
      if(dl == 0.) continue;
      vframes_[i] = internal::cross_directions(Vector_3(d / dl), n);
    }
  }

  std::size_t node_index(const Node& n) const { return 4 * vindex_.at(n.vertex) + std::size_t(n.direction & 3); }
  std::optional<Path> to_path(const std::optional<internal::Graph_path>& gp) const
  {
    if(!gp || gp->vertices.size() < 2) return std::nullopt;
    Path p;
    for(std::size_t i = 0; i < gp->vertices.size(); ++i) {
      p.vertices.push_back(verts_[gp->vertices[i]]);
      if(i + 1 < gp->vertices.size()) p.directions.push_back(vframes_[gp->vertices[i]][gp->directions[i]]);
    }
    return p;
  }

  void update_graph()
  {
    if(!graph_dirty_) return;
    // G depends on the cut edges only: a path added and removed again (a rejected candidate) leaves it as is
    std::vector<char> cut(edges_.size());
    for(std::size_t i = 0; i < edges_.size(); ++i) cut[i] = is_cut(edges_[i]);
    graph_dirty_ = false;
    if(cut == graph_cut_) return;
    // kept as members: the graph refers to them when it computes the arcs of a start node
    std::vector<std::vector<std::size_t>>& blocked = graph_blocked_;
    std::vector<unsigned char>& mask = graph_mask_;
    // blocked neighbours and tangent classes at vertex i, from its cut edges
    auto set_vertex = [&](std::size_t i) {
      blocked[i].clear();
      mask[i] = 0;
      for(halfedge_descriptor h : halfedges_around_target(verts_[i], tm_)) {
        if(!cut[eindex_.at(edge(h, tm_))]) continue;
        const std::size_t j = vindex_.at(source(h, tm_));
        blocked[i].push_back(j);
        mask[i] |= (unsigned char)(1u << (internal::closest_direction(vframes_[i], Vector_3(points_[j] - points_[i])) % 2));
      }
    };
    if(graph_cut_.empty()) {
      blocked.assign(verts_.size(), {});
      mask.assign(verts_.size(), 0);
      for(std::size_t i = 0; i < verts_.size(); ++i) set_vertex(i);
      std::vector<char>& excluded = graph_excluded_;
      excluded = singular_;
      for(std::size_t i = 0; i < verts_.size(); ++i)
        if(vframes_[i][0] == Vector_3(0, 0, 0)) excluded[i] = 1; // no field there
      graph_.build(vframes_, nbrs_, points_, excluded, blocked, mask, length_weight_);
      graph_cut_.swap(cut);
      return;
    }
    // incremental: only the nodes within two rings of a vertex whose cut edges changed get new arcs
    std::vector<std::size_t> changed;
    for(std::size_t e = 0; e < edges_.size(); ++e)
      if(cut[e] != graph_cut_[e]) {
        changed.push_back(vindex_.at(source(edges_[e], tm_)));
        changed.push_back(vindex_.at(target(edges_[e], tm_)));
      }
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    for(std::size_t i : changed) set_vertex(i); // reads the new cut state
    graph_cut_.swap(cut);
    std::vector<std::size_t> ring = changed;
    for(int r = 0; r < 2; ++r) {
      const std::size_t n = ring.size();
      for(std::size_t k = 0; k < n; ++k) ring.insert(ring.end(), nbrs_[ring[k]].begin(), nbrs_[ring[k]].end());
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    }
    graph_.rebuild_nodes(ring);
  }

  // the next boundary halfedge of the loop after `h`, turning around target(h) inside the patch
  halfedge_descriptor next_boundary(halfedge_descriptor h) const
  {
    halfedge_descriptor g = next(h, tm_);
    while(!is_cut(edge(g, tm_))) g = next(opposite(g, tm_), tm_);
    return g;
  }

  Vector_3 vec(halfedge_descriptor h) const
  {
    return points_[vindex_.at(target(h, tm_))] - points_[vindex_.at(source(h, tm_))];
  }

  static double angle(const Vector_3& a, const Vector_3& b)
  {
    const double c = CGAL::to_double(a * b) / std::sqrt(CGAL::to_double(a * a) * CGAL::to_double(b * b));
    return std::acos((std::max)(-1., (std::min)(1., c)));
  }

  // The turn at target(h) between h and the next boundary halfedge `out` (see the class documentation), in
  // quarter turns (positive: convex), and `fan`, the angle of the patch between h and `out` (scaled so that
  // the full turn around a cone vertex is 2 pi).
  struct Turn_measure
  {
    int quarter_turns = 0;
    double fan = 0.;
    halfedge_descriptor out;
  };
  Turn_measure measure_turn(halfedge_descriptor h) const
  {
    const halfedge_descriptor out = next_boundary(h);
    const vertex_descriptor v = target(h, tm_);
    std::size_t f = findex_.at(face(h, tm_));
    const int a = internal::closest_direction(frames_.dirs[f], vec(h));
    Vector_3 d = frames_.dirs[f][a];
    double fan = 0.;
    halfedge_descriptor g = h;
    for(;;) {
      const halfedge_descriptor gn = next(g, tm_); // leaves v inside face(g)
      fan += angle(vec(gn), -vec(g));
      if(is_cut(edge(gn, tm_))) break;
      const std::size_t f2 = findex_.at(face(opposite(gn, tm_), tm_));
      d = internal::transport_across_edge(d, vec(gn), frames_.normals[f], frames_.normals[f2]);
      f = f2;
      g = opposite(gn, tm_);
    }
    const int a2 = internal::closest_direction(frames_.dirs[f], d);
    const int b = internal::closest_direction(frames_.dirs[f], vec(out));
    const int t = ((b - a2) % 4 + 4) % 4;
    double total = 0.;
    bool on_border = false;
    for(halfedge_descriptor k : halfedges_around_target(v, tm_)) {
      if(is_border(k, tm_)) { on_border = true; continue; }
      total += angle(vec(next(k, tm_)), -vec(k));
    }
    if(!on_border && total > 0.) fan *= 2. * CGAL_PI / total; // cone vertices: angles relative to the full turn
    const double measured = (CGAL_PI - fan) / (CGAL_PI / 2.);
    int best = t;
    for(int k = t - 8; k <= t + 8; k += 4)
      if(std::abs(k - measured) < std::abs(best - measured)) best = k;
    return Turn_measure{best, fan, out};
  }

  // whether the edge `e` stays on a patch boundary whatever the paths: it is on a feature path or the border
  bool is_fixed(edge_descriptor e) const { return edge_features_[eindex_.at(e)] > 0 || is_border(e, tm_); }

  // The turn at target(h); a sharp tip between two fixed lines is a corner, not a U-turn (see `max_tip_angle`),
  // and so is a straight turn made a corner by add_corner().
  Turn classify(halfedge_descriptor h) const
  {
    const Turn_measure m = measure_turn(h);
    if(m.quarter_turns == 0) return !added_corner_.empty() && added_corner_[hindex_[h]] ? RIGHT_TURN : STRAIGHT;
    if(m.quarter_turns == 1) return RIGHT_TURN;
    if(m.quarter_turns == -1) return LEFT_TURN;
    if(m.quarter_turns >= 2 && m.fan < max_tip_angle && is_fixed(edge(h, tm_)) && is_fixed(edge(m.out, tm_)))
      return RIGHT_TURN;
    return U_TURN;
  }

  void update() const { if(dirty_) const_cast<Patch_layout*>(this)->rebuild(); }
  void update_arcs() const
  {
    update();
    if(arcs_dirty_) const_cast<Patch_layout*>(this)->build_arcs();
  }

  // The faces reachable from face index `s` without crossing a cut edge, all labelled `id` in `label`
  // (whose unlabelled entries are -1), returned in ascending index order (deterministic patch contents).
  std::vector<face_descriptor> flood(std::size_t s, std::size_t id, std::vector<std::size_t>& label) const
  {
    std::vector<std::size_t> ids{s}, stack{s};
    label[s] = id;
    while(!stack.empty()) {
      const std::size_t fi = stack.back();
      stack.pop_back();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(faces_[fi], tm_), tm_)) {
        if(is_cut(edge(h, tm_))) continue;
        const std::size_t fj = findex_.at(face(opposite(h, tm_), tm_));
        if(label[fj] == std::size_t(-1)) { label[fj] = id; stack.push_back(fj); ids.push_back(fj); }
      }
    }
    std::sort(ids.begin(), ids.end());
    std::vector<face_descriptor> result;
    result.reserve(ids.size());
    for(std::size_t i : ids) result.push_back(faces_[i]);
    return result;
  }

  // Boundary loops, turns, corners, side lengths, inner singularities and Euler characteristic of a patch
  // whose faces are set. Only the patch's own faces and cut edges are looked at, so a patch can be built
  // for a hypothetical set of cut edges (see `preview()`).
  void build_boundary(Patch& P) const
  {
    std::vector<char>& visited = scratch_halfedge_;
    std::vector<char>& on_loop = scratch_on_loop_;
    std::vector<char>& seen = scratch_seen_;
    visited.resize(num_halfedges(tm_), 0);
    on_loop.resize(verts_.size(), 0);
    seen.resize(verts_.size(), 0);
    std::size_t boundary_halfedges = 0;
    for(face_descriptor f : P.faces)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm_), tm_)) {
        if(!is_cut(edge(h, tm_)) || visited[hindex_[h]]) continue;
        std::vector<halfedge_descriptor> loop;
        std::vector<Turn> turns;
        halfedge_descriptor g = h;
        do {
          visited[hindex_[g]] = 1;
          loop.push_back(g);
          turns.push_back(classify(g));
          on_loop[vindex_[target(g, tm_)]] = 1;
          g = next_boundary(g);
        } while(g != h && loop.size() <= 3 * faces_.size());
        boundary_halfedges += loop.size();
        P.loops.push_back(std::move(loop));
        P.turns.push_back(std::move(turns));
      }
    // Euler characteristic of the patch cut open along its boundary: every loop position is a vertex
    std::vector<std::size_t> touched;
    for(face_descriptor f : P.faces)
      for(vertex_descriptor v : vertices_around_face(halfedge(f, tm_), tm_))
        if(!seen[vindex_[v]]) { seen[vindex_[v]] = 1; touched.push_back(vindex_[v]); }
    std::sort(touched.begin(), touched.end());
    std::size_t interior = 0;
    for(std::size_t i : touched)
      if(!on_loop[i]) {
        ++interior;
        if(singular_[i]) P.singularities.push_back(verts_[i]);
      }
    for(std::size_t i : touched) seen[i] = on_loop[i] = 0;
    for(const auto& loop : P.loops) for(halfedge_descriptor g : loop) visited[hindex_[g]] = 0;
    const long V = long(interior + boundary_halfedges);
    const long E = long((3 * P.faces.size() - boundary_halfedges) / 2 + boundary_halfedges);
    P.euler_characteristic = int(V - E + long(P.faces.size()));
    for(std::size_t i = 0; !P.loops.empty() && i < P.loops[0].size(); ++i)
      if(P.turns[0][i] != STRAIGHT) P.corners.push_back(target(P.loops[0][i], tm_));
    // side lengths of the first loop, measured along the field of the patch's own faces
    if(P.loops.empty()) return;
    const auto& L = P.loops[0];
    const auto& T = P.turns[0];
    const std::size_t start = first_side_start(T);
    double len = 0.;
    for(std::size_t j = 0; j < L.size(); ++j) {
      const std::size_t i = (start + j) % L.size();
      const auto& dirs = frames_.dirs[findex_.at(face(L[i], tm_))];
      const Vector_3 e = vec(L[i]);
      len += std::abs(CGAL::to_double(e * dirs[internal::closest_direction(dirs, e)]));
      if(T[i] != STRAIGHT || j + 1 == L.size()) { P.side_lengths.push_back(len); len = 0.; }
    }
  }

  // sides start after a corner so that the loop's origin does not split a side
  static std::size_t first_side_start(const std::vector<Turn>& T)
  {
    for(std::size_t i = 0; i < T.size(); ++i) if(T[i] != STRAIGHT) return (i + 1) % T.size();
    return 0;
  }

  void rebuild()
  {
    CGAL::Real_timer timer;
    timer.start();
    face_patch_.assign(faces_.size(), std::size_t(-1));
    patches_.clear();
    for(std::size_t s = 0; s < faces_.size(); ++s) {
      if(face_patch_[s] != std::size_t(-1)) continue;
      patches_.emplace_back();
      patches_.back().faces = flood(s, patches_.size() - 1, face_patch_);
    }
    for(Patch& P : patches_) build_boundary(P);
    dirty_ = false;
    arcs_dirty_ = true;
    rebuild_seconds_ = timer.time();
  }

  // Arcs (maximal chains of cut edges broken at corners and at vertices of cut degree other than 2), the
  // arcs of every side and the T-junctions: global, built when asked for.
  void build_arcs()
  {
    std::vector<char> corner(verts_.size(), 0);
    for(const Patch& P : patches_)
      for(std::size_t l = 0; l < P.loops.size(); ++l)
        for(std::size_t i = 0; i < P.loops[l].size(); ++i)
          if(P.turns[l][i] != STRAIGHT) corner[vindex_.at(target(P.loops[l][i], tm_))] = 1;
    std::vector<int> cut_degree(verts_.size(), 0);
    for(std::size_t i = 0; i < edges_.size(); ++i)
      if(is_cut(edges_[i])) { ++cut_degree[vindex_.at(source(edges_[i], tm_))]; ++cut_degree[vindex_.at(target(edges_[i], tm_))]; }
    auto breaks = [&](vertex_descriptor v) { const std::size_t i = vindex_.at(v); return corner[i] || cut_degree[i] != 2; };
    auto next_cut = [&](halfedge_descriptor h) -> halfedge_descriptor {
      for(halfedge_descriptor g : halfedges_around_source(target(h, tm_), tm_))
        if(g != opposite(h, tm_) && is_cut(edge(g, tm_))) return g;
      return h;
    };
    arcs_.clear();
    arc_of_edge_.assign(edges_.size(), std::size_t(-1));
    for(std::size_t i = 0; i < edges_.size(); ++i) {
      if(!is_cut(edges_[i]) || arc_of_edge_[i] != std::size_t(-1)) continue;
      halfedge_descriptor h = halfedge(edges_[i], tm_);
      // walk back to the start of the chain (or once around a closed chain)
      halfedge_descriptor s = h;
      while(!breaks(source(s, tm_))) {
        const halfedge_descriptor p = opposite(next_cut(opposite(s, tm_)), tm_);
        if(p == h) break;
        s = p;
      }
      Arc a;
      halfedge_descriptor g = s;
      do {
        arc_of_edge_[eindex_.at(edge(g, tm_))] = arcs_.size();
        a.halfedges.push_back(g);
        if(breaks(target(g, tm_))) break;
        g = next_cut(g);
      } while(g != s);
      for(int side = 0; side < 2; ++side) {
        const halfedge_descriptor k = side == 0 ? a.halfedges.front() : opposite(a.halfedges.front(), tm_);
        if(!is_border(k, tm_)) a.patches[side] = std::ptrdiff_t(face_patch_[findex_.at(face(k, tm_))]);
      }
      for(halfedge_descriptor k : a.halfedges) {
        const halfedge_descriptor kf = is_border(k, tm_) ? opposite(k, tm_) : k;
        const auto& dirs = frames_.dirs[findex_.at(face(kf, tm_))];
        const Vector_3 e = vec(k);
        a.length += std::abs(CGAL::to_double(e * dirs[internal::closest_direction(dirs, e)]));
      }
      arcs_.push_back(std::move(a));
    }
    // sides of the first loop: arcs from one corner to the next (the same split as the side lengths)
    t_junctions_ = 0;
    std::vector<char> tj(verts_.size(), 0);
    for(Patch& P : patches_) {
      P.sides.clear();
      if(P.loops.empty()) continue;
      const auto& L = P.loops[0];
      const auto& T = P.turns[0];
      const std::size_t start = first_side_start(T);
      std::vector<std::size_t> side;
      std::size_t last_arc = std::size_t(-1);
      for(std::size_t j = 0; j < L.size(); ++j) {
        const std::size_t i = (start + j) % L.size();
        const std::size_t arc = arc_of_edge_[eindex_.at(edge(L[i], tm_))];
        if(arc != last_arc) { side.push_back(arc); last_arc = arc; }
        const std::size_t vi = vindex_.at(target(L[i], tm_));
        if(T[i] == STRAIGHT && cut_degree[vi] >= 3 && !tj[vi]) { tj[vi] = 1; ++t_junctions_; }
        if(T[i] != STRAIGHT || j + 1 == L.size()) {
          P.sides.push_back(side);
          side.clear();
          last_arc = std::size_t(-1);
        }
      }
    }
    arcs_dirty_ = false;
  }

  const TriangleMesh& tm_;
  GeomTraits gt_;
  double length_weight_ = 0.01;
  std::vector<vertex_descriptor> verts_;
  std::vector<face_descriptor> faces_;
  std::vector<edge_descriptor> edges_;
  std::vector<Point_3> points_;
  // O(1) indices of the mesh elements (0 .. n-1)
  template <typename Map>
  struct Index
  {
    Map map;
    template <typename Key> std::size_t at(const Key& k) const { return std::size_t(get(map, k)); }
    template <typename Key> std::size_t operator[](const Key& k) const { return std::size_t(get(map, k)); }
  };
  Index<decltype(CGAL::get_initialized_vertex_index_map(std::declval<const TriangleMesh&>()))> vindex_;
  Index<decltype(CGAL::get_initialized_face_index_map(std::declval<const TriangleMesh&>()))> findex_;
  Index<decltype(CGAL::get_initialized_edge_index_map(std::declval<const TriangleMesh&>()))> eindex_;
  Index<decltype(CGAL::get_initialized_halfedge_index_map(std::declval<const TriangleMesh&>()))> hindex_;
  internal::Face_frames<TriangleMesh, GeomTraits> frames_;
  std::vector<std::array<Vector_3, 4>> vframes_;
  std::vector<std::vector<std::size_t>> nbrs_;
  std::vector<char> singular_;
  std::vector<int> singularity_index_;
  std::vector<int> edge_paths_;
  std::vector<int> edge_features_; // number of feature paths on each edge
  std::vector<char> added_corner_;  // per halfedge: its target is a corner of its patch (add_corner())
  std::vector<Path> paths_;
  std::vector<char> alive_;
  internal::Direction_graph<Vector_3> graph_;
  std::vector<std::vector<std::size_t>> graph_blocked_;
  std::vector<unsigned char> graph_mask_;
  std::vector<char> graph_excluded_;
  std::vector<char> graph_cut_; // the cut edges G was built for
  bool graph_dirty_ = true;
  bool dirty_ = true;
  bool arcs_dirty_ = true;
  // scratch flags of build_boundary(), all zero between calls
  mutable std::vector<char> scratch_halfedge_, scratch_on_loop_, scratch_seen_;
  std::vector<std::size_t> scratch_label_; // face labels of preview(), all -1 between calls
  std::vector<std::size_t> face_patch_;
  std::vector<Patch> patches_;
  std::vector<Arc> arcs_;
  std::vector<std::size_t> arc_of_edge_;
  std::size_t t_junctions_ = 0;
  double rebuild_seconds_ = 0.;
};

namespace internal {

// The path through the vertices `vs` of `layout`'s mesh, each edge's direction its own unit vector: a path
// made of straight segments (a cut) rather than traced along the field.
template <typename Layout>
typename Layout::Path straight_path(const Layout& layout, std::vector<typename Layout::vertex_descriptor> vs)
{
  typename Layout::Path q;
  q.vertices = std::move(vs);
  for(std::size_t i = 0; i + 1 < q.vertices.size(); ++i) {
    const auto e = layout.point(q.vertices[i + 1]) - layout.point(q.vertices[i]);
    const double l = std::sqrt(CGAL::to_double(e * e));
    q.directions.push_back(l > 0. ? e / l : e);
  }
  return q;
}

} // namespace internal

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_PATCH_LAYOUT_H
