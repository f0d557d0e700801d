// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Feature-aligned, curvature-guided 4-RoSy cross field on a triangle mesh, its matchings and
// singularities (Pietroni et al. 2021, section 4.3), a per-vertex field for tracing and dump writers.

#ifndef CGAL_QUAD_REMESHING_CROSS_FIELD_H
#define CGAL_QUAD_REMESHING_CROSS_FIELD_H

#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/internal/cross_field/face_geometry.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <iomanip>
#include <iostream>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

/// weight of the soft alignment of the cross field to principal curvature directions (`double`, >= 0)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(curvature_alignment_weight_t, curvature_alignment_weight, curvature_alignment_weight)
/// number of face-ring averaging steps applied to the curvature directions before they guide the field (`int`, >= 0)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(curvature_smoothing_steps_t, curvature_smoothing_steps, curvature_smoothing_steps)

namespace CGAL {
namespace Quad_remeshing {

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `compute_cross_field()`.
*/
struct Cross_field_statistics
{
  std::size_t faces = 0;             ///< faces of the mesh
  std::size_t constrained_faces = 0; ///< faces aligned to a feature edge (hard constraint)
  std::size_t two_feature_faces = 0; ///< constrained faces with two or three feature edges (aligned to the longest)
  std::size_t curvature_faces = 0;   ///< free faces softly pulled towards a principal curvature direction
  std::size_t free_components = 0;   ///< components (through non-feature edges) without any constrained face, solved as smoothest fields
  double energy = 0.;                ///< smoothness energy of the result: sum over non-feature interior edges of w_fg |u_f - r_fg u_g|^2
  double seconds = 0.;               ///< time spent

  /// the figures as a report record
  Report report() const
  {
    Report r = Report::object();
    r["faces"] = faces;
    r["constrained_faces"] = constrained_faces;
    r["two_feature_faces"] = two_feature_faces;
    r["curvature_faces"] = curvature_faces;
    r["free_components"] = free_components;
    r["energy"] = energy;
    r["seconds"] = seconds;
    return r;
  }
};

/*!
  \ingroup PkgQuadRemeshingRef
  Figures of `compute_cross_field_singularities()`.
*/
struct Cross_field_singularity_statistics
{
  /// number of singular vertices by valence (valence 4 - k for index k in quarter turns)
  std::map<int, std::size_t> singularities_by_valence;
  std::size_t singular_vertices = 0; ///< vertices of non-zero index
  int index_sum_quarter_turns = 0;   ///< sum of the indices in quarter turns, over all vertices
  double seconds = 0.;               ///< time spent

  /// sum of the indices in full turns (the Euler characteristic on a closed mesh without features)
  double index_sum() const { return index_sum_quarter_turns / 4.; }

