// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Robust input (polygon-soup path with repair) and output of meshes.

#ifndef CGAL_QUAD_REMESHING_IO_H
#define CGAL_QUAD_REMESHING_IO_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/internal/is_finite_point.h>
#include <CGAL/Quad_remeshing/parameters.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  Thrown for input that cannot be used: an unreadable, empty or malformed file, non-finite
  coordinates, out-of-range indices, or faces that are not triangles. The message says which.
*/
class Bad_input : public std::invalid_argument
{
public:
  explicit Bad_input(const std::string& what) : std::invalid_argument(what) {}
};

/*!
  \ingroup PkgQuadRemeshingRef
  What `read_and_repair()` found and changed.
*/
struct Repair_statistics
{
  std::size_t input_vertices = 0;             ///< points in the file
  std::size_t input_faces = 0;                ///< polygons in the file
  std::size_t merged_duplicate_points = 0;    ///< points removed because another point had the same position
  std::size_t removed_degenerate_faces = 0;   ///< soup polygons with a repeated vertex, and zero-area mesh faces removed
  std::size_t removed_duplicate_faces = 0;    ///< polygons on the same vertices as another (either orientation)
  std::size_t removed_isolated_points = 0;    ///< points used by no face
  std::size_t duplicated_points = 0;          ///< points duplicated to split non-manifold vertices or edges while orienting
  bool orientation_changed = false;           ///< some faces were reversed to orient the soup consistently
  std::size_t vertices = 0;                   ///< vertices of the repaired mesh
  std::size_t faces = 0;                      ///< faces of the repaired mesh
  std::size_t components = 0;                 ///< connected components of the repaired mesh
  std::size_t boundary_cycles = 0;            ///< boundary cycles of the repaired mesh
  double seconds = 0.;                        ///< time spent

