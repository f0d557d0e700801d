// quad_remesh: the command-line program of CGAL Quad_remeshing.
//
// It calls the pipeline stages one by one (so that --until and --dump fall out naturally), records
// each stage's figures in a JSON report and prints a summary.
//
// Exit codes: 0 done, 1 the pipeline failed (with the reason), 2 bad input or arguments.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Quad_remeshing/IO.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/Patch_layout.h>
#include <CGAL/Quad_remeshing/assemble_quad_mesh.h>
#include <CGAL/Quad_remeshing/internal/pipeline/assembly_repairs.h>
#include <CGAL/Quad_remeshing/internal/pipeline/fidelity_refinement.h>
#include <CGAL/Quad_remeshing/internal/pipeline/tip_snapping.h>
#include <CGAL/Quad_remeshing/cross_field.h>
#include <CGAL/Quad_remeshing/detect_feature_edges.h>
#include <CGAL/Quad_remeshing/quadrangulate_polygon.h>
#include <CGAL/Quad_remeshing/quantize_patch_sides.h>
#include <CGAL/Quad_remeshing/remesh_for_quadrangulation.h>
#include <CGAL/Quad_remeshing/smooth_quad_mesh.h>
#include <CGAL/Quad_remeshing/trace_patch_layout.h>
#include <CGAL/Quad_remeshing/refine_patch_layout.h>
#include <CGAL/Quad_remeshing/internal/pipeline/layout_conversion.h>
#include <CGAL/Quad_remeshing/internal/pipeline/quad_count.h>
#include <CGAL/Quad_remeshing/internal/pipeline/quad_sizing.h>
#include <CGAL/Quad_remeshing/internal/pipeline/time_budget.h>
#include <CGAL/Quad_remeshing/html_report.h>
#include <CGAL/Quad_remeshing/quad_mesh_quality.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <vector>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace QR = CGAL::Quad_remeshing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                 Triangle_mesh;
typedef CGAL::Surface_mesh<Kernel::Point_3>                 Quad_mesh;