  /// the figures as a report record: `singularities` (object valence -> count), `singular_vertices`,
  /// `index_sum` (full turns), `seconds`
  Report report() const
  {
    Report r = Report::object();
    Report s = Report::object();
    for(const auto& vc : singularities_by_valence) s[std::to_string(vc.first)] = vc.second;
    r["singularities"] = s;
    r["singular_vertices"] = singular_vertices;
    r["index_sum"] = index_sum();
    r["seconds"] = seconds;
    return r;
  }
};

namespace internal {

constexpr double default_curvature_alignment_weight = 0.1; // compute_cross_field()'s `curvature_alignment_weight`
constexpr int default_curvature_smoothing_steps = 8;       // compute_cross_field()'s `curvature_smoothing_steps`

template <typename Point, typename VPM>
Vec3d to_vec3d(const Point& p)
{
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

template <typename TriangleMesh, typename VPM>
Face_frame face_frame(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm, VPM vpm)
{
  const auto h = halfedge(f, tm);
  typedef typename boost::property_traits<VPM>::value_type Point;
  const Vec3d p0 = to_vec3d<Point, VPM>(get(vpm, source(h, tm)));
  const Vec3d p1 = to_vec3d<Point, VPM>(get(vpm, target(h, tm)));
  const Vec3d p2 = to_vec3d<Point, VPM>(get(vpm, target(next(h, tm), tm)));
  return make_face_frame(p0, p1, p2);
}

template <typename TriangleMesh, typename VPM>
Vec3d edge_vector(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm, VPM vpm)
{
  typedef typename boost::property_traits<VPM>::value_type Point;
  return v_sub(to_vec3d<Point, VPM>(get(vpm, target(h, tm))), to_vec3d<Point, VPM>(get(vpm, source(h, tm))));
}

// Angle of the tangent vector d of a face of normal n, measured from the unit edge direction e
// counterclockwise about n. Parallel transport across the edge keeps this angle.
inline double angle_from_edge(const Vec3d& d, const Vec3d& e, const Vec3d& n)
{
  return std::atan2(v_dot(d, v_cross(n, e)), v_dot(d, e));
}

template <typename Vector_3>
Vec3d vector_to_vec3d(const Vector_3& v)
{
  return {{CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z())}};
}

// Rotation (in [-pi/4, pi/4]) and matching (quarter turns in 0..3) from face(h) to face(opposite(h)):
// the field of face(opposite(h)) equals the transported field of face(h) rotated by
// `rotation + matching * pi/2` counterclockwise.
template <typename TriangleMesh, typename VPM, typename FaceFieldMap>
double halfedge_field_rotation(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                               const TriangleMesh& tm, VPM vpm, FaceFieldMap field, int& matching)
{
  const auto f = face(h, tm), g = face(opposite(h, tm), tm);
  const Vec3d e = v_normalized(edge_vector(h, tm, vpm));
  const Face_frame ff = face_frame(f, tm, vpm), fg = face_frame(g, tm, vpm);
  const double tf = angle_from_edge(vector_to_vec3d(get(field, f)), e, ff.n);
  const double tg = angle_from_edge(vector_to_vec3d(get(field, g)), e, fg.n);
  int k = 0;
  const double delta = reduce_quarter_turn(tg - tf, k);
  matching = ((k % 4) + 4) % 4;
  return delta;
}

} // namespace internal

/*!
  \ingroup PkgQuadRemeshingRef
  Computes a smooth 4-RoSy cross field on the faces of `tmesh`, aligned with the feature edges.

  The field of a face is stored as one unit vector in the plane of the face; the cross is that vector and its
  rotations by multiples of 90 degrees about the face normal. Every face with a feature edge gets exactly the
  direction of that edge (a hard constraint; a face with several feature edges is aligned with the longest one,
  the lowest halfedge on a tie, since in general no cross fits two non-orthogonal edges). The other faces minimise
  the discrete smoothness energy \f$\sum_{(f,g)} w_{fg}\,|u_f - r_{fg}\,u_g|^2\f$ over the interior non-feature edges,
  with \f$w_{fg} = |e|^2 / (A_f + A_g)\f$,
  where \f$u_f = e^{4i\theta_f}\f$ is the fourth power of the field in the face's local frame and \f$r_{fg}\f$
  the Levi-Civita transport across the shared edge, plus the soft term
  \f$w\,\alpha_f\,|u_f - c_f|^2\f$ that pulls a face towards a smoothed direction of largest principal curvature.
  Each face first gets the target \f$a_f^2\,e^{4i\phi_f}\f$ from its own shape operator, with \f$\phi_f\f$ the angle of
  its largest principal curvature direction and \f$a_f = (|k_1| - |k_2|)/(|k_1| + |k_2|)\f$ its curvature anisotropy
  (counted only where the curvature is noticeable at the scale of the mesh edges and \f$a_f \geq 0.2\f$); these
  targets are then averaged (area weighted, transported across the edges, not across features) over
  `curvature_smoothing_steps` face rings. The average's argument gives \f$c_f\f$ and its magnitude
  \f$\alpha_f \leq 1\f$ (faces without a target of their own get none): consistent directions keep their
  pull, noisy ones cancel, which avoids close pairs of opposite singularities made by per-face curvature
  noise. The sparse Hermitian system is solved with Eigen's `SimplicialLDLT`, and the results are normalised. A component (connected through non-feature edges) without a
  constrained face has no boundary condition (the energy alone is minimised by the null field); there the field is
  the smoothest unit field, the eigenvector of the smallest eigenvalue of the connection Laplacian (Knoeppel et al.
  2013), found by inverse power iteration (at most 30 steps, until no direction moves by more than 2.5e-5 rad) from a deterministic start, with the curvature pull added to each
  step. A tiny multiple (1e-8) of the mass matrix keeps the matrix definite. Degenerate faces get a valid
  (arbitrary) frame. The result is deterministic.

  @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
  @tparam EdgeIsFeatureMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
          as key type and `bool` as value type
  @tparam FaceCrossFieldMap a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
          as key type and `GeomTraits::Vector_3` as value type
  @tparam NamedParameters a sequence of named parameters

  @param tmesh the triangle mesh
  @param edge_is_feature_map the feature edges (border edges are treated as features whatever the map says)
  @param face_cross_field_map receives the unit representative of the cross of every face
  @param np an optional sequence of named parameters among the ones listed below

  @pre `CGAL::is_triangle_mesh(tmesh)`

  \cgalNamedParamsBegin
    \cgalParamNBegin{curvature_alignment_weight}
      \cgalParamDescription{weight \f$w\f$ of the soft alignment to principal curvature directions; 0 gives the smoothest field}
      \cgalParamType{`double`}
      \cgalParamDefault{`0.1`}
    \cgalParamNEnd
    \cgalParamNBegin{curvature_smoothing_steps}
      \cgalParamDescription{number of one-ring averaging steps applied to the curvature targets (0: each face's own
                             curvature direction; 8 spans about two quad edge lengths on a mesh pre-remeshed at half
                             the quad edge length)}
      \cgalParamType{`int`, >= 0}
      \cgalParamDefault{`8`}
    \cgalParamNEnd
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{face_index_map}
      \cgalParamDescription{a property map associating to each face of `tmesh` a unique index between `0` and `num_faces(tmesh) - 1`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
      \cgalParamDefault{an automatically indexed internal map}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{a class model of `Kernel`}
      \cgalParamDefault{a \cgal Kernel deduced from the point type}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether to print figures and timing to `std::cerr`, prefixed by `[cross-field]`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the figures of the computation
*/
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename FaceCrossFieldMap,
          typename NamedParameters = parameters::Default_named_parameters>
Cross_field_statistics compute_cross_field(const TriangleMesh& tmesh, EdgeIsFeatureMap edge_is_feature_map,
                                           FaceCrossFieldMap face_cross_field_map,
                                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GTr;
  typedef typename GTr::face_descriptor face_descriptor;
  typedef typename GTr::halfedge_descriptor halfedge_descriptor;
  typedef typename GTr::vertex_descriptor vertex_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GT::Vector_3 Vector_3;
  typedef std::complex<double> Cplx;
  using namespace internal;

  CGAL::Real_timer timer;
  timer.start();
  if(!CGAL::is_triangle_mesh(tmesh)) throw std::invalid_argument("compute_cross_field: the mesh is not a triangle mesh");
  const double weight = choose_parameter(get_parameter(np, internal_np::curvature_alignment_weight), default_curvature_alignment_weight);
  if(!(weight >= 0.) || !std::isfinite(weight))
    throw std::invalid_argument("compute_cross_field: curvature_alignment_weight must be finite and >= 0");
  const int smoothing_steps = choose_parameter(get_parameter(np, internal_np::curvature_smoothing_steps), default_curvature_smoothing_steps);
  if(smoothing_steps < 0) throw std::invalid_argument("compute_cross_field: curvature_smoothing_steps must be >= 0");
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tmesh));
  auto fim = CGAL::get_initialized_face_index_map(tmesh, np);
  auto vim = CGAL::get_initialized_vertex_index_map(tmesh, np);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;

