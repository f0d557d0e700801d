// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Maps the triangles of one patch onto a convex polygon with a fixed boundary (mean-value Tutte map),
// and locates points of the polygon in that map.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_ASSEMBLY_PARAMETERIZE_PATCH_H
#define CGAL_QUAD_REMESHING_INTERNAL_ASSEMBLY_PARAMETERIZE_PATCH_H

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// A patch as an indexed triangle set: `points` in 3D, `triangles` counterclockwise, and the 2D
// position of every vertex (fixed on the boundary, solved inside).
struct Patch_map
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::array<double, 2>> uv;
  std::vector<bool> fixed;
  // a uniform grid over the uv bounding box, for point location
  double x0 = 0, y0 = 0, cell = 1;
  std::size_t nx = 0, ny = 0;
  std::vector<std::vector<std::size_t>> grid;
};

inline double angle_at(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c)
{
  // angle at a in triangle (a, b, c)
  double u[3], v[3];
  for(int i = 0; i < 3; ++i) { u[i] = b[i] - a[i]; v[i] = c[i] - a[i]; }
  const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
  const double s = std::sqrt(cx * cx + cy * cy + cz * cz);
  const double d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  // (no angle where b or c coincides with a: atan2(0, -0) would be pi, and its weight infinite)
  if(s == 0. && d == 0.) return 0.;
  return std::atan2(s, d);
}

// Solves for the free vertices with mean-value weights (Floater 2003): they are positive, so with a
// convex boundary polygon the map is a bijection (Tutte/Floater), whatever the triangle shapes. Should
// the weights still break down (an overflow makes the map NaN), the uniform weights of Tutte's map, which
// always work on a connected patch, are used instead.
inline void solve_mean_value_map(Patch_map& m)
{
  const std::size_t n = m.points.size();
  std::vector<std::size_t> index(n, std::size_t(-1));
  std::size_t nfree = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(!m.fixed[v]) index[v] = nfree++;
  if(nfree == 0) return;

  auto length = [&](std::size_t a, std::size_t b) {
    double s = 0;
    for(int i = 0; i < 3; ++i) s += (m.points[a][i] - m.points[b][i]) * (m.points[a][i] - m.points[b][i]);
    return std::sqrt(s);
  };
  // true if the map has finite coordinates
  auto solve = [&](bool uniform) {
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd bx = Eigen::VectorXd::Zero(Eigen::Index(nfree)), by = Eigen::VectorXd::Zero(Eigen::Index(nfree));
    std::vector<double> diagonal(nfree, 0.);
    // For the edge (i, j) in triangle (i, j, k), the angle at i between ij and ik contributes tan(angle/2)/|ij|
    // (uniform: 1/2, each interior edge seen from its two triangles).
    for(const auto& t : m.triangles)
      for(int c = 0; c < 3; ++c)
      {
        const std::size_t i = t[c], j = t[(c + 1) % 3], k = t[(c + 2) % 3];
        if(m.fixed[i]) continue;
        const double half = uniform ? 0. : std::tan(0.5 * angle_at(m.points[i], m.points[j], m.points[k]));
        for(std::size_t other : {j, k})
        {
          const double w = uniform ? 0.5 : half / (std::max)(length(i, other), 1e-300);
          const Eigen::Index row = Eigen::Index(index[i]);
          diagonal[index[i]] += w;
          if(m.fixed[other]) { bx[row] += w * m.uv[other][0]; by[row] += w * m.uv[other][1]; }
          else triplets.emplace_back(row, Eigen::Index(index[other]), -w);
        }
      }
    for(std::size_t r = 0; r < nfree; ++r)
      triplets.emplace_back(Eigen::Index(r), Eigen::Index(r), diagonal[r] > 0 ? diagonal[r] : 1.);
    Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(nfree), static_cast<Eigen::Index>(nfree));
    A.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
    solver.compute(A);
    if(solver.info() != Eigen::Success) return false;
    const Eigen::VectorXd x = solver.solve(bx), y = solver.solve(by);
    if(!x.allFinite() || !y.allFinite()) return false;
    for(std::size_t v = 0; v < n; ++v)
      if(!m.fixed[v]) m.uv[v] = {x[Eigen::Index(index[v])], y[Eigen::Index(index[v])]};
    return true;
  };
  if(!solve(false) && !solve(true)) throw std::runtime_error("patch parameterization: factorization failed");
}

