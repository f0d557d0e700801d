// quad_remesh_batch: runs quad_remesh over many meshes, one process per mesh (a crash or a time-out is
// recorded, not fatal), and writes one CSV row and one JSON line per mesh plus a summary.
//
//   quad_remesh_batch [options] MESH... | --manifest FILE
//     --exe PATH          the quad_remesh program (default: the one built next to this program)
//     --out DIR           where outputs, reports and results go (default: batch_out)
//     --time-limit S      per-mesh wall-clock limit; the process is killed after it (default 600)
//     --shard I/N         process only the meshes whose index modulo N is I (for job arrays)
//     --resume            skip meshes whose report already exists in DIR
//     --manifest FILE     one mesh path per line ('#' starts a comment)
//     --html              also write each mesh's HTML report (quad_remesh --html DIR/<name>.html)
//     --target-seconds S  count and list the meshes that took S seconds or more (issue #10: 30)
//     --target-kb-per-triangle K
//                         count and list the meshes whose peak memory reached K KiB per input triangle
//                         or more (issue #10: 2)
//     -- ARGS...          passed on to quad_remesh (e.g. -- --until remesh --faces 2000)
// Results: DIR/results.csv, DIR/results.jsonl (appended), DIR/summary.json, DIR/summary.html (a page
// with one row per mesh of this run, linking to its report, log and output), DIR/summary.md (the same
// as a Markdown table, as in the user manual), and a summary on stdout.

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/internal/html/writer.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace QR = CGAL::Quad_remeshing;