namespace {

const std::vector<std::string> stage_names = {"repair", "features", "remesh", "field",
                                              "layout", "quantize", "quadrangulate", "smooth"};

// The stages this build of the program can run (the others are reported as not available).
bool stage_available(const std::string& name)
{
  return std::find(stage_names.begin(), stage_names.end(), name) != stage_names.end();
}

const char* usage_text =
  "usage: quad_remesh INPUT [-o OUTPUT] [--edge-length L | --faces N | --scale S]\n"
  "                   [--sizing-tolerance F] [--feature-tolerance F] [--surface-tolerance F]\n"
  "                   [--fidelity-tolerance F] [--component-resolution R]\n"
  "                   [--feature-angle DEG] [--feature-gap-angle DEG]\n"
  "                   [--features FILE]\n"
  "                   [--until STAGE] [--dump DIR]\n"
  "                   [--report FILE.json] [--seed N] [--threads N] [--time-limit S]\n"
  "                   [--html FILE.html] [--adaptive-remeshing] [--no-hold-sharp-edges]\n"
  "                   [--no-refine-layout] [--refine-far-regions]\n"
  "                   [--verbose | --quiet] [--help]\n"
  "\n"
  "Turns the triangle mesh INPUT (OFF, OBJ, PLY or STL) into a pure-quad mesh that keeps its feature\n"
  "lines (sharp creases and boundaries) as chains of edges.\n"
  "\n"
  "  -o OUTPUT            output mesh (.obj, .off or .ply); default: INPUT's name with _quad.obj\n"
  "  --edge-length L      target quad edge length (absolute units)\n"
  "  --faces N            approximate number of output quads (the sizing tolerance is then 0 unless\n"
  "                       given; the quad edge length grows until the quantization's counts give at\n"
  "                       most 10% more, which bent feature lines may prevent)\n"
  "  --scale S            multiply the default edge length by S\n"
  "  --sizing-tolerance F smaller quads (down to a quarter) where the surface or a feature line bends,\n"
  "                       keeping a quad's sagitta under F times the bounding-box diagonal (default\n"
  "                       0.002; 0: the uniform edge length everywhere)\n"
  "  --component-resolution R  a connected component (but the largest) whose bounding-box diagonal\n"
  "                       spans fewer than R quad edges gets shorter ones, down to a quarter, in the\n"
  "                       remeshing and the quantization (default 8; 0: one length for all)\n"
  "  --feature-tolerance F quad edges along a bent feature line stay within F times the bounding-box\n"
  "                       diagonal of the line (default 0.002; 0: no bound)\n"
  "  --surface-tolerance F quad edges across a bend of the surface (a fillet) stay within F times the\n"
  "                       bounding-box diagonal along the normal (default 0.002, 0 with --faces\n"
  "                       unless given; 0: no bound)\n"
  "  --fidelity-tolerance F  the patches whose triangles stray farther than F times the bounding-box\n"
  "                       diagonal from their quads get half as many quads again along each side (at\n"
  "                       most 2 rounds, the second if the first added at most a fifth of the quads;\n"
  "                       kept if closer by a tenth and at most 1.5 times the quads); then the\n"
  "                       input's tips still farther than that each take the nearest free quad\n"
  "                       vertex, held while the quads are smoothed again (up to 3 rounds, each\n"
  "                       kept if closer); last, the quad vertices still farther than half of it\n"
  "                       from the input move onto it as far as their quads allow, kept if closer\n"
  "                       (default 0.004, 0 with --faces unless given; 0: none)\n"
  "  --feature-angle DEG  dihedral angle above which an edge is a feature (default 35; 180: none)\n"
  "  --feature-gap-angle DEG  dihedral angle above which a few edges continuing a feature line\n"
  "                       across a gap, to another feature edge, are features too (default: the\n"
  "                       feature angle minus 10; the feature angle or more: no gap is closed)\n"
  "  --features FILE      use these feature edges instead of detecting them (CGAL .polylines.txt\n"
  "                       or one 'i j' vertex-index pair per line)\n"
  "  --until STAGE        stop after STAGE and write its mesh as OUTPUT; stages, in order:\n"
  "                       repair, features, remesh, field, layout, quantize, quadrangulate, smooth\n"
  "  --dump DIR           write every finished stage's result into DIR (the quantize stage: its\n"
  "                       integer program's input, 6_quantization_problem.txt)\n"
  "  --report FILE.json   write the figures of every stage as JSON\n"
  "  --html FILE.html     write a self-contained report with a 3D viewer of every stage\n"
  "  --seed N             random seed (default 0); the same input and seed give the same output\n"
  "  --threads N          worker threads of the layout and quantize stages (default: the hardware\n"
  "                       threads; the output does not depend on N)\n"
  "  --time-limit S       time limit in seconds of the whole run (default: none): the layout rounds, the\n"
  "                       quantize solves and the smoothing iterations stop early to meet it (the report\n"
  "                       and the summary say what they gave up); the output then depends on the\n"
  "                       machine's speed and load\n"
  "  --adaptive-remeshing run the adaptive remeshing pass (experimental)\n"
  "  --refine-far-regions remesh again, at half and then a quarter of the length, the regions that\n"
  "                       the remeshing leaves farther than 70% of 0.002 times the diagonal from the\n"
  "                       input (thin tips, tight bends) (experimental: the output gets closer to the\n"
  "                       input on some meshes, farther on others)\n"
  "  --no-refine-layout   leave the triangles as they are where a layout patch stays non-convex for\n"
  "                       want of a vertex (by default they get one, and those patches are cut again;\n"
  "                       --refine-layout, the default, is accepted too)\n"
  "  --no-hold-sharp-edges let the uniform remeshing pass smooth away the sharp edges that are not\n"
  "                       features and the long creases (held in place by default)\n"
  "  --verbose            print progress of every stage\n"
  "  --quiet              print nothing but errors\n"
  "  --list-stages        print every stage and whether this build can run it\n"
  "\n"
  "Exit codes: 0 done, 1 the pipeline failed, 2 bad input or arguments.\n";

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string input, output, features_file, until = "smooth", dump_dir, report_file, html_file;
  double edge_length = 0., scale = 1., feature_angle = 35., feature_gap_angle = -1., time_limit = 0.,
         sizing_tolerance = -1., // negative: the default, see sizing()
         feature_tolerance = QR::internal::default_feature_tolerance,
         surface_tolerance = -1., // negative: the default, see surface()
         fidelity_tolerance = -1., // negative: the default, see fidelity()
         component_resolution = QR::internal::default_component_resolution;
  long faces = 0;
  unsigned seed = 0, threads = (std::max)(1u, std::thread::hardware_concurrency());
  bool verbose = false, quiet = false, adaptive_remeshing = false, hold_sharp_edges = true, refine_layout = true,
       refine_far_regions = false;

  // the sizing tolerance in use: as given, else 0 with --faces (a count of quads asks for the uniform
  // size that gives it), else the library's default
  double sizing() const
  {
    if(sizing_tolerance >= 0.) return sizing_tolerance;
    return faces > 0 ? 0. : QR::internal::default_sizing_tolerance;
  }
  // the surface tolerance in use, the same way
  double surface() const
  {
    if(surface_tolerance >= 0.) return surface_tolerance;
    return faces > 0 ? 0. : QR::internal::default_surface_tolerance;
  }
  // the fidelity tolerance in use, the same way
  double fidelity() const
  {
    if(fidelity_tolerance >= 0.) return fidelity_tolerance;
    return faces > 0 ? 0. : QR::internal::default_fidelity_tolerance;
  }
};

double parse_number(const std::string& option, const std::string& text, double min_value)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !std::isfinite(v) || v < min_value)
    throw Usage_error("invalid value '" + text + "' for " + option);
  return v;
}

