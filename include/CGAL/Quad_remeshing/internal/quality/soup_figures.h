// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Combinatorial, validity and shape figures of an indexed polygon soup.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUALITY_SOUP_FIGURES_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUALITY_SOUP_FIGURES_H

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {
namespace quality {

typedef std::vector<std::vector<std::size_t>> Index_polygons;

// Union-find with path halving; sizes are small enough that no rank is needed for speed here.
struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t i)
  {
    while(parent[i] != i) { parent[i] = parent[parent[i]]; i = parent[i]; }
    return i;
  }
  void join(std::size_t a, std::size_t b)
  {
    a = find(a); b = find(b);
    if(a != b) parent[std::max(a, b)] = std::min(a, b); // smaller root: deterministic
  }
};

// One occurrence of an undirected edge in a polygon.
struct Edge_use
{
  std::size_t face;
  bool forward;  // traversed from the smaller to the larger vertex index
};

// The uses of one edge: a range of `Soup_edges::use_list`.
struct Edge_uses
{
  const Edge_use* first;
  const Edge_use* last;
  std::size_t size() const { return std::size_t(last - first); }
  const Edge_use& operator[](std::size_t i) const { return first[i]; }
};

// The unique undirected edges of a soup (sides joining two equal indices are ignored: they belong
// to degenerate faces and have no length) with the polygons that use them.
struct Soup_edges
{
  std::vector<std::pair<std::size_t, std::size_t>> ends; // (smaller, larger) index
  // the uses of edge e are use_list[use_begin[e]], ..., use_list[use_begin[e + 1] - 1]: flat arrays
  // rather than a vector per edge, which took most of the memory of the measure of a large mesh
  std::vector<Edge_use> use_list;
  std::vector<std::size_t> use_begin;

  Soup_edges(std::size_t nv, const Index_polygons& polygons)
  {
    // sort the sides by key: deterministic numbering without hashing
    std::vector<std::array<std::size_t, 3>> sides; // a, b, 2 face + forward (the order of a, b, face, forward)
    std::size_t n = 0;
    for(const std::vector<std::size_t>& p : polygons) n += p.size();
    sides.reserve(n);
    for(std::size_t f = 0; f < polygons.size(); ++f)
    {
      const std::vector<std::size_t>& p = polygons[f];
      for(std::size_t i = 0; i < p.size(); ++i)
      {
        const std::size_t a = p[i], b = p[(i + 1) % p.size()];
        if(a == b) continue;
        sides.push_back({std::min(a, b), std::max(a, b), 2 * f + std::size_t(a < b)});
      }
    }
    std::sort(sides.begin(), sides.end());
    use_list.reserve(sides.size());
    for(std::size_t i = 0; i < sides.size(); ++i)
    {
      if(i == 0 || sides[i][0] != sides[i - 1][0] || sides[i][1] != sides[i - 1][1])
      {
        ends.emplace_back(sides[i][0], sides[i][1]);
        use_begin.push_back(use_list.size());
      }
      use_list.push_back(Edge_use{sides[i][2] / 2, (sides[i][2] & 1) != 0});
    }
    use_begin.push_back(use_list.size());
    (void)nv;
  }

  std::size_t size() const { return ends.size(); }
  Edge_uses uses(std::size_t e) const
  {
    return Edge_uses{use_list.data() + use_begin[e], use_list.data() + use_begin[e + 1]};
  }
};

// True when the normals `n` and `m` (not zero) are turned by more than 120 degrees from each other: a
// quad whose normal is so turned from that of every quad across its edges lies flipped over in the
// surface (Quad_mesh_quality::flipped_quads; smooth_quad_mesh() turns such quads back).
template <typename Vector_3>
bool normals_turned_over(const Vector_3& n, const Vector_3& m)
{
  const double nn = CGAL::to_double(n.squared_length()), mm = CGAL::to_double(m.squared_length());
  return CGAL::to_double(n * m) < -0.5 * std::sqrt(nn * mm); // cos(120 degrees)
}

// True when every corner of the closed polygon `point(0)`, ..., `point(n - 1)` is flat: the cross product
// of its two sides is at most `relative_tolerance` times the squared longest side (zero area).
template <typename PointAt>
bool polygon_corners_are_flat(std::size_t n, PointAt point, double relative_tolerance)
{
  double longest2 = 0.;
  for(std::size_t i = 0; i < n; ++i)
    longest2 = (std::max)(longest2, CGAL::to_double(CGAL::squared_distance(point(i), point((i + 1) % n))));
  for(std::size_t i = 0; i < n; ++i)
  {
    const auto a = point(i) - point((i + n - 1) % n);
    const auto b = point((i + 1) % n) - point(i);
    if(std::sqrt(CGAL::to_double(CGAL::cross_product(a, b).squared_length())) > relative_tolerance * longest2)
      return false;
  }
  return true;
}

