// stage_benchmark: times the pipeline's stages one by one, calling the package's public stage functions
// directly (as quad_remesh() chains them), against the performance targets of the issues.
//
//   stage_benchmark [options]
//     --data DIR          the bundled meshes (default: the repository's data/meshes)
//     --only TEXT         run only the measurements whose name contains TEXT
//     --threads N         threads of the layout, the quantization and quad_remesh() (default 1)
//     --all-meshes DIR    also time the quantization, GLPK and solver-free fallback, on every mesh of DIR
//                         (slow: every stage before it runs first)
//     --json FILE         also write the results as JSON
//     --strict            exit code 1 when a measurement misses its target
//     --verbose           print each measurement's own timing and figures to stderr
//     --help
// Output: one line per measurement, `name  measured_s  target_s  PASS|FAIL`, then a summary. Exit code 0
// unless an error occurs (a missed target is reported, not an error, without --strict).
//
// Every measurement is deterministic: fixed meshes, fixed edge lengths, fixed candidate seeds, and the
// quantization limited by branch-and-bound nodes rather than time.

// the kernel first: the package's headers call the kernel's global functions (CGAL::cross_product, ...)
// without including a kernel header themselves
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Timer.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Quad_remeshing/quad_remesh.h>
#include <CGAL/Quad_remeshing/IO.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace QR = CGAL::Quad_remeshing;
namespace QRP = CGAL::Quad_remeshing::parameters;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index V;
typedef Mesh::Face_index F;
typedef Mesh::Edge_index E;
typedef QR::Patch_layout<Mesh, K> Layout;

struct Options
{
  std::string data, only, json, all_meshes;
  unsigned threads = 1;
  bool strict = false, verbose = false;
};

// Wall-clock time (what the targets are about) and the process's CPU time (all threads): on a loaded
// machine the wall-clock time grows, the CPU time much less.
struct Timing
{
  double wall = 0., cpu = 0.;
};

class Stopwatch
{
public:
  Stopwatch() { wall_.start(); cpu_.start(); }
  Timing time() const { return Timing{wall_.time(), cpu_.time()}; }

private:
  CGAL::Real_timer wall_;
  CGAL::Timer cpu_;
};

struct Result
{
  std::string name;
  double seconds = 0., cpu_seconds = 0., target = 0.;
  QR::Report details = QR::Report::object();
  bool pass() const { return seconds < target; }
  void set(const Timing& t) { seconds = t.wall; cpu_seconds = t.cpu; }
};

std::string default_data_dir()
{
#ifdef QR_BENCHMARK_DATA_DIR
  return QR_BENCHMARK_DATA_DIR;
#else
  return "data/meshes";
#endif
}

std::string base_name(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::string s = slash == std::string::npos ? path : path.substr(slash + 1);
  return s.substr(0, s.find_last_of('.'));
}

// A mesh taken through the stages up to the cross field, as quad_remesh() does; the layout when traced.
struct Prepared
{
  std::string name;
  Mesh tm;
  Mesh::Property_map<E, bool> feature;
  Mesh::Property_map<V, bool> corner;
  Mesh::Property_map<F, K::Vector_3> field;
  Mesh::Property_map<V, int> singularity;
  double quad_edge_length = 0.;
  QR::Report figures = QR::Report::object();
  std::unique_ptr<Layout> layout; // traced by trace_stage()

  Prepared() = default;
  Prepared(const Prepared&) = delete; // the layout refers to tm
};

// reading, features and remeshing (not timed by the measurements that start after them)
void read_and_remesh(const std::string& path, double quad_edge_length, bool verbose, Prepared& p,
                     bool adaptive = false)
{
  p.name = base_name(path);
  QR::read_and_repair(path, p.tm);
  p.feature = p.tm.add_property_map<E, bool>("e:bench_feature", false).first;
  p.corner = p.tm.add_property_map<V, bool>("v:bench_corner", false).first;
  QR::detect_feature_edges(p.tm, p.feature, QRP::combine(QRP::feature_angle(35.).verbose(verbose),
                                                         QRP::vertex_is_feature_corner_map(p.corner)));
  p.quad_edge_length = quad_edge_length > 0. ? quad_edge_length : QR::default_quad_edge_length(p.tm);
  const auto remeshing = QR::remesh_for_quadrangulation(
    p.tm, p.feature, QRP::combine(QRP::quad_edge_length(p.quad_edge_length).verbose(verbose),
                                  QRP::vertex_is_feature_corner_map(p.corner), QRP::adaptive_remeshing(adaptive),
                                  QRP::far_region_rounds(0u))); // (as quad_remesh() and the command line by default)
  if(adaptive) p.figures["distance_after"] = remeshing.distance_after;
  p.tm.collect_garbage(); // the later stages index elements densely
  p.figures["faces"] = p.tm.number_of_faces();
  p.figures["quad_edge_length"] = p.quad_edge_length;
}