  Cross_field_statistics stats;
  const std::size_t nf = num_faces(tmesh);
  stats.faces = nf;
  std::vector<face_descriptor> face_of(nf);
  std::vector<Face_frame> frames(nf);
  for(face_descriptor f : faces(tmesh)) {
    const std::size_t i = get(fim, f);
    face_of[i] = f;
    frames[i] = face_frame(f, tmesh, vpm);
  }
  auto is_feature = [&](halfedge_descriptor h) {
    return is_border_edge(h, tmesh) || bool(get(edge_is_feature_map, edge(h, tmesh)));
  };

  // Hard constraints: direction of the longest feature edge of a face.
  std::vector<char> fixed(nf, 0);
  std::vector<Vec3d> fixed_dir(nf);
  for(std::size_t i = 0; i < nf; ++i) {
    int count = 0;
    double best = -1.;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(face_of[i], tmesh), tmesh)) {
      if(!is_feature(h)) continue;
      ++count;
      const Vec3d e = edge_vector(h, tmesh, vpm);
      const double l = v_norm(e);
      if(l > best) { best = l; fixed_dir[i] = v_scale(e, l > 0. ? 1. / l : 0.); }
    }
    if(count == 0) continue;
    if(best <= 0.) fixed_dir[i] = frames[i].e1; // zero-length feature edge: nothing to align with
    fixed[i] = 1;
    ++stats.constrained_faces;
    if(count > 1) ++stats.two_feature_faces;
  }

  // Soft curvature targets from vertex normals (angle-weighted by face area here: sum of unit face normals times area).
  std::vector<double> soft_w(nf, 0.);
  std::vector<Cplx> soft_c(nf, Cplx(0., 0.));
  if(weight > 0.) {
    std::vector<Vec3d> vnormal(num_vertices(tmesh), Vec3d{{0., 0., 0.}});
    double total_len = 0.;
    std::size_t nedges = 0;
    for(std::size_t i = 0; i < nf; ++i)
      for(vertex_descriptor v : vertices_around_face(halfedge(face_of[i], tmesh), tmesh)) {
        Vec3d& vn = vnormal[get(vim, v)];
        vn = v_add(vn, v_scale(frames[i].n, frames[i].area));
      }
    for(auto e : edges(tmesh)) { total_len += v_norm(edge_vector(halfedge(e, tmesh), tmesh, vpm)); ++nedges; }
    for(Vec3d& vn : vnormal) vn = v_normalized(vn);
    const double mean_len = nedges ? total_len / double(nedges) : 0.;
    for(std::size_t i = 0; i < nf; ++i) {
      if(fixed[i]) continue;
      std::array<Vec3d, 3> p, vn;
      int j = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(face_of[i], tmesh), tmesh)) {
        p[j] = to_vec3d<Point, decltype(vpm)>(get(vpm, source(h, tmesh)));
        vn[j] = vnormal[get(vim, source(h, tmesh))];
        ++j;
      }
      const Face_curvature c = face_curvature(frames[i], p, vn);
      // ignore curvature that is flat at the scale of the edges (noise) and isotropic regions
      if(!c.ok || std::abs(c.k_max) * mean_len < 1e-3) continue;
      const double a = (std::abs(c.k_max) - std::abs(c.k_min)) / (std::abs(c.k_max) + std::abs(c.k_min));
      if(a < 0.2) continue;
      soft_w[i] = weight * a * a;
      soft_c[i] = std::polar(1., 4. * c.angle);
    }
  }

  // Connection r_fg across each non-feature interior edge: u_g expressed in f's frame.
  auto connection = [&](halfedge_descriptor h, std::size_t fi, std::size_t gi) {
    const Vec3d e = edge_vector(h, tmesh, vpm);
    return std::polar(1., 4. * (frames[fi].angle(e) - frames[gi].angle(e)));
  };

  // A face's curvature direction is measured on its own three vertex normals: noisy at the scale of the
  // edges, and the noise creates close pairs of opposite singularities. Average the anisotropy-weighted
  // targets a_f^2 c_f (transported, area weighted) over a few face rings: where the directions agree the pull
  // stays, where they disagree the targets cancel and the pull fades. Faces without a target of their own get none.
  if(weight > 0. && smoothing_steps > 0) {
    std::vector<Cplx> z(nf), next(nf);
    std::vector<double> area(nf), next_area(nf);
    for(std::size_t i = 0; i < nf; ++i) {
      area[i] = fixed[i] ? 0. : frames[i].area;
      z[i] = soft_w[i] / weight * soft_c[i] * area[i];
    }
    // transports and neighbours once: the steps reuse them
    std::vector<std::array<std::pair<std::size_t, Cplx>, 3>> ring(nf);
    std::vector<int> ring_size(nf, 0);
    for(std::size_t i = 0; i < nf; ++i) {
      if(fixed[i]) continue;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(face_of[i], tmesh), tmesh)) {
        if(is_feature(h)) continue;
        const std::size_t j = get(fim, face(opposite(h, tmesh), tmesh));
        if(!fixed[j]) ring[i][std::size_t(ring_size[i]++)] = {j, connection(h, i, j)};
      }
    }
    for(int step = 0; step < smoothing_steps; ++step) {
      for(std::size_t i = 0; i < nf; ++i) {
        next[i] = z[i];
        next_area[i] = area[i];
        for(int k = 0; k < ring_size[i]; ++k) {
          next[i] += ring[i][std::size_t(k)].second * z[ring[i][std::size_t(k)].first];
          next_area[i] += area[ring[i][std::size_t(k)].first];
        }
      }
      z.swap(next);
      area.swap(next_area);
    }
    for(std::size_t i = 0; i < nf; ++i) {
      // only faces with a target of their own keep one: the averaging must not spread the pull onto flat
      // or isotropic faces (on CAD models those belong to the feature lines)
      if(!(soft_w[i] > 0.)) continue;
      const double a = area[i] > 0. ? std::abs(z[i]) / area[i] : 0.;
      soft_w[i] = a > 1e-12 ? weight * a : 0.;
      soft_c[i] = a > 1e-12 ? z[i] / std::abs(z[i]) : Cplx(0., 0.);
    }
  }
  for(std::size_t i = 0; i < nf; ++i)
    if(soft_w[i] > 0.) ++stats.curvature_faces;

  // Components of free faces (through non-feature edges); a component touching no constrained face
  // ("unanchored") has no boundary condition and is solved as the smoothest field instead.
  std::vector<long> component(nf, -1);
  std::vector<char> anchored;
  {
    std::vector<std::size_t> stack;
    for(std::size_t s = 0; s < nf; ++s) {
      if(fixed[s] || component[s] >= 0) continue;
      const long c = long(anchored.size());
      anchored.push_back(0);
      component[s] = c;
      stack.assign(1, s);
      while(!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        for(halfedge_descriptor h : halfedges_around_face(halfedge(face_of[i], tmesh), tmesh)) {
          if(is_feature(h)) continue;
          const std::size_t j = get(fim, face(opposite(h, tmesh), tmesh));
          if(fixed[j]) { anchored[std::size_t(c)] = 1; continue; }
          if(component[j] < 0) { component[j] = c; stack.push_back(j); }
        }
      }
      if(!anchored[std::size_t(c)]) ++stats.free_components;
    }
  }

  // Edge weights |e|^2 / (A_f + A_g): the ratio of dual to primal edge length of the face graph, so that
  // the energy approximates the continuous Dirichlet energy whatever the triangle shapes.
  auto edge_weight = [&](halfedge_descriptor h, std::size_t i, std::size_t j) {
    const Vec3d e = edge_vector(h, tmesh, vpm);
    const double a = frames[i].area + frames[j].area;
    const double w = a > 0. ? v_dot(e, e) / a : 1.;
    return std::isfinite(w) ? std::min(std::max(w, 1e-3), 1e3) : 1.; // bounded on degenerate faces
  };

  // Assemble and solve the Hermitian system over the free faces.
  std::vector<Cplx> u(nf, Cplx(1., 0.));
  std::vector<long> unknown(nf, -1);
  long n_unknowns = 0;
  for(std::size_t i = 0; i < nf; ++i) {
    if(fixed[i]) u[i] = std::polar(1., 4. * frames[i].angle(fixed_dir[i]));
    else unknown[i] = n_unknowns++;
  }
  if(n_unknowns > 0) {
    typedef Eigen::Matrix<Cplx, Eigen::Dynamic, 1> CVector;
    std::vector<Eigen::Triplet<Cplx>> triplets;
    triplets.reserve(std::size_t(n_unknowns) * 4);
    CVector b = CVector::Zero(n_unknowns);
    std::vector<double> diag(std::size_t(n_unknowns), 0.), mass(std::size_t(n_unknowns), 0.);
    double mean_area = 0., mean_diag = 0.;
    for(std::size_t i = 0; i < nf; ++i) {
      if(unknown[i] < 0) continue;
      const long r = unknown[i];
      diag[std::size_t(r)] = soft_w[i];
      mass[std::size_t(r)] = std::max(frames[i].area, 1e-300);
      mean_area += mass[std::size_t(r)];
      b[r] += soft_w[i] * soft_c[i];
      for(halfedge_descriptor h : halfedges_around_face(halfedge(face_of[i], tmesh), tmesh)) {
        if(is_feature(h)) continue;
        const std::size_t j = get(fim, face(opposite(h, tmesh), tmesh));
        const double w = edge_weight(h, i, j);
        const Cplx rij = w * connection(h, i, j);
        diag[std::size_t(r)] += w;
        if(unknown[j] < 0) b[r] += rij * u[j];
        else triplets.emplace_back(r, unknown[j], -rij);
      }
      mean_diag += diag[std::size_t(r)];
    }
    mean_area /= double(n_unknowns);
    mean_diag /= double(n_unknowns);
    // A tiny multiple of the mass matrix keeps the matrix definite on unanchored components (their
    // connection Laplacian is only semi-definite when the holonomy is trivial, e.g. on a flat torus).
    const double eps = 1e-8 * mean_diag / mean_area;
    for(long r = 0; r < n_unknowns; ++r)
      triplets.emplace_back(r, r, Cplx(diag[std::size_t(r)] + eps * mass[std::size_t(r)], 0.));
    Eigen::SparseMatrix<Cplx> A(n_unknowns, n_unknowns);
    A.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<Cplx>> solver;
    solver.compute(A);
    if(solver.info() != Eigen::Success) throw std::runtime_error("compute_cross_field: factorisation failed");
    CVector x = solver.solve(b);
    if(stats.free_components > 0) {
      // Unanchored components: inverse power iteration towards the smoothest field (the eigenvector of the
      // smallest eigenvalue of the connection Laplacian, as in Knoeppel et al. 2013), with the curvature
      // pull W c added to every step. Anchored components have a right-hand side independent of x and
      // keep their direct solution. The start is deterministic.
      std::vector<std::size_t> comp_of_unknown(static_cast<std::size_t>(n_unknowns), 0);
      for(std::size_t i = 0; i < nf; ++i)
        if(unknown[i] >= 0) comp_of_unknown[std::size_t(unknown[i])] = std::size_t(component[i]);
      CVector y = CVector::Zero(n_unknowns);
      for(long r = 0; r < n_unknowns; ++r)
        if(!anchored[comp_of_unknown[std::size_t(r)]]) y[r] = (std::abs(x[r]) > 0.) ? x[r] : Cplx(1., 0.);
      for(int it = 0; it < 30; ++it) {
        // normalise each unanchored component to unit mean magnitude (area weighted)
        std::vector<double> norm2(anchored.size(), 0.), area(anchored.size(), 0.);
        for(long r = 0; r < n_unknowns; ++r) {
          const std::size_t c = comp_of_unknown[std::size_t(r)];
          if(anchored[c]) continue;
          norm2[c] += mass[std::size_t(r)] * std::norm(y[r]);
          area[c] += mass[std::size_t(r)];
        }
        CVector rhs = b;
        for(long r = 0; r < n_unknowns; ++r) {
          const std::size_t c = comp_of_unknown[std::size_t(r)];
          if(anchored[c] || !(norm2[c] > 0.)) continue;
          rhs[r] += mean_diag / mean_area * mass[std::size_t(r)] * y[r] * std::sqrt(area[c] / norm2[c]);
        }
        const CVector y_new = solver.solve(rhs);
        // stop once no unanchored face turns its direction by more than ~2.5e-5 rad (1e-4 on the fourth power)
        double change = 0.;
        for(long r = 0; r < n_unknowns; ++r) {
          const double a = std::abs(y[r]), bn = std::abs(y_new[r]);
          if(a > 0. && bn > 0.) change = std::max(change, std::abs(y_new[r] / bn - y[r] / a));
          else if(a > 0. || bn > 0.) change = 1.;
        }
        y = y_new;
        if(change < 1e-4) break;
      }
      for(long r = 0; r < n_unknowns; ++r)
        if(!anchored[comp_of_unknown[std::size_t(r)]]) x[r] = y[r];
    }
    for(std::size_t i = 0; i < nf; ++i)
      if(unknown[i] >= 0) {
        const Cplx v = x[unknown[i]];
        // a vanishing solution (possible only at exact cancellation) keeps the frame's axis
        u[i] = (std::abs(v) > 1e-300 && std::isfinite(std::abs(v))) ? v / std::abs(v) : Cplx(1., 0.);
      }
  }

  // Output and energy of the normalised field.
  for(std::size_t i = 0; i < nf; ++i) {
    const Vec3d d = fixed[i] ? fixed_dir[i] : frames[i].direction(std::arg(u[i]) / 4.);
    put(face_cross_field_map, face_of[i], Vector_3(d[0], d[1], d[2]));
  }
  for(auto e : edges(tmesh)) {
    const halfedge_descriptor h = halfedge(e, tmesh);
    if(is_feature(h)) continue;
    const std::size_t i = get(fim, face(h, tmesh)), j = get(fim, face(opposite(h, tmesh), tmesh));
    stats.energy += edge_weight(h, i, j) * std::norm(u[i] - connection(h, i, j) * u[j]);
  }
  stats.seconds = timer.time();
  if(verbose)
    std::cerr << "[cross-field] " << nf << " faces, " << stats.constrained_faces << " constrained ("
              << stats.two_feature_faces << " with several features), " << stats.curvature_faces
              << " curvature-guided, " << stats.free_components << " unconstrained components; energy " << stats.energy << "; "
              << stats.seconds << " s" << std::endl;
  return stats;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Returns the matching of the cross field across the edge of `h`: the number `k` in 0..3 of quarter turns
  (counterclockwise about the normal of `face(opposite(h))`) by which the field of `face(h)`, transported across
  the edge, must be rotated to be closest to the field of `face(opposite(h))`. The matching of `opposite(h)` is
  `(4 - k) % 4` (up to an exact tie at 45 degrees). Returns 0 on a border halfedge.

  @tparam TriangleMesh a model of `FaceGraph`
  @tparam FaceCrossFieldMap a model of `ReadablePropertyMap` from faces to `GeomTraits::Vector_3`
  @tparam NamedParameters a sequence of named parameters

  @param tmesh the triangle mesh
  @param face_cross_field_map the field, as computed by `compute_cross_field()`
  @param h a halfedge of `tmesh`
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
  \cgalNamedParamsEnd
