// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of the package, on top of CGAL 5.5's named-parameter mechanism.

#ifndef CGAL_QUAD_REMESHING_PARAMETERS_H
#define CGAL_QUAD_REMESHING_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>

namespace CGAL {
namespace Quad_remeshing {

/// Tags of the package's own named parameters (one enum per parameter, as in `CGAL::internal_np`).
namespace internal_np {
} // namespace internal_np

/*!
  \ingroup PkgQuadRemeshingRef
  Makers of named parameters.

  This namespace re-exports every maker of `CGAL::parameters` (so `CGAL::Quad_remeshing::parameters::verbose(true)`
  works) and adds the package's own parameters.

  CGAL 5.5 builds the chaining members (`.verbose(true).geom_traits(k)`) from a closed list, so a
  package outside CGAL cannot add members. The package's own parameters therefore come in two forms:
  - `feature_angle(40.)` starts a pack; CGAL's members can be chained after it:
    `feature_angle(40.).verbose(true)`;
  - `feature_angle(np, 40.)` adds the parameter on top of an existing pack `np`;
  and `combine(np1, np2, ...)` concatenates packs of any length (a later pack wins on a repeated tag).
*/
namespace parameters {
using namespace CGAL::parameters;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::is_default_parameter;

namespace internal {

// Re-links the nodes of a pack `b` on top of a pack `a`.
template <typename A>
const A& relink(const A& a, const CGAL::Named_function_parameters<bool, CGAL::internal_np::all_default_t>&)
{
  return a; // `default_values()` carries nothing
}

template <typename A, typename T, typename Tag>
CGAL::Named_function_parameters<T, Tag, A>
relink(const A& a, const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& b)
{
  return CGAL::Named_function_parameters<T, Tag, A>(b.v, a);
}

template <typename A, typename T, typename Tag, typename Base>
auto relink(const A& a, const CGAL::Named_function_parameters<T, Tag, Base>& b)
{
  auto below = relink(a, static_cast<const Base&>(b));
  return CGAL::Named_function_parameters<T, Tag, decltype(below)>(b.v, below);
}

} // namespace internal

/*!
  Concatenates named-parameter packs of any length, mixing CGAL's and this package's parameters.
  When a tag appears in several packs, the value of the last pack wins.
*/
template <typename NP>
NP combine(const NP& np)
{
  return np;
}

template <typename NP1, typename NP2, typename... NPs>
auto combine(const NP1& np1, const NP2& np2, const NPs&... rest)
{
  return combine(internal::relink(np1, np2), rest...);
}

} // namespace parameters
} // namespace Quad_remeshing
} // namespace CGAL

/// Declares a named parameter of the package: tag type `TAG_T` and value `TAG` in
/// `CGAL::Quad_remeshing::internal_np`, and the two makers `NAME(value)` and `NAME(np, value)` in
/// `CGAL::Quad_remeshing::parameters`. Each stage header declares its own parameters with it, so that
/// stages do not edit a shared list.
#define CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(TAG_T, TAG, NAME)                                   \
  namespace CGAL {                                                                                 \
  namespace Quad_remeshing {                                                                       \
  namespace internal_np {                                                                          \
  enum TAG_T { TAG };                                                                              \
  }                                                                                                \
  namespace parameters {                                                                           \
  template <typename K>                                                                            \
  CGAL::Named_function_parameters<K, internal_np::TAG_T> NAME(const K& k)                          \
  {                                                                                                \
    return CGAL::Named_function_parameters<K, internal_np::TAG_T>(k);                              \
  }                                                                                                \
  template <typename K, typename T, typename Tag, typename Base>                                   \
  CGAL::Named_function_parameters<K, internal_np::TAG_T, CGAL::Named_function_parameters<T, Tag, Base>> \
  NAME(const CGAL::Named_function_parameters<T, Tag, Base>& np, const K& k)                        \
  {                                                                                                \
    return CGAL::Named_function_parameters<K, internal_np::TAG_T,                                  \
                                           CGAL::Named_function_parameters<T, Tag, Base>>(k, np);  \
  }                                                                                                \
  }                                                                                                \
  }                                                                                                \
  }

// Parameters shared by several stages (a stage's own parameters live in its header).
/// target edge length of the output quad mesh (absolute units, `double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(quad_edge_length_t, quad_edge_length, quad_edge_length)
/// approximate number of quads of the output (`std::size_t`, 0 = from the quad edge length)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(number_of_quads_t, number_of_quads, number_of_quads)
/// dihedral-angle threshold in degrees above which an edge is a feature (`double`)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(feature_angle_t, feature_angle, feature_angle)
/// number of worker threads a stage may use (`unsigned`, 1 = sequential)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(number_of_threads_t, number_of_threads, number_of_threads)
/// if > 0, quads get smaller where the surface or a feature line bends, so that a quad's sagitta
/// stays under this fraction of the bounding-box diagonal (`double`, 0 = uniform quad edge length)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(sizing_tolerance_t, sizing_tolerance, sizing_tolerance)
/// the quad edges along a bent feature line stay within this fraction of the bounding-box diagonal of
/// the line (`double`, 0 = no bound): the quantization gives such arcs enough edges
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(feature_tolerance_t, feature_tolerance, feature_tolerance)
/// the quad edges of the layout's other arcs (across the surface) stay within this fraction of the
/// bounding-box diagonal along the surface normal (`double`, 0 = no bound): the quantization gives an arc
/// over a bend of the surface enough edges
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(surface_tolerance_t, surface_tolerance, surface_tolerance)
/// the patches whose triangles stray farther than this fraction of the bounding-box diagonal from their
/// assembled quads get more quads (`double`, 0 = no such refinement)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(fidelity_tolerance_t, fidelity_tolerance, fidelity_tolerance)

#endif // CGAL_QUAD_REMESHING_PARAMETERS_H