// compute_cross_field() + compute_cross_field_singularities(); returns their times
Timing field_stage(Prepared& p, bool verbose)
{
  p.field = p.tm.add_property_map<F, K::Vector_3>("f:bench_field", K::Vector_3(0, 0, 0)).first;
  p.singularity = p.tm.add_property_map<V, int>("v:bench_singularity", 0).first;
  const Stopwatch t;
  const auto fs = QR::compute_cross_field(p.tm, p.feature, p.field, CGAL::parameters::verbose(verbose));
  const auto ss = QR::compute_cross_field_singularities(p.tm, p.feature, p.field, p.singularity,
                                                        CGAL::parameters::verbose(verbose));
  const Timing s = t.time();
  p.figures["field"] = fs.report();
  p.figures["singular_vertices"] = ss.singular_vertices;
  return s;
}

// a Patch_layout and trace_patch_layout(); returns their times
Timing trace_stage(Prepared& p, unsigned threads, bool verbose)
{
  const Stopwatch t;
  p.layout = std::make_unique<Layout>(p.tm, p.field, p.singularity);
  const auto st = QR::trace_patch_layout(p.tm, p.feature, *p.layout,
                                         QR::parameters::combine(CGAL::parameters::verbose(verbose),
                                                                 QR::parameters::number_of_threads(threads)));
  const Timing s = t.time();
  p.figures["layout"] = st.layout.report();
  return s;
}

// the pipeline's quantization problem (the layout's arcs and patches as sides, the default tolerances) +
// quantize_patch_sides(), with or without the MIP solver; returns their times
Timing quantize_stage(const Prepared& p, bool use_solver, unsigned threads, bool verbose, QR::Report& figures)
{
  const Stopwatch t;
  const QR::internal::Quadrangulation_layout<Mesh, Layout> polygons(p.tm, *p.layout);
  const auto problem =
    QR::internal::pipeline_quantization_problem(p.tm, *p.layout, polygons, p.feature, p.quad_edge_length,
                                                QR::internal::default_sizing_tolerance,
                                                QR::internal::default_feature_tolerance,
                                                QR::internal::default_surface_tolerance).problem;
  std::vector<int> counts;
  const auto st = QR::quantize_patch_sides(problem, counts,
    QRP::combine(QRP::use_mip_solver(use_solver), QRP::number_of_threads(threads), CGAL::parameters::verbose(verbose)));
  const Timing s = t.time();
  figures["patches"] = problem.patches.size();
  figures["arcs"] = problem.arcs.size();
  figures["clusters"] = st.clusters;
  figures["fallback_clusters"] = st.fallback_clusters;
  figures["objective"] = st.objective;
  return s;
}

// the edge length that gives about `faces` triangles after remesh_for_quadrangulation(), whose uniform pass
// uses half the quad edge length: an equilateral triangle of side l/2 has area sqrt(3) l^2 / 16
double quad_edge_length_for_triangles(const Mesh& tm, std::size_t faces)
{
  const double area = CGAL::to_double(CGAL::Polygon_mesh_processing::area(tm));
  return std::sqrt(16. * area / (std::sqrt(3.) * double(faces)));
}

class Benchmark
{
public:
  explicit Benchmark(const Options& o) : opt_(o) {}