*/
template <typename TriangleMesh, typename FaceCrossFieldMap, typename NamedParameters = parameters::Default_named_parameters>
int cross_field_matching(const TriangleMesh& tmesh, FaceCrossFieldMap face_cross_field_map,
                         typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                         const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if(is_border_edge(h, tmesh)) return 0;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tmesh));
  int k = 0;
  internal::halfedge_field_rotation(h, tmesh, vpm, face_cross_field_map, k);
  return k;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Computes the singularity index of every vertex of a cross field.

  The index of an interior vertex that is on no feature edge is \f$k = (K_v + \sum_h \delta_h) / (\pi/2)\f$ in
  quarter turns, where \f$K_v\f$ is the angle defect of the vertex and \f$\delta_h \in [-\pi/4, \pi/4]\f$ the
  rotation of the field relative to parallel transport across each edge around it. `vertex_singularity_map`
  receives `k`: `0` for a regular vertex, `+1` for a singularity of valence 3, `-1` for valence 5, and in general
  valence `4 - k`. Vertices on a border or a feature edge are, after the cut along the features, border vertices
  of the patches; as in the paper their singular status is dropped and they get 0. On a closed mesh without
  features the indices sum to four times its Euler characteristic.

  @tparam TriangleMesh a model of `FaceListGraph`, `HalfedgeListGraph` and `VertexListGraph`
  @tparam EdgeIsFeatureMap a model of `ReadablePropertyMap` from edges to `bool`
  @tparam FaceCrossFieldMap a model of `ReadablePropertyMap` from faces to `GeomTraits::Vector_3`
  @tparam VertexSingularityMap a model of `WritablePropertyMap` from vertices to `int`
  @tparam NamedParameters a sequence of named parameters

  @param tmesh the triangle mesh
  @param edge_is_feature_map the feature edges used for the field (border edges are features)
  @param face_cross_field_map the field, as computed by `compute_cross_field()`
  @param vertex_singularity_map receives the index of every vertex in quarter turns
  @param np an optional sequence of named parameters among the ones listed below

  @pre `CGAL::is_triangle_mesh(tmesh)`

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{verbose}
      \cgalParamDescription{whether to print the counts to `std::cerr`, prefixed by `[cross-field]`}
      \cgalParamType{`bool`}
      \cgalParamDefault{`false`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return the counts by valence and the index sum
*/
template <typename TriangleMesh, typename EdgeIsFeatureMap, typename FaceCrossFieldMap, typename VertexSingularityMap,
          typename NamedParameters = parameters::Default_named_parameters>
Cross_field_singularity_statistics
compute_cross_field_singularities(const TriangleMesh& tmesh, EdgeIsFeatureMap edge_is_feature_map,
                                  FaceCrossFieldMap face_cross_field_map, VertexSingularityMap vertex_singularity_map,
                                  const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GTr;
  typedef typename GTr::halfedge_descriptor halfedge_descriptor;
  typedef typename GTr::vertex_descriptor vertex_descriptor;
  using namespace internal;

  CGAL::Real_timer timer;
  timer.start();
  if(!CGAL::is_triangle_mesh(tmesh))
    throw std::invalid_argument("compute_cross_field_singularities: the mesh is not a triangle mesh");
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tmesh));

  Cross_field_singularity_statistics stats;
  for(vertex_descriptor v : vertices(tmesh)) {
    bool on_feature = halfedge(v, tmesh) == GTr::null_halfedge();
    double sum = 0.;
    if(!on_feature)
      for(halfedge_descriptor h : halfedges_around_target(v, tmesh)) {
        if(is_border_edge(h, tmesh) || bool(get(edge_is_feature_map, edge(h, tmesh)))) { on_feature = true; break; }
        int k = 0;
        // Rotation crossing the edge of h counterclockwise around v, i.e. from face(h) to face(opposite(h)).
        sum += halfedge_field_rotation(h, tmesh, vpm, face_cross_field_map, k);
        // angle of the corner of face(h) at v
        const Vec3d a = v_normalized(v_scale(edge_vector(h, tmesh, vpm), -1.));
        const Vec3d b = v_normalized(edge_vector(next(h, tmesh), tmesh, vpm));
        sum -= std::atan2(v_norm(v_cross(a, b)), v_dot(a, b));
      }
    int index = 0;
    if(!on_feature) index = int(std::lround((2. * CGAL_PI + sum) / (0.5 * CGAL_PI)));
    put(vertex_singularity_map, v, index);
    if(index != 0) {
      ++stats.singular_vertices;
      ++stats.singularities_by_valence[4 - index];
      stats.index_sum_quarter_turns += index;
    }
  }
  stats.seconds = timer.time();
  if(verbose) {
    std::cerr << "[cross-field] " << stats.singular_vertices << " singular vertices (";
    for(const auto& vc : stats.singularities_by_valence) std::cerr << " valence " << vc.first << ": " << vc.second;
    std::cerr << " ), index sum " << stats.index_sum() << "; " << stats.seconds << " s" << std::endl;
  }
  return stats;
}

