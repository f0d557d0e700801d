// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sampled surface and feature-line distances between two polygon soups.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUALITY_DISTANCES_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUALITY_DISTANCES_H

#include <CGAL/Quad_remeshing/internal/quality/soup_figures.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <thread>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {
namespace quality {

// Triangles of a soup: a quad is cut along its shorter diagonal, a larger polygon is triangulated
// as a hole (a fan if that fails), and zero-area triangles are dropped since they hold no samples
// and only slow the tree down.
template <typename K>
std::vector<typename K::Triangle_3> triangulate_soup(const std::vector<typename K::Point_3>& pts,
                                                     const Index_polygons& polygons)
{
  typedef typename K::Point_3 Point_3;
  typedef typename K::Triangle_3 Triangle_3;
  std::vector<Triangle_3> out;
  std::size_t n = 0; // an upper bound: zero-area triangles are dropped
  for(const std::vector<std::size_t>& f : polygons) n += f.size() < 3 ? 0 : f.size() - 2;
  out.reserve(n);
  auto add = [&](const Point_3& a, const Point_3& b, const Point_3& c) {
    Triangle_3 t(a, b, c);
    if(!t.is_degenerate()) out.push_back(t);
  };
  for(const std::vector<std::size_t>& f : polygons)
  {
    if(f.size() < 3) continue;
    if(f.size() == 3) { add(pts[f[0]], pts[f[1]], pts[f[2]]); continue; }
    if(f.size() == 4)
    {
      const std::array<Point_3, 4> p = {pts[f[0]], pts[f[1]], pts[f[2]], pts[f[3]]};
      if(CGAL::squared_distance(p[0], p[2]) <= CGAL::squared_distance(p[1], p[3]))
      { add(p[0], p[1], p[2]); add(p[0], p[2], p[3]); }
      else
      { add(p[1], p[2], p[3]); add(p[1], p[3], p[0]); }
      continue;
    }
    std::vector<Point_3> polyline;
    for(std::size_t v : f) polyline.push_back(pts[v]);
    std::vector<CGAL::Triple<int, int, int>> tris;
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polyline, std::back_inserter(tris));
    if(tris.size() + 2 == f.size())
      for(const auto& t : tris) add(polyline[t.first], polyline[t.second], polyline[t.third]);
    else
      for(std::size_t i = 1; i + 1 < f.size(); ++i) add(polyline[0], polyline[i], polyline[i + 1]);
  }
  return out;
}

// Calls `sample(point)` on every vertex of the soup's polygons, on the centre and every edge midpoint of
// each polygon (with three corners or more), and on the centroid of each of `triangles` (the soup's
// triangulate_soup()): where a quad mesh strays from a surface at or between its vertices (a quad across a
// groove, a vertex inside a thin blade of the surface, a twisted quad whose triangle bulges away while
// its centre and edge midpoints stay near).
template <typename Point_3, typename Triangle_3, typename Sample>
void for_each_soup_sample(const std::vector<Point_3>& pts, const Index_polygons& polygons,
                          const std::vector<Triangle_3>& triangles, const Sample& sample)
{
  std::vector<bool> used(pts.size(), false);
  for(const std::vector<std::size_t>& f : polygons)
  {
    if(f.size() < 3) continue;
    typename CGAL::Kernel_traits<Point_3>::Kernel::Vector_3 sum = CGAL::NULL_VECTOR;
    for(std::size_t i : f) { sum = sum + (pts[i] - CGAL::ORIGIN); used[i] = true; }
    sample(CGAL::ORIGIN + sum / double(f.size()));
    for(std::size_t i = 0; i < f.size(); ++i) sample(CGAL::midpoint(pts[f[i]], pts[f[(i + 1) % f.size()]]));
  }
  for(std::size_t i = 0; i < pts.size(); ++i)
    if(used[i]) sample(pts[i]);
  for(const Triangle_3& t : triangles) sample(CGAL::centroid(t));
}

// Runs `work(begin, end)` over [0, n) split into `threads` contiguous chunks; each index is
// computed independently, so the result does not depend on the number of threads.
template <typename Work>
void parallel_chunks(std::size_t n, unsigned threads, const Work& work)
{
  threads = (std::max)(1u, threads);
  if(threads == 1 || n < 4096) { work(std::size_t(0), n); return; }
  std::vector<std::thread> pool;
  const std::size_t chunk = (n + threads - 1) / threads;
  for(unsigned t = 0; t < threads; ++t)
  {
    const std::size_t b = (std::min)(n, t * chunk), e = (std::min)(n, b + chunk);
    if(b < e) pool.emplace_back([&work, b, e]() { work(b, e); });
  }
  for(std::thread& th : pool) th.join();
}

