// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Best-fit square of a single quad (the scaled Jacobian is internal::quality::quad_scaled_jacobian).

#ifndef CGAL_QUAD_REMESHING_INTERNAL_SMOOTHING_QUAD_GEOMETRY_H
#define CGAL_QUAD_REMESHING_INTERNAL_SMOOTHING_QUAD_GEOMETRY_H

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// The square (rotated and scaled in the quad's mean plane) closest in the least-squares sense to the
// quad, returned as its four corners in the quad's order. With the corners written as complex numbers
// x_k in the plane (origin at the centroid) and the square as a * i^k, the best a is (1/4) sum (-i)^k x_k.
template <typename Vector_3, typename Point_3>
std::array<Point_3, 4> best_fit_square(const std::array<Point_3, 4>& p)
{
  const Point_3 c = CGAL::centroid(p[0], p[1], p[2], p[3]);
  Vector_3 n = CGAL::cross_product(Vector_3(p[0], p[2]), Vector_3(p[1], p[3]));
  const double nl = std::sqrt(CGAL::to_double(n.squared_length()));
  if(nl == 0.) return p;
  n = n / nl;
  // a frame (u, v) of the plane with u x v = n, so that counterclockwise means positive rotation
  Vector_3 u(c, p[0]);
  u = u - (u * n) * n;
  double ul = std::sqrt(CGAL::to_double(u.squared_length()));
  if(ul == 0.) return p;
  u = u / ul;
  const Vector_3 v = CGAL::cross_product(n, u);
  double re = 0., im = 0.;
  // (-i)^k for k = 0..3: 1, -i, -1, i
  const double wr[4] = {1., 0., -1., 0.};
  const double wi[4] = {0., -1., 0., 1.};
  for(int k = 0; k < 4; ++k)
  {
    const Vector_3 d(c, p[k]);
    const double x = CGAL::to_double(d * u), y = CGAL::to_double(d * v);
    re += wr[k] * x - wi[k] * y;
    im += wr[k] * y + wi[k] * x;
  }
  re *= 0.25;
  im *= 0.25;
  std::array<Point_3, 4> q;
  // a * i^k: i^k = 1, i, -1, -i
  const double ir[4] = {1., 0., -1., 0.};
  const double ii[4] = {0., 1., 0., -1.};
  for(int k = 0; k < 4; ++k)
  {
    const double x = re * ir[k] - im * ii[k];
    const double y = re * ii[k] + im * ir[k];
    q[k] = c + x * u + y * v;
  }
  return q;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
