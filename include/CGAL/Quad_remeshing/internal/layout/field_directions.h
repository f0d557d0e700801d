// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The four directions of a per-face cross field, the matching between neighbouring frames and the
// per-vertex frames the direction graph uses.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_LAYOUT_FIELD_DIRECTIONS_H
#define CGAL_QUAD_REMESHING_INTERNAL_LAYOUT_FIELD_DIRECTIONS_H

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/// The four unit directions of a cross given by one representative `d` in the plane of normal `n`;
/// direction `k` is `d` rotated by `k` quarter turns counterclockwise around `n`.
template <typename Vector_3>
std::array<Vector_3, 4> cross_directions(const Vector_3& d, const Vector_3& n)
{
  const Vector_3 t = CGAL::cross_product(n, d);
  return {{d, t, -d, -t}};
}

/// Index (0..3) of the direction of `dirs` closest to `v` (largest dot product; the lowest index wins a tie
/// so that the result is deterministic).
template <typename Vector_3>
int closest_direction(const std::array<Vector_3, 4>& dirs, const Vector_3& v)
{
  int best = 0;
  double best_dot = -1e300;
  for(int k = 0; k < 4; ++k) {
    const double d = CGAL::to_double(dirs[k] * v);
    if(d > best_dot + 1e-15) { best_dot = d; best = k; }
  }
  return best;
}

/// Rotates `v` around the common edge direction `e` from the plane of normal `n_from` into the plane of
/// normal `n_to` (the parallel transport across an edge of two flat faces).
template <typename Vector_3>
Vector_3 transport_across_edge(const Vector_3& v, const Vector_3& e, const Vector_3& n_from, const Vector_3& n_to)
{
  const double el = std::sqrt(CGAL::to_double(e * e));
  if(el == 0.) return v;
  const Vector_3 eu = e / el;
  const Vector_3 b_from = CGAL::cross_product(n_from, eu), b_to = CGAL::cross_product(n_to, eu);
  // coordinates in the frame (edge, in-plane normal to the edge) are kept
  return eu * CGAL::to_double(v * eu) + b_to * CGAL::to_double(v * b_from);
}

/// Per-face frames of a cross field: the four unit directions of every face, the face normals.
template <typename TriangleMesh, typename GT>
struct Face_frames
{
  typedef typename GT::Vector_3 Vector_3;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  std::vector<std::array<Vector_3, 4>> dirs; // indexed by face index
  std::vector<Vector_3> normals;

  template <typename FaceIndexMap, typename VPM, typename FaceFieldMap>
  void build(const TriangleMesh& tm, FaceIndexMap fim, VPM vpm, FaceFieldMap field, const GT& gt)
  {
    dirs.assign(num_faces(tm), std::array<Vector_3, 4>());
    normals.assign(num_faces(tm), Vector_3(0, 0, 0));
    for(face_descriptor f : faces(tm)) {
      const Vector_3 n = Polygon_mesh_processing::compute_face_normal(
          f, tm, CGAL::parameters::vertex_point_map(vpm).geom_traits(gt));
      Vector_3 d = get(field, f);
      d = d - n * CGAL::to_double(d * n); // keep the representative in the face plane
      const double l = std::sqrt(CGAL::to_double(d * d));
      d = (l > 0.) ? d / l : Vector_3(0, 0, 0);
      const std::size_t i = get(fim, f);
      normals[i] = n;
      dirs[i] = cross_directions(d, n);
    }
  }
};

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