Options parse_arguments(int argc, char** argv, bool& help)
{
  Options o;
  help = false;
  int density_options = 0;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Usage_error("option " + a + " needs a value");
      return argv[++i];
    };
    if(a == "--help" || a == "-h") { help = true; return o; }
    else if(a == "--list-stages")
    {
      for(const std::string& n : stage_names)
        std::cout << n << (stage_available(n) ? " available" : " not_available") << "\n";
      std::exit(0);
    }
    else if(a == "-o" || a == "--output") o.output = value();
    else if(a == "--edge-length") { o.edge_length = parse_number(a, value(), 1e-300); ++density_options; }
    else if(a == "--faces") { o.faces = long(parse_number(a, value(), 1.)); ++density_options; }
    else if(a == "--scale") { o.scale = parse_number(a, value(), 1e-6); ++density_options; }
    else if(a == "--feature-angle") o.feature_angle = parse_number(a, value(), 0.);
    else if(a == "--feature-gap-angle") o.feature_gap_angle = parse_number(a, value(), 0.);
    else if(a == "--features") o.features_file = value();
    else if(a == "--until")
    {
      o.until = value();
      if(std::find(stage_names.begin(), stage_names.end(), o.until) == stage_names.end())
        throw Usage_error("unknown stage '" + o.until + "' for --until");
    }
    else if(a == "--dump") o.dump_dir = value();
    else if(a == "--report") o.report_file = value();
    else if(a == "--html") o.html_file = value();
    else if(a == "--seed") o.seed = unsigned(parse_number(a, value(), 0.));
    else if(a == "--threads") o.threads = unsigned(parse_number(a, value(), 1.));
    else if(a == "--time-limit") o.time_limit = parse_number(a, value(), 0.);
    else if(a == "--sizing-tolerance") o.sizing_tolerance = parse_number(a, value(), 0.);
    else if(a == "--component-resolution") o.component_resolution = parse_number(a, value(), 0.);
    else if(a == "--feature-tolerance") o.feature_tolerance = parse_number(a, value(), 0.);
    else if(a == "--surface-tolerance") o.surface_tolerance = parse_number(a, value(), 0.);
    else if(a == "--fidelity-tolerance") o.fidelity_tolerance = parse_number(a, value(), 0.);
    else if(a == "--verbose" || a == "-v") o.verbose = true;
    else if(a == "--adaptive-remeshing") o.adaptive_remeshing = true;
    else if(a == "--refine-layout") o.refine_layout = true;
    else if(a == "--no-refine-layout") o.refine_layout = false;
    else if(a == "--refine-far-regions") o.refine_far_regions = true;
    else if(a == "--no-hold-sharp-edges") o.hold_sharp_edges = false;
    else if(a == "--quiet" || a == "-q") o.quiet = true;
    else if(!a.empty() && a[0] == '-') throw Usage_error("unknown option '" + a + "'");
    else if(o.input.empty()) o.input = a;
    else throw Usage_error("more than one input file ('" + o.input + "', '" + a + "')");
  }
  if(o.input.empty()) throw Usage_error("no input file");
  if(density_options > 1) throw Usage_error("--edge-length, --faces and --scale are exclusive");
  if(o.verbose && o.quiet) throw Usage_error("--verbose and --quiet are exclusive");
  if(o.output.empty())
  {
    std::string stem = o.input;
    const std::size_t slash = stem.find_last_of("/\\");
    const std::size_t dot = stem.find_last_of('.');
    if(dot != std::string::npos && (slash == std::string::npos || dot > slash)) stem = stem.substr(0, dot);
    o.output = stem + "_quad.obj";
  }
  return o;
}

// A stage that the program does not have yet: reported as such, never faked.
struct Stage_not_available : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Everything the stages hand to each other.
typedef boost::graph_traits<Triangle_mesh>::edge_descriptor edge_descriptor;
typedef boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Triangle_mesh>::face_descriptor face_descriptor;
typedef QR::Patch_layout<Triangle_mesh, Kernel> Layout;

struct Pipeline_state
{
  Triangle_mesh input;   // the repaired input, for the final quality figures
  Triangle_mesh tmesh;   // the triangle mesh the stages work on (remeshed in place)
  QR::Repair_statistics repair;
  Triangle_mesh::Property_map<edge_descriptor, bool> feature;
  Triangle_mesh::Property_map<vertex_descriptor, bool> corner;
  Triangle_mesh::Property_map<face_descriptor, Kernel::Vector_3> field;
  Triangle_mesh::Property_map<vertex_descriptor, int> singularity;
  double quad_edge_length = 0.;
  std::unique_ptr<Layout> layout;
  std::unique_ptr<QR::internal::Quadrangulation_layout<Triangle_mesh, Layout>> polygons;
  std::vector<int> arc_edge_counts;
  QR::Side_quantization_problem quantization_problem; // what arc_edge_counts solve (the assembly may solve it again)
  Quad_mesh qmesh;
  Quad_mesh::Property_map<Quad_mesh::Edge_index, bool> qfeature;
  bool has_quads = false;
};

class Pipeline
{
public:
  explicit Pipeline(const Options& o) : opt_(o), budget_(o.time_limit) { report_ = QR::Report::object(); }

  int run()
  {
    report_["status"] = "failed";
    report_["error"] = "";
    report_["input"]["file"] = opt_.input;
    report_["stages"] = QR::Report::array();
    if(!opt_.dump_dir.empty()) make_directory(opt_.dump_dir);

    int exit_code = 0;
    try {
      for(const std::string& name : stage_names)
      {
        run_stage(name);
        if(name == opt_.until) break;
      }
      // the time limit covers the stages, not the measurement of the output's quality
      report_["time_limit"] = budget_.report();
      write_output();
      report_["status"] = "ok";
    } catch(const QR::Bad_input& e) {
      fail(e.what());
      exit_code = 2;
    } catch(const Stage_not_available& e) {
      fail(e.what());
      exit_code = 1;
    } catch(const std::exception& e) {
      fail(std::string("stage '") + current_stage_ + "' failed: " + e.what());
      exit_code = 1;
    }
    if(!report_.find("time_limit")) report_["time_limit"] = budget_.report();
    write_report();
    write_html();
    if(!opt_.quiet) print_summary();
    return exit_code;
  }

private:
  void fail(const std::string& message)
  {
    report_["status"] = "failed";
    report_["error"] = message;
    std::cerr << "quad_remesh: " << message << "\n";
  }