namespace {

const std::vector<std::string> stage_names = {"repair", "features", "remesh", "field",
                                              "layout", "quantize", "quadrangulate", "smooth"};
const std::vector<std::string> quality_keys = {
  "irregular_vertices", "irregular_boundary_vertices", "angle_deviation", "edge_length_deviation",
  "mean_scaled_jacobian", "min_scaled_jacobian", "non_positive_scaled_jacobian", "flipped_quads", "pure_quad", "valid",
  "hausdorff_max", "feature_coverage"};

struct Options
{
  std::string exe, out = "batch_out", manifest;
  double time_limit = 600.;
  double target_seconds = 0., target_kb_per_triangle = 0.; // 0: no target
  unsigned shard = 0, shards = 1;
  bool resume = false, html = false;
  std::vector<std::string> meshes, extra;
};

struct Run
{
  std::string mesh, name, status;
  int exit_code = -1;
  double seconds = 0.;
  long peak_kb = 0;
  QR::Report report;
};

std::string base_name(const std::string& path)
{
  std::string s = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  return s.substr(0, s.find_last_of('.'));
}

bool file_exists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

std::string default_exe(const char* argv0)
{
#ifdef QR_QUAD_REMESH_EXE
  if(file_exists(QR_QUAD_REMESH_EXE)) return QR_QUAD_REMESH_EXE;
#endif
  std::string self = argv0;
  const std::size_t slash = self.find_last_of('/');
  return (slash == std::string::npos ? std::string(".") : self.substr(0, slash)) + "/quad_remesh";
}

// Runs one mesh in its own process group, kills it at the time limit, measures time and peak memory.
Run run_one(const Options& o, const std::string& mesh)
{
  Run r;
  r.mesh = mesh;
  r.name = base_name(mesh);
  const std::string report_file = o.out + "/" + r.name + ".json";
  const std::string output_file = o.out + "/" + r.name + "_quad.obj";
  const std::string log_file = o.out + "/" + r.name + ".log";
  std::remove(report_file.c_str());

  std::vector<std::string> args = {o.exe, mesh, "-o", output_file, "--report", report_file};
  if(o.html)
  {
    const std::string html_file = o.out + "/" + r.name + ".html";
    std::remove(html_file.c_str());
    args.insert(args.end(), {"--html", html_file});
  }
  args.insert(args.end(), o.extra.begin(), o.extra.end());
  std::vector<char*> argv;
  for(std::string& a : args) argv.push_back(&a[0]);
  argv.push_back(nullptr);

  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if(pid < 0) { r.status = "fork_failed"; return r; }
  if(pid == 0)
  {
    setpgid(0, 0);
    FILE* log = std::fopen(log_file.c_str(), "w");
    if(log) { dup2(fileno(log), 1); dup2(fileno(log), 2); }
    execv(argv[0], argv.data());
    std::perror("execv");
    _exit(127);
  }
  int status = 0;
  struct rusage usage;
  std::memset(&usage, 0, sizeof(usage));
  bool timed_out = false;
  for(;;)
  {
    const pid_t w = wait4(pid, &status, WNOHANG, &usage);
    if(w == pid) break;
    if(w < 0 && errno != EINTR) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(!timed_out && elapsed > o.time_limit)
    {
      timed_out = true;
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.peak_kb = usage.ru_maxrss;
  if(timed_out) r.status = "timeout";
  else if(WIFSIGNALED(status)) { r.status = "crashed"; r.exit_code = 128 + WTERMSIG(status); }
  else
  {
    r.exit_code = WEXITSTATUS(status);
    r.status = r.exit_code == 0 ? "ok" : (r.exit_code == 2 ? "bad_input" : "failed");
  }
  std::ifstream in(report_file);
  if(in)
  {
    std::stringstream ss;
    ss << in.rdbuf();
    try { r.report = QR::Report::parse(ss.str()); } catch(const std::exception&) { r.status += "+bad_report"; }
  }
  return r;
}

std::string csv_escape(const std::string& s)
{
  if(s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for(char c : s) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string number_or_empty(const QR::Report* v)
{
  if(!v || v->is_null()) return "";
  std::ostringstream os;
  if(v->kind() == QR::Report::BOOLEAN) os << (v->boolean() ? 1 : 0);
  else if(v->kind() == QR::Report::NUMBER) os << v->number();
  else os << v->string();
  return os.str();
}

const QR::Report* stage_of(const QR::Report& report, const std::string& name)
{
  if(const QR::Report* stages = report.find("stages"))
    for(const QR::Report& s : stages->elements())
      if(s.find("name") && s.find("name")->string() == name) return &s;
  return nullptr;
}

const QR::Report* quality_of(const QR::Report& report)
{
  const QR::Report* out = report.find("output");
  return out ? out->find("quality") : nullptr;
}

double percentile(std::vector<double> v, double p)
{
  if(v.empty()) return 0.;
  std::sort(v.begin(), v.end());
  const double x = p * double(v.size() - 1);
  const std::size_t i = std::size_t(std::floor(x));
  const std::size_t j = std::min(i + 1, v.size() - 1);
  return v[i] + (x - double(i)) * (v[j] - v[i]);
}

using QR::internal::html::escape_html;

// A file name relative to the summary page (all files are in the output directory), as a link target:
// percent-encoded except the characters that are safe in a path.
std::string href(const std::string& file)
{
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for(unsigned char c : file)
  {
    if(std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') out += char(c);
    else { out += '%'; out += hex[c >> 4]; out += hex[c & 15]; }
  }
  return out;
}

// The summary page: self-contained (no script, no external file), one row per mesh of this run with its
// status, times, output size and quality figures; failures sort first so that they are not missed.
void write_summary_html(const std::string& path, const Options& o, const std::vector<Run>& runs,
                        const QR::Report& summary)
{
  std::ofstream os(path);
  if(!os) { std::cerr << "quad_remesh_batch: cannot write " << path << "\n"; return; }
  std::vector<const Run*> order;
  for(const Run& r : runs) order.push_back(&r);
  std::stable_sort(order.begin(), order.end(), [](const Run* a, const Run* b) {
    return (a->status == "ok") < (b->status == "ok");
  });
  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>quad_remesh batch summary</title>\n"
     << "<style>body{font:13px/1.35 system-ui,sans-serif;margin:16px;color:#222}table{border-collapse:collapse}"
     << "td,th{padding:2px 7px;border-bottom:1px solid #ddd;text-align:right;white-space:nowrap}"
     << "td:first-child,th:first-child,td.text{text-align:left}th{background:#eee;position:sticky;top:0}"
     << "tr.fail td{background:#fde8e8}.err{color:#a00;white-space:normal;text-align:left;max-width:40em}</style>\n"
     << "</head>\n<body>\n<h1>quad_remesh batch summary</h1>\n<p>";
  for(std::size_t i = 0; i < summary.keys().size(); ++i)
    os << (i > 0 ? ", " : "") << escape_html(summary.keys()[i]) << ": <b>" << number_or_empty(&summary.elements()[i]) << "</b>";
  os << "</p>\n<p>program: <code>" << escape_html(o.exe) << "</code>";
  for(const std::string& a : o.extra) os << " <code>" << escape_html(a) << "</code>";
  os << "</p>\n<table>\n<tr><th>mesh</th><th>status</th><th>seconds</th><th>peak MiB</th><th>input F</th><th>output F</th>";
  for(const std::string& s : stage_names) os << "<th>" << s << " s</th>";
  for(const std::string& k : quality_keys) os << "<th>" << escape_html(k) << "</th>";
  os << "<th>files</th><th>error</th></tr>\n";
  for(const Run* r : order)
  {
    const QR::Report* input = r->report.find("input");
    const QR::Report* output = r->report.find("output");
    const QR::Report* q = quality_of(r->report);
    const QR::Report* err = r->report.find("error");
    os << "<tr" << (r->status == "ok" ? "" : " class=\"fail\"") << "><td>" << escape_html(r->name) << "</td><td class=\"text\">"
       << escape_html(r->status) << "</td><td>" << std::fixed << std::setprecision(2) << r->seconds
       << std::defaultfloat << std::setprecision(6) << "</td><td>" << r->peak_kb / 1024 << "</td><td>"
       << number_or_empty(input ? input->find("F") : nullptr) << "</td><td>"
       << number_or_empty(output ? output->find("F") : nullptr) << "</td>";
    for(const std::string& s : stage_names)
    {
      const QR::Report* st = stage_of(r->report, s);
      os << "<td>" << number_or_empty(st ? st->find("seconds") : nullptr) << "</td>";
    }
    for(const std::string& k : quality_keys) os << "<td>" << escape_html(number_or_empty(q ? q->find(k) : nullptr)) << "</td>";
    os << "<td class=\"text\">";
    const std::pair<const char*, const char*> files[] = {
      {".html", "report"}, {".json", "json"}, {".log", "log"}, {"_quad.obj", "output"}};
    for(const auto& f : files)
      if(file_exists(o.out + "/" + r->name + f.first))
        os << "<a href=\"" << href(r->name + f.first) << "\">" << f.second << "</a> ";
    os << "</td><td class=\"err\">" << escape_html(err ? err->string() : std::string()) << "</td></tr>\n";
  }
  os << "</table>\n</body>\n</html>\n";
}

// The summary as a Markdown table (Doxygen renders it; the manual's development-set table is one), one
// row per mesh of this run in the order run, then the summary figures.
void write_summary_markdown(const std::string& path, const std::vector<Run>& runs, const QR::Report& summary)
{
  std::ofstream os(path);
  if(!os) { std::cerr << "quad_remesh_batch: cannot write " << path << "\n"; return; }
  auto fixed = [](const QR::Report* v, int digits) {
    if(!v || v->kind() != QR::Report::NUMBER) return std::string("-");
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v->number();
    return s.str();
  };
  os << "| mesh | status | seconds | peak MiB | quads | irregular | SJ mean | SJ min | SJ <= 0 | flipped "
        "| feature coverage | Hausdorff / diagonal | valid |\n"
     << "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|\n";
  for(const Run& r : runs)
  {
    const QR::Report* output = r.report.find("output");
    const QR::Report* q = quality_of(r.report);
    auto get = [&](const char* k) { return q ? q->find(k) : nullptr; };
    const QR::Report* valid = get("valid");
    os << "| " << r.name << " | " << r.status << " | " << std::fixed << std::setprecision(1) << r.seconds << " | "
       << r.peak_kb / 1024 << " | " << fixed(output ? output->find("F") : nullptr, 0) << " | "
       << fixed(get("irregular_vertices"), 0) << " | " << fixed(get("mean_scaled_jacobian"), 3) << " | "
       << fixed(get("min_scaled_jacobian"), 3) << " | " << fixed(get("non_positive_scaled_jacobian"), 0) << " | "
       << fixed(get("flipped_quads"), 0) << " | " << fixed(get("feature_coverage"), 3) << " | " << fixed(get("hausdorff_max"), 4) << " | "
       << (valid ? (valid->boolean() ? "yes" : "no") : "-") << " |\n";
  }
  os << "\n";
  for(std::size_t i = 0; i < summary.keys().size(); ++i)
    os << (i > 0 ? ", " : "") << summary.keys()[i] << " " << number_or_empty(&summary.elements()[i]);
  os << "\n";
}

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw std::runtime_error("option " + a + " needs a value");
      return argv[++i];
    };
    if(a == "--") { for(++i; i < argc; ++i) o.extra.push_back(argv[i]); }
    else if(a == "--exe") o.exe = value();
    else if(a == "--out") o.out = value();
    else if(a == "--time-limit") o.time_limit = std::stod(value());
    else if(a == "--manifest") o.manifest = value();
    else if(a == "--resume") o.resume = true;
    else if(a == "--html") o.html = true;
    else if(a == "--target-seconds") o.target_seconds = std::stod(value());
    else if(a == "--target-kb-per-triangle") o.target_kb_per_triangle = std::stod(value());
    else if(a == "--shard")
    {
      const std::string s = value();
      if(std::sscanf(s.c_str(), "%u/%u", &o.shard, &o.shards) != 2 || o.shards == 0 || o.shard >= o.shards)
        throw std::runtime_error("--shard expects I/N with 0 <= I < N");
    }
    else if(a == "--help" || a == "-h") throw std::runtime_error("help");
    else if(!a.empty() && a[0] == '-') throw std::runtime_error("unknown option " + a);
    else o.meshes.push_back(a);
  }
  if(!o.manifest.empty())
  {
    std::ifstream in(o.manifest);
    if(!in) throw std::runtime_error("cannot read the manifest " + o.manifest);
    std::string line;
    while(std::getline(in, line))
    {
      line = line.substr(0, line.find('#'));
      line.erase(0, line.find_first_not_of(" \t\r"));
      line.erase(line.find_last_not_of(" \t\r") + 1);
      if(!line.empty()) o.meshes.push_back(line);
    }
  }
  if(o.meshes.empty()) throw std::runtime_error("no mesh given");
  return o;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  try {
    o = parse(argc, argv);
  } catch(const std::exception& e) {
    if(std::string(e.what()) != "help") std::cerr << "quad_remesh_batch: " << e.what() << "\n\n";
    std::cerr << "usage: quad_remesh_batch [--exe PATH] [--out DIR] [--time-limit S] [--shard I/N] [--resume]\n"
                 "                         [--html] [--target-seconds S] [--target-kb-per-triangle K]\n"
                 "                         [--manifest FILE] MESH... [-- quad_remesh options]\n";
    return 2;
  }
  if(o.exe.empty()) o.exe = default_exe(argv[0]);
  if(!file_exists(o.exe)) { std::cerr << "quad_remesh_batch: no program at " << o.exe << "\n"; return 2; }
  mkdir(o.out.c_str(), 0755);

  const std::string csv_path = o.out + "/results.csv";
  const bool new_csv = !file_exists(csv_path);
  std::ofstream csv(csv_path, std::ios::app);
  std::ofstream jsonl(o.out + "/results.jsonl", std::ios::app);
  if(new_csv)
  {
    csv << "mesh,status,exit_code,seconds,peak_kb,input_F,output_V,output_F";
    for(const std::string& s : stage_names) csv << "," << s << "_s";
    for(const std::string& k : quality_keys) csv << "," << k;
    csv << ",error\n";
  }

  std::vector<Run> runs;
  for(std::size_t i = 0; i < o.meshes.size(); ++i)
  {
    if(i % o.shards != o.shard) continue;
    const std::string& mesh = o.meshes[i];
    if(o.resume && file_exists(o.out + "/" + base_name(mesh) + ".json"))
    {
      std::cout << "skip " << mesh << " (already done)\n";
      continue;
    }
    Run r = run_one(o, mesh);
    const QR::Report* input = r.report.find("input");
    const QR::Report* output = r.report.find("output");
    csv << csv_escape(r.mesh) << "," << r.status << "," << r.exit_code << "," << r.seconds << "," << r.peak_kb
        << "," << number_or_empty(input ? input->find("F") : nullptr)
        << "," << number_or_empty(output ? output->find("V") : nullptr)
        << "," << number_or_empty(output ? output->find("F") : nullptr);
    for(const std::string& s : stage_names)
    {
      const QR::Report* st = stage_of(r.report, s);
      csv << "," << number_or_empty(st ? st->find("seconds") : nullptr);
    }
    const QR::Report* q = quality_of(r.report);
    for(const std::string& k : quality_keys) csv << "," << number_or_empty(q ? q->find(k) : nullptr);
    const QR::Report* err = r.report.find("error");
    csv << "," << csv_escape(err ? err->string() : std::string()) << "\n";
    csv.flush();

    QR::Report line = QR::Report::object();
    line["mesh"] = r.mesh;
    line["status"] = r.status;
    line["exit_code"] = r.exit_code;
    line["seconds"] = r.seconds;
    line["peak_kb"] = r.peak_kb;
    line["report"] = r.report;
    line.write_json(jsonl, -1);
    jsonl << "\n";
    jsonl.flush();
    std::cout << r.name << ": " << r.status << " in " << r.seconds << " s, peak " << r.peak_kb / 1024 << " MiB"
              << (err && !err->string().empty() ? " (" + err->string() + ")" : std::string()) << "\n";
    runs.push_back(std::move(r));
  }

  // Summary, like the paper's Thingi10K statistics.
  QR::Report summary = QR::Report::object();
  std::size_t ok = 0, quad_outputs = 0, inverted_outputs = 0;
  std::vector<double> times, sj, irregular, peak_mib, kb_per_triangle;
  std::vector<std::string> over_time, over_memory;
  for(const Run& r : runs)
  {
    if(r.status == "ok") ++ok;
    times.push_back(r.seconds);
    peak_mib.push_back(double(r.peak_kb) / 1024.);
    if(o.target_seconds > 0. && r.seconds >= o.target_seconds) over_time.push_back(r.name);
    // per triangle of the input as read (before the repair); a run refused before reading has none
    const QR::Report* input = r.report.find("input");
    const QR::Report* input_faces = input ? input->find("F") : nullptr;
    if(input_faces && input_faces->number() > 0.)
    {
      kb_per_triangle.push_back(double(r.peak_kb) / input_faces->number());
      if(o.target_kb_per_triangle > 0. && kb_per_triangle.back() >= o.target_kb_per_triangle)
        over_memory.push_back(r.name);
    }
    // the quad figures of quad outputs only: a run stopped before the quad stages (--until remesh) writes
    // triangles, whose scaled Jacobian is 0 and whose vertices are all irregular as quad vertices
    const QR::Report* q = quality_of(r.report);
    const QR::Report* pure_quad = q ? q->find("pure_quad") : nullptr;
    if(pure_quad && pure_quad->boolean())
    {
      ++quad_outputs;
      if(const QR::Report* v = q->find("mean_scaled_jacobian")) sj.push_back(v->number());
      if(const QR::Report* v = q->find("irregular_vertices")) irregular.push_back(v->number());
      // inverted in either sense: a scaled Jacobian <= 0, or flipped over (see Quad_mesh_quality)
      const QR::Report* bad_sj = q->find("non_positive_scaled_jacobian");
      const QR::Report* flipped = q->find("flipped_quads");
      if((bad_sj && bad_sj->number() > 0.) || (flipped && flipped->number() > 0.)) ++inverted_outputs;
    }
  }
  summary["meshes"] = runs.size();
  summary["succeeded"] = ok;
  summary["success_rate"] = runs.empty() ? 0. : double(ok) / double(runs.size());
  summary["seconds_median"] = percentile(times, 0.5);
  summary["seconds_p90"] = percentile(times, 0.9);
  summary["seconds_p99"] = percentile(times, 0.99);
  summary["seconds_max"] = percentile(times, 1.0);
  summary["quad_outputs"] = quad_outputs;
  if(quad_outputs > 0)
  {
    summary["SJ_mean_median"] = percentile(sj, 0.5);
    summary["irregular_median"] = percentile(irregular, 0.5);
    summary["outputs_with_inverted_quads"] = inverted_outputs;
  }
  summary["peak_mib_median"] = percentile(peak_mib, 0.5);
  summary["peak_mib_max"] = percentile(peak_mib, 1.0);
  summary["kb_per_input_triangle_median"] = percentile(kb_per_triangle, 0.5);
  summary["kb_per_input_triangle_max"] = percentile(kb_per_triangle, 1.0);
  auto list_misses = [&](const char* key, double target, const std::vector<std::string>& names) {
    if(!(target > 0.)) return;
    summary[key] = names.size();
    std::cout << key << " (" << target << "): " << names.size();
    for(const std::string& n : names) std::cout << " " << n;
    std::cout << "\n";
  };
  list_misses("over_time_target", o.target_seconds, over_time);
  list_misses("over_memory_target", o.target_kb_per_triangle, over_memory);
  std::ofstream(o.out + "/summary.json") << summary.to_json() << "\n";
  write_summary_html(o.out + "/summary.html", o, runs, summary);
  write_summary_markdown(o.out + "/summary.md", runs, summary);
  std::cout << "summary: " << summary.to_json(-1) << "\n";
  return 0;
}
