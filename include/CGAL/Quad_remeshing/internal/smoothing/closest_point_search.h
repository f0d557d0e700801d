// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The closest point of an AABB tree's primitives to a point, as AABB_tree::closest_point_and_primitive()
// finds it, with a cheaper test of the tree's boxes.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_SMOOTHING_CLOSEST_POINT_SEARCH_H
#define CGAL_QUAD_REMESHING_INTERNAL_SMOOTHING_CLOSEST_POINT_SEARCH_H

#include <CGAL/AABB_tree.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/number_utils.h>

#include <algorithm>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

/*
  Traversal traits of an AABB tree for the closest primitive to a query point. They walk the tree in the
  order of CGAL's own projection traits and keep the closest point the same way, so the answer is the same,
  ties included. Two tests differ:
  - CGAL asks an exact predicate whether a box meets the ball around the query through the closest point
    so far (a sixth of truck's whole run, where the smoothing queries the tree a few million times, with an
    exact fallback whenever the query lies on the surface). Here the squared distance to the box is computed
    in doubles and compared with the ball's squared radius enlarged by 1e-10 of itself, which admits every
    box the exact test admits. A box admitted beyond those is farther than the ball, so its primitives are
    farther than the closest point and change nothing (the comparison of their points is exact).
  - CGAL projects the query onto both primitives of a pair of leaves. Here a primitive is projected only if
    its own box passes the same test; one that fails is farther than the closest point, so skipping it
    changes nothing.
*/
template <typename AABBTraits>
class Closest_point_search
{
  typedef typename AABBTraits::Point_3 Point;
  typedef typename AABBTraits::Primitive Primitive;
  typedef typename AABBTraits::Point_and_primitive_id Point_and_primitive_id;

public:
  // `bound`: if not negative, a squared distance from `query` to a point of the primitives (the search
  // then tests only the boxes within it; the answer does not change, see closest_point_and_primitive())
  Closest_point_search(const Point& query, const Point_and_primitive_id& hint, const AABBTraits& traits,
                       double bound = -1.)
    : closest_(hint), traits_(traits), squared_radius_(squared_distance(query, hint.first))
  {
    if(bound >= 0.) squared_radius_ = (std::min)(squared_radius_, bound);
  }

  constexpr bool go_further() const { return true; }

  void intersection(const Point& query, const Primitive& primitive)
  {
    // The projection onto the triangle is the costliest step of the search, and the tree's leaves come in
    // pairs whose boxes it does not test: a triangle whose box is outside the ball cannot be closer.
    if(!within_ball(query, CGAL::internal::Primitive_helper<AABBTraits>::get_datum(primitive, traits_).bbox()))
      return;
    const Point p = traits_.closest_point_object()(query, primitive, closest_.first);
    if(!traits_.equal_3_object()(p, closest_.first))
    {
      closest_.first = p;
      closest_.second = primitive.id();
      squared_radius_ = (std::min)(squared_radius_, squared_distance(query, p));
    }
  }

  template <typename Node>
  bool do_intersect(const Point& query, const Node& node) const
  {
    return within_ball(query, node.bbox());
  }

  const Point_and_primitive_id& closest_point_and_primitive() const { return closest_; }

private:
  bool within_ball(const Point& query, const CGAL::Bbox_3& b) const
  {
    double d = 0.;
    for(int i = 0; i < 3; ++i)
    {
      const double x = CGAL::to_double(query[i]);
      if(x < b.min(i)) d += (b.min(i) - x) * (b.min(i) - x);
      else if(x > b.max(i)) d += (x - b.max(i)) * (x - b.max(i));
    }
    return d <= squared_radius_ * (1. + 1e-10);
  }

  // (the ball's squared radius as CGAL's test computes it, kept rather than computed at every box)
  double squared_distance(const Point& query, const Point& p) const
  {
    return CGAL::to_double(traits_.squared_distance_object()(query, p));
  }

  Point_and_primitive_id closest_;
  const AABBTraits& traits_;
  double squared_radius_;
};

/*
  The closest point of the primitives of `tree` to `query` and its primitive, as
  `tree.closest_point_and_primitive(query)` gives them (see Closest_point_search).
  `bound`, if not negative, is the squared distance from `query` to some point of the primitives (a point
  on the face where the query was last time): only the boxes within it are tested, and only their
  primitives projected, which is most of the saving when `query` moved little. The answer is the same
  as without it, ties included. The search starts from the same hint; a primitive farther than the bound
  is farther than the closest point, so it is never the answer; the primitives as close as the closest
  point are all within the bound and are visited in the same order, so the first of them (or the hint,
  if its point is the closest) is still the one kept. A primitive whose box is within the bound but whose
  point is not can still replace the hint for a while, as it would have without it.
*/
template <typename AABBTraits>
typename AABBTraits::Point_and_primitive_id closest_point_and_primitive(const CGAL::AABB_tree<AABBTraits>& tree,
                                                                        const typename AABBTraits::Point_3& query,
                                                                        double bound = -1.)
{
  Closest_point_search<AABBTraits> search(query, tree.best_hint(query), tree.traits(), bound);
  tree.traversal(query, search);
  return search.closest_point_and_primitive();
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_SMOOTHING_CLOSEST_POINT_SEARCH_H