// Distances from query points to the primitives of a tree. Consecutive queries usually come from
// the same triangle or segment, so the previous closest point is a good hint.
template <typename Tree, typename Point_3>
std::vector<double> distances_to_tree(const Tree& tree, const std::vector<Point_3>& queries, unsigned threads)
{
  std::vector<double> d(queries.size(), std::numeric_limits<double>::infinity());
  if(tree.empty() || queries.empty()) return d;
  parallel_chunks(queries.size(), threads, [&](std::size_t b, std::size_t e) {
    auto hint = tree.closest_point_and_primitive(queries[b]);
    d[b] = std::sqrt(CGAL::to_double(CGAL::squared_distance(queries[b], hint.first)));
    for(std::size_t i = b + 1; i < e; ++i)
    {
      hint = tree.closest_point_and_primitive(queries[i], hint);
      d[i] = std::sqrt(CGAL::to_double(CGAL::squared_distance(queries[i], hint.first)));
    }
  });
  return d;
}

// One direction of the Hausdorff distance: the referenced vertices of A and about `n_samples`
// points spread uniformly over A's area, measured against the triangles of B.
struct One_sided_distance
{
  double max = 0.;        // vertices and area samples
  double sum = 0.;        // area samples only (so that the mean is area-weighted)
  double sum_squares = 0.;
  std::size_t area_samples = 0, vertex_samples = 0;
  std::array<double, 3> max_point = {{0., 0., 0.}}; // where the maximum is reached (on A)
};

template <typename K, typename Tree>
One_sided_distance one_sided_distance(const std::vector<typename K::Point_3>& pts,
                                      const Index_polygons& polygons,
                                      const std::vector<typename K::Triangle_3>& triangles,
                                      const Tree& other, std::size_t n_samples, unsigned seed,
                                      unsigned threads)
{
  typedef typename K::Point_3 Point_3;
  One_sided_distance r;
  std::vector<Point_3> q;
  std::vector<char> referenced(pts.size(), 0);
  for(const std::vector<std::size_t>& f : polygons)
    for(std::size_t v : f) referenced[v] = 1;
  for(std::size_t v = 0; v < pts.size(); ++v)
    if(referenced[v]) q.push_back(pts[v]);
  r.vertex_samples = q.size();

  double area = 0.;
  for(const auto& t : triangles) area += std::sqrt(CGAL::to_double(t.squared_area()));
  if(area > 0. && n_samples > 0)
  {
    // Each triangle gets its expected number of samples, the fractional part being decided by a
    // coin toss, so that small triangles are neither over- nor under-represented.
    CGAL::Random rng(seed);
    const double density = double(n_samples) / area;
    for(const auto& t : triangles)
    {
      const double expected = std::sqrt(CGAL::to_double(t.squared_area())) * density;
      std::size_t k = std::size_t(std::floor(expected));
      if(rng.get_double() < expected - double(k)) ++k;
      const auto e1 = t[1] - t[0], e2 = t[2] - t[0];
      for(std::size_t i = 0; i < k; ++i)
      {
        double u = rng.get_double(), v = rng.get_double();
        if(u + v > 1.) { u = 1. - u; v = 1. - v; }
        q.push_back(t[0] + u * e1 + v * e2);
      }
    }
  }
  const std::vector<double> d = distances_to_tree(other, q, threads);
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    if(d[i] > r.max)
    {
      r.max = d[i];
      r.max_point = {{CGAL::to_double(q[i].x()), CGAL::to_double(q[i].y()), CGAL::to_double(q[i].z())}};
    }
    if(i < r.vertex_samples) continue;
    r.sum += d[i];
    r.sum_squares += d[i] * d[i];
    ++r.area_samples;
  }
  return r;
}

// Samples segments every `step`: each sample is the midpoint of a piece and carries its length;
// the segment ends are added with zero weight so that they count for the maximum only.
template <typename K>
void sample_segments(const std::vector<typename K::Segment_3>& segments, double step,
                     std::vector<typename K::Point_3>& samples, std::vector<double>& weights)
{
  for(const auto& s : segments)
  {
    const double length = std::sqrt(CGAL::to_double(s.squared_length()));
    const std::size_t n = (std::max)(std::size_t(1), std::size_t(std::ceil(length / step)));
    const auto dir = s.target() - s.source();
    for(std::size_t i = 0; i < n; ++i)
    {
      samples.push_back(s.source() + ((double(i) + 0.5) / double(n)) * dir);
      weights.push_back(length / double(n));
    }
    samples.push_back(s.source());
    weights.push_back(0.);
    samples.push_back(s.target());
    weights.push_back(0.);
  }
}

template <typename K>
struct Tree_types
{
  typedef std::vector<typename K::Triangle_3> Triangles;
  typedef std::vector<typename K::Segment_3> Segments;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, typename Triangles::const_iterator>>> Triangle_tree;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, typename Segments::const_iterator>>> Segment_tree;
};

} // namespace quality
} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_QUALITY_DISTANCES_H