inline void build_location_grid(Patch_map& m)
{
  double x1 = -std::numeric_limits<double>::max(), y1 = x1;
  m.x0 = m.y0 = std::numeric_limits<double>::max();
  for(const auto& p : m.uv)
  {
    m.x0 = (std::min)(m.x0, p[0]); m.y0 = (std::min)(m.y0, p[1]);
    x1 = (std::max)(x1, p[0]); y1 = (std::max)(y1, p[1]);
  }
  const double w = (std::max)(x1 - m.x0, 1e-12), h = (std::max)(y1 - m.y0, 1e-12);
  const double cells = (std::max)(1., std::sqrt(double(m.triangles.size())));
  m.cell = (std::max)(w, h) / cells;
  m.nx = std::size_t(w / m.cell) + 1;
  m.ny = std::size_t(h / m.cell) + 1;
  m.grid.assign(m.nx * m.ny, {});
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    double a0 = std::numeric_limits<double>::max(), b0 = a0, a1 = -a0, b1 = -a0;
    for(std::size_t v : m.triangles[t])
    {
      a0 = (std::min)(a0, m.uv[v][0]); b0 = (std::min)(b0, m.uv[v][1]);
      a1 = (std::max)(a1, m.uv[v][0]); b1 = (std::max)(b1, m.uv[v][1]);
    }
    const std::size_t i0 = std::size_t((a0 - m.x0) / m.cell), i1 = (std::min)(m.nx - 1, std::size_t((a1 - m.x0) / m.cell));
    const std::size_t j0 = std::size_t((b0 - m.y0) / m.cell), j1 = (std::min)(m.ny - 1, std::size_t((b1 - m.y0) / m.cell));
    for(std::size_t j = j0; j <= j1; ++j)
      for(std::size_t i = i0; i <= i1; ++i) m.grid[j * m.nx + i].push_back(t);
  }
}

// Barycentric coordinates of q in triangle t (in uv).
inline std::array<double, 3> barycentric(const Patch_map& m, std::size_t t, const std::array<double, 2>& q)
{
  const auto& a = m.uv[m.triangles[t][0]];
  const auto& b = m.uv[m.triangles[t][1]];
  const auto& c = m.uv[m.triangles[t][2]];
  const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  if(det == 0.) return {-1., -1., -1.};
  const double l1 = ((q[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (q[1] - a[1])) / det;
  const double l2 = ((b[0] - a[0]) * (q[1] - a[1]) - (q[0] - a[0]) * (b[1] - a[1])) / det;
  return {1. - l1 - l2, l1, l2};
}

// The 3D point of the patch whose uv is q: the containing triangle (or, at the rim, the one whose
// clamped barycentric coordinates deviate least), interpolated.
inline std::array<double, 3> lift(const Patch_map& m, const std::array<double, 2>& q)
{
  std::size_t best_t = std::size_t(-1);
  double best_violation = std::numeric_limits<double>::max();
  std::array<double, 3> best_l{{1., 0., 0.}};
  auto consider = [&](std::size_t t) {
    const std::array<double, 3> l = barycentric(m, t, q);
    const double violation = (std::max)(0., -(std::min)(l[0], (std::min)(l[1], l[2])));
    if(violation < best_violation) { best_violation = violation; best_t = t; best_l = l; }
  };
  long i = long((q[0] - m.x0) / m.cell), j = long((q[1] - m.y0) / m.cell);
  i = (std::max)(0L, (std::min)(long(m.nx) - 1, i));
  j = (std::max)(0L, (std::min)(long(m.ny) - 1, j));
  for(std::size_t t : m.grid[std::size_t(j) * m.nx + std::size_t(i)]) consider(t);
  if(best_violation > 1e-9)
    for(std::size_t t = 0; t < m.triangles.size(); ++t) consider(t);
  if(best_t == std::size_t(-1)) throw std::runtime_error("patch parameterization: empty patch");
  double s = 0;
  for(double& l : best_l) { l = (std::max)(0., l); s += l; }
  std::array<double, 3> p{{0., 0., 0.}};
  for(int c = 0; c < 3; ++c)
    for(int k = 0; k < 3; ++k) p[k] += best_l[c] / s * m.points[m.triangles[best_t][c]][k];
  return p;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
