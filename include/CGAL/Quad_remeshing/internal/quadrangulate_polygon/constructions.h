// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Combinatorial constructions and the 2D embedding behind quadrangulate_polygon().

#ifndef CGAL_QUAD_REMESHING_INTERNAL_QUADRANGULATE_POLYGON_CONSTRUCTIONS_H
#define CGAL_QUAD_REMESHING_INTERNAL_QUADRANGULATE_POLYGON_CONSTRUCTIONS_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// The raw output of a construction: quads over vertex ids, the boundary vertices being
// 0..N-1 in counterclockwise loop order (vertex 0 = corner 0).
struct Quad_connectivity
{
  std::size_t number_of_vertices = 0;
  std::vector<std::array<std::size_t, 4>> quads;
};

// Offsets of the sides along the boundary loop: side i starts at loop index offset[i].
inline std::vector<std::size_t> side_offsets(const std::vector<int>& e)
{
  std::vector<std::size_t> off(e.size() + 1, 0);
  for(std::size_t i = 0; i < e.size(); ++i) off[i + 1] = off[i] + std::size_t(e[i]);
  return off;
}

// Regular e0 x e1 grid of a 4-sided patch with e0 == e2, e1 == e3.
inline Quad_connectivity build_regular_grid(const std::vector<int>& e)
{
  const std::size_t a = std::size_t(e[0]), b = std::size_t(e[1]);
  const std::size_t N = 2 * (a + b);
  // loop index of grid point (x, y) when on the boundary, else a fresh interior id
  std::vector<std::size_t> id((a + 1) * (b + 1));
  std::size_t next = N;
  for(std::size_t y = 0; y <= b; ++y)
    for(std::size_t x = 0; x <= a; ++x)
    {
      std::size_t v;
      if(y == 0) v = x;                              // side 0
      else if(x == a) v = a + y;                     // side 1
      else if(y == b) v = a + b + (a - x);           // side 2 (runs backwards in x)
      else if(x == 0) v = 2 * a + b + (b - y);       // side 3 (runs backwards in y)
      else v = next++;
      id[y * (a + 1) + x] = v;
    }
  Quad_connectivity c;
  c.number_of_vertices = next;
  for(std::size_t y = 0; y < b; ++y)
    for(std::size_t x = 0; x < a; ++x)
      c.quads.push_back({id[y * (a + 1) + x], id[y * (a + 1) + x + 1],
                         id[(y + 1) * (a + 1) + x + 1], id[(y + 1) * (a + 1) + x]});
  return c;
}

// Tarini's construction: one centre of valence n, region R_i at the corner between sides i and
// i+1 is an s_{i+1} x s_i grid. Requires every s_i >= 1 and e_i = s_{i-1} + s_{i+1}.
inline Quad_connectivity build_single_singularity(const std::vector<int>& e, const std::vector<int>& s)
{
  const std::size_t n = e.size();
  const std::vector<std::size_t> off = side_offsets(e);
  const std::size_t N = off[n];
  std::size_t next = N;
  const std::size_t centre = next++;
  // interior points of separatrix i: sep[i][b] for b = 1..s_i-1 (index 0 = centre, s_i = landing)
  std::vector<std::vector<std::size_t>> sep(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t si = std::size_t(s[i]);
    sep[i].assign(si + 1, centre);
    for(std::size_t b = 1; b < si; ++b) sep[i][b] = next++;
    sep[i][si] = off[i] + std::size_t(s[(i + n - 1) % n]); // lands s_{i-1} edges after corner i
  }
  Quad_connectivity c;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = (i + 1) % n;
    const std::size_t A = std::size_t(s[j]), B = std::size_t(s[i]);
    // G(a, b), a in 0..A along separatrix j, b in 0..B along separatrix i
    std::vector<std::size_t> G((A + 1) * (B + 1));
    for(std::size_t b = 0; b <= B; ++b)
      for(std::size_t a = 0; a <= A; ++a)
      {
        std::size_t v;
        if(b == B) v = (off[i] + std::size_t(s[(i + n - 1) % n]) + a) % N;   // end part of side i
        else if(a == A) v = (off[j] + (B - b)) % N;                          // start part of side j
        else if(a == 0) v = sep[i][b];
        else if(b == 0) v = sep[j][a];
        else v = next++;
        G[b * (A + 1) + a] = v;
      }
    // orientation fixed by the boundary edge G(a,B) -> G(a+1,B), which runs counterclockwise
    for(std::size_t b = 0; b < B; ++b)
      for(std::size_t a = 0; a < A; ++a)
        c.quads.push_back({G[(b + 1) * (A + 1) + a], G[(b + 1) * (A + 1) + a + 1],
                           G[b * (A + 1) + a + 1], G[b * (A + 1) + a]});
  }
  c.number_of_vertices = next;
  return c;
}

