// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangles of one patch as an indexed mesh cut open along the patch's boundary arcs.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_ASSEMBLY_CUT_OPEN_PATCH_H
#define CGAL_QUAD_REMESHING_INTERNAL_ASSEMBLY_CUT_OPEN_PATCH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/*
  A patch's triangles with one local vertex per fan of patch triangles around a mesh vertex that
  the cut edges do not separate. A patch whose boundary walks an arc twice (a bridge to an inner
  loop, a slit, the seam of a band) is a disk only once cut open this way: without the copies, the
  two sides of such an arc would share their vertices and the map onto the polygon would fold.
*/
template <typename TriangleMesh>
class Cut_open_patch
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

public:
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef std::unordered_set<edge_descriptor, boost::hash<edge_descriptor>> Edge_set;

  /// The edges of `tm` along a patch's sides: `sides` is a range of sides, each a range of side arcs
  /// whose `arc` indexes `arcs`, an arc's `vertices` being its chain of mesh vertices (the layout
  /// description of `assemble_quad_mesh()`); the cut edges of the patch.
  template <typename Sides, typename Arcs>
  static Edge_set edges_along(const TriangleMesh& tm, const Sides& sides, const Arcs& arcs)
  {
    Edge_set edges;
    for(const auto& side : sides)
      for(const auto& side_arc : side)
      {
        const auto& chain = arcs[side_arc.arc].vertices;
        for(std::size_t q = 0; q + 1 < chain.size(); ++q)
        {
          const auto h = halfedge(chain[q], chain[q + 1], tm);
          if(h.second) edges.insert(edge(h.first, tm));
        }
      }
    return edges;
  }

  /// `cut_edges`: the patch's boundary edges
  Cut_open_patch(const TriangleMesh& tm, const std::vector<face_descriptor>& faces, const Edge_set& cut_edges)
    : tm_(tm)
  {
    corners_.resize(faces.size());
    for(std::size_t i = 0; i < faces.size(); ++i)
    {
      face_index_.emplace(faces[i], i);
      int c = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(faces[i], tm), tm))
      {
        if(c == 3) throw std::invalid_argument("assemble_quad_mesh: the mesh must be triangulated");
        corners_[i][std::size_t(c++)] = target(h, tm);
      }
      if(c != 3) throw std::invalid_argument("assemble_quad_mesh: the mesh must be triangulated");
    }
    // union-find over the corners (face, corner): corners of one vertex in two triangles that share
    // an uncut edge belong to one fan
    std::vector<std::size_t> parent(3 * faces.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto find = [&](std::size_t x) {
      while(parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    auto unite = [&](std::size_t a, std::size_t b) {
      a = find(a);
      b = find(b);
      if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
    };
    for(std::size_t i = 0; i < faces.size(); ++i)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(faces[i], tm), tm))
      {
        const face_descriptor g = face(opposite(h, tm), tm);
        if(g == GT::null_face()) continue;
        const auto it = face_index_.find(g);
        if(it == face_index_.end()) continue;
        if(cut_edges.count(edge(h, tm))) continue;
        const vertex_descriptor s = source(h, tm), t = target(h, tm);
        unite(slot(i, s), slot(it->second, s));
        unite(slot(i, t), slot(it->second, t));
      }
    // local vertices, numbered in the order of their first corner
    std::vector<std::size_t> id_of_root(parent.size(), std::size_t(-1));
    local_of_slot_.resize(parent.size());
    for(std::size_t x = 0; x < parent.size(); ++x)
    {
      const std::size_t r = find(x);
      if(id_of_root[r] == std::size_t(-1))
      {
        id_of_root[r] = vertex_of.size();
        vertex_of.push_back(corners_[x / 3][x % 3]);
      }
      local_of_slot_[x] = id_of_root[r];
    }
    triangles.resize(faces.size());
    for(std::size_t i = 0; i < faces.size(); ++i)
      for(std::size_t c = 0; c < 3; ++c) triangles[i][c] = local_of_slot_[3 * i + c];
  }

  /// The local copies of `u` and `w` seen from the patch triangle on the left of the mesh edge
  /// from `u` to `w`; false if that triangle is not in the patch.
  bool left_of(vertex_descriptor u, vertex_descriptor w, std::size_t& local_u, std::size_t& local_w) const
  {
    const auto h = halfedge(u, w, tm_);
    if(!h.second) return false;
    const face_descriptor f = face(h.first, tm_);
    if(f == GT::null_face()) return false;
    const auto it = face_index_.find(f);
    if(it == face_index_.end()) return false;
    local_u = local_of_slot_[slot(it->second, u)];
    local_w = local_of_slot_[slot(it->second, w)];
    return true;
  }

  std::vector<vertex_descriptor> vertex_of;               ///< local vertex -> mesh vertex
  std::vector<std::array<std::size_t, 3>> triangles;      ///< in the order of the patch's faces

private:
  std::size_t slot(std::size_t face, vertex_descriptor v) const
  {
    for(std::size_t c = 0; c < 3; ++c)
      if(corners_[face][c] == v) return 3 * face + c;
    throw std::logic_error("cut_open_patch: a vertex is not a corner of the triangle");
  }

  const TriangleMesh& tm_;
  std::unordered_map<face_descriptor, std::size_t, boost::hash<face_descriptor>> face_index_;
  std::vector<std::array<vertex_descriptor, 3>> corners_;
  std::vector<std::size_t> local_of_slot_;
};

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_ASSEMBLY_CUT_OPEN_PATCH_H
