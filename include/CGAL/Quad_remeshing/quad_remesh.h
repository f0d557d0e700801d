// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The whole pipeline in one call.

#ifndef CGAL_QUAD_REMESHING_QUAD_REMESH_H
#define CGAL_QUAD_REMESHING_QUAD_REMESH_H

#include <CGAL/Quad_remeshing/Patch_layout.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/assemble_quad_mesh.h>
#include <CGAL/Quad_remeshing/cross_field.h>
#include <CGAL/Quad_remeshing/detect_feature_edges.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/quadrangulate_polygon.h>
#include <CGAL/Quad_remeshing/quantize_patch_sides.h>
#include <CGAL/Quad_remeshing/remesh_for_quadrangulation.h>
#include <CGAL/Quad_remeshing/smooth_quad_mesh.h>
#include <CGAL/Quad_remeshing/refine_patch_layout.h>
#include <CGAL/Quad_remeshing/trace_patch_layout.h>
#include <CGAL/Quad_remeshing/internal/pipeline/assembly_repairs.h>
#include <CGAL/Quad_remeshing/internal/pipeline/layout_conversion.h>
#include <CGAL/Quad_remeshing/internal/pipeline/quad_count.h>
#include <CGAL/Quad_remeshing/internal/pipeline/fidelity_refinement.h>
#include <CGAL/Quad_remeshing/internal/pipeline/quad_sizing.h>
#include <CGAL/Quad_remeshing/internal/pipeline/time_budget.h>
#include <CGAL/Quad_remeshing/internal/pipeline/tip_snapping.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// Removed elements of a Surface_mesh stay in its arrays until collected; other models have none.
template <typename Mesh>
void collect_garbage(Mesh&) {}
template <typename P>
void collect_garbage(CGAL::Surface_mesh<P>& sm) { sm.collect_garbage(); }