  void run_stage(const std::string& name)
  {
    current_stage_ = name;
    if(opt_.verbose) std::cerr << "[" << name << "] start\n";
    CGAL::Real_timer timer;
    timer.start();
    QR::Report stage = QR::Report::object();
    stage["name"] = name;
    QR::Report figures;
    try {
      figures = dispatch(name);
    } catch(const Stage_not_available&) {
      stage["status"] = "not_available";
      stage["seconds"] = timer.time();
      report_["stages"].push_back(stage);
      throw;
    } catch(...) {
      stage["status"] = "failed";
      stage["seconds"] = timer.time();
      report_["stages"].push_back(stage);
      throw;
    }
    stage["status"] = "ok";
    stage["seconds"] = timer.time();
    for(std::size_t i = 0; i < figures.keys().size(); ++i)
    {
      const std::string& k = figures.keys()[i];
      if(k == "seconds") continue;
      // the stage record's own "name" and "status" stay; a stage's figure of that name is renamed
      stage[(k == "status" || k == "name") ? "stage_" + k : k] = figures.elements()[i];
    }
    report_["stages"].push_back(stage);
    if(opt_.verbose) std::cerr << "[" << name << "] done in " << stage["seconds"].number() << " s\n";
    last_stage_ = name;
  }

  QR::Report dispatch(const std::string& name)
  {
    if(!stage_available(name))
      throw Stage_not_available("stage '" + name + "' is not available in this version of quad_remesh");
    if(name == "repair") return stage_repair();
    if(name == "features") return stage_features();
    if(name == "remesh") return stage_remesh();
    if(name == "field") return stage_field();
    if(name == "layout") return stage_layout();
    if(name == "quantize") return stage_quantize();
    if(name == "quadrangulate") return stage_quadrangulate();
    if(name == "smooth") return stage_smooth();
    throw Stage_not_available("stage '" + name + "' is not available in this version of quad_remesh");
  }

  QR::Report stage_repair()
  {
    state_.repair = QR::read_and_repair(opt_.input, state_.tmesh, CGAL::parameters::verbose(opt_.verbose));
    state_.input = state_.tmesh;
    report_["input"]["V"] = state_.repair.input_vertices;
    report_["input"]["F"] = state_.repair.input_faces;
    dump_mesh("1_repair.off", state_.tmesh);
    return state_.repair.report();
  }

  QR::Report stage_features()
  {
    namespace QRP = QR::parameters;
    state_.feature = state_.tmesh.add_property_map<edge_descriptor, bool>("e:qr_feature", false).first;
    state_.corner = state_.tmesh.add_property_map<vertex_descriptor, bool>("v:qr_corner", false).first;
    bool given = false;
    if(!opt_.features_file.empty())
    {
      QR::read_feature_edges(opt_.features_file, state_.tmesh, state_.feature);
      given = true;
    }
    const QR::Feature_detection_statistics st = QR::detect_feature_edges(
      state_.tmesh, state_.feature,
      QRP::combine(QRP::feature_angle(opt_.feature_angle).verbose(opt_.verbose), QRP::use_given_feature_edges(given),
                   QRP::feature_gap_angle(opt_.feature_gap_angle < 0. ? QR::internal::default_feature_gap_angle(opt_.feature_angle)
                                                                      : opt_.feature_gap_angle),
                   QRP::vertex_is_feature_corner_map(state_.corner)));
    if(!opt_.dump_dir.empty())
    {
      // CGAL polylines: one two-point polyline per feature edge
      std::ofstream out(opt_.dump_dir + "/2_features.polylines.txt");
      out.precision(17);
      for(auto e : edges(state_.tmesh))
        if(state_.feature[e])
          out << "2 " << state_.tmesh.point(source(e, state_.tmesh)) << " " << state_.tmesh.point(target(e, state_.tmesh)) << "\n";
    }
    extra_layers_.push_back(QR::feature_edges_layer("feature lines", state_.tmesh, state_.feature));
    return st.report();
  }