/*!
  \ingroup PkgQuadRemeshingRef
  Computes a per-vertex cross field for streamline tracing: at each vertex, the area-weighted average of the
  fourth powers of the fields of the incident faces, expressed in the vertex tangent plane (normal: area-weighted
  face normals), and brought back to a unit vector. Singular vertices (non-zero value in `vertex_singularity_map`)
  and vertices where the average vanishes get the null vector, which flags them.

  @tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
  @tparam FaceCrossFieldMap a model of `ReadablePropertyMap` from faces to `GeomTraits::Vector_3`
  @tparam VertexSingularityMap a model of `ReadablePropertyMap` from vertices to `int`
  @tparam VertexCrossFieldMap a model of `WritablePropertyMap` from vertices to `GeomTraits::Vector_3`
  @tparam NamedParameters a sequence of named parameters

  @param tmesh the triangle mesh
  @param face_cross_field_map the field, as computed by `compute_cross_field()`
  @param vertex_singularity_map the indices, as computed by `compute_cross_field_singularities()`
  @param vertex_cross_field_map receives a unit representative of the cross in the tangent plane of each vertex, or the null vector
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{an instance of a geometric traits class}
      \cgalParamType{a class model of `Kernel`}
      \cgalParamDefault{a \cgal Kernel deduced from the point type}
    \cgalParamNEnd
  \cgalNamedParamsEnd
*/
template <typename TriangleMesh, typename FaceCrossFieldMap, typename VertexSingularityMap, typename VertexCrossFieldMap,
          typename NamedParameters = parameters::Default_named_parameters>
