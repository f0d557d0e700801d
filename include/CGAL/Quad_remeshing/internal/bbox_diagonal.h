// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The length of a bounding box's diagonal: the scale every relative tolerance of the package refers to.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_BBOX_DIAGONAL_H
#define CGAL_QUAD_REMESHING_INTERNAL_BBOX_DIAGONAL_H

#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

inline double bbox_diagonal(const CGAL::Bbox_3& box)
{
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

// the diagonal of the bounding box of the vertices of a mesh
template <typename PolygonMesh>
double mesh_bbox_diagonal(const PolygonMesh& pm)
{
  CGAL::Bbox_3 box;
  for(auto v : vertices(pm)) box += get(CGAL::vertex_point, pm, v).bbox();
  return bbox_diagonal(box);
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_BBOX_DIAGONAL_H
