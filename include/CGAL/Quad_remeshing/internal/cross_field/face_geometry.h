// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Per-face local frames, corner angles and a per-face shape operator, in plain doubles, for the
// cross-field solver.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_CROSS_FIELD_FACE_GEOMETRY_H
#define CGAL_QUAD_REMESHING_INTERNAL_CROSS_FIELD_FACE_GEOMETRY_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <complex>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

typedef std::array<double, 3> Vec3d;

inline Vec3d v_sub(const Vec3d& a, const Vec3d& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline Vec3d v_add(const Vec3d& a, const Vec3d& b) { return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}}; }
inline Vec3d v_scale(const Vec3d& a, double s) { return {{a[0] * s, a[1] * s, a[2] * s}}; }
inline double v_dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3d v_cross(const Vec3d& a, const Vec3d& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline double v_norm(const Vec3d& a) { return std::sqrt(v_dot(a, a)); }
inline Vec3d v_normalized(const Vec3d& a)
{
  const double l = v_norm(a);
  return (l > 0. && std::isfinite(l)) ? v_scale(a, 1. / l) : Vec3d{{0., 0., 0.}};
}

/// A unit vector orthogonal to the unit vector `n` (deterministic choice).
inline Vec3d any_orthogonal(const Vec3d& n)
{
  const Vec3d axis = (std::abs(n[0]) < 0.6) ? Vec3d{{1., 0., 0.}} : Vec3d{{0., 1., 0.}};
  return v_normalized(v_cross(axis, n));
}

/// Orthonormal frame (e1, e2, n) of a face. `e1` is the direction of the face's first halfedge, so the
/// frame depends on the combinatorics only; degenerate faces get an arbitrary but valid frame so that
/// the solver never sees NaNs.
struct Face_frame
{
  Vec3d e1{{1., 0., 0.}}, e2{{0., 1., 0.}}, n{{0., 0., 1.}};
  double area = 0.;

  /// angle of the tangent vector `v` in this frame
  double angle(const Vec3d& v) const { return std::atan2(v_dot(v, e2), v_dot(v, e1)); }
  /// the unit tangent vector of angle `a`
  Vec3d direction(double a) const { return v_add(v_scale(e1, std::cos(a)), v_scale(e2, std::sin(a))); }
};

inline Face_frame make_face_frame(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2)
{
  Face_frame fr;
  const Vec3d a = v_sub(p1, p0), b = v_sub(p2, p0);
  const Vec3d c = v_cross(a, b);
  const double cl = v_norm(c);
  fr.area = 0.5 * cl;
  Vec3d e1 = v_normalized(a);
  if(v_norm(e1) == 0.) e1 = v_normalized(b);
  if(v_norm(e1) == 0.) e1 = Vec3d{{1., 0., 0.}};
  Vec3d n = (cl > 0. && std::isfinite(cl)) ? v_scale(c, 1. / cl) : any_orthogonal(e1);
  // re-orthogonalise e1 against n (exact for non-degenerate faces up to rounding)
  e1 = v_normalized(v_sub(e1, v_scale(n, v_dot(e1, n))));
  if(v_norm(e1) == 0.) e1 = any_orthogonal(n);
  fr.e1 = e1;
  fr.n = n;
  fr.e2 = v_cross(n, e1);
  return fr;
}

/// Principal curvatures (`k_max` of largest magnitude first) and the direction of `k_max` of a face,
/// from the least-squares shape operator that maps its three edge vectors to the differences of the
/// vertex normals (Rusinkiewicz's per-face estimate). `ok` is false when the face is degenerate.
struct Face_curvature
{
  double k_max = 0., k_min = 0.;
  double angle = 0.; ///< angle of the `k_max` direction in the face frame
  bool ok = false;
};

inline Face_curvature face_curvature(const Face_frame& fr, const std::array<Vec3d, 3>& p, const std::array<Vec3d, 3>& vn)
{
  Face_curvature res;
  if(fr.area <= 0.) return res;
  // unknowns (a, b, c) of S = [[a, b], [b, c]]; normal equations of the 6 scalar equations
  double M[3][3] = {{0., 0., 0.}, {0., 0., 0.}, {0., 0., 0.}}, r[3] = {0., 0., 0.};
  for(int i = 0; i < 3; ++i) {
    const Vec3d e = v_sub(p[(i + 1) % 3], p[i]), dn = v_sub(vn[(i + 1) % 3], vn[i]);
    const double ex = v_dot(e, fr.e1), ey = v_dot(e, fr.e2), nx = v_dot(dn, fr.e1), ny = v_dot(dn, fr.e2);
    // a ex + b ey = nx  ;  b ex + c ey = ny
    const double rows[2][3] = {{ex, ey, 0.}, {0., ex, ey}};
    const double rhs[2] = {nx, ny};
    for(int k = 0; k < 2; ++k)
      for(int s = 0; s < 3; ++s) {
        r[s] += rows[k][s] * rhs[k];
        for(int t = 0; t < 3; ++t) M[s][t] += rows[k][s] * rows[k][t];
      }
  }
  const double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
                   + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  const double scale = M[0][0] + M[1][1] + M[2][2];
  if(!(std::abs(det) > 1e-12 * scale * scale * scale)) return res;
  double x[3];
  for(int s = 0; s < 3; ++s) { // Cramer's rule, 3x3
    double A[3][3];
    for(int i = 0; i < 3; ++i)
      for(int j = 0; j < 3; ++j) A[i][j] = (j == s) ? r[i] : M[i][j];
    x[s] = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
          + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) / det;
  }
  const double a = x[0], b = x[1], c = x[2];
  const double mean = 0.5 * (a + c), dev = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
  const double l1 = mean + dev, l2 = mean - dev;
  // eigenvector of l1 has angle 0.5*atan2(2b, a - c); that of l2 is orthogonal
  const double t1 = 0.5 * std::atan2(2. * b, a - c);
  if(std::abs(l1) >= std::abs(l2)) { res.k_max = l1; res.k_min = l2; res.angle = t1; }
  else { res.k_max = l2; res.k_min = l1; res.angle = t1 + 0.5 * CGAL_PI; }
  res.ok = std::isfinite(res.k_max) && std::isfinite(res.k_min) && std::isfinite(res.angle);
  return res;
}

/// `a` reduced to the representative of `a` modulo a quarter turn in [-pi/4, pi/4], and the number of
/// quarter turns removed
inline double reduce_quarter_turn(double a, int& k)
{
  const double q = 0.5 * CGAL_PI;
  const double kk = std::round(a / q);
  k = int(kk);
  return a - kk * q;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_CROSS_FIELD_FACE_GEOMETRY_H
