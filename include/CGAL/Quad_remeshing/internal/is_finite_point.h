// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a point has finite coordinates: the readers refuse a NaN or infinite input vertex, and the
// smoothing leaves a vertex where it is rather than move it to such a target.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_IS_FINITE_POINT_H
#define CGAL_QUAD_REMESHING_INTERNAL_IS_FINITE_POINT_H

#include <CGAL/number_utils.h>

#include <cmath>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

template <typename Point_3>
bool is_finite_point(const Point_3& p)
{
  return std::isfinite(CGAL::to_double(p.x())) && std::isfinite(CGAL::to_double(p.y())) &&
         std::isfinite(CGAL::to_double(p.z()));
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_IS_FINITE_POINT_H