  /// true if anything was changed
  bool repaired() const
  {
    return merged_duplicate_points + removed_degenerate_faces + removed_duplicate_faces + removed_isolated_points
             + duplicated_points > 0 || orientation_changed;
  }

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["input_vertices"] = input_vertices;
    r["input_faces"] = input_faces;
    r["merged_duplicate_points"] = merged_duplicate_points;
    r["removed_degenerate_faces"] = removed_degenerate_faces;
    r["removed_duplicate_faces"] = removed_duplicate_faces;
    r["removed_isolated_points"] = removed_isolated_points;
    r["duplicated_points"] = duplicated_points;
    r["orientation_changed"] = orientation_changed;
    r["repaired"] = repaired();
    r["V"] = vertices;
    r["F"] = faces;
    r["components"] = components;
    r["boundary_cycles"] = boundary_cycles;
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {

inline std::string lower_extension(const std::string& fname)
{
  const std::size_t dot = fname.find_last_of('.');
  if(dot == std::string::npos || fname.find_first_of("/\\", dot) != std::string::npos) return std::string();
  std::string ext = fname.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

inline bool is_supported_mesh_extension(const std::string& ext)
{
  return ext == "off" || ext == "obj" || ext == "ply" || ext == "stl";
}

// CGAL's readers reject "nan"/"inf" without saying why: look for such a token (ASCII files) so
// that the error message can name the cause.
inline bool has_non_finite_token(const std::string& fname)
{
  std::ifstream in(fname);
  std::string token;
  while(in >> token)
  {
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end); // also parses "nan", "inf" and overflows
    if(end != token.c_str() && *end == '\0' && !std::isfinite(value)) return true;
  }
  return false;
}

// CGAL 5.5's PLY reader trusts the header (a `property` line before any `element` line crashes it,
// found by fuzzing): check the header's grammar first. Returns an empty string if the header is fine,
// else what is wrong.
inline std::string check_ply_header(const std::string& fname)
{
  std::ifstream in(fname, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff file_size = in.tellg();
  in.seekg(0, std::ios::beg);
  std::string line;
  std::size_t line_no = 0, header_bytes = 0;
  bool has_element = false;
  auto words_of = [](const std::string& l) {
    std::vector<std::string> w;
    std::istringstream is(l);
    std::string x;
    while(is >> x) w.push_back(x);
    return w;
  };
  static const std::vector<std::string> types = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                                 "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32",
                                                 "float64"};
  auto is_type = [&](const std::string& t) { return std::find(types.begin(), types.end(), t) != types.end(); };
  while(std::getline(in, line))
  {
    header_bytes += line.size() + 1;
    if(header_bytes > (1u << 16)) return "the PLY header is too long";
    if(!line.empty() && line.back() == '\r') line.pop_back();
    const std::vector<std::string> w = words_of(line);
    ++line_no;
    if(line_no == 1)
    {
      if(w.size() != 1 || w[0] != "ply") return "not a PLY file (the first line must be 'ply')";
      continue;
    }
    if(w.empty()) return "empty line in the PLY header";
    if(w[0] == "format")
    {
      if(w.size() != 3 || (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
        return "bad PLY format line";
    }
    else if(w[0] == "comment" || w[0] == "obj_info") {}
    else if(w[0] == "element")
    {
      if(w.size() != 3 || w[2].find_first_not_of("0123456789") != std::string::npos || w[2].size() > 12)
        return "bad PLY element line";
      if(std::stoll(w[2]) > file_size) return "a PLY element count exceeds the file size";
      has_element = true;
    }
    else if(w[0] == "property")
    {
      if(!has_element) return "a PLY property comes before any element";
      const bool ok = (w.size() == 3 && is_type(w[1]))
                      || (w.size() == 5 && w[1] == "list" && is_type(w[2]) && is_type(w[3]));
      if(!ok) return "bad PLY property line";
    }
    else if(w[0] == "end_header") return std::string();
    else return "unknown keyword '" + w[0].substr(0, 20) + "' in the PLY header";
  }
  return "the PLY header has no end_header";
}

// CGAL 5.5's OFF reader allocates the vertex and face counts of the header before reading any of
// them (a 500-byte file whose header claimed 170 million faces took 4 GB, found by fuzzing): check
// the counts against what the file can hold. A vertex takes at least 6 bytes in text ("0 0 0\n")
// and 12 in binary, a face at least 2 ("0\n") and 4. The header is read as CGAL reads it: '#'
// comments, a keyword ending in OFF (prefixes ST, C, N, 4, n), then either the counts or BINARY and
// big-endian 32-bit counts (a dimension first for the n prefix). Returns an empty string if the
// counts are possible (or the header is not one CGAL would accept, which its reader then reports),
// else what is wrong. `*unused_prefix_at` gets the offsets in the file of the keyword's colour prefix C
// and, in an ASCII file, of its texture prefix ST, in increasing order (see off_content_without_prefixes()).
inline std::string check_off_header(const std::string& fname, std::vector<long long>* unused_prefix_at = nullptr)
{
  if(unused_prefix_at) unused_prefix_at->clear();
  std::ifstream in(fname, std::ios::binary);
  in.seekg(0, std::ios::end);
  const long long file_size = static_cast<long long>(in.tellg());
  in.seekg(0, std::ios::beg);
  // the first character after spaces and '#' comment lines; false at the end of the file
  auto first_after_comments = [&](char& c) {
    while(in.get(c)) {
      if(c == '#') { std::string rest; std::getline(in, rest); continue; }
      if(!std::isspace(static_cast<unsigned char>(c))) return true;
    }
    return false;
  };
  // the next token after spaces and '#' comments
  auto next_token = [&](std::string& tok) {
    tok.clear();
    char c;
    if(!first_after_comments(c)) return false;
    tok.push_back(c);
    while(in.get(c) && !std::isspace(static_cast<unsigned char>(c)) && tok.size() < 64) tok.push_back(c);
    return true;
  };
  // a count as the stream extraction of CGAL's reader takes it: an optional sign, then the leading digits
  // (it stops at the first other character, e.g. "170835621+0.7" is 170835621); false when no digit
  // leads (the reader fails on it). A negative count (-1) wraps to a huge unsigned one in the reader.
  auto count = [&](const std::string& t, long long& n) {
    const std::size_t i = (!t.empty() && (t[0] == '+' || t[0] == '-')) ? 1 : 0;
    std::size_t j = i;
    while(j < t.size() && std::isdigit(static_cast<unsigned char>(t[j]))) ++j;
    if(j == i) return false;
    if(t[0] == '-') n = -1;
    else n = j - i > 18 ? file_size + 1 : std::stoll(t.substr(i, j - i));
    return true;
  };
  std::string keyword, tok;
  // The keyword as CGAL's header parser reads it: the first character that is not a space (after '#'
  // comment lines), whatever it is, then letters and digits; the character that ends them is consumed
  // ("NOFF\"BINARY" is NOFF then BINARY, found by fuzzing). The parser accepts more than the documented
  // keywords (e.g. "\0OFF\xc7", found by fuzzing): any keyword holding "OFF" is checked.
  long long keyword_at = -1;
  {
    char k = 0;
    if(!first_after_comments(k)) return std::string();
    keyword_at = static_cast<long long>(in.tellg()) - 1;
    keyword.push_back(k);
    while(keyword.size() < 41 && in.get(k) && std::isalnum(static_cast<unsigned char>(k))) keyword.push_back(k);
  }
  if(keyword.find("OFF") == std::string::npos) return std::string();
  // The parser's prefixes, in this order: ST (texture coordinates), C (colours), N (normals), 4 (homogeneous
  // coordinates), n (a dimension); it accepts the keyword only if exactly OFF follows them. Attributes are
  // left out of the file (see off_content_without_prefixes()) only then: stripping the first ST of
  // "STSTOFF", which the parser refuses, would make a keyword it takes (found by fuzzing).
  std::size_t j = 0;
  auto take = [&](const char* prefix) {
    const std::string p(prefix);
    if(keyword.compare(j, p.size(), p) != 0) return false;
    j += p.size();
    return true;
  };
  const bool textures = take("ST");
  const long long colour_at = take("C") ? keyword_at + static_cast<long long>(j) - 1 : -1;
  const bool normals = take("N");
  const long long homogeneous = take("4") ? 1 : 0;
  const bool dimensional = take("n");
  const bool parsed = keyword.compare(j, std::string::npos, "OFF") == 0;
  if(unused_prefix_at && parsed && colour_at >= 0) unused_prefix_at->push_back(colour_at);
  long long nv = 0, nf = 0;
  // CGAL reads the word after the keyword as letters and digits only: "BINARY\x03..." is BINARY too; when
  // the character that ends the word is not a newline, the rest of that line is skipped
  std::string word;
  char c = 0;
  if(!first_after_comments(c)) return std::string();
  const std::streampos word_start = in.tellg() - std::streamoff(1);
  word.push_back(c);
  while(word.size() < 64 && in.get(c) && std::isalnum(static_cast<unsigned char>(c))) word.push_back(c);
  if(word == "BINARY") {
    if(in && c != '\n') { std::string rest; std::getline(in, rest); }
    auto read32 = [&](long long& n) {
      unsigned char b[4];
      if(!in.read(reinterpret_cast<char*>(b), 4)) return false;
      n = static_cast<std::int32_t>((std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                                    (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]));
      return true;
    };
    long long dim = 0, ne = 0;
    if((dimensional && !read32(dim)) || !read32(nv) || !read32(nf) || !read32(ne)) return std::string();
    if(nv < 0 || nf < 0) return "the OFF header has a negative count";
    if(12 * nv + 4 * nf > file_size)
      return "the OFF header's " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
             " faces cannot fit in a file of " + std::to_string(file_size) + " bytes";
    // As in the ASCII case, every face's vertex count is allocated before its indices are read (a 135-byte
    // file claiming 2^31 - 16 vertices in a face made the reader take 16 GiB). A binary vertex is big-endian
    // float32s: the point, the normal with the N prefix, the texture coordinates with ST (one more each
    // with the homogeneous prefix 4; the reader takes no colour there); a face is its int32 count and
    // that many int32 indices.
    const long long vertex_bytes =
        4 * ((3 + homogeneous) + (normals ? 3 + homogeneous : 0) + (textures ? 2 + homogeneous : 0));
    long long at = static_cast<long long>(in.tellg()) + nv * vertex_bytes;
    for(long long i = 0; i < nf; ++i) {
      long long k = 0;
      // the reader does not fail on a count cut short by the end of the file: it takes the bytes it got
      // and allocates (7.7 GB for a 122-byte file, found by fuzzing)
      if(at + 4 > file_size)
        return "the binary OFF file ends before the vertex count of face " + std::to_string(i);
      if(!in.seekg(at) || !read32(k)) return std::string();
      if(k < 0 || 4 * k > file_size)
        return "face " + std::to_string(i) + " of the binary OFF file claims " + std::to_string(k) +
               " vertices, more than a file of " + std::to_string(file_size) + " bytes can hold";
      at += 4 + 4 * k;
    }
    return std::string();
  }
  // CGAL 5.5's ASCII scanner reads the texture coordinates of the prefix ST past the numbers of a vertex
  // line that has none (a read out of bounds, found by fuzzing); they are not used either
  if(unused_prefix_at && parsed && textures)
    unused_prefix_at->insert(unused_prefix_at->begin(), {keyword_at, keyword_at + 1});
  in.clear();
  in.seekg(word_start);
  if(!next_token(tok)) return std::string();
  if(dimensional && !next_token(tok)) return std::string();
  if(!count(tok, nv) || !next_token(tok) || !count(tok, nf)) return std::string();
  if(nv < 0 || nf < 0) return "the OFF header has a negative count";
  if(nv > file_size || nf > file_size || 6 * nv + 2 * nf > file_size)
    return "the OFF header's " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
           " faces cannot fit in a file of " + std::to_string(file_size) + " bytes";
  // The reader allocates each face's vertex count before reading its indices too (a 2580-byte file with
  // a face of 36666666666666 vertices, found by fuzzing). A face of k vertices takes at least 2k bytes:
  // the first number of every face line (after the rest of the header line and the nv vertex lines,
  // blank and '#' lines skipped) must be at most half the file size.
  std::string line;
  std::getline(in, line);
  auto next_line = [&]() {
    while(std::getline(in, line)) {
      std::size_t i = 0;
      while(i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if(i < line.size() && line[i] != '#') { line.erase(0, i); return true; }
    }
    return false;
  };
  for(long long i = 0; i < nv; ++i)
    if(!next_line()) return std::string();
  for(long long i = 0; i < nf; ++i) {
    if(!next_line()) return std::string();
    long long k = 0;
    const std::string first = line.substr(0, line.find_first_of(" \t\r"));
    if(!count(first, k)) return std::string();
    if(k < 0 || 2 * k > file_size)
      return "face " + std::to_string(i) + " of the OFF file claims " + first.substr(0, 20) +
             " vertices, more than a file of " + std::to_string(file_size) + " bytes can hold";
  }
  return std::string();
}

// CGAL 5.5's OFF scanner reads a vertex's colour past the numbers of its line when the keyword has the
// colour prefix C and a vertex line has no colour (a heap overflow, found by fuzzing), and in ASCII files
// the texture coordinates of the prefix ST likewise. Neither is used here: the file's content without
// the prefix characters at the offsets `unused_prefix_at` (in increasing order, from check_off_header()).
inline std::string off_content_without_prefixes(const std::string& fname, const std::vector<long long>& unused_prefix_at)
{
  std::ifstream in(fname, std::ios::binary);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for(auto it = unused_prefix_at.rbegin(); it != unused_prefix_at.rend(); ++it)
    if(*it >= 0 && static_cast<std::size_t>(*it) < content.size())
      content.erase(static_cast<std::size_t>(*it), 1);
  return content;
}

// Removes the points no polygon uses and renumbers the polygons; returns the number removed.
template <typename Point, typename Polygon>
std::size_t remove_unused_points(std::vector<Point>& points, std::vector<Polygon>& polygons)
{
  std::vector<std::size_t> new_id(points.size(), std::size_t(-1));
  for(const Polygon& p : polygons)
    for(std::size_t v : p) new_id[v] = 0;
  std::size_t n = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    if(new_id[i] == 0)
    {
      new_id[i] = n;
      points[n++] = points[i];
    }
  const std::size_t removed = points.size() - n;
  points.resize(n);
  for(Polygon& p : polygons)
    for(auto& v : p) v = new_id[v];
  return removed;
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef

  reads a triangle mesh from an OFF, OBJ, PLY or STL file through the polygon-soup path and repairs it:
  duplicate points are merged, polygons with a repeated vertex and duplicate polygons (in either
  orientation) are removed, unused points are dropped, the soup is oriented consistently (points are
  duplicated where needed, which splits non-manifold vertices and edges), the mesh is built, and
  faces of zero area are removed by collapsing or flipping edges.

  @tparam TriangleMesh a model of `MutableFaceGraph`
  @tparam NamedParameters a sequence of named parameters

  @param fname the file; its format is chosen from the extension (`.off`, `.obj`, `.ply`, `.stl`, any case)
  @param tmesh the output mesh; it is cleared first
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether progress and what was repaired are printed to `std::cerr`}
      \cgalParamType{Boolean}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return what was found and changed

  @throws Bad_input if the file cannot be opened or parsed, has no face, has a non-finite coordinate,
  an index out of range, or a face that is not a triangle; also if nothing is left after the repair, or
  if faces with three collinear corners are left that the repair cannot collapse (no later stage can
  work on them: `remesh_for_quadrangulation()` refuses them too).
*/
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Repair_statistics read_and_repair(const std::string& fname,
                                  TriangleMesh& tmesh,
                                  const NamedParameters& np = parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;
  typedef std::vector<std::size_t> Polygon;

  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  CGAL::Real_timer timer;
  timer.start();
  Repair_statistics stats;

  const std::string ext = internal::lower_extension(fname);
  if(!internal::is_supported_mesh_extension(ext))
    throw Bad_input("'" + fname + "': unsupported file extension (expected .off, .obj, .ply or .stl)");
  {
    std::ifstream probe(fname, std::ios::binary);
    if(!probe) throw Bad_input("'" + fname + "': cannot open the file");
    if(probe.peek() == std::ifstream::traits_type::eof()) throw Bad_input("'" + fname + "': the file is empty");
  }

  std::vector<long long> unused_prefix_at; // an OFF keyword's colour and texture prefixes, read without them
  if(ext == "ply" || ext == "off")
  {
    const std::string problem = ext == "ply" ? internal::check_ply_header(fname)
                                             : internal::check_off_header(fname, &unused_prefix_at);
    if(!problem.empty()) throw Bad_input("'" + fname + "': " + problem);
  }

  std::vector<Point> points;
  std::vector<Polygon> polygons;
  bool ok = false;
  try {
    if(ext == "off" && !unused_prefix_at.empty())
    {
      std::istringstream is(internal::off_content_without_prefixes(fname, unused_prefix_at));
      ok = CGAL::IO::read_OFF(is, points, polygons, CGAL::parameters::verbose(false));
    }
    else
      ok = CGAL::IO::read_polygon_soup(fname, points, polygons, CGAL::parameters::verbose(false));
  } catch(const std::exception& e) {
    throw Bad_input("'" + fname + "': cannot parse the file (" + e.what() + ")");
  }
  if(!ok)
  {
    if(internal::has_non_finite_token(fname))
      throw Bad_input("'" + fname + "': a vertex has a non-finite coordinate (NaN or infinity)");
    throw Bad_input("'" + fname + "': cannot parse the file as " + ext);
  }
  stats.input_vertices = points.size();
  stats.input_faces = polygons.size();
  if(polygons.empty()) throw Bad_input("'" + fname + "': the mesh has no face");

  for(const Point& p : points)
    if(!internal::is_finite_point(p))
      throw Bad_input("'" + fname + "': a vertex has a non-finite coordinate (NaN or infinity)");
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    if(polygons[f].size() != 3)
      throw Bad_input("'" + fname + "': face " + std::to_string(f) + " has " + std::to_string(polygons[f].size())
                      + " vertices; the input must be a triangle mesh");
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        throw Bad_input("'" + fname + "': face " + std::to_string(f) + " uses vertex " + std::to_string(v)
                        + " but there are only " + std::to_string(points.size()));
  }

  // Soup repair, one step at a time so that the report can say what each step did.
  stats.merged_duplicate_points = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  {
    const std::size_t before = polygons.size();
    polygons.erase(std::remove_if(polygons.begin(), polygons.end(),
                                  [](const Polygon& p) { return p[0] == p[1] || p[1] == p[2] || p[2] == p[0]; }),
                   polygons.end());
    stats.removed_degenerate_faces = before - polygons.size();
  }
  stats.removed_duplicate_faces = PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  stats.removed_isolated_points = internal::remove_unused_points(points, polygons);
  if(polygons.empty()) throw Bad_input("'" + fname + "': no valid face is left after removing degenerate faces");

  const std::size_t points_before_orientation = points.size();
  // every polygon is a triangle: a flat copy is enough to see what the orientation changed
  std::vector<std::array<std::size_t, 3>> polygons_before;
  polygons_before.reserve(polygons.size());
  for(const Polygon& p : polygons) polygons_before.push_back({p[0], p[1], p[2]});
  PMP::orient_polygon_soup(points, polygons);
  stats.duplicated_points = points.size() - points_before_orientation;
  stats.orientation_changed = polygons.size() != polygons_before.size();
  for(std::size_t f = 0; f < polygons.size() && !stats.orientation_changed; ++f)
    stats.orientation_changed = polygons[f].size() != 3 || polygons[f][0] != polygons_before[f][0] ||
                                polygons[f][1] != polygons_before[f][1] || polygons[f][2] != polygons_before[f][2];
  std::vector<std::array<std::size_t, 3>>().swap(polygons_before);

  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Bad_input("'" + fname + "': the faces cannot be turned into a manifold mesh even after repair");
  clear(tmesh);
  PMP::polygon_soup_to_polygon_mesh(points, polygons, tmesh);
  // the soup is no longer needed: free it before the mesh repair and the figures
  std::vector<Point>().swap(points);
  std::vector<Polygon>().swap(polygons);

  // Zero-area faces (collinear corners) break normals and every later stage: collapse them away.
  const std::size_t faces_before = num_faces(tmesh);
  PMP::remove_degenerate_faces(tmesh);
  tmesh.collect_garbage();
  stats.removed_degenerate_faces += faces_before - std::min(faces_before, std::size_t(num_faces(tmesh)));
  if(num_faces(tmesh) == 0) throw Bad_input("'" + fname + "': every face is degenerate");
  std::size_t degenerate_left = 0;
  for(auto f : faces(tmesh)) degenerate_left += PMP::is_degenerate_triangle_face(f, tmesh);
  if(degenerate_left > 0)
    throw Bad_input("'" + fname + "': " + std::to_string(degenerate_left) +
                    " degenerate face(s) (three collinear corners) that the repair cannot collapse");

  stats.vertices = num_vertices(tmesh);
  stats.faces = num_faces(tmesh);
  {
    auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), tmesh);
    stats.components = PMP::connected_components(tmesh, fcc);
    std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> cycles;
    PMP::extract_boundary_cycles(tmesh, std::back_inserter(cycles));
    stats.boundary_cycles = cycles.size();
  }
  stats.seconds = timer.time();
  if(verbose)
  {
    std::cerr << "[repair] " << fname << ": " << stats.input_vertices << " points, " << stats.input_faces
              << " faces -> " << stats.vertices << " vertices, " << stats.faces << " faces, "
              << stats.components << " component(s), " << stats.boundary_cycles << " boundary cycle(s)";
    if(stats.repaired())
      std::cerr << "; merged " << stats.merged_duplicate_points << " duplicate points, removed "
                << stats.removed_degenerate_faces << " degenerate and " << stats.removed_duplicate_faces
                << " duplicate faces and " << stats.removed_isolated_points << " unused points, duplicated "
                << stats.duplicated_points << " points to orient" << (stats.orientation_changed ? " (faces reversed)" : "");
    std::cerr << " (" << stats.seconds << " s)\n";
  }
  return stats;
}

/*!
  \ingroup PkgQuadRemeshingRef

  writes a polygon mesh (triangles, quads or any polygons) to an OFF, OBJ or PLY file, with enough
  digits to round-trip double coordinates.

  @tparam PolygonMesh a model of `FaceListGraph`
  @param fname the file; its format is chosen from the extension
  @param pmesh the mesh
  @throws std::runtime_error if the extension is not supported or the file cannot be written
*/
template <typename PolygonMesh>
void write_mesh(const std::string& fname, const PolygonMesh& pmesh)
{
  const std::string ext = internal::lower_extension(fname);
  if(ext != "off" && ext != "obj" && ext != "ply")
    throw std::runtime_error("'" + fname + "': unsupported output extension (expected .off, .obj or .ply)");
  if(!CGAL::IO::write_polygon_mesh(fname, pmesh, CGAL::parameters::stream_precision(17)))
    throw std::runtime_error("'" + fname + "': cannot write the file");
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_IO_H