  int run()
  {
    measure("remesh_fandisk", 2., [&](Result& r) { remesh_stage("fandisk", r); });
    measure("remesh_abc_00000006", 6., [&](Result& r) { remesh_stage("abc_00000006", r); });
    // the same target with the adaptive pass (quad_remesh --until remesh --adaptive-remeshing)
    measure("remesh_abc_00000006_adaptive", 6., [&](Result& r) { remesh_stage("abc_00000006", r, true); });
    measure("cross_field_40k", 1., [&](Result& r) { cross_field_40k(r); });
    measure("direction_graph_1000_traces_fandisk", 2., [&](Result& r) { direction_graph(r); });
    measure("layout_fandisk", 3., [&](Result& r) { r.set(trace_stage(prepared("fandisk"), opt_.threads, opt_.verbose)); r.details = prepared("fandisk").figures["layout"]; });
    measure("layout_abc_00000006", 10., [&](Result& r) { r.set(trace_stage(prepared("abc_00000006"), opt_.threads, opt_.verbose)); r.details = prepared("abc_00000006").figures["layout"]; });
    measure("quantize_fandisk_glpk", 1., [&](Result& r) { r.set(quantize_stage(traced("fandisk"), true, opt_.threads, opt_.verbose, r.details)); });
    measure("quantize_fandisk_fallback", 1., [&](Result& r) { r.set(quantize_stage(traced("fandisk"), false, opt_.threads, opt_.verbose, r.details)); });
    if(!opt_.all_meshes.empty()) all_meshes();
    measure("quadrangulate_polygon_all_small", 10., [&](Result& r) { quadrangulate_all(r); });
    measure("end_to_end_fandisk", 10., [&](Result& r) { end_to_end(r); });

    std::size_t passed = 0;
    for(const Result& r : results_) passed += r.pass() ? 1 : 0;
    std::cout << passed << "/" << results_.size() << " measurements within target";
    if(errors_) std::cout << ", " << errors_ << " error(s)";
    std::cout << "\n";
    if(!opt_.json.empty()) write_json(passed);
    if(errors_) return 1;
    return (opt_.strict && passed != results_.size()) ? 1 : 0;
  }

private:
  bool selected(const std::string& name) const { return opt_.only.empty() || name.find(opt_.only) != std::string::npos; }

  void measure(const std::string& name, double target, const std::function<void(Result&)>& body)
  {
    if(!selected(name)) return;
    Result r;
    r.name = name;
    r.target = target;
    try {
      body(r);
    } catch(const std::exception& e) {
      ++errors_;
      std::cout << std::left << std::setw(44) << name << "  ERROR: " << e.what() << std::endl;
      return;
    }
    std::cout << std::left << std::setw(44) << name << std::right << std::fixed << std::setprecision(3)
              << std::setw(9) << r.seconds << std::setw(9) << r.target << "  " << (r.pass() ? "PASS" : "FAIL")
              << std::endl;
    std::cout.unsetf(std::ios::floatfield);
    if(opt_.verbose) std::cerr << "[stage_benchmark] " << name << ": " << r.seconds << " s (cpu " << r.cpu_seconds << " s), " << r.details.to_json(-1) << "\n";
    results_.push_back(std::move(r));
  }

  std::string mesh_path(const std::string& name) const { return opt_.data + "/" + name + ".off"; }

  // the mesh `name` of the data directory through the cross field, at the default quad edge length
  Prepared& prepared(const std::string& name)
  {
    for(auto& p : cache_) if(p->name == name) return *p;
    auto p = std::make_unique<Prepared>();
    read_and_remesh(mesh_path(name), 0., opt_.verbose, *p);
    field_stage(*p, opt_.verbose);
    cache_.push_back(std::move(p)); // only once prepared: a failure is not cached
    return *cache_.back();
  }

  Prepared& traced(const std::string& name)
  {
    Prepared& p = prepared(name);
    if(!p.layout) trace_stage(p, opt_.threads, opt_.verbose);
    return p;
  }

  // #3: reading, repair, features and remeshing at the default density (quad_remesh --until remesh
  // without writing the result)
  void remesh_stage(const std::string& name, Result& r, bool adaptive = false)
  {
    auto p = std::make_unique<Prepared>();
    const Stopwatch t;
    read_and_remesh(mesh_path(name), 0., opt_.verbose, *p, adaptive);
    r.set(t.time());
    r.details = p->figures;
  }

  // #4: the cross field of fandisk remeshed to about 40 000 triangles (one correction of the length if the
  // first remeshing is more than 10% off)
  void cross_field_40k(Result& r)
  {
    const std::size_t wanted = 40000;
    Mesh input;
    QR::read_and_repair(mesh_path("fandisk"), input);
    double length = quad_edge_length_for_triangles(input, wanted);
    auto p = std::make_unique<Prepared>();
    read_and_remesh(mesh_path("fandisk"), length, opt_.verbose, *p);
    const double ratio = double(p->tm.number_of_faces()) / double(wanted);
    if(std::abs(ratio - 1.) > 0.1) {
      length *= std::sqrt(ratio);
      p = std::make_unique<Prepared>();
      read_and_remesh(mesh_path("fandisk"), length, opt_.verbose, *p);
    }
    std::cout << "  (fandisk remeshed with quad edge length " << length << ": " << p->tm.number_of_faces()
              << " faces)\n";
    r.set(field_stage(*p, opt_.verbose));
    r.details = p->figures;
  }