// quad_remesh() on Surface_mesh input and output (every stage is run on a Surface_mesh, whose indices
// stay dense once its garbage is collected)
template <typename TriangleMesh, typename QuadMesh, typename NamedParameters>
Report quad_remesh_on_surface_meshes(const TriangleMesh& tmesh, QuadMesh& qmesh, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type K;
  typedef Patch_layout<TriangleMesh, K> Layout;
  namespace QRP = parameters;

  CGAL::Real_timer timer;
  timer.start();
  Report report = Report::object();
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const std::function<void(const std::string&)> no_callback = [](const std::string&) {};
  const auto progress = choose_parameter(get_parameter(np, CGAL::internal_np::callback), no_callback);
  const double angle = choose_parameter(get_parameter(np, internal_np::feature_angle), 35.);
  const double gap_angle =
    choose_parameter(get_parameter(np, internal_np::feature_gap_angle), internal::default_feature_gap_angle(angle));
  const unsigned threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 1u);
  internal::Time_budget budget(choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), 0.));

  TriangleMesh tm(tmesh);
  auto feature = get(CGAL::dynamic_edge_property_t<bool>(), tm);
  auto corner = get(CGAL::dynamic_vertex_property_t<bool>(), tm);

  progress("features");
  report["features"] = detect_feature_edges(tm, feature,
    QRP::combine(QRP::feature_angle(angle).verbose(verbose), QRP::feature_gap_angle(gap_angle),
                 QRP::vertex_is_feature_corner_map(corner))).report();

  progress("remesh");
  const std::size_t wanted_quads = choose_parameter(get_parameter(np, internal_np::number_of_quads), std::size_t(0));
  const double length = choose_parameter(get_parameter(np, internal_np::quad_edge_length),
                                         wanted_quads > 0 ? quad_edge_length_from_face_count(tm, wanted_quads)
                                                          : default_quad_edge_length(tm));
  const bool adaptive = choose_parameter(get_parameter(np, internal_np::adaptive_remeshing), false);
  const bool hold_sharp = choose_parameter(get_parameter(np, internal_np::hold_sharp_edges), true);
  const double resolution =
    choose_parameter(get_parameter(np, internal_np::component_resolution), internal::default_component_resolution);
  report["remesh"] = remesh_for_quadrangulation(tm, feature,
    QRP::combine(QRP::quad_edge_length(length).verbose(verbose), QRP::adaptive_remeshing(adaptive),
                 QRP::hold_sharp_edges(hold_sharp), QRP::component_resolution(resolution),
                 QRP::remeshing_tolerance(choose_parameter(get_parameter(np, internal_np::remeshing_tolerance),
                                                           internal::default_remeshing_tolerance)),
                 QRP::feature_angle(angle), QRP::vertex_is_feature_corner_map(corner),
                 QRP::far_region_rounds(choose_parameter(get_parameter(np, internal_np::far_region_rounds), 0u)))).report();
  internal::collect_garbage(tm); // later stages index elements densely

  progress("field");
  auto field = get(CGAL::dynamic_face_property_t<typename K::Vector_3>(), tm);
  auto singularity = get(CGAL::dynamic_vertex_property_t<int>(), tm);
  report["field"] = compute_cross_field(tm, feature, field,
    QRP::combine(CGAL::parameters::verbose(verbose),
                 QRP::curvature_alignment_weight(
                   choose_parameter(get_parameter(np, internal_np::curvature_alignment_weight),
                                    internal::default_curvature_alignment_weight)),
                 QRP::curvature_smoothing_steps(
                   choose_parameter(get_parameter(np, internal_np::curvature_smoothing_steps),
                                    internal::default_curvature_smoothing_steps)))).report();
  report["singularities"] =
    compute_cross_field_singularities(tm, feature, field, singularity, CGAL::parameters::verbose(verbose)).report();

  progress("layout");
  auto layout_ptr = std::make_unique<Layout>(tm, field, singularity);
  const auto layout_np =
    QRP::combine(CGAL::parameters::verbose(verbose).maximum_running_time(budget.stage_limit(internal::layout_time_share)),
                 QRP::number_of_threads(threads));
  Trace_patch_layout_statistics layout_stats = trace_patch_layout(tm, feature, *layout_ptr, layout_np);
  // where patches stay non-convex for want of a vertex, the mesh is refined and the layout repaired (unless
  // turned off)
  std::optional<Refine_patch_layout_statistics> refinement;
  if(choose_parameter(get_parameter(np, internal_np::layout_refinement), true))
    refinement = refine_patch_layout(tm, feature, field, singularity, layout_ptr, layout_stats, layout_np);
  layout_ptr->release_direction_graph(); // (no more paths are traced)
  const Layout& layout = *layout_ptr;
  report["layout"] = layout_stats.report();
  if(refinement) report["layout"]["refinement"] = refinement->report();
  budget.record("layout", report["layout"]);

  progress("quantize");
  const internal::Quadrangulation_layout<TriangleMesh, Layout> polygons(tm, layout);
  std::vector<int> counts;
  auto solve = [&](const Side_quantization_problem& problem, std::vector<int>& c) {
    return quantize_patch_sides(problem, c, QRP::number_of_threads(threads)
                                              .maximum_running_time(budget.stage_limit(internal::quantize_time_share)));
  };
  // a count of quads asks for the uniform size that gives it: no sizing tolerance unless given
  const internal::Quad_count_quantization qc = internal::quantize_for_quad_count(
    tm, layout, polygons, feature, length,
    choose_parameter(get_parameter(np, internal_np::sizing_tolerance),
                     wanted_quads > 0 ? 0. : internal::default_sizing_tolerance),
    choose_parameter(get_parameter(np, internal_np::feature_tolerance), internal::default_feature_tolerance),
    choose_parameter(get_parameter(np, internal_np::surface_tolerance),
                     wanted_quads > 0 ? 0. : internal::default_surface_tolerance),
    wanted_quads, counts, solve, resolution);
  const internal::Pipeline_quantization_problem& qp = qc.qp;
  report["quantize"] = qc.stats.report();
  budget.record("quantize", report["quantize"]);
  if(wanted_quads > 0) qc.add_to(report["quantize"]);
  report["quantize"]["bent_feature_arcs"] = qp.bent_feature_arcs;
  report["quantize"]["bent_surface_arcs"] = qp.bent_surface_arcs;
  if(!qp.sizing.empty())
    report["quantize"]["smallest_local_quad_edge_length"] = *std::min_element(qp.sizing.begin(), qp.sizing.end());

  progress("quadrangulate");
  const auto description = internal::layout_description(tm, layout, polygons, feature);
  auto qfeature = get(CGAL::dynamic_edge_property_t<bool>(), qmesh);
  const internal::Repaired_assembly assembly =
    internal::assemble_with_count_repairs(tm, description, qp.problem, counts, solve, qmesh, qfeature, verbose);
  report["quadrangulate"] = assembly.stats.report();
  report["quadrangulate"]["count_repairs"] = assembly.count_repairs;
  report["quadrangulate"]["repaired_patches"] = assembly.repaired_patches;

  progress("smooth");
  CGAL::Real_timer smoothing;
  smoothing.start();
  report["smooth"] = smooth_quad_mesh(qmesh, tm, feature,
                                      CGAL::parameters::edge_is_constrained_map(qfeature).verbose(verbose)
                                        .maximum_running_time(budget.stage_limit(internal::smooth_time_share))).report();
  budget.record("smooth", report["smooth"]);

  progress("fidelity");
  // where the smoothed quads stray from the surface, more quads (see internal::refine_for_fidelity())
  const double fidelity = choose_parameter(get_parameter(np, internal_np::fidelity_tolerance),
                                           wanted_quads > 0 ? 0. : internal::default_fidelity_tolerance);
  const double rebuild_seconds = assembly.stats.seconds + smoothing.time();
  if(fidelity > 0. && budget.limited() && budget.left() < 3. * rebuild_seconds)
  {
    budget.degraded("fidelity", "no time left for more quads where the quads stray from the surface");
    report["fidelity"]["skipped_for_time_limit"] = true;
  }
  else
  {
    // The quads kept by the refinement and then by the tips go into `better` (a new mesh each time: see
    // internal::copy_quad_mesh()), and into `qmesh` once at the end.
    std::unique_ptr<QuadMesh> better;
    std::vector<bool> better_feature; // the constrained edges of `better`, in the order of edges()
    std::vector<bool> made_feature;   // those of the quads make() made last
    auto make = [&](const Side_quantization_problem& problem, std::vector<int>& c, QuadMesh& out) {
      auto out_feature = get(CGAL::dynamic_edge_property_t<bool>(), out);
      internal::assemble_with_count_repairs(tm, description, problem, c, solve, out, out_feature, false);
      smooth_quad_mesh(out, tm, feature, CGAL::parameters::edge_is_constrained_map(out_feature)
                                           .maximum_running_time(budget.stage_limit(internal::smooth_time_share)));
      made_feature.clear();
      for(auto e : edges(out)) made_feature.push_back(get(out_feature, e));
    };
    auto keep = [&](QuadMesh& candidate) { // (the quad mesh make() made last)
      better = std::make_unique<QuadMesh>(std::move(candidate));
      better_feature = made_feature;
    };
    const double diagonal = internal::mesh_bbox_diagonal(tm);
    const internal::Fidelity_refinement_statistics fs = internal::refine_for_fidelity(
      tm, description, qp.problem, counts, solve, make, keep, qmesh, fidelity * diagonal, verbose);
    report["fidelity"] = fs.report(diagonal);

    // quad vertices onto the input's tips that the quads cut off (see internal::snap_quads_to_input_tips())
    const QuadMesh& current = better ? *better : qmesh;
    auto current_feature = get(CGAL::dynamic_edge_property_t<bool>(), current);
    {
      std::size_t i = 0;
      for(auto e : edges(current)) put(current_feature, e, better ? bool(better_feature[i++]) : bool(get(qfeature, e)));
    }
    auto smooth_held = [&](QuadMesh& m, const auto& m_feature, const auto& held) {
      smooth_quad_mesh(m, tm, feature, CGAL::parameters::edge_is_constrained_map(m_feature).vertex_is_constrained_map(held)
                                         .number_of_iterations(internal::tip_smoothing_iterations)
                                         .maximum_running_time(budget.stage_limit(internal::smooth_time_share)));
    };
    std::unique_ptr<QuadMesh> snapped;
    auto keep_tips = [&](QuadMesh& candidate, const auto&) { snapped = std::make_unique<QuadMesh>(std::move(candidate)); };
    const double input_diagonal = internal::mesh_bbox_diagonal(tmesh);
    const internal::Tip_snapping_statistics ts = internal::snap_quads_to_input_tips(
      tmesh, current, current_feature, fidelity * input_diagonal, smooth_held, keep_tips, verbose);
    report["fidelity"]["tips"] = ts.report(input_diagonal);
    if(snapped || better)
    {
      const QuadMesh& result = snapped ? *snapped : *better;
      CGAL::clear(qmesh);
      CGAL::copy_face_graph(result, qmesh);
    }
  }
  report["time_limit"] = budget.report();
  report["seconds"] = timer.time();
  return report;
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef

  turns a triangle mesh into a pure-quad mesh that reproduces its feature lines, running every stage
  with its defaults: `detect_feature_edges()`, `remesh_for_quadrangulation()` (on a copy of `tmesh`),
  `compute_cross_field()` and `compute_cross_field_singularities()`, `Patch_layout`,
  `trace_patch_layout()` and `refine_patch_layout()` (unless `layout_refinement` is false),
  `quantize_patch_sides()`, `quadrangulate_polygon()` per patch,
  `assemble_quad_mesh()` and `smooth_quad_mesh()`. Where the patterns of some patches cannot be glued
  (`Quad_assembly_conflict`), the arcs of those patches get more edges and the counts are solved again
  (at most 4 times; the `quadrangulate` record's `count_repairs` and `repaired_patches` say how often
  and for how many patches). Last, where the smoothed quads stray from the triangle mesh farther than
  `fidelity_tolerance` (a tip thinner than a quad cut short, quads across a groove), the arcs of those
  patches get half as many edges again, the counts are solved again and the quads assembled and smoothed
  again; the new quads replace the old ones if they are closer by a tenth at least and at most 1.5 times
  as many as the first (at most 2 rounds, the second only if the first added at most a fifth of the
  quads; the `fidelity` record says what was done). Then the input vertices still farther than
  `fidelity_tolerance` from the quads (the tip of an ear or a tusk, narrower than a quad) each take the
  nearest free quad vertex (not on a feature line or the border, within two mean quad edge lengths, its
  normal agreeing, one per quad edge length or, if that is not closer, per two, at most 64), which moves
  onto it and is held while the quads are smoothed 10 more times; the result is kept if the largest
  distance between the input and the quads, both ways, falls and no more quads are inverted, and the
  tips it left get the next round (at most 3, the tips taken before still held; the `fidelity` record's
  `tips`). Last, if the quads are still farther than `fidelity_tolerance` from the input, their free
  vertices farther than half of it move onto the input (the remeshed triangles the smoothing projects
  onto can themselves be that far from it where it bends tightly), each as far as its quads stay turned
  the same way and keep a fair shape, kept if closer (`tips`: `pulled`, `pulled_kept`).

  \code{.cpp}
  Mesh tmesh, qmesh;
  CGAL::Quad_remeshing::read_and_repair("fandisk.off", tmesh);
  CGAL::Quad_remeshing::quad_remesh(tmesh, qmesh);
  \endcode

  @tparam TriangleMesh a model of `FaceListGraph` with an internal point property map (e.g.
          `CGAL::Surface_mesh`, or `CGAL::Polyhedron_3`, which need not have ids); the stages run on
          a `CGAL::Surface_mesh` of the points of the geometric traits, a copy of `tmesh` unless it is one
  @tparam QuadMesh a model of `MutableFaceGraph` (e.g. `CGAL::Surface_mesh` or `CGAL::Polyhedron_3`); a
          mesh of another type than that `CGAL::Surface_mesh` is cleared and gets a copy of its quads
  @tparam NamedParameters a sequence of named parameters

  @param tmesh the input triangle mesh (not changed)
  @param qmesh the output, empty on entry
  @param np an optional sequence of named parameters among the ones listed below; they are also
         passed on to the stages (e.g. `feature_angle`, `quad_edge_length`, `number_of_threads`)

  \cgalNamedParamsBegin
    \cgalParamNBegin{quad_edge_length}
      \cgalParamDescription{the target edge length of the quads}
      \cgalParamType{`double`}
      \cgalParamDefault{`default_quad_edge_length(tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{number_of_quads}
      \cgalParamDescription{if positive, the approximate number of quads of the output: the remeshing is made for
                            `quad_edge_length_from_face_count(tmesh, n)`, the sizing tolerance is 0 unless given,
                            and the quad edge length of the quantization grows until its arc counts give at most
                            10% more quads than asked for (at most 4 solves; a layout with more patches than the
                            count allows keeps it above); ignored for the remeshing if `quad_edge_length` is given}
      \cgalParamType{`std::size_t`}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{sizing_tolerance}
      \cgalParamDescription{if positive, quads get smaller (down to a quarter of `quad_edge_length`) where the
                            surface or a feature line bends, so that the sagitta of a quad diagonal stays under
                            this fraction of the bounding-box diagonal; the arcs' target edge counts are measured
                            in the local length (see the user manual for the measured effect); 0 gives the
                            uniform `quad_edge_length` everywhere}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.002` (`0` with `number_of_quads`)}
    \cgalParamNEnd
    \cgalParamNBegin{component_resolution}
      \cgalParamDescription{passed on to `remesh_for_quadrangulation()`, and used the same way by the
                            quantization: a connected component other than the largest whose bounding-box
                            diagonal spans fewer than this many quad edges gets shorter quads (down to a
                            quarter of `quad_edge_length`); `0`: one length for every component}
      \cgalParamType{`double`}
      \cgalParamDefault{`8`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_tolerance}
      \cgalParamDescription{the quad edges along a feature line (a crease or the boundary) that bends stay within
                            this fraction of the bounding-box diagonal of the line: the quantization gives such
                            arcs at least the edges that takes, up to about twice their target count (0: no
                            such bound)}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.002`}
    \cgalParamNEnd
    \cgalParamNBegin{surface_tolerance}
      \cgalParamDescription{if positive, the quad edges of the layout's arcs that are not on a feature line stay within
                            this fraction of the bounding-box diagonal along the surface normal: an arc over a bend
                            of the surface (a fillet, a rounded body) gets at least the edges that takes, up to about
                            twice its target count. The density elsewhere does not change (see the user manual for
                            the measured effect). 0: no such bound}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.002` (`0` with `number_of_quads`)}
    \cgalParamNEnd
    \cgalParamNBegin{fidelity_tolerance}
      \cgalParamDescription{if positive, the patches whose triangles are farther than this fraction of the
                            bounding-box diagonal from the smoothed quads, or whose quads are farther from
                            them (measured at the vertices of the triangles and at the vertices, centre, edge
                            midpoints and triangle centroids of the quads), get half as many quads again along each arc, and the quads are made
                            again; they are kept if they are closer by a tenth at least and at most 1.5 times as
                            many as the first quads. At most 2 rounds, the second only if the first added
                            at most a fifth of the quads.
                            0: no such refinement}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.004` (`0` with `number_of_quads`)}
    \cgalParamNEnd
    \cgalParamNBegin{adaptive_remeshing}
      \cgalParamDescription{whether `remesh_for_quadrangulation()` runs its adaptive pass after the uniform one
                            (experimental, see there)}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
    \cgalParamNBegin{far_region_rounds}
      \cgalParamDescription{passed on to `remesh_for_quadrangulation()`: how many times the regions its uniform
                            pass leaves farther than 70% of `remeshing_tolerance` from the input are remeshed
                            again at a quarter, then an eighth, of the quad edge length. Off by default here (the
                            stage's own default is 2): the triangles get closer to the input (elephant 0.72% ->
                            0.19% of the diagonal), but the later stages react to the finer triangles in ways that
                            do not follow that distance. On the 22 development meshes (qmeval) it brought 7
                            outputs closer to the input (face 0.52% -> 0.35%, fertility 0.46% -> 0.35%, elephant
                            0.48% -> 0.40%) and 9 farther (truck 0.46% -> 0.68% with an inverted quad, featuretype
                            0.39% -> 0.56%, camelhead 0.46% -> 0.54%), chair_doublesided's mean scaled Jacobian fell
                            from 0.92 to 0.64, and the median quad count rose 7%}
      \cgalParamType{`unsigned`}
      \cgalParamDefault{`0`}
    \cgalParamNEnd
    \cgalParamNBegin{layout_refinement}
      \cgalParamDescription{whether `refine_patch_layout()` runs after `trace_patch_layout()`: the triangle mesh
                            gets a vertex where a cut across a thin wedge needs one, or a straight cut
                            extending a side at a concave turn its vertices, and the patches that stay
                            non-convex for want of them are cut. On the 22 development meshes it leaves 12
                            invalid patches instead of 54 (bunny and fertility none), raises truck's mean
                            scaled Jacobian from 0.78 to 0.84 and leaves no quad flipped over (truck has 6
                            without it); the layouts it changes move the quantization, which lands elsewhere
                            on elephant, whose output goes from 0.45% to 0.41% of the diagonal from the input
                            (qmeval)}
      \cgalParamType{Boolean}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{hold_sharp_edges}
      \cgalParamDescription{whether `remesh_for_quadrangulation()` holds the sharp edges that are not features in
                            place (see there)}
      \cgalParamType{Boolean}
      \cgalParamDefault{`true`}
    \cgalParamNEnd
    \cgalParamNBegin{remeshing_tolerance}
      \cgalParamDescription{passed on to `remesh_for_quadrangulation()`: the distance to the input, as a fraction of
                            the bounding-box diagonal, beyond which the bends of the feature lines are held
                            (and that the adaptive pass aims at)}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.002`}
    \cgalParamNEnd
    \cgalParamNBegin{curvature_alignment_weight}
      \cgalParamDescription{passed on to `compute_cross_field()`: the weight of the pull of the cross field towards
                            the principal curvature directions (0: the smoothest field)}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.1`}
    \cgalParamNEnd
    \cgalParamNBegin{curvature_smoothing_steps}
      \cgalParamDescription{passed on to `compute_cross_field()`: the face-ring averaging steps of the curvature
                            directions}
      \cgalParamType{`int`}
      \cgalParamDefault{`8`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_angle}
      \cgalParamDescription{the dihedral angle in degrees above which an edge is a feature}
      \cgalParamType{`double`}
      \cgalParamDefault{`35`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_gap_angle}
      \cgalParamDescription{the dihedral angle in degrees above which an edge can close a gap in a feature
                            line (see `detect_feature_edges()`)}
      \cgalParamType{`double`}
      \cgalParamDefault{`feature_angle - 10`}
    \cgalParamNEnd
    \cgalParamNBegin{maximum_running_time}
      \cgalParamDescription{a time limit in seconds for the whole run. The stages that can stop early get a
                            share of the time left when they start: the layout rounds (fewer paths: patches
                            may be less regular), the quantization solves (the best solution found, or the
                            solver-free fallback) and the smoothing iterations. The other stages always run
                            to their end, so a limit shorter than they take is exceeded. The report's
                            `"time_limit"` record says whether the limit was met and what each stage gave up.
                            With a limit the output depends on the speed and load of the machine.}
      \cgalParamType{`double`}
      \cgalParamDefault{`0` (no limit: the output depends on the input and the parameters only)}
    \cgalParamNEnd
    \cgalParamNBegin{callback}
      \cgalParamDescription{called with the name of each stage when it starts}
      \cgalParamType{a callable `void(const std::string&)`}
      \cgalParamDefault{none}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether the stages print their progress and timing to `std::cerr`}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the report of every stage (key: the stage name) and the total `"seconds"`
  @throws std::invalid_argument or std::runtime_error with the reason when a stage fails
*/
template <typename TriangleMesh, typename QuadMesh, typename NamedParameters = parameters::Default_named_parameters>
Report quad_remesh(const TriangleMesh& tmesh, QuadMesh& qmesh, const NamedParameters& np = parameters::default_values())
{
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type K;
  typedef CGAL::Surface_mesh<typename K::Point_3> Mesh;
  // the output of a Surface_mesh run, copied into `qmesh` if it is of another type
  auto run = [&](const Mesh& input) -> Report {
    if constexpr(std::is_same<QuadMesh, Mesh>::value)
      return internal::quad_remesh_on_surface_meshes(input, qmesh, np);
    else
    {
      Mesh quads;
      Report report = internal::quad_remesh_on_surface_meshes(input, quads, np);
      CGAL::clear(qmesh);
      CGAL::copy_face_graph(quads, qmesh);
      return report;
    }
  };
  if constexpr(std::is_same<TriangleMesh, Mesh>::value)
    return run(tmesh);
  else
  {
    Mesh input;
    CGAL::copy_face_graph(tmesh, input);
    return run(input);
  }
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_QUAD_REMESH_H
