// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quantization that meets a requested number of quads (quad_remesh()'s `number_of_quads`, the CLI's --faces).

#ifndef CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_QUAD_COUNT_H
#define CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_QUAD_COUNT_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/quadrangulate_polygon.h>
#include <CGAL/Quad_remeshing/quantize_patch_sides.h>
#include <CGAL/Quad_remeshing/internal/pipeline/layout_conversion.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// The number of quads the patterns of quadrangulate_polygon() have for these arc counts (the assembly
// may merge or leave out a few at slit tips).
inline std::size_t number_of_quads(const Side_quantization_problem& pb, const std::vector<int>& counts)
{
  std::size_t n = 0;
  for(const auto& patch : pb.patches)
  {
    std::vector<int> e;
    for(const auto& side : patch)
    {
      int c = 0;
      for(std::size_t a : side) c += counts[a];
      e.push_back(c);
    }
    n += quadrangulate_polygon(e).quads.size();
  }
  return n;
}

struct Quad_count_quantization
{
  Pipeline_quantization_problem qp;  // the problem of the last solve
  Side_quantization_statistics stats; // its solve
  double quad_edge_length = 0.;       // the length it was made for
  std::size_t solves = 0;
  std::size_t predicted_quads = 0;    // number_of_quads() of the result (0 without a wanted count)

  // the figures, added to the quantize stage's report record
  void add_to(Report& r) const
  {
    r["face_count_solves"] = solves;
    r["face_count_quad_edge_length"] = quad_edge_length;
    r["face_count_predicted_quads"] = predicted_quads;
  }
};

// Builds the pipeline's quantization problem for `quad_edge_length` and solves it into `counts` with
// `solve(problem, counts)` (which returns the solve's Side_quantization_statistics). With `wanted_quads`
// > 0, the arcs' counts overshoot what a length from the area promises (rounding up is cheaper than
// down, bent feature lines and small patches take extra edges): the quad count the counts give is
// checked and the length made longer until it is within 10% of the request, in at most 4 solves. The
// count goes as length^-k: k = 2 first, then k measured on the last two solves (between 0.5 and 2).
// Only longer: the triangle mesh was made for the first length.
template <typename TriangleMesh, typename Layout, typename EdgeIsFeatureMap, typename Solve>
Quad_count_quantization
quantize_for_quad_count(const TriangleMesh& tm, const Layout& layout,
                        const Quadrangulation_layout<TriangleMesh, Layout>& ql, EdgeIsFeatureMap edge_is_feature,
                        double quad_edge_length, double sizing_tolerance, double feature_tolerance,
                        double surface_tolerance, std::size_t wanted_quads, std::vector<int>& counts,
                        const Solve& solve, double component_resolution = default_component_resolution)
{
  Quad_count_quantization r;
  double length = quad_edge_length, last_length = 0., last_count = 0.;
  for(;;)
  {
    r.qp = pipeline_quantization_problem(tm, layout, ql, edge_is_feature, length, sizing_tolerance,
                                         feature_tolerance, surface_tolerance, component_resolution);
    r.stats = solve(r.qp.problem, counts);
    r.quad_edge_length = length;
    ++r.solves;
    if(wanted_quads == 0) break;
    r.predicted_quads = number_of_quads(r.qp.problem, counts);
    const double ratio = double(r.predicted_quads) / double(wanted_quads);
    if(ratio < 1.1 || r.solves == 4) break;
    double k = 2.;
    if(last_count > 0. && double(r.predicted_quads) < last_count)
      k = (std::min)(2., (std::max)(0.5, std::log(last_count / double(r.predicted_quads)) / std::log(length / last_length)));
    last_length = length;
    last_count = double(r.predicted_quads);
    length *= std::pow(ratio, 1. / k);
  }
  return r;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_QUAD_COUNT_H