void compute_vertex_cross_field(const TriangleMesh& tmesh, FaceCrossFieldMap face_cross_field_map,
                                VertexSingularityMap vertex_singularity_map, VertexCrossFieldMap vertex_cross_field_map,
                                const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh> GTr;
  typedef typename GTr::halfedge_descriptor halfedge_descriptor;
  typedef typename GTr::vertex_descriptor vertex_descriptor;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GT::Vector_3 Vector_3;
  using namespace internal;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tmesh));

  for(vertex_descriptor v : vertices(tmesh)) {
    Vector_3 out(0, 0, 0);
    if(get(vertex_singularity_map, v) == 0 && halfedge(v, tmesh) != GTr::null_halfedge()) {
      Vec3d n{{0., 0., 0.}};
      for(halfedge_descriptor h : halfedges_around_target(v, tmesh))
        if(!is_border(h, tmesh)) {
          const Face_frame fr = face_frame(face(h, tmesh), tmesh, vpm);
          n = v_add(n, v_scale(fr.n, fr.area));
        }
      n = v_normalized(n);
      if(v_norm(n) > 0.) {
        const Vec3d e1 = any_orthogonal(n), e2 = v_cross(n, e1);
        std::complex<double> s(0., 0.);
        for(halfedge_descriptor h : halfedges_around_target(v, tmesh)) {
          if(is_border(h, tmesh)) continue;
          const Face_frame fr = face_frame(face(h, tmesh), tmesh, vpm);
          const Vec3d d = vector_to_vec3d(get(face_cross_field_map, face(h, tmesh)));
          // rotate d from the face plane into the tangent plane: keep its angle to the rotation axis n_f x n
          const Vec3d axis = v_cross(fr.n, n);
          const double sn = v_norm(axis), cs = v_dot(fr.n, n);
          Vec3d dr = d;
          if(sn > 1e-12) {
            const Vec3d k = v_scale(axis, 1. / sn);
            // Rodrigues' rotation by the angle between the normals
            dr = v_add(v_add(v_scale(d, cs), v_scale(v_cross(k, d), sn)), v_scale(k, v_dot(k, d) * (1. - cs)));
          }
          s += fr.area * std::polar(1., 4. * std::atan2(v_dot(dr, e2), v_dot(dr, e1)));
        }
        if(std::abs(s) > 1e-12 * (std::abs(s.real()) + std::abs(s.imag()) + 1e-300) && std::abs(s) > 0.) {
          const double a = std::arg(s) / 4.;
          const Vec3d d = v_add(v_scale(e1, std::cos(a)), v_scale(e2, std::sin(a)));
          out = Vector_3(d[0], d[1], d[2]);
        }
      }
    }
    put(vertex_cross_field_map, v, out);
  }
}