  // #5: the direction graph G on fandisk with its real cross field (a layout of the feature paths) and
  // 1000 candidate paths traced from fixed vertices towards the feature lines
  void direction_graph(Result& r)
  {
    Prepared& p = prepared("fandisk");
    const Stopwatch t;
    Layout layout(p.tm, p.field, p.singularity);
    layout.add_feature_paths(p.feature);
    const auto size = layout.direction_graph_size();
    const double build = t.time().wall;
    std::vector<Layout::Node> ends;
    for(V v : p.tm.vertices())
      if(layout.is_on_cut(v)) for(int k = 0; k < 4; ++k) ends.push_back(Layout::Node{v, k});
    std::size_t found = 0;
    const std::size_t n = p.tm.number_of_vertices();
    for(std::size_t i = 0; i < 1000; ++i)
      found += layout.trace(Layout::Node{V(Mesh::size_type((i * 7919) % n)), int(i % 4)}, ends) ? 1 : 0;
    r.set(t.time());
    r.details["faces"] = p.tm.number_of_faces();
    r.details["graph_nodes"] = size.first;
    r.details["graph_arcs"] = size.second;
    r.details["build_seconds"] = build;
    r.details["paths_found"] = found;
  }

  // #7 on many meshes: GLPK and the fallback, each on the same layout
  void all_meshes()
  {
    std::vector<std::string> files;
    if(DIR* d = opendir(opt_.all_meshes.c_str())) {
      while(const dirent* e = readdir(d)) {
        const std::string f = e->d_name;
        if(QR::internal::is_supported_mesh_extension(QR::internal::lower_extension(f)))
          files.push_back(opt_.all_meshes + "/" + f);
      }
      closedir(d);
    } else {
      ++errors_;
      std::cout << "cannot read the directory " << opt_.all_meshes << "\n";
      return;
    }
    std::sort(files.begin(), files.end());
    for(const std::string& f : files) {
      const std::string name = base_name(f);
      if(!selected("quantize_glpk:" + name) && !selected("quantize_fallback:" + name)) continue;
      auto p = std::make_unique<Prepared>();
      try {
        read_and_remesh(f, 0., opt_.verbose, *p);
        field_stage(*p, opt_.verbose);
        trace_stage(*p, opt_.threads, opt_.verbose);
      } catch(const std::exception& e) {
        ++errors_;
        std::cout << std::left << std::setw(44) << ("quantize:" + name) << "  ERROR before quantization: " << e.what() << std::endl;
        continue;
      }
      measure("quantize_glpk:" + name, 10., [&](Result& r) { r.set(quantize_stage(*p, true, opt_.threads, opt_.verbose, r.details)); });
      measure("quantize_fallback:" + name, 10., [&](Result& r) { r.set(quantize_stage(*p, false, opt_.threads, opt_.verbose, r.details)); });
    }
  }

  // #8: every polygon of 2 to 6 sides with side edge counts 1..8 (n <= 4) or 1..6 (n = 5, 6) and an even
  // perimeter, (1, 1) excepted (a perimeter of 4 at least is required)
  void quadrangulate_all(Result& r)
  {
    std::size_t cases = 0, quads = 0;
    const Stopwatch t;
    for(std::size_t n = 2; n <= 6; ++n) {
      const int max_e = n <= 4 ? 8 : 6;
      std::vector<int> e(n, 1);
      for(;;) {
        int sum = 0;
        for(int x : e) sum += x;
        if(sum % 2 == 0 && sum >= 4) {
          quads += QR::quadrangulate_polygon(e).quads.size();
          ++cases;
        }
        std::size_t i = 0; // next vector, odometer order
        while(i < n && e[i] == max_e) e[i++] = 1;
        if(i == n) break;
        ++e[i];
      }
    }
    r.set(t.time());
    r.details["polygons"] = cases;
    r.details["quads"] = quads;
  }