  QR::Report stage_remesh()
  {
    namespace QRP = QR::parameters;
    if(opt_.edge_length > 0) state_.quad_edge_length = opt_.edge_length;
    else if(opt_.faces > 0) state_.quad_edge_length = QR::quad_edge_length_from_face_count(state_.tmesh, std::size_t(opt_.faces));
    else state_.quad_edge_length = QR::quad_edge_length_from_scale(state_.tmesh, opt_.scale);
    const QR::Remeshing_statistics st = QR::remesh_for_quadrangulation(
      state_.tmesh, state_.feature,
      QRP::combine(QRP::quad_edge_length(state_.quad_edge_length).verbose(opt_.verbose),
                   QRP::adaptive_remeshing(opt_.adaptive_remeshing), QRP::hold_sharp_edges(opt_.hold_sharp_edges),
                   QRP::component_resolution(opt_.component_resolution),
                   QRP::feature_angle(opt_.feature_angle),
                   QRP::vertex_is_feature_corner_map(state_.corner),
                   QRP::far_region_rounds(opt_.refine_far_regions ? 2u : 0u)));
    // later stages index elements densely: drop the removed ones (property maps are compacted with them)
    state_.tmesh.collect_garbage();
    dump_mesh("3_remesh.off", state_.tmesh);
    QR::Report r = st.report();
    r["quad_edge_length"] = state_.quad_edge_length;
    return r;
  }

  QR::Report stage_field()
  {
    state_.field = state_.tmesh.add_property_map<face_descriptor, Kernel::Vector_3>("f:qr_field", CGAL::NULL_VECTOR).first;
    state_.singularity = state_.tmesh.add_property_map<vertex_descriptor, int>("v:qr_singularity", 0).first;
    const auto st = QR::compute_cross_field(state_.tmesh, state_.feature, state_.field,
                                            CGAL::parameters::verbose(opt_.verbose).random_seed(opt_.seed));
    const auto ss = QR::compute_cross_field_singularities(state_.tmesh, state_.feature, state_.field, state_.singularity,
                                                          CGAL::parameters::verbose(opt_.verbose));
    if(!opt_.dump_dir.empty())
    {
      std::ofstream f(opt_.dump_dir + "/4_field.obj");
      QR::write_cross_field_OBJ(f, state_.tmesh, state_.field);
      std::ofstream g(opt_.dump_dir + "/4_singularities.ply");
      QR::write_cross_field_singularities_PLY(g, state_.tmesh, state_.singularity);
    }
    if(!opt_.html_file.empty())
    {
      extra_layers_.push_back(QR::cross_field_layer("cross field", state_.tmesh, state_.field));
      extra_layers_.back().visible = false;
      extra_layers_.push_back(QR::singularities_layer("singularities", state_.tmesh, state_.singularity));
    }
    QR::Report r = st.report();
    const QR::Report rs = ss.report();
    for(std::size_t i = 0; i < rs.keys().size(); ++i)
      if(rs.keys()[i] != "seconds") r[rs.keys()[i]] = rs.elements()[i];
    return r;
  }

  QR::Report stage_layout()
  {
    state_.layout = std::make_unique<Layout>(state_.tmesh, state_.field, state_.singularity);
    const auto np = QR::parameters::combine(CGAL::parameters::verbose(opt_.verbose).maximum_running_time(
                                              budget_.stage_limit(QR::internal::layout_time_share)),
                                            QR::parameters::number_of_threads(opt_.threads));
    auto st = QR::trace_patch_layout(state_.tmesh, state_.feature, *state_.layout, np);
    // where patches stay non-convex for want of a vertex, the mesh is refined and the layout repaired (unless
    // --no-refine-layout)
    std::optional<QR::Refine_patch_layout_statistics> rs;
    if(opt_.refine_layout)
      rs = QR::refine_patch_layout(state_.tmesh, state_.feature, state_.field, state_.singularity, state_.layout, st, np);
    state_.layout->release_direction_graph(); // (no more paths are traced)
    budget_.record("layout", st.report());
    QR::Report r = st.report();
    if(rs) r["refinement"] = rs->report();
    if(!opt_.dump_dir.empty())
    {
      std::ofstream f(opt_.dump_dir + "/5_layout.ply");
      state_.layout->write_ply(f);
      std::ofstream g(opt_.dump_dir + "/5_paths.polylines.txt");
      state_.layout->write_polylines(g);
    }
    if(!opt_.html_file.empty()) extra_layers_.push_back(QR::patch_layout_layer("patch layout", *state_.layout));
    return r;
  }

  // The quantize stage's solve. Under --time-limit every solve gets the quantize share of the time then
  // left, so the solves together stay within it; no time limit unless asked for: the default node limit
  // keeps the result independent of the load.
  QR::Side_quantization_statistics solve(const QR::Side_quantization_problem& problem, std::vector<int>& counts)
  {
    namespace QRP = QR::parameters;
    return QR::quantize_patch_sides(problem, counts,
                                    QRP::number_of_threads(opt_.threads).maximum_running_time(
                                      budget_.stage_limit(QR::internal::quantize_time_share)));
  }

