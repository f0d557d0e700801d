// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Details of write_html_report(): reading three.js, encoding it, and writing the scene as JSON.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_HTML_WRITER_H
#define CGAL_QUAD_REMESHING_INTERNAL_HTML_WRITER_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/internal/html/viewer_page.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <ios>
#include <iterator>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {
namespace html {

template <typename Point>
std::array<double, 3> to_array(const Point& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

inline std::string read_text_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) return std::string();
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline std::string base64(const std::string& s)
{
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((s.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for(; i + 2 < s.size(); i += 3)
  {
    const unsigned v = (unsigned(static_cast<unsigned char>(s[i])) << 16) |
                       (unsigned(static_cast<unsigned char>(s[i + 1])) << 8) | unsigned(static_cast<unsigned char>(s[i + 2]));
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += digits[(v >> 6) & 63];
    out += digits[v & 63];
  }
  if(i < s.size())
  {
    unsigned v = unsigned(static_cast<unsigned char>(s[i])) << 16;
    if(i + 1 < s.size()) v |= unsigned(static_cast<unsigned char>(s[i + 1])) << 8;
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < s.size() ? digits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

inline std::string data_url(const std::string& module_source)
{
  return "data:text/javascript;base64," + base64(module_source);
}

// The ES modules of three.js the page imports, each under the specifier of its import map entry.
struct Threejs_modules
{
  std::vector<std::pair<std::string, std::string>> modules; // specifier, source
  std::string revision;
};

inline std::size_t replace_all(std::string& s, const std::string& from, const std::string& to)
{
  std::size_t n = 0;
  for(std::size_t pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()), ++n)
    s.replace(pos, from.size(), to);
  return n;
}

// Since r170, three.module.js imports './three.core.js'. A relative specifier cannot be resolved from a
// data: URL, so it is renamed to the bare specifier 'three/core', mapped by the import map.
inline Threejs_modules read_threejs(const std::string& dir)
{
  if(dir.empty())
    throw std::runtime_error("write_html_report: no three.js directory given (named parameter threejs_directory, "
                             "environment variable QR_THREEJS_DIR or macro QR_THREEJS_DIR); run `npm ci` in viewer/");
  const std::string main_path = dir + "/build/three.module.js";
  const std::string core_path = dir + "/build/three.core.js";
  const std::string controls_path = dir + "/examples/jsm/controls/OrbitControls.js";
  std::string main = read_text_file(main_path);
  std::string controls = read_text_file(controls_path);
  const auto missing = [](const std::string& path) {
    return std::runtime_error("write_html_report: cannot read three.js file '" + path +
                              "' (run `npm ci` in viewer/, or give the directory of the npm package three)");
  };
  if(main.empty()) throw missing(main_path);
  if(controls.empty()) throw missing(controls_path);
  Threejs_modules m;
  const bool split = main.find("'./three.core.js'") != std::string::npos;
  if(split)
  {
    std::string core = read_text_file(core_path);
    if(core.empty()) throw missing(core_path);
    replace_all(main, "'./three.core.js'", "'three/core'");
    const std::string key = "const REVISION = '";
    const std::size_t r = core.find(key);
    if(r != std::string::npos) m.revision = core.substr(r + key.size(), core.find('\'', r + key.size()) - r - key.size());
    m.modules.emplace_back("three/core", std::move(core));
  }
  else
  {
    const std::string key = "const REVISION = '";
    const std::size_t r = main.find(key);
    if(r != std::string::npos) m.revision = main.substr(r + key.size(), main.find('\'', r + key.size()) - r - key.size());
  }
  if(main.find("from './") != std::string::npos || controls.find("from './") != std::string::npos)
    throw std::runtime_error("write_html_report: unsupported layout of the three.js package in '" + dir +
                             "' (a module imports a relative file that cannot be inlined)");
  m.modules.emplace_back("three", std::move(main));
  m.modules.emplace_back("three/addons/controls/OrbitControls.js", std::move(controls));
  return m;
}

// JSON text that may sit inside a <script> element: "</" and "<!--" must not appear in it.
inline std::string script_safe(const std::string& json)
{
  std::string s = json;
  replace_all(s, "</", "<\\/");
  replace_all(s, "<!--", "<\\!--");
  return s;
}

inline void write_string(std::ostream& os, const std::string& s)
{
  std::ostringstream tmp;
  Report(s).write_json(tmp, 0);
  os << tmp.str();
}

inline void write_number(std::ostream& os, double d)
{
  if(std::isfinite(d)) os << d;
  else os << "null";
}

inline void write_points(std::ostream& os, const std::vector<std::array<double, 3>>& points)
{
  os << '[';
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    if(i > 0) os << ',';
    write_number(os, points[i][0]);
    os << ',';
    write_number(os, points[i][1]);
    os << ',';
    write_number(os, points[i][2]);
  }
  os << ']';
}

template <typename Color>
void write_color(std::ostream& os, const Color& c)
{
  os << '[' << int(c.red()) << ',' << int(c.green()) << ',' << int(c.blue()) << ']';
}

template <typename Color>
void write_colors(std::ostream& os, const std::vector<Color>& colors)
{
  os << '[';
  for(std::size_t i = 0; i < colors.size(); ++i)
  {
    if(i > 0) os << ',';
    write_color(os, colors[i]);
  }
  os << ']';
}

inline std::pair<double, double> finite_range(const std::vector<double>& v, double lo, double hi)
{
  double a = std::numeric_limits<double>::infinity(), b = -a;
  for(double x : v)
    if(std::isfinite(x)) { a = (std::min)(a, x); b = (std::max)(b, x); }
  if(!std::isfinite(a)) { a = 0.; b = 1.; }
  return {std::isfinite(lo) ? lo : a, std::isfinite(hi) ? hi : b};
}

inline const char* color_map_name(int m)
{
  switch(m)
  {
    case 1: return "red_to_green";
    case 2: return "blue_to_red";
    default: return "viridis";
  }
}

template <typename Layer>
void check_layer(const Layer& l)
{
  const auto fail = [&](const std::string& what) {
    throw std::invalid_argument("write_html_report: layer '" + l.name + "': " + what);
  };
  const auto& p = l.polygons;
  for(const auto& f : p.faces)
  {
    if(f.size() < 3) fail("a face has fewer than 3 vertices");
    for(std::size_t i : f)
      if(i >= p.points.size()) fail("a face index is out of range");
  }
  if(!p.face_colors.empty() && p.face_colors.size() != p.faces.size()) fail("face_colors must have one colour per face");
  if(!p.face_scalars.empty() && p.face_scalars.size() != p.faces.size()) fail("face_scalars must have one value per face");
  if(l.segments.endpoints.size() % 2 != 0) fail("segments need two endpoints each");
  if(!l.segments.colors.empty() && 2 * l.segments.colors.size() != l.segments.endpoints.size())
    fail("segment colors must have one colour per segment");
  if(!l.points.colors.empty() && l.points.colors.size() != l.points.points.size())
    fail("point colors must have one colour per point");
}

template <typename Layer>
void write_layer(std::ostream& os, const Layer& l)
{
  const auto& p = l.polygons;
  os << "{\"name\":";
  write_string(os, l.name);
  os << ",\"visible\":" << (l.visible ? "true" : "false");
  os << ",\"polygons\":{\"points\":";
  write_points(os, p.points);
  os << ",\"faces\":[";
  for(std::size_t f = 0; f < p.faces.size(); ++f)
  {
    os << (f > 0 ? ",[" : "[");
    for(std::size_t i = 0; i < p.faces[f].size(); ++i) os << (i > 0 ? "," : "") << p.faces[f][i];
    os << ']';
  }
  os << "],\"face_colors\":";
  write_colors(os, p.face_colors);
  os << ",\"face_scalars\":[";
  for(std::size_t f = 0; f < p.face_scalars.size(); ++f)
  {
    if(f > 0) os << ',';
    write_number(os, p.face_scalars[f]);
  }
  const auto range = finite_range(p.face_scalars, p.scalar_min, p.scalar_max);
  os << "],\"range\":[";
  write_number(os, range.first);
  os << ',';
  write_number(os, range.second);
  os << "],\"scalar_name\":";
  write_string(os, p.scalar_name);
  os << ",\"color_map\":\"" << color_map_name(int(p.color_map)) << "\",\"color\":";
  write_color(os, p.color);
  os << ",\"wireframe\":" << (p.wireframe ? "true" : "false") << ",\"wireframe_color\":";
  write_color(os, p.wireframe_color);
  os << ",\"opacity\":";
  write_number(os, (std::max)(0., (std::min)(1., p.opacity)));
  os << "},\"segments\":{\"endpoints\":";
  write_points(os, l.segments.endpoints);
  os << ",\"colors\":";
  write_colors(os, l.segments.colors);
  os << ",\"color\":";
  write_color(os, l.segments.color);
  os << "},\"points\":{\"points\":";
  write_points(os, l.points.points);
  os << ",\"colors\":";
  write_colors(os, l.points.colors);
  os << ",\"color\":";
  write_color(os, l.points.color);
  os << ",\"size\":";
  write_number(os, l.points.size);
  os << "},\"legend\":[";
  for(std::size_t i = 0; i < l.legend.size(); ++i)
  {
    os << (i > 0 ? ",{\"label\":" : "{\"label\":");
    write_string(os, l.legend[i].label);
    os << ",\"color\":";
    write_color(os, l.legend[i].color);
    os << '}';
  }
  os << "]}";
}

// Bins the finite values on [min, max]; a value equal to max falls in the last bin.
template <typename Histogram>
void write_histogram(std::ostream& os, const Histogram& h)
{
  const auto range = finite_range(h.values, h.min, h.max);
  const std::size_t bins = (std::max)(std::size_t(1), h.bins);
  std::vector<std::size_t> counts(bins, 0);
  std::size_t n = 0;
  double sum = 0.;
  const double width = range.second - range.first;
  for(double x : h.values)
  {
    if(!std::isfinite(x) || x < range.first || x > range.second) continue;
    std::size_t b = width > 0. ? std::size_t((x - range.first) / width * double(bins)) : 0;
    counts[(std::min)(b, bins - 1)] += 1;
    ++n;
    sum += x;
  }
  os << "{\"title\":";
  write_string(os, h.title);
  os << ",\"min\":";
  write_number(os, range.first);
  os << ",\"max\":";
  write_number(os, range.second);
  os << ",\"count\":" << n << ",\"mean\":";
  write_number(os, n > 0 ? sum / double(n) : 0.);
  os << ",\"counts\":[";
  for(std::size_t i = 0; i < bins; ++i) os << (i > 0 ? "," : "") << counts[i];
  os << "]}";
}

inline std::string escape_html(const std::string& s)
{
  std::string out;
  for(char c : s)
  {
    switch(c)
    {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

template <typename Scene>
void write_page(std::ostream& os, const Scene& scene, const Threejs_modules& three)
{
  for(const auto& l : scene.layers) check_layer(l);
  std::ostringstream data;
  data.precision(9); // float precision is what the GPU gets anyway
  data << "{\"title\":";
  write_string(data, scene.title);
  data << ",\"layers\":[";
  for(std::size_t i = 0; i < scene.layers.size(); ++i)
  {
    if(i > 0) data << ",\n";
    write_layer(data, scene.layers[i]);
  }
  data << "],\"histograms\":[";
  for(std::size_t i = 0; i < scene.histograms.size(); ++i)
  {
    if(i > 0) data << ",\n";
    write_histogram(data, scene.histograms[i]);
  }
  data << "]}";

  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
     << "<meta name=\"generator\" content=\"CGAL Quad_remeshing write_html_report, three.js r" << escape_html(three.revision)
     << "\">\n<title>" << escape_html(scene.title) << "</title>\n<style>" << page_style() << "</style>\n"
     << "<script>" << page_guard_script() << "</script>\n"
     << "<script type=\"importmap\">\n{\"imports\":{";
  for(std::size_t i = 0; i < three.modules.size(); ++i)
    os << (i > 0 ? ",\n" : "\n") << '"' << three.modules[i].first << "\":\"" << data_url(three.modules[i].second) << '"';
  os << "\n}}\n</script>\n</head>\n<body>\n"
     << "<div id=\"view\"><div id=\"help\">left drag: orbit, right drag: pan, wheel: zoom</div></div>\n"
     << "<div id=\"side\">\n<h1>" << escape_html(scene.title) << "</h1>\n"
     << "<h2>Layers</h2><div id=\"qr-layers\"></div><button id=\"qr-fit\">fit view</button>\n"
     << "<h2>Summary</h2><div id=\"qr-summary\"></div>\n"
     << "<h2>Histograms</h2><div id=\"qr-histograms\"></div>\n"
     << "<h2>Report</h2><div id=\"qr-report-tables\"></div>\n"
     << "<details><summary>JSON</summary><pre id=\"qr-report-json\"></pre></details>\n</div>\n"
     << "<script type=\"application/json\" id=\"qr-scene\">" << script_safe(data.str()) << "</script>\n"
     << "<script type=\"application/json\" id=\"qr-report\">" << script_safe(scene.report.to_json(1)) << "</script>\n"
     << "<script type=\"module\">" << viewer_module_script() << "</script>\n</body>\n</html>\n";
}

} // namespace html
} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_HTML_WRITER_H