/*!
  \ingroup PkgQuadRemeshingRef
  Writes the cross field as OBJ line segments: for every face, the two segments of its cross through the
  centroid, of half-length `scale` times the mean edge length of the face (`v` lines then `l` lines).

  @tparam TriangleMesh a model of `FaceListGraph`
  @tparam FaceCrossFieldMap a model of `ReadablePropertyMap` from faces to `GeomTraits::Vector_3`

  @param os the output stream
  @param tmesh the triangle mesh
  @param face_cross_field_map the field
  @param scale half-length of the segments relative to the mean edge length of each face
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return `true` if the stream is still good
*/
template <typename TriangleMesh, typename FaceCrossFieldMap, typename NamedParameters = parameters::Default_named_parameters>
bool write_cross_field_OBJ(std::ostream& os, const TriangleMesh& tmesh, FaceCrossFieldMap face_cross_field_map,
                           double scale = 0.4, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using namespace internal;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tmesh));
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  os << std::setprecision(17) << "# cross field: two segments per face\n";
  std::size_t n = 0;
  for(auto f : faces(tmesh)) {
    const Face_frame fr = face_frame(f, tmesh, vpm);
    Vec3d c{{0., 0., 0.}};
    double len = 0.;
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, tmesh), tmesh)) {
      c = v_add(c, to_vec3d<Point, decltype(vpm)>(get(vpm, target(h, tmesh))));
      len += v_norm(edge_vector(h, tmesh, vpm));
      ++k;
    }
    if(k == 0) continue;
    c = v_scale(c, 1. / k);
    len *= scale / k;
    const Vec3d d = v_scale(v_normalized(vector_to_vec3d(get(face_cross_field_map, f))), len);
    const Vec3d t = v_cross(fr.n, d);
    for(const Vec3d& w : {d, t}) {
      const Vec3d a = v_sub(c, w), b = v_add(c, w);
      os << "v " << a[0] << ' ' << a[1] << ' ' << a[2] << "\nv " << b[0] << ' ' << b[1] << ' ' << b[2] << '\n';
      os << "l " << n + 1 << ' ' << n + 2 << '\n';
      n += 2;
    }
  }
  return bool(os);
}