template <typename Point_3>
bool polygon_is_degenerate(const std::vector<Point_3>& pts, const std::vector<std::size_t>& f)
{
  const std::size_t n = f.size();
  if(n < 3) return true;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      if(f[i] == f[j] || pts[f[i]] == pts[f[j]]) return true;
  return polygon_corners_are_flat(n, [&](std::size_t i) -> const Point_3& { return pts[f[i]]; }, 1e-12);
}

// Verdict's quad scaled Jacobian: the smallest corner sine, signed by the normal of the quad's
// principal axes (parallel to the diagonal cross product, so warped quads are handled); 0 when the
// quad has no normal or a zero-length side.
template <typename Point_3>
double quad_scaled_jacobian(const std::array<Point_3, 4>& p)
{
  const auto d0 = p[2] - p[0], d1 = p[3] - p[1];
  const auto n = CGAL::cross_product(d0, d1);
  const double nl = std::sqrt(CGAL::to_double(n.squared_length()));
  // parallel diagonals (a flat or collapsed quad): the normal is rounding noise
  if(!(nl > 1e-12 * std::sqrt(CGAL::to_double(d0.squared_length()) * CGAL::to_double(d1.squared_length())))) return 0.;
  double sj = std::numeric_limits<double>::infinity();
  for(int i = 0; i < 4; ++i)
  {
    const auto e_in = p[i] - p[(i + 3) % 4];
    const auto e_out = p[(i + 1) % 4] - p[i];
    const double l = std::sqrt(CGAL::to_double(e_in.squared_length()) * CGAL::to_double(e_out.squared_length()));
    if(!(l > 0.)) return 0.;
    sj = (std::min)(sj, CGAL::to_double(n * CGAL::cross_product(e_in, e_out)) / (nl * l));
  }
  return (std::max)(-1., (std::min)(1., sj));
}

// Interior angles of a quad in degrees; a corner that turns against the quad's normal is reflex
// (360 - angle), so that a concave or bow-tie quad cannot look right-angled. A corner with a
// zero-length side gets a negative value and is skipped by the callers.
template <typename Point_3>
std::array<double, 4> quad_corner_angles(const std::array<Point_3, 4>& p)
{
  const double pi = 3.14159265358979323846;
  const auto n = CGAL::cross_product(p[2] - p[0], p[3] - p[1]);
  std::array<double, 4> angles;
  for(int i = 0; i < 4; ++i)
  {
    const auto a = p[(i + 3) % 4] - p[i];
    const auto b = p[(i + 1) % 4] - p[i];
    if(!(CGAL::to_double(a.squared_length()) > 0.) || !(CGAL::to_double(b.squared_length()) > 0.))
    {
      angles[i] = -1.;
      continue;
    }
    const auto c = CGAL::cross_product(a, b);
    double angle = std::atan2(std::sqrt(CGAL::to_double(c.squared_length())), CGAL::to_double(a * b)) * 180. / pi;
    // the turn e_in x e_out equals -(a x b): it points along n at a convex corner
    if(CGAL::to_double(n * c) > 0.) angle = 360. - angle;
    angles[i] = angle;
  }
  return angles;
}

// All figures of a soup that do not need a second mesh.
struct Soup_figures
{
  std::size_t vertices = 0, unreferenced_vertices = 0, faces = 0, edges = 0;
  std::size_t triangles = 0, quads = 0, other_faces = 0;
  std::size_t non_manifold_edges = 0, non_manifold_vertices = 0, inconsistent_edges = 0;
  std::size_t boundary_edges = 0, degenerate_faces = 0, duplicate_position_vertices = 0;
  std::size_t interior_vertices = 0, boundary_vertices = 0;
  std::size_t irregular_vertices = 0, irregular_boundary_vertices = 0;
  std::map<std::size_t, std::size_t> interior_valences, boundary_valences;
  double angle_deviation = 0., max_angle_deviation = 0.;
  double mean_edge_length = 0., min_edge_length = 0., max_edge_length = 0., edge_length_deviation = 0.;
  double mean_scaled_jacobian = 0., min_scaled_jacobian = 0.;
  std::size_t non_positive_scaled_jacobian = 0, flipped_quads = 0;
  long euler_characteristic = 0;
  std::size_t components = 0, boundary_loops = 0;
};