  QR::Report stage_quantize()
  {
    namespace QRP = QR::parameters;
    state_.polygons = std::make_unique<QR::internal::Quadrangulation_layout<Triangle_mesh, Layout>>(state_.tmesh,
                                                                                                   *state_.layout);
    // With --faces the quad edge length grows until the counts give at most 10% more quads than asked for
    // (see quantize_for_quad_count()).
    const QR::internal::Quad_count_quantization qc = QR::internal::quantize_for_quad_count(
      state_.tmesh, *state_.layout, *state_.polygons, state_.feature, state_.quad_edge_length, opt_.sizing(),
      opt_.feature_tolerance, opt_.surface(), std::size_t((std::max)(0L, opt_.faces)), state_.arc_edge_counts,
      [&](const QR::Side_quantization_problem& problem, std::vector<int>& counts) { return solve(problem, counts); },
      opt_.component_resolution);
    const QR::internal::Pipeline_quantization_problem& qp = qc.qp;
    state_.quantization_problem = qp.problem;
    const QR::Side_quantization_statistics& st = qc.stats;
    const QR::Side_quantization_problem& pb = qp.problem;
    if(!opt_.dump_dir.empty())
    {
      std::ofstream f(opt_.dump_dir + "/6_quantization_problem.txt");
      QR::internal::write_quantization_problem(f, pb);
    }
    QR::Report r = st.report();
    budget_.record("quantize", r);
    if(opt_.faces > 0) qc.add_to(r);
    r["sizing_tolerance"] = opt_.sizing();
    r["feature_tolerance"] = opt_.feature_tolerance;
    r["surface_tolerance"] = opt_.surface();
    r["bent_feature_arcs"] = qp.bent_feature_arcs;
    r["bent_surface_arcs"] = qp.bent_surface_arcs;
    if(!qp.sizing.empty()) r["smallest_local_quad_edge_length"] = *std::min_element(qp.sizing.begin(), qp.sizing.end());
    r["relaxed_patches"] = state_.polygons->relaxed_patches;
    r["added_corners"] = state_.polygons->added_corners;
    r["dropped_corners"] = state_.polygons->dropped_corners;
    return r;
  }

  QR::Report stage_quadrangulate()
  {
    const auto description =
      QR::internal::layout_description(state_.tmesh, *state_.layout, *state_.polygons, state_.feature);
    state_.qfeature = state_.qmesh.add_property_map<Quad_mesh::Edge_index, bool>("e:qr_feature", false).first;
    // patterns that cannot be glued get more edges on their arcs (the counts are solved again)
    const QR::internal::Repaired_assembly assembly = QR::internal::assemble_with_count_repairs(
      state_.tmesh, description, state_.quantization_problem, state_.arc_edge_counts,
      [&](const QR::Side_quantization_problem& problem, std::vector<int>& counts) { return solve(problem, counts); },
      state_.qmesh, state_.qfeature, opt_.verbose);
    const QR::Quad_assembly_statistics& st = assembly.stats;
    std::size_t simple = 0, general = 0;
    std::map<int, int> irregular;
    for(const auto& pattern : assembly.patterns)
    {
      if(pattern.strategy == QR::Polygon_quadrangulation::SIMPLE) ++simple; else ++general;
      for(const auto& kv : pattern.irregular_vertices_by_valence) irregular[kv.first] += kv.second;
    }
    state_.has_quads = true;
    if(!opt_.dump_dir.empty()) QR::write_mesh(opt_.dump_dir + "/7_quadrangulate.obj", state_.qmesh);
    QR::Report r = st.report();
    r["count_repairs"] = assembly.count_repairs;
    r["repaired_patches"] = assembly.repaired_patches;
    r["simple_patches"] = simple;
    r["general_patches"] = general;
    for(const auto& kv : irregular) r["pattern_irregular_vertices"][std::to_string(kv.first)] = kv.second;
    return r;
  }

  QR::Report stage_smooth()
  {
    CGAL::Real_timer timer;
    timer.start();
    QR::Quad_smoothing_statistics st = QR::smooth_quad_mesh(
      state_.qmesh, state_.tmesh, state_.feature,
      CGAL::parameters::edge_is_constrained_map(state_.qfeature).verbose(opt_.verbose).maximum_running_time(
        budget_.stage_limit(QR::internal::smooth_time_share)));
    budget_.record("smooth", st.report());
    QR::Report r = st.report();

    // where the smoothed quads stray from the surface, more quads (see QR::internal::refine_for_fidelity();
    // quad_remesh() does the same)
    const double diagonal = QR::internal::mesh_bbox_diagonal(state_.tmesh);
    if(opt_.fidelity() > 0. && budget_.limited() && budget_.left() < 3. * timer.time())
    {
      budget_.degraded("smooth", "no time left for more quads where the quads stray from the surface");
      r["fidelity"]["skipped_for_time_limit"] = true;
      return r;
    }
    const auto description =
      QR::internal::layout_description(state_.tmesh, *state_.layout, *state_.polygons, state_.feature);
    auto solve_counts = [&](const QR::Side_quantization_problem& problem, std::vector<int>& counts) { return solve(problem, counts); };
    auto make = [&](const QR::Side_quantization_problem& problem, std::vector<int>& counts, Quad_mesh& out) {
      auto out_feature = out.add_property_map<Quad_mesh::Edge_index, bool>("e:qr_feature", false).first;
      QR::internal::assemble_with_count_repairs(state_.tmesh, description, problem, counts, solve_counts, out,
                                                out_feature, false);
      st = QR::smooth_quad_mesh(out, state_.tmesh, state_.feature,
                                CGAL::parameters::edge_is_constrained_map(out_feature).maximum_running_time(
                                  budget_.stage_limit(QR::internal::smooth_time_share)));
    };
    QR::Report kept_smoothing = r;
    auto keep = [&](Quad_mesh& better) {
      state_.qmesh = std::move(better);
      state_.qfeature = state_.qmesh.property_map<Quad_mesh::Edge_index, bool>("e:qr_feature").first;
      kept_smoothing = st.report();
    };
    const QR::internal::Fidelity_refinement_statistics fs = QR::internal::refine_for_fidelity(
      state_.tmesh, description, state_.quantization_problem, state_.arc_edge_counts, solve_counts, make, keep,
      state_.qmesh, opt_.fidelity() * diagonal, opt_.verbose);
    r = kept_smoothing;
    r["fidelity"] = fs.report(diagonal);
    // quad vertices onto the input's tips that the quads cut off (see QR::internal::snap_quads_to_input_tips())
    auto smooth_held = [&](Quad_mesh& m, const auto& m_feature, const auto& held) {
      QR::smooth_quad_mesh(m, state_.tmesh, state_.feature,
                           CGAL::parameters::edge_is_constrained_map(m_feature).vertex_is_constrained_map(held)
                             .number_of_iterations(QR::internal::tip_smoothing_iterations)
                             .maximum_running_time(budget_.stage_limit(QR::internal::smooth_time_share)));
    };
    auto keep_tips = [&](Quad_mesh& better, const auto& better_feature) {
      Quad_mesh m = better; // (a copy keeps the indices)
      auto f = m.add_property_map<Quad_mesh::Edge_index, bool>("e:qr_feature", false).first;
      for(auto e : m.edges()) f[e] = get(better_feature, e);
      state_.qmesh = std::move(m);
      state_.qfeature = state_.qmesh.property_map<Quad_mesh::Edge_index, bool>("e:qr_feature").first;
    };
    const double input_diagonal = QR::internal::mesh_bbox_diagonal(state_.input);
    const QR::internal::Tip_snapping_statistics ts = QR::internal::snap_quads_to_input_tips(
      state_.input, state_.qmesh, state_.qfeature, opt_.fidelity() * input_diagonal, smooth_held, keep_tips,
      opt_.verbose);
    r["fidelity"]["tips"] = ts.report(input_diagonal);
    return r;
  }