/*!
  \ingroup PkgQuadRemeshingRef
  Writes the singular vertices as a coloured ASCII PLY point cloud: valence 3 (index +1) red, valence 5
  (index -1) blue, other valences green; each vertex carries its `valence` as an `int` property.

  @tparam TriangleMesh a model of `VertexListGraph`
  @tparam VertexSingularityMap a model of `ReadablePropertyMap` from vertices to `int`

  @param os the output stream
  @param tmesh the triangle mesh
  @param vertex_singularity_map the indices, as computed by `compute_cross_field_singularities()`
  @param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  @return `true` if the stream is still good
*/
template <typename TriangleMesh, typename VertexSingularityMap, typename NamedParameters = parameters::Default_named_parameters>
bool write_cross_field_singularities_PLY(std::ostream& os, const TriangleMesh& tmesh, VertexSingularityMap vertex_singularity_map,
                                         const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(vertex_point, tmesh));
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point;
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> sing;
  for(auto v : vertices(tmesh))
    if(get(vertex_singularity_map, v) != 0) sing.push_back(v);
  os << "ply\nformat ascii 1.0\nelement vertex " << sing.size()
     << "\nproperty double x\nproperty double y\nproperty double z\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int valence\nend_header\n";
  os << std::setprecision(17);
  for(auto v : sing) {
    const internal::Vec3d p = internal::to_vec3d<Point, decltype(vpm)>(get(vpm, v));
    const int k = get(vertex_singularity_map, v);
    const char* rgb = (k == 1) ? "255 0 0" : (k == -1) ? "0 0 255" : "0 200 0";
    os << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << rgb << ' ' << 4 - k << '\n';
  }
  return bool(os);
}

} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_CROSS_FIELD_H