template <typename Point_3>
Soup_figures compute_soup_figures(const std::vector<Point_3>& pts, const Index_polygons& polygons)
{
  Soup_figures r;
  const std::size_t nv = pts.size();
  for(const std::vector<std::size_t>& p : polygons)
    for(std::size_t v : p)
      if(v >= nv) throw std::invalid_argument("quad_mesh_quality: a polygon refers to a vertex index out of range");

  std::vector<char> referenced(nv, 0);
  for(const std::vector<std::size_t>& p : polygons)
    for(std::size_t v : p) referenced[v] = 1;
  r.vertices = std::size_t(std::count(referenced.begin(), referenced.end(), char(1)));
  r.unreferenced_vertices = nv - r.vertices;
  r.faces = polygons.size();
  for(const std::vector<std::size_t>& p : polygons)
  {
    if(p.size() == 3) ++r.triangles;
    else if(p.size() == 4) ++r.quads;
    else ++r.other_faces;
    if(polygon_is_degenerate(pts, p)) ++r.degenerate_faces;
  }
  {
    std::vector<Point_3> sorted;
    for(std::size_t v = 0; v < nv; ++v)
      if(referenced[v]) sorted.push_back(pts[v]);
    std::sort(sorted.begin(), sorted.end());
    for(std::size_t i = 0; i < sorted.size();)
    {
      std::size_t j = i + 1;
      while(j < sorted.size() && sorted[j] == sorted[i]) ++j;
      if(j - i > 1) r.duplicate_position_vertices += j - i;
      i = j;
    }
  }

  const Soup_edges edges(nv, polygons);
  r.edges = edges.size();
  r.euler_characteristic = long(r.vertices) - long(r.edges) + long(r.faces);

  // per-edge classification, valences, components, boundary loops
  std::vector<std::size_t> valence(nv, 0);
  std::vector<char> on_boundary(nv, 0);
  Union_find face_sets(polygons.size());
  Union_find boundary_sets(nv);
  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    const Edge_uses u = edges.uses(e);
    const std::size_t a = edges.ends[e].first, b = edges.ends[e].second;
    ++valence[a];
    ++valence[b];
    for(std::size_t k = 1; k < u.size(); ++k) face_sets.join(u[0].face, u[k].face);
    if(u.size() == 1)
    {
      ++r.boundary_edges;
      on_boundary[a] = on_boundary[b] = 1;
      boundary_sets.join(a, b);
    }
    else if(u.size() > 2) ++r.non_manifold_edges;
    else if(u[0].forward == u[1].forward) ++r.inconsistent_edges;
  }
  {
    std::vector<char> root(polygons.size(), 0);
    for(std::size_t f = 0; f < polygons.size(); ++f) root[face_sets.find(f)] = 1;
    r.components = std::size_t(std::count(root.begin(), root.end(), char(1)));
    std::vector<char> broot(nv, 0);
    for(std::size_t v = 0; v < nv; ++v)
      if(on_boundary[v]) broot[boundary_sets.find(v)] = 1;
    r.boundary_loops = std::size_t(std::count(broot.begin(), broot.end(), char(1)));
  }
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(!referenced[v]) continue;
    if(on_boundary[v])
    {
      ++r.boundary_vertices;
      ++r.boundary_valences[valence[v]];
      if(valence[v] < 2 || valence[v] > 3) ++r.irregular_boundary_vertices;
    }
    else
    {
      ++r.interior_vertices;
      ++r.interior_valences[valence[v]];
      if(valence[v] != 4) ++r.irregular_vertices;
    }
  }

  // Non-manifold vertices: the faces around a vertex must form a single fan, i.e. be connected
  // through edges incident to that vertex.
  {
    // the faces and the edges around every vertex, as flat arrays (a vector per vertex took more memory
    // than the soup)
    std::vector<std::size_t> face_begin(nv + 1, 0), edge_begin(nv + 1, 0);
    for(const std::vector<std::size_t>& p : polygons)
      for(std::size_t v : p) ++face_begin[v + 1];
    for(std::size_t e = 0; e < edges.size(); ++e)
    {
      ++edge_begin[edges.ends[e].first + 1];
      ++edge_begin[edges.ends[e].second + 1];
    }
    std::partial_sum(face_begin.begin(), face_begin.end(), face_begin.begin());
    std::partial_sum(edge_begin.begin(), edge_begin.end(), edge_begin.begin());
    std::vector<std::size_t> vertex_faces(face_begin[nv]), vertex_edges(edge_begin[nv]);
    {
      std::vector<std::size_t> fill(face_begin.begin(), face_begin.end() - 1);
      for(std::size_t f = 0; f < polygons.size(); ++f)
        for(std::size_t v : polygons[f]) vertex_faces[fill[v]++] = f;
      fill.assign(edge_begin.begin(), edge_begin.end() - 1);
      for(std::size_t e = 0; e < edges.size(); ++e)
      {
        vertex_edges[fill[edges.ends[e].first]++] = e;
        vertex_edges[fill[edges.ends[e].second]++] = e;
      }
    }
    for(std::size_t v = 0; v < nv; ++v)
    {
      const auto fb = vertex_faces.begin() + std::ptrdiff_t(face_begin[v]);
      auto fe = vertex_faces.begin() + std::ptrdiff_t(face_begin[v + 1]);
      std::sort(fb, fe);
      fe = std::unique(fb, fe);
      const std::size_t n_faces = std::size_t(fe - fb);
      if(n_faces < 2) continue;
      Union_find fans(n_faces);
      for(std::size_t i = edge_begin[v]; i < edge_begin[v + 1]; ++i)
      {
        const Edge_uses u = edges.uses(vertex_edges[i]);
        const std::size_t i0 = std::size_t(std::lower_bound(fb, fe, u[0].face) - fb);
        for(std::size_t k = 1; k < u.size(); ++k)
          fans.join(i0, std::size_t(std::lower_bound(fb, fe, u[k].face) - fb));
      }
      std::size_t n_fans = 0;
      for(std::size_t i = 0; i < n_faces; ++i)
        if(fans.find(i) == i) ++n_fans;
      if(n_fans > 1) ++r.non_manifold_vertices;
    }
  }

  // edge lengths
  if(edges.size() > 0)
  {
    std::vector<double> lengths(edges.size());
    double sum = 0.;
    for(std::size_t e = 0; e < edges.size(); ++e)
    {
      lengths[e] = std::sqrt(CGAL::to_double(CGAL::squared_distance(pts[edges.ends[e].first], pts[edges.ends[e].second])));
      sum += lengths[e];
    }
    r.mean_edge_length = sum / double(edges.size());
    r.min_edge_length = *std::min_element(lengths.begin(), lengths.end());
    r.max_edge_length = *std::max_element(lengths.begin(), lengths.end());
    double dev = 0.;
    for(double l : lengths) dev += std::abs(l - r.mean_edge_length);
    r.edge_length_deviation = r.mean_edge_length > 0. ? 100. * dev / double(edges.size()) / r.mean_edge_length : 0.;
  }

  // Quads flipped over: the normal of a quad's diagonals turned by more than 120 degrees from that of
  // every quad across its edges (joined consistently). The scaled Jacobian cannot show it, being measured
  // in the quad's own plane: a convex quad lying upside down in the surface scores as well as any.
  {
    typedef decltype(pts[0] - pts[0]) Vector_3;
    auto diagonal_normal = [&](const std::vector<std::size_t>& f) {
      return CGAL::cross_product(pts[f[2]] - pts[f[0]], pts[f[3]] - pts[f[1]]);
    };
    std::vector<std::size_t> neighbours(polygons.size(), 0), against(polygons.size(), 0);
    for(std::size_t e = 0; e < edges.size(); ++e)
    {
      const Edge_uses u = edges.uses(e);
      if(u.size() != 2 || u[0].forward == u[1].forward) continue;
      const std::size_t f = u[0].face, g = u[1].face;
      if(polygons[f].size() != 4 || polygons[g].size() != 4) continue;
      const Vector_3 n = diagonal_normal(polygons[f]), m = diagonal_normal(polygons[g]);
      const double nn = CGAL::to_double(n.squared_length()), mm = CGAL::to_double(m.squared_length());
      if(!(nn > 0.) || !(mm > 0.)) continue; // (no direction to compare)
      ++neighbours[f];
      ++neighbours[g];
      if(normals_turned_over(n, m))
      {
        ++against[f];
        ++against[g];
      }
    }
    for(std::size_t f = 0; f < polygons.size(); ++f)
      if(neighbours[f] > 0 && against[f] == neighbours[f]) ++r.flipped_quads;
  }

  // quad shape
  double sum_sj = 0., sum_ad = 0.;
  std::size_t n_angles = 0;
  r.min_scaled_jacobian = std::numeric_limits<double>::infinity();
  for(const std::vector<std::size_t>& f : polygons)
  {
    if(f.size() != 4) continue;
    const std::array<Point_3, 4> q = {pts[f[0]], pts[f[1]], pts[f[2]], pts[f[3]]};
    const double sj = quad_scaled_jacobian(q);
    sum_sj += sj;
    r.min_scaled_jacobian = (std::min)(r.min_scaled_jacobian, sj);
    if(sj <= 0.) ++r.non_positive_scaled_jacobian;
    for(double angle : quad_corner_angles(q))
    {
      if(angle < 0.) continue;
      const double dev = std::abs(angle - 90.);
      sum_ad += dev;
      r.max_angle_deviation = (std::max)(r.max_angle_deviation, dev);
      ++n_angles;
    }
  }
  if(r.quads > 0) r.mean_scaled_jacobian = sum_sj / double(r.quads);
  else r.min_scaled_jacobian = 0.;
  r.angle_deviation = n_angles > 0 ? sum_ad / double(n_angles) : 0.;
  return r;
}

} // namespace quality
} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_QUALITY_SOUP_FIGURES_H