  // #9: quad_remesh() on fandisk, reading excluded
  void end_to_end(Result& r)
  {
    Mesh tm, qm;
    QR::read_and_repair(mesh_path("fandisk"), tm);
    const Stopwatch t;
    const QR::Report report = QR::quad_remesh(tm, qm, QRP::number_of_threads(opt_.threads).verbose(opt_.verbose));
    r.set(t.time());
    r.details["quads"] = qm.number_of_faces();
    for(const char* stage : {"features", "remesh", "field", "singularities", "layout", "quantize", "quadrangulate", "smooth"})
      if(const QR::Report* s = report.find(stage))
        if(const QR::Report* x = s->find("seconds")) r.details["stage_seconds"][stage] = *x;
  }

  void write_json(std::size_t passed) const
  {
    QR::Report root = QR::Report::object();
    root["threads"] = opt_.threads;
    root["passed"] = passed;
    root["errors"] = errors_;
    QR::Report& list = root["measurements"];
    list = QR::Report::array();
    for(const Result& r : results_) {
      QR::Report m = QR::Report::object();
      m["name"] = r.name;
      m["seconds"] = r.seconds;
      m["cpu_seconds"] = r.cpu_seconds;
      m["target_seconds"] = r.target;
      m["pass"] = r.pass();
      m["details"] = r.details;
      list.push_back(m);
    }
    std::ofstream out(opt_.json);
    out << root.to_json() << "\n";
    if(!out) throw std::runtime_error("cannot write " + opt_.json);
  }

  Options opt_;
  std::vector<Result> results_;
  std::size_t errors_ = 0;
  std::vector<std::unique_ptr<Prepared>> cache_;
};

void usage(std::ostream& os)
{
  os << "usage: stage_benchmark [--data DIR] [--only TEXT] [--threads N] [--all-meshes DIR] [--json FILE]\n"
        "                       [--strict] [--verbose] [--help]\n"
        "Times the stages against the issues' targets; one line per measurement: name, seconds, target, PASS|FAIL.\n"
        "  remesh_fandisk, remesh_abc_00000006  read_and_repair + detect_feature_edges + remesh_for_quadrangulation (< 2 s, < 6 s)\n"
        "  remesh_abc_00000006_adaptive         the same with the adaptive pass (< 6 s)\n"
        "  cross_field_40k                      compute_cross_field + singularities, fandisk remeshed to ~40k faces (< 1 s)\n"
        "  direction_graph_1000_traces_fandisk  layout of the feature paths, G, 1000 traces, real field (< 2 s)\n"
        "  layout_fandisk, layout_abc_00000006  Patch_layout + trace_patch_layout (< 3 s, < 10 s)\n"
        "  quantize_fandisk_glpk / _fallback    quantization_problem + quantize_patch_sides (< 1 s)\n"
        "  quadrangulate_polygon_all_small      quadrangulate_polygon, n = 2..6, all small side counts (< 10 s)\n"
        "  end_to_end_fandisk                   quad_remesh() (< 10 s)\n"
        "  --all-meshes DIR adds quantize_glpk:<mesh> and quantize_fallback:<mesh> for every mesh of DIR (< 10 s)\n"
        "Exit code: 0, or 1 on an error (or a missed target with --strict), 2 on bad arguments.\n";
}

} // namespace

int main(int argc, char** argv)
{
  Options opt;
  opt.data = default_data_dir();
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) { std::cerr << "stage_benchmark: " << a << " needs a value\n"; std::exit(2); }
      return argv[++i];
    };
    if(a == "--help" || a == "-h") { usage(std::cout); return 0; }
    else if(a == "--data") opt.data = value();
    else if(a == "--only") opt.only = value();
    else if(a == "--json") opt.json = value();
    else if(a == "--all-meshes") opt.all_meshes = value();
    else if(a == "--strict") opt.strict = true;
    else if(a == "--verbose") opt.verbose = true;
    else if(a == "--threads") {
      const std::string v = value();
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if(v.empty() || *end != '\0' || n < 1 || n > 256) {
        std::cerr << "stage_benchmark: invalid value '" << v << "' for --threads\n";
        return 2;
      }
      opt.threads = unsigned(n);
    }
    else { std::cerr << "stage_benchmark: unknown option " << a << "\n"; usage(std::cerr); return 2; }
  }
  try {
    return Benchmark(opt).run();
  } catch(const std::exception& e) {
    std::cerr << "stage_benchmark: " << e.what() << "\n";
    return 1;
  }
}
