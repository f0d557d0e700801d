// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pipeline's assembly: patterns for the arc counts, and new counts where the patterns of some
// patches cannot be glued (quad_remesh() and the command line share it).

#ifndef CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_ASSEMBLY_REPAIRS_H
#define CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_ASSEMBLY_REPAIRS_H

#include <CGAL/Quad_remeshing/assemble_quad_mesh.h>
#include <CGAL/Quad_remeshing/quadrangulate_polygon.h>
#include <CGAL/Quad_remeshing/quantize_patch_sides.h>

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// The pattern of every patch of `d` for the arc counts `counts`.
template <typename TriangleMesh>
std::vector<Polygon_quadrangulation> patch_patterns(const Patch_layout_description<TriangleMesh>& d,
                                                    const std::vector<int>& counts)
{
  std::vector<Polygon_quadrangulation> patterns;
  patterns.reserve(d.patches.size());
  for(const auto& patch : d.patches)
  {
    std::vector<int> e;
    for(const auto& side : patch.sides)
    {
      int c = 0;
      for(const auto& sa : side) c += counts[sa.arc];
      e.push_back(c);
    }
    patterns.push_back(quadrangulate_polygon(e));
  }
  return patterns;
}

struct Repaired_assembly
{
  Quad_assembly_statistics stats;
  std::vector<Polygon_quadrangulation> patterns; // the patterns assembled
  std::size_t count_repairs = 0;                 // solves made again because patterns conflicted
  std::size_t repaired_patches = 0;              // patches whose arcs got more edges for that
};

constexpr std::size_t max_count_repairs = 4;

// Assembles the quad mesh for the arc counts `counts`, solutions of `problem` (whose arcs and patches
// are those of `d`). Where the patterns of some patches conflict (Quad_assembly_conflict: a chord of a
// pattern and an arc of few edges join the same two vertices), every arc of those patches gets a
// minimum above its count and `solve(problem, counts)` runs again, at most max_count_repairs times;
// `counts` then holds the counts assembled. The last conflict is rethrown.
template <typename TriangleMesh, typename QuadMesh, typename EdgeFeatureMap, typename Solve>
Repaired_assembly assemble_with_count_repairs(const TriangleMesh& tm, const Patch_layout_description<TriangleMesh>& d,
                                              Side_quantization_problem problem, std::vector<int>& counts,
                                              const Solve& solve, QuadMesh& qmesh, EdgeFeatureMap qmesh_edge_is_feature,
                                              bool verbose)
{
  Repaired_assembly r;
  std::vector<bool> repaired(d.patches.size(), false);
  for(;;)
  {
    r.patterns = patch_patterns(d, counts);
    try
    {
      r.stats = assemble_quad_mesh(tm, d, counts, r.patterns, qmesh, qmesh_edge_is_feature, verbose);
      return r;
    }
    catch(const Quad_assembly_conflict& conflict)
    {
      if(r.count_repairs == max_count_repairs) throw;
      for(std::size_t p : conflict.patches)
      {
        if(!repaired[p]) ++r.repaired_patches;
        repaired[p] = true;
        for(const auto& side : problem.patches[p])
          for(std::size_t a : side)
            if(problem.arcs[a].fixed == 0) problem.arcs[a].minimum = (std::max)(problem.arcs[a].minimum, counts[a] + 1);
      }
      if(verbose)
        std::cerr << "[assemble] " << conflict.what() << ": " << conflict.patches.size()
                  << " patches get more edges, solving again\n";
      solve(problem, counts);
      ++r.count_repairs;
    }
  }
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_ASSEMBLY_REPAIRS_H
