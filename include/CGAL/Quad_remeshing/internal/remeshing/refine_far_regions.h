// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// After the uniform pass: where the remeshed surface strays from the input (a thin tip cut off, a bend
// tighter than the edge length), remesh_for_quadrangulation() remeshes again at half the length. This
// header finds those regions.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_REMESHING_REFINE_FAR_REGIONS_H
#define CGAL_QUAD_REMESHING_INTERNAL_REMESHING_REFINE_FAR_REGIONS_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// a far region's faces are refined when they are farther than this share of `remeshing_tolerance` from
// the input (the rest is a margin for the points between the samples)
constexpr double far_region_share = 0.7;

// The faces of `tmesh` that are farther than `max_distance` from the input (`input`: an AABB tree of its
// triangles; samples: each face's centroid and edge midpoints), and the faces nearest to the input points
// (`input_points`, its vertices) farther than that from `tmesh`, grown by the ring of faces around their
// vertices; sorted by descriptor. `largest_distance` receives the largest distance measured either way (a
// face's samples after the first one farther than `max_distance` are not measured).
template <typename TriangleMesh, typename VPM, typename InputTree, typename Point>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
far_faces(const TriangleMesh& tmesh, VPM vpm, const InputTree& input, const std::vector<Point>& input_points,
          double max_distance, double& largest_distance)
{
  typedef boost::graph_traits<TriangleMesh> GTr;
  typedef typename GTr::face_descriptor face_descriptor;
  typedef typename GTr::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VPM> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

  const double max_squared = max_distance * max_distance;
  double largest = 0.;
  auto marked = get(CGAL::dynamic_face_property_t<bool>(), tmesh);
  for(face_descriptor f : faces(tmesh)) put(marked, f, false);
  std::vector<face_descriptor> seeds;
  // the remeshed surface to the input
  for(face_descriptor f : faces(tmesh))
  {
    const auto h = halfedge(f, tmesh);
    const Point& p = get(vpm, source(h, tmesh));
    const Point& q = get(vpm, target(h, tmesh));
    const Point& r = get(vpm, target(next(h, tmesh), tmesh));
    const Point samples[4] = {CGAL::centroid(p, q, r), CGAL::midpoint(p, q), CGAL::midpoint(q, r), CGAL::midpoint(r, p)};
    for(const Point& s : samples)
    {
      const double d = CGAL::to_double(input.squared_distance(s));
      largest = (std::max)(largest, d);
      if(d > max_squared)
      {
        put(marked, f, true);
        seeds.push_back(f);
        break; // (the face's other samples are not measured)
      }
    }
  }
  // the input to the remeshed surface
  {
    Tree tree(faces(tmesh).first, faces(tmesh).second, tmesh, vpm);
    tree.accelerate_distance_queries();
    for(const Point& p : input_points)
    {
      const auto cp = tree.closest_point_and_primitive(p);
      const double d = CGAL::to_double(CGAL::squared_distance(p, cp.first));
      largest = (std::max)(largest, d);
      if(d > max_squared && !get(marked, cp.second))
      {
        put(marked, cp.second, true);
        seeds.push_back(cp.second);
      }
    }
  }
  largest_distance = std::sqrt(largest);
  std::vector<face_descriptor> result = seeds;
  for(face_descriptor f : seeds)
    for(vertex_descriptor v : vertices_around_face(halfedge(f, tmesh), tmesh))
      for(face_descriptor g : faces_around_target(halfedge(v, tmesh), tmesh))
        if(g != GTr::null_face() && !get(marked, g))
        {
          put(marked, g, true);
          result.push_back(g);
        }
  std::sort(result.begin(), result.end());
  return result;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_REMESHING_REFINE_FAR_REGIONS_H