  void write_output()
  {
    // The mesh of the last finished stage is the output (triangles before the quad stages).
    report_["output"]["file"] = opt_.output;
    report_["output"]["stage"] = last_stage_;
    if(state_.has_quads)
    {
      QR::write_mesh(opt_.output, state_.qmesh);
      report_["output"]["V"] = num_vertices(state_.qmesh);
      report_["output"]["F"] = num_faces(state_.qmesh);
      measure_output(state_.qmesh);
    }
    else
    {
      QR::write_mesh(opt_.output, state_.tmesh);
      report_["output"]["V"] = num_vertices(state_.tmesh);
      report_["output"]["F"] = num_faces(state_.tmesh);
      measure_output(state_.tmesh);
    }
  }

  // Quality of the output and its fidelity to the (repaired) input, with the evaluation's own
  // definition of feature lines (boundaries and creases above the feature angle).
  template <typename Mesh>
  void measure_output(const Mesh& out)
  {
    namespace QRP = QR::parameters;
    const QR::Quad_mesh_quality q = QR::quad_mesh_quality(out);
    QR::Report quality = q.report();
    auto features = get(CGAL::dynamic_edge_property_t<bool>(), state_.input);
    QR::detect_evaluation_feature_edges(state_.input, features, QRP::feature_angle((std::min)(opt_.feature_angle, 180.)));
    const QR::Feature_fidelity f =
      QR::feature_fidelity(state_.input, features, out,
                           QRP::feature_angle((std::min)(opt_.feature_angle, 180.)).random_seed(opt_.seed)
                             .number_of_points_on_faces(std::size_t(20000)));
    const QR::Report fr = f.report();
    for(std::size_t i = 0; i < fr.keys().size(); ++i)
      if(fr.keys()[i] != "seconds") quality[fr.keys()[i]] = fr.elements()[i];
    quality["seconds"] = q.seconds + f.seconds;
    report_["output"]["quality"] = quality;
  }

  void dump_mesh(const std::string& name, const Triangle_mesh& m)
  {
    if(opt_.dump_dir.empty()) return;
    QR::write_mesh(opt_.dump_dir + "/" + name, m);
  }

  static void make_directory(const std::string& dir)
  {
    struct stat st;
    if(stat(dir.c_str(), &st) == 0)
    {
      if(!S_ISDIR(st.st_mode)) throw Usage_error("--dump: '" + dir + "' is not a directory");
      return;
    }
    if(mkdir(dir.c_str(), 0755) != 0) throw Usage_error("--dump: cannot create directory '" + dir + "'");
  }

  void write_report()
  {
    if(opt_.report_file.empty()) return;
    std::ofstream out(opt_.report_file);
    if(!out) { std::cerr << "quad_remesh: cannot write the report '" << opt_.report_file << "'\n"; return; }
    report_.write_json(out);
    out << "\n";
  }

