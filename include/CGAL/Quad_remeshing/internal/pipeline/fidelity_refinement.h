// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pipeline's last step: patches whose smoothed quads stray from the surface get more quads, and the
// result is kept if it is closer (quad_remesh() and the command line share it).

#ifndef CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_FIDELITY_REFINEMENT_H
#define CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_FIDELITY_REFINEMENT_H

#include <CGAL/Quad_remeshing/assemble_quad_mesh.h>
#include <CGAL/Quad_remeshing/quad_mesh_quality.h>
#include <CGAL/Quad_remeshing/quantize_patch_sides.h>
#include <CGAL/Quad_remeshing/Report.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <iostream>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/*
  How far a quad mesh is from each patch of `d` on the triangle mesh `tm`, both ways: from the vertices
  of the patch's triangles to the quads (a tip of the patch cut short, quads across a bend), and from
  points of the quads (their vertices; the centre, the edge midpoints and the centroids of the two
  triangles of each quad: quality::for_each_soup_sample()) to the triangles, each such
  distance counting for the patch of the triangle nearest to it (a quad bridging a groove). The quads are
  triangulated as the package's quality measures do (internal::quality::triangulate_soup(): a quad along
  its shorter diagonal). The tree of `tm` and the patch of each face are built once, for every quad
  mesh measured.
*/
template <typename TriangleMesh>
class Patch_distances_to_quads
{
  typedef typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef typename K::Triangle_3 Triangle;
  typedef CGAL::AABB_triangle_primitive<K, typename std::vector<Triangle>::const_iterator> Quad_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Quad_primitive>> Quad_tree;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh> Tri_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Tri_primitive>> Tri_tree;

public:
  Patch_distances_to_quads(const TriangleMesh& tm, const Patch_layout_description<TriangleMesh>& d)
    : tm_(tm), d_(d), surface_(faces(tm).first, faces(tm).second, tm)
  {
    surface_.accelerate_distance_queries();
    const auto vim = get(CGAL::vertex_index, tm);
    const auto fim = get(CGAL::face_index, tm);
    std::size_t face_slots = 0; // (indices are dense only without removed elements)
    for(auto v : vertices(tm)) vertex_slots_ = (std::max)(vertex_slots_, std::size_t(get(vim, v)) + 1);
    for(auto f : faces(tm)) face_slots = (std::max)(face_slots, std::size_t(get(fim, f)) + 1);
    patch_of_.assign(face_slots, d.patches.size());
    for(std::size_t p = 0; p < d.patches.size(); ++p)
      for(auto f : d.patches[p].faces) patch_of_[std::size_t(get(fim, f))] = p;
  }

  // the distance of each patch of `d` to `qmesh` (absolute)
  template <typename QuadMesh>
  std::vector<double> operator()(const QuadMesh& qmesh) const
  {
    std::vector<double> distance(d_.patches.size(), 0.);
    std::vector<Point> points;
    quality::Index_polygons polygons;
    quality::mesh_to_soup(qmesh, get(CGAL::vertex_point, qmesh), points, polygons);
    const std::vector<Triangle> triangles = quality::triangulate_soup<K>(points, polygons);
    if(triangles.empty() || d_.patches.empty()) return distance;

    // from the triangle mesh to the quads
    Quad_tree quads(triangles.begin(), triangles.end());
    quads.accelerate_distance_queries();
    const auto vpm = get(CGAL::vertex_point, tm_);
    const auto vim = get(CGAL::vertex_index, tm_);
    std::vector<double> at_vertex(vertex_slots_, -1.);
    for(std::size_t p = 0; p < d_.patches.size(); ++p)
      for(auto f : d_.patches[p].faces)
        for(auto v : vertices_around_face(halfedge(f, tm_), tm_))
        {
          double& x = at_vertex[std::size_t(get(vim, v))];
          if(x < 0.) x = std::sqrt(CGAL::to_double(quads.squared_distance(get(vpm, v))));
          distance[p] = (std::max)(distance[p], x);
        }

    // from the quads (vertices, centres, edge midpoints, triangle centroids) to the triangle mesh
    const auto fim = get(CGAL::face_index, tm_);
    auto measure = [&](const Point& s) {
      const auto hit = surface_.closest_point_and_primitive(s);
      const std::size_t p = patch_of_[std::size_t(get(fim, hit.second))];
      if(p < distance.size())
        distance[p] = (std::max)(distance[p], std::sqrt(CGAL::to_double(CGAL::squared_distance(s, hit.first))));
    };
    quality::for_each_soup_sample(points, polygons, triangles, measure);
    return distance;
  }

private:
  const TriangleMesh& tm_;
  const Patch_layout_description<TriangleMesh>& d_;
  Tri_tree surface_;
  std::size_t vertex_slots_ = 0;
  std::vector<std::size_t> patch_of_; // the patch of each face index (d.patches.size(): none)
};

struct Fidelity_refinement_statistics
{
  double tolerance = 0.;        // absolute
  std::size_t rounds = 0;       // quad meshes made again
  std::size_t kept = 0;         // of which were closer and kept
  std::size_t refined_patches = 0;
  bool second_round_skipped = false; // the first round added too many quads for a second
  double distance_before = 0.;  // largest patch distance of the first quad mesh (absolute)
  double distance_after = 0.;   // of the quad mesh kept
  double seconds = 0.;