// The general fallback for any even boundary length N >= 4: a ring of N quads along the whole
// boundary, and inside it a regular a x b grid with a + b = N/2 whose boundary is the inner ring.
// Every boundary vertex gets exactly one interior neighbour, so no quad has three boundary
// vertices on one straight side; this is what keeps the uniform-weight embedding valid.
inline Quad_connectivity build_ring_and_grid(std::size_t N)
{
  const std::size_t half = N / 2;
  const std::size_t a = half / 2, b = half - a;     // a >= 1, b >= 1 for N >= 4
  Quad_connectivity c;
  std::size_t next = N;
  std::vector<std::size_t> ring(N);
  for(std::size_t k = 0; k < N; ++k) ring[k] = next++;
  for(std::size_t k = 0; k < N; ++k)
  {
    const std::size_t k1 = (k + 1) % N;
    c.quads.push_back({k, k1, ring[k1], ring[k]});
  }
  std::vector<std::size_t> id((a + 1) * (b + 1));
  for(std::size_t y = 0; y <= b; ++y)
    for(std::size_t x = 0; x <= a; ++x)
    {
      std::size_t v;
      if(y == 0) v = ring[x];
      else if(x == a) v = ring[a + y];
      else if(y == b) v = ring[a + b + (a - x)];
      else if(x == 0) v = ring[(2 * a + b + (b - y)) % N];
      else v = next++;
      id[y * (a + 1) + x] = v;
    }
  for(std::size_t y = 0; y < b; ++y)
    for(std::size_t x = 0; x < a; ++x)
      c.quads.push_back({id[y * (a + 1) + x], id[y * (a + 1) + x + 1],
                         id[(y + 1) * (a + 1) + x + 1], id[(y + 1) * (a + 1) + x]});
  c.number_of_vertices = next;
  return c;
}

// Boundary positions: corners on the regular n-gon inscribed in the unit circle (side 0 at the
// bottom, horizontal), side i split uniformly; n == 2 uses the two half circles.
inline std::vector<std::array<double, 2>> polygon_boundary_positions(const std::vector<int>& e)
{
  const std::size_t n = e.size();
  const double pi = 3.14159265358979323846;
  std::vector<std::array<double, 2>> p;
  if(n == 2)
  {
    // side 0: lower half circle from angle pi to 2 pi; side 1: upper half from 0 to pi
    for(std::size_t i = 0; i < 2; ++i)
      for(int k = 0; k < e[i]; ++k)
      {
        const double t = pi * (1.0 + double(i)) + pi * double(k) / double(e[i]);
        p.push_back({std::cos(t), std::sin(t)});
      }
    return p;
  }
  std::vector<std::array<double, 2>> corner(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    const double t = -pi / 2 - pi / double(n) + 2 * pi * double(k) / double(n);
    corner[k] = {std::cos(t), std::sin(t)};
  }
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 2>& A = corner[i];
    const std::array<double, 2>& B = corner[(i + 1) % n];
    for(int k = 0; k < e[i]; ++k)
    {
      const double t = double(k) / double(e[i]);
      p.push_back({(1 - t) * A[0] + t * B[0], (1 - t) * A[1] + t * B[1]});
    }
  }
  return p;
}

// Interior positions by a uniform-weight harmonic (Tutte) map with the boundary fixed.
inline std::vector<std::array<double, 2>>
harmonic_positions(const Quad_connectivity& c, const std::vector<std::array<double, 2>>& boundary)
{
  const std::size_t V = c.number_of_vertices, N = boundary.size();
  std::vector<std::set<std::size_t>> nb(V);
  for(const auto& q : c.quads)
    for(int k = 0; k < 4; ++k)
    {
      nb[q[k]].insert(q[(k + 1) % 4]);
      nb[q[(k + 1) % 4]].insert(q[k]);
    }
  std::vector<std::array<double, 2>> pos(V, {0., 0.});
  for(std::size_t v = 0; v < N; ++v) pos[v] = boundary[v];
  const std::size_t M = V - N;
  if(M == 0) return pos;
  std::vector<Eigen::Triplet<double>> trip;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(Eigen::Index(M), 2);
  for(std::size_t v = N; v < V; ++v)
  {
    const Eigen::Index r = Eigen::Index(v - N);
    trip.emplace_back(r, r, double(nb[v].size()));
    for(std::size_t w : nb[v])
    {
      if(w < N) { rhs(r, 0) += boundary[w][0]; rhs(r, 1) += boundary[w][1]; }
      else trip.emplace_back(r, Eigen::Index(w - N), -1.0);
    }
  }
  Eigen::SparseMatrix<double> L{Eigen::Index(M), Eigen::Index(M)};
  L.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(L);
  if(solver.info() != Eigen::Success)
    throw std::runtime_error("quadrangulate_polygon: harmonic system could not be factorized");
  const Eigen::MatrixXd x = solver.solve(rhs);
  for(std::size_t v = N; v < V; ++v)
    pos[v] = {x(Eigen::Index(v - N), 0), x(Eigen::Index(v - N), 1)};
  return pos;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_QUADRANGULATE_POLYGON_CONSTRUCTIONS_H