  // The HTML report: one viewer layer per finished stage that has something to show.
  void write_html()
  {
    if(opt_.html_file.empty()) return;
    try {
      QR::Html_report_scene scene;
      scene.title = "quad_remesh: " + opt_.input.substr(opt_.input.find_last_of('/') + 1); // the path is in the report
      // shown at first: the latest surface (the quad mesh, else the patch layout, else the input) and
      // the lines and points but the cross field; the other layers are a click away
      if(num_faces(state_.input) > 0)
        scene.layers.push_back(QR::polygon_mesh_layer("input (repaired)", state_.input));
      for(QR::Html_layer& l : extra_layers_) scene.layers.push_back(l);
      if(state_.has_quads && num_faces(state_.qmesh) > 0)
      {
        scene.layers.push_back(QR::scaled_jacobian_layer("quad mesh (scaled Jacobian)", state_.qmesh));
        scene.layers.push_back(QR::irregular_vertices_layer("irregular vertices", state_.qmesh));
        scene.histograms = QR::quad_mesh_histograms(state_.qmesh);
      }
      else if(report_["status"].string() == "ok" && last_stage_ != "repair" && num_faces(state_.tmesh) > 0 &&
              std::none_of(extra_layers_.begin(), extra_layers_.end(),
                           [](const QR::Html_layer& l) { return !l.polygons.faces.empty(); })) // no patch layout
        scene.layers.push_back(QR::polygon_mesh_layer("output of stage '" + last_stage_ + "'", state_.tmesh));
      std::size_t surface = 0; // the last layer with faces stays shown
      for(std::size_t i = 0; i < scene.layers.size(); ++i)
        if(!scene.layers[i].polygons.faces.empty()) surface = i;
      for(std::size_t i = 0; i < scene.layers.size(); ++i)
        if(!scene.layers[i].polygons.faces.empty() && i != surface) scene.layers[i].visible = false;
      scene.report = report_;
      QR::write_html_report(opt_.html_file, scene);
    } catch(const std::exception& e) {
      std::cerr << "quad_remesh: cannot write the HTML report: " << e.what() << "\n";
    }
  }

  void print_summary()
  {
    std::ostream& os = std::cout;
    os << "quad_remesh: " << opt_.input << " -> "
       << (report_["status"].string() == "ok" ? opt_.output : std::string("(no output)")) << "\n";
    for(const QR::Report& s : report_["stages"].elements())
    {
      os << "  " << s.find("name")->string() << ": " << s.find("status")->string();
      if(const QR::Report* sec = s.find("seconds")) os << " (" << sec->number() << " s)";
      os << "\n";
    }
    if(const QR::Report* out = report_.find("output"))
      if(out->find("V"))
      {
        os << "  output: " << out->find("V")->number() << " vertices, " << out->find("F")->number()
           << " faces (after stage '" << out->find("stage")->string() << "')\n";
        if(const QR::Report* q = out->find("quality"))
        {
          auto num = [&](const char* k) { const QR::Report* v = q->find(k); return v ? v->number() : 0.; };
          os << "  quality: irregular " << num("irregular_vertices") << ", angle deviation " << num("angle_deviation")
             << " deg, scaled Jacobian mean " << num("mean_scaled_jacobian") << " min " << num("min_scaled_jacobian")
             << ", inverted " << num("non_positive_scaled_jacobian") << " + flipped over " << num("flipped_quads")
             << ", Hausdorff " << num("hausdorff_max") << " of the diagonal, feature coverage " << num("feature_coverage")
             << ", valid " << (q->find("valid") && q->find("valid")->boolean() ? "yes" : "no") << "\n";
        }
      }
    if(budget_.limited())
      os << "  time limit: " << opt_.time_limit << " s, " << (report_["time_limit"]["met"].boolean() ? "met" : "exceeded")
         << (budget_.any_degraded() ? "; degraded: " + budget_.summary() : std::string("; nothing degraded")) << "\n";
    os << "  status: " << report_["status"].string();
    if(!report_["error"].string().empty()) os << " (" << report_["error"].string() << ")";
    os << "\n";
  }

  Options opt_;
  QR::Report report_;
  std::vector<QR::Html_layer> extra_layers_; // layers the stages add for the HTML report
  Pipeline_state state_;
  QR::internal::Time_budget budget_; // --time-limit: shares of the time left for the stages that can stop early
  std::string current_stage_, last_stage_;
};

} // namespace

int main(int argc, char** argv)
{
#if defined(__GLIBC__) && defined(M_ARENA_MAX)
  // glibc gives each new thread its own malloc arena (up to 8 per core), which keeps what its thread freed
  // resident: with the worker threads of the layout and the quantization that was up to 10 MiB more peak
  // memory (rocker_arm 44 -> 39 MiB, plate_holes 55 -> 48 MiB) for no measurable speed. Two arenas: the main
  // thread's and one for the workers (one alone made the threads wait on each other: truck 26.8 -> 29.5 s).
  mallopt(M_ARENA_MAX, 2);
#endif
  Options options;
  try {
    bool help = false;
    options = parse_arguments(argc, argv, help);
    if(help) { std::cout << usage_text; return 0; }
  } catch(const Usage_error& e) {
    std::cerr << "quad_remesh: " << e.what() << "\n\n" << usage_text;
    return 2;
  }
  try {
    Pipeline pipeline(options);
    return pipeline.run();
  } catch(const Usage_error& e) {
    std::cerr << "quad_remesh: " << e.what() << "\n";
    return 2;
  } catch(const std::exception& e) {
    std::cerr << "quad_remesh: unexpected error: " << e.what() << "\n";
    return 1;
  }
}