  // the figures as a report record, the distances as fractions of `diagonal`
  Report report(double diagonal) const
  {
    Report r = Report::object();
    r["tolerance"] = diagonal > 0. ? tolerance / diagonal : 0.;
    r["rounds"] = rounds;
    r["kept"] = kept;
    r["refined_patches"] = refined_patches;
    r["second_round_skipped"] = second_round_skipped;
    r["distance_before"] = diagonal > 0. ? distance_before / diagonal : 0.;
    r["distance_after"] = diagonal > 0. ? distance_after / diagonal : 0.;
    r["seconds"] = seconds;
    return r;
  }
};

constexpr std::size_t max_fidelity_rounds = 2;
// more quads are kept only if they bring the largest distance down by a tenth at least: a round adds
// whole strips of quads across the mesh (face: 60% more quads), not worth a closeness the evaluators
// cannot tell from the old one
constexpr double keep_below = 0.9;
// nor if they are more than this many times the first quads: the arcs raised in a patch add strips of
// quads that run across the whole mesh, and two rounds took a box of 445 quads to 1712
constexpr double max_fidelity_growth = 1.5;
// and a second round only if the first added at most a fifth: each round makes the quads again, and on
// truck, whose first round added 32%, the second took 14 s and was not kept
constexpr double max_growth_for_second_round = 1.2;

/*
  `current` is the smoothed quad mesh of the arc counts `counts`, solutions of `problem` (arcs and
  patches of `d`). While some patch is farther than `tolerance` (absolute) from it
  (Patch_distances_to_quads), at most max_fidelity_rounds times: the arcs of those patches get a
  minimum of half as many edges again as they have, `solve(problem, counts)` solves again, and
  `make(problem, counts, candidate)` assembles and smooths the quads of the new counts into the empty
  `candidate` (it may change `counts`, e.g. for the count repairs of the assembly). The candidate is
  handed to `keep(candidate)` (which replaces `current` with it) if its largest distance is smaller by a
  tenth (keep_below) and it has at most max_fidelity_growth times the quads of `current` at the start;
  otherwise the refinement stops. The second round starts only if the quads kept have at most
  max_growth_for_second_round times the first ones. The sizing field sees the curvature of the triangle mesh only: it
  cannot tell that a patch's quads cut a thin tip short, nor where the smoothing pulls them off it.
  `counts` ends with the counts of the quads kept. A failure of a later assembly keeps `current`.
*/
template <typename TriangleMesh, typename QuadMesh, typename Solve, typename Make, typename Keep>
Fidelity_refinement_statistics refine_for_fidelity(const TriangleMesh& tm, const Patch_layout_description<TriangleMesh>& d,
                                                   Side_quantization_problem problem, std::vector<int>& counts,
                                                   const Solve& solve, const Make& make, const Keep& keep,
                                                   const QuadMesh& current, double tolerance, bool verbose)
{
  Fidelity_refinement_statistics st;
  st.tolerance = tolerance;
  if(!(tolerance > 0.)) return st;
  CGAL::Real_timer timer;
  timer.start();
  const Patch_distances_to_quads<TriangleMesh> patch_distances(tm, d);
  std::vector<double> distance = patch_distances(current);
  double worst = distance.empty() ? 0. : *std::max_element(distance.begin(), distance.end());
  st.distance_before = st.distance_after = worst;
  std::vector<bool> refined(d.patches.size(), false);
  const std::size_t first_faces = std::size_t(num_faces(current));
  while(st.rounds < max_fidelity_rounds && worst > tolerance)
  {
    if(st.rounds > 0 && double(num_faces(current)) > max_growth_for_second_round * double(first_faces))
    {
      st.second_round_skipped = true;
      break;
    }
    std::size_t far = 0;
    for(std::size_t p = 0; p < d.patches.size(); ++p)
    {
      if(!(distance[p] > tolerance)) continue;
      ++far;
      if(!refined[p]) ++st.refined_patches;
      refined[p] = true;
      for(const auto& side : problem.patches[p])
        for(std::size_t a : side)
          if(problem.arcs[a].fixed == 0)
            problem.arcs[a].minimum = (std::max)(problem.arcs[a].minimum, counts[a] + (std::max)(1, counts[a] / 2));
    }
    ++st.rounds;
    std::vector<int> c = counts;
    QuadMesh candidate;
    std::vector<double> candidate_distance;
    try
    {
      solve(problem, c);
      make(problem, c, candidate);
      candidate_distance = patch_distances(candidate);
    }
    catch(const std::exception& e)
    {
      if(verbose) std::cerr << "[fidelity] more quads on " << far << " patches failed (" << e.what() << "): kept the quads before\n";
      break;
    }
    const double candidate_worst =
      candidate_distance.empty() ? 0. : *std::max_element(candidate_distance.begin(), candidate_distance.end());
    const bool closer = candidate_worst < keep_below * worst;
    const bool affordable = double(num_faces(candidate)) <= max_fidelity_growth * double(first_faces);
    if(verbose)
      std::cerr << "[fidelity] " << far << " patches farther than " << tolerance << " from their quads (at most "
                << worst << "): with more quads (" << num_faces(candidate) << ") " << candidate_worst
                << (!closer ? ", not closer by a tenth: not kept\n"
                            : !affordable ? ", but more than 1.5 times the first quads: not kept\n" : ", kept\n");
    if(!closer || !affordable) break;
    keep(candidate);
    ++st.kept;
    counts = c;
    distance = candidate_distance;
    worst = candidate_worst;
    st.distance_after = worst;
  }
  st.seconds = timer.time();
  return st;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_FIDELITY_REFINEMENT_H
