// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Adaptive pass of remesh_for_quadrangulation(): split / collapse / flip / tangential relaxation /
// projection driven by a per-vertex sizing field, with the feature rules of the uniform pass.

#ifndef CGAL_QUAD_REMESHING_INTERNAL_REMESHING_ADAPTIVE_REMESHING_H
#define CGAL_QUAD_REMESHING_INTERNAL_REMESHING_ADAPTIVE_REMESHING_H

#include <CGAL/Quad_remeshing/internal/remeshing/remeshing_helpers.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// The input surface and its feature polylines, as AABB trees for projections and distances.
template <typename GT>
struct Remeshing_reference
{
  typedef typename GT::Point_3 Point;
  typedef typename GT::Segment_3 Segment;
  typedef typename GT::Triangle_3 Triangle;
  typedef CGAL::AABB_triangle_primitive<GT, typename std::vector<Triangle>::const_iterator> Tri_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GT, Tri_primitive>> Tri_tree;
  typedef CGAL::AABB_segment_primitive<GT, typename std::vector<Segment>::const_iterator> Seg_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<GT, Seg_primitive>> Seg_tree;

  std::vector<Triangle> triangles;
  std::vector<Segment> feature_segments;
  std::vector<Point> points; // the input vertices, where the input-to-output distance is measured
  Tri_tree surface;
  Seg_tree features;

  void build_surface()
  {
    surface.rebuild(triangles.begin(), triangles.end());
    surface.accelerate_distance_queries();
  }

  void build_features()
  {
    if(!feature_segments.empty())
    {
      features.rebuild(feature_segments.begin(), feature_segments.end());
      features.accelerate_distance_queries();
    }
  }
};

// Split / collapse / flip / relax on a triangle mesh whose vertices carry a target edge length (`size`).
// Feature rules: a feature edge is split at its midpoint (moved onto the nearest input feature segment
// when that is close), never flipped, collapsed only along its line (the removed vertex is a regular
// line vertex and the new chord stays within `feature_tolerance` of it); fixed vertices (corners, line
// ends, junctions) never move nor are removed; feature vertices never move otherwise.
template <typename TriangleMesh, typename VPM, typename EFM, typename VCM, typename SizeMap, typename GT>
class Adaptive_remesher
{
  typedef boost::graph_traits<TriangleMesh> GTr;
  typedef typename GTr::vertex_descriptor vertex_descriptor;
  typedef typename GTr::halfedge_descriptor halfedge_descriptor;
  typedef typename GTr::edge_descriptor edge_descriptor;
  typedef typename GTr::face_descriptor face_descriptor;
  typedef typename GT::Point_3 Point;
  typedef typename GT::Vector_3 Vector;
  typedef typename GT::Segment_3 Segment;

public:
  Adaptive_remesher(TriangleMesh& tm, VPM vpm, EFM efm, VCM vcm, SizeMap size,
                    const Remeshing_reference<GT>& ref, double feature_tolerance, std::size_t max_faces)
    : tm_(tm), vpm_(vpm), efm_(efm), vcm_(vcm), size_(size), ref_(ref), feature_tol_(feature_tolerance),
      max_faces_(max_faces)
  {}

  // one iteration of the loop
  void iterate()
  {
    split_long_edges();
    collapse_short_edges();
    flip_edges();
    relax_and_project();
  }

  int feature_degree(vertex_descriptor v) const
  {
    int n = 0;
    for(halfedge_descriptor h : halfedges_around_target(v, tm_))
      if(get(efm_, edge(h, tm_))) ++n;
    return n;
  }
  bool is_fixed(vertex_descriptor v) const
  {
    if(get(vcm_, v)) return true;
    const int n = feature_degree(v);
    return n != 0 && n != 2;
  }

  // Puts the constraint lines back where they drifted: while some point of `line_points` (points of the
  // input's constraint polylines) is farther than `tolerance` from every constrained edge, the nearest
  // constrained edge is split at the farthest such point (unless that point is within a tenth of the
  // edge length of an endpoint or the split would fold a face). At most `rounds` rounds; returns the
  // number of vertices inserted.
  std::size_t restore_lines(const std::vector<Point>& line_points, double tolerance, unsigned rounds)
  {
    typedef CGAL::AABB_segment_primitive<GT, typename std::vector<Segment>::const_iterator> Prim;
    typedef CGAL::AABB_tree<CGAL::AABB_traits<GT, Prim>> Tree;
    std::size_t inserted = 0;
    for(unsigned round = 0; round < rounds; ++round)
    {
      std::vector<Segment> segments;
      std::vector<edge_descriptor> owner;
      for(edge_descriptor e : edges(tm_))
        if(get(efm_, e))
        {
          segments.emplace_back(point(source(halfedge(e, tm_), tm_)), point(target(halfedge(e, tm_), tm_)));
          owner.push_back(e);
        }
      if(segments.empty()) return inserted;
      Tree tree(segments.begin(), segments.end());
      tree.accelerate_distance_queries();
      // per edge, the farthest point out of tolerance (deterministic: the first of equal ones)
      std::vector<std::pair<double, std::size_t>> worst(segments.size(), {0., std::size_t(-1)});
      for(std::size_t i = 0; i < line_points.size(); ++i)
      {
        const auto cp = tree.closest_point_and_primitive(line_points[i]);
        const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(line_points[i], cp.first)));
        const std::size_t k = std::size_t(cp.second - segments.cbegin());
        if(d > tolerance && d > worst[k].first) worst[k] = {d, i};
      }
      std::size_t done = 0;
      for(std::size_t k = 0; k < segments.size(); ++k)
      {
        if(worst[k].second == std::size_t(-1)) continue;
        const halfedge_descriptor h = halfedge(owner[k], tm_);
        const Point& q = line_points[worst[k].second];
        if(!is_safe_split_point(h, q, 0.01, 0.5)) continue;
        split_edge(h, q);
        ++done;
      }
      inserted += done;
      if(done == 0) break;
    }
    return inserted;
  }

private:
  const Point& point(vertex_descriptor v) const { return get(vpm_, v); }
  double length(halfedge_descriptor h) const
  {
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(point(source(h, tm_)), point(target(h, tm_)))));
  }
  double target_length(halfedge_descriptor h) const
  {
    return (std::min)(get(size_, source(h, tm_)), get(size_, target(h, tm_)));
  }
  static Vector normal(const Point& p, const Point& q, const Point& r)
  {
    return CGAL::cross_product(q - p, r - p);
  }
  static double cosine(const Vector& a, const Vector& b)
  {
    const double l = std::sqrt(CGAL::to_double(a * a) * CGAL::to_double(b * b));
    return l > 0. ? CGAL::to_double(a * b) / l : -1.;
  }

  // The midpoint of a feature edge goes onto the nearest input feature segment if that is within a
  // quarter of the edge length (the input line the edge is a chord of); other midpoints onto the surface
  // if it is within half the edge length.
  Point split_point(halfedge_descriptor h, bool feature) const
  {
    const Point m = CGAL::midpoint(point(source(h, tm_)), point(target(h, tm_)));
    const double l = length(h);
    Point q = m;
    if(feature)
    {
      if(ref_.feature_segments.empty()) return m;
      q = ref_.features.closest_point(m);
    }
    else
      q = ref_.surface.closest_point(m, point(source(h, tm_))); // the search starts from an endpoint
    if(!(CGAL::to_double(CGAL::squared_distance(m, q)) <= (feature ? 0.0625 : 0.25) * l * l)) return m;
    // the projection must not land near an endpoint (e.g. on an input corner that is already a vertex)
    // nor fold a face of the edge: the midpoint itself is used then
    return is_safe_split_point(h, q, 0.09, 0.) ? q : m;
  }

  // Whether splitting the edge of `h` at `q` is safe: the squared distance of `q` to both endpoints is at
  // least `min_squared_fraction` times the squared edge length, and the normals of the two faces replacing
  // each face of the edge stay within acos(`min_cosine`) of its normal.
  bool is_safe_split_point(halfedge_descriptor h, const Point& q, double min_squared_fraction, double min_cosine) const
  {
    const Point& a = point(source(h, tm_));
    const Point& b = point(target(h, tm_));
    const double near2 = min_squared_fraction * CGAL::to_double(CGAL::squared_distance(a, b));
    if(CGAL::to_double(CGAL::squared_distance(a, q)) < near2 ||
       CGAL::to_double(CGAL::squared_distance(b, q)) < near2)
      return false;
    for(halfedge_descriptor g : {h, opposite(h, tm_)})
    {
      if(is_border(g, tm_)) continue;
      const Point& c = point(target(next(g, tm_), tm_));
      const Point& u = point(source(g, tm_));
      const Point& w = point(target(g, tm_));
      const Vector n = normal(u, w, c);
      if(cosine(n, normal(u, q, c)) < min_cosine || cosine(n, normal(q, w, c)) < min_cosine) return false;
    }
    return true;
  }

  // Splits the edge of `h` at `p` and triangulates both sides; the new edges are not features.
  vertex_descriptor split_edge(halfedge_descriptor h, const Point& p)
  {
    const double s = 0.5 * (get(size_, source(h, tm_)) + get(size_, target(h, tm_)));
    const bool feature = get(efm_, edge(h, tm_));
    const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, tm_); // source -> m, then h: m -> target
    const vertex_descriptor m = target(hnew, tm_);
    put(vpm_, m, p);
    put(size_, m, s);
    put(vcm_, m, false);
    put(efm_, edge(hnew, tm_), feature);
    put(efm_, edge(h, tm_), feature);
    if(!is_border(h, tm_))
      put(efm_, edge(CGAL::Euler::split_face(hnew, next(h, tm_), tm_), tm_), false);
    const halfedge_descriptor oh = opposite(h, tm_);
    if(!is_border(oh, tm_))
      put(efm_, edge(CGAL::Euler::split_face(oh, next(next(oh, tm_), tm_), tm_), tm_), false);
    return m;
  }

  // Splits every edge longer than 4/3 of its target length, longest (relative to it) first, until the
  // mesh has `max_faces` faces.
  void split_long_edges()
  {
    std::size_t nf = std::size_t(std::distance(faces(tm_).begin(), faces(tm_).end()));
    std::vector<std::pair<double, edge_descriptor>> todo;
    for(edge_descriptor e : edges(tm_))
    {
      const halfedge_descriptor h = halfedge(e, tm_);
      const double l = length(h);
      if(l > 4. / 3. * target_length(h)) todo.emplace_back(-l / target_length(h), e);
    }
    std::sort(todo.begin(), todo.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for(const auto& t : todo)
    {
      if(nf >= max_faces_) break;
      const halfedge_descriptor h = halfedge(t.second, tm_);
      nf += is_border(t.second, tm_) ? 1 : 2;
      split_edge(h, split_point(h, get(efm_, t.second)));
    }
  }

  // Can `x` be removed by collapsing the edge of `h` (x -> k) onto `k`?
  bool can_collapse(halfedge_descriptor h) const
  {
    const vertex_descriptor x = source(h, tm_), k = target(h, tm_);
    if(is_fixed(x)) return false;
    const bool feature = get(efm_, edge(h, tm_));
    if(!feature && feature_degree(x) != 0) return false; // never across a line
    if(feature)
    {
      // x is a regular line vertex: the new chord (k, c) must stay close to it and not exist yet
      for(halfedge_descriptor g : halfedges_around_source(x, tm_))
      {
        const vertex_descriptor c = target(g, tm_);
        if(c == k || !get(efm_, edge(g, tm_))) continue;
        if(halfedge(k, c, tm_).second) return false;
        const double d2 = CGAL::to_double(CGAL::squared_distance(Segment(point(k), point(c)), point(x)));
        if(d2 > feature_tol_ * feature_tol_) return false;
      }
    }
    if(!CGAL::Euler::does_satisfy_link_condition(edge(h, tm_), tm_)) return false;
    // no long edge, no flipped or degenerate face
    const Point& pk = point(k);
    for(halfedge_descriptor g : halfedges_around_source(x, tm_))
    {
      const vertex_descriptor y = target(g, tm_);
      if(y == k) continue;
      if(std::sqrt(CGAL::to_double(CGAL::squared_distance(pk, point(y)))) >
         4. / 3. * (std::min)(get(size_, k), get(size_, y)))
        return false;
      if(is_border(g, tm_)) continue;
      const vertex_descriptor z = target(next(g, tm_), tm_);
      if(z == k) continue; // a face that disappears
      const Vector before = normal(point(x), point(y), point(z));
      const Vector after = normal(pk, point(y), point(z));
      if(cosine(before, after) < 0.7) return false;
    }
    return true;
  }

  // Removes source(h) onto target(h), keeping the feature flags of merged edges.
  template <typename RemovedMap>
  void collapse(halfedge_descriptor h, RemovedMap removed)
  {
    const vertex_descriptor x = source(h, tm_), k = target(h, tm_);
    std::vector<std::pair<vertex_descriptor, bool>> merged;
    for(halfedge_descriptor g : {h, opposite(h, tm_)})
      if(!is_border(g, tm_))
      {
        const vertex_descriptor y = target(next(g, tm_), tm_);
        merged.emplace_back(y, get(efm_, edge(halfedge(x, y, tm_).first, tm_)) ||
                                 get(efm_, edge(halfedge(k, y, tm_).first, tm_)));
      }
    const Point pk = point(k);
    const double sk = get(size_, k);
    const bool ck = get(vcm_, k);
    // Euler::collapse_edge() keeps target(halfedge(e)): give it k's place and properties
    const vertex_descriptor kept = CGAL::Euler::collapse_edge(edge(h, tm_), tm_);
    put(removed, kept == k ? x : k, true);
    put(vpm_, kept, pk);
    put(size_, kept, sk);
    put(vcm_, kept, ck);
    for(const auto& m : merged)
      put(efm_, edge(halfedge(kept, m.first, tm_).first, tm_), m.second);
  }

  // Collapses every edge shorter than 4/5 of its target length, shortest first.
  void collapse_short_edges()
  {
    std::vector<std::pair<double, std::pair<vertex_descriptor, vertex_descriptor>>> todo;
    for(edge_descriptor e : edges(tm_))
    {
      const halfedge_descriptor h = halfedge(e, tm_);
      const double l = length(h);
      if(l < 0.8 * target_length(h))
        todo.push_back({l / target_length(h), {source(h, tm_), target(h, tm_)}});
    }
    std::sort(todo.begin(), todo.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    auto removed = get(CGAL::dynamic_vertex_property_t<bool>(), tm_);
    for(vertex_descriptor v : vertices(tm_)) put(removed, v, false);
    for(const auto& t : todo)
    {
      const vertex_descriptor a = t.second.first, b = t.second.second;
      if(get(removed, a) || get(removed, b)) continue;
      const auto hb = halfedge(a, b, tm_);
      if(!hb.second) continue;
      const halfedge_descriptor h = hb.first;
      if(!(length(h) < 0.8 * target_length(h))) continue;
      if(can_collapse(h)) collapse(h, removed);
      else if(can_collapse(opposite(h, tm_))) collapse(opposite(h, tm_), removed);
    }
  }

  int valence(vertex_descriptor v) const
  {
    int n = 0;
    for(halfedge_descriptor h : halfedges_around_target(v, tm_)) { (void)h; ++n; }
    return n;
  }
  int target_valence(vertex_descriptor v) const { return is_border(v, tm_) ? 4 : 6; }

  // Flips non-feature edges that bring the four vertices closer to their ideal valence, if the two faces
  // are nearly coplanar and the flip neither folds them nor joins two feature vertices.
  void flip_edges()
  {
    for(edge_descriptor e : edges(tm_))
    {
      if(get(efm_, e) || is_border(e, tm_)) continue;
      const halfedge_descriptor h = halfedge(e, tm_), o = opposite(h, tm_);
      const vertex_descriptor a = source(h, tm_), b = target(h, tm_);
      const vertex_descriptor c = target(next(h, tm_), tm_), d = target(next(o, tm_), tm_);
      if(c == d || halfedge(c, d, tm_).second) continue;
      if(feature_degree(c) > 0 && feature_degree(d) > 0) continue;
      const int va = valence(a) - target_valence(a), vb = valence(b) - target_valence(b);
      const int vc = valence(c) - target_valence(c), vd = valence(d) - target_valence(d);
      const int before = va * va + vb * vb + vc * vc + vd * vd;
      const int after = (va - 1) * (va - 1) + (vb - 1) * (vb - 1) + (vc + 1) * (vc + 1) + (vd + 1) * (vd + 1);
      if(after >= before) continue;
      const Vector n1 = normal(point(a), point(b), point(c)), n2 = normal(point(b), point(a), point(d));
      if(cosine(n1, n2) < 0.94) continue; // about 20 degrees: a crease, keep it
      const Vector m1 = normal(point(a), point(d), point(c)), m2 = normal(point(b), point(c), point(d));
      if(cosine(m1, m2) < 0.94 || cosine(m1, n1) < 0.9 || cosine(m2, n1) < 0.9) continue;
      CGAL::Euler::flip_edge(h, tm_);
    }
  }

  // Moves every free vertex towards the area-weighted centroid of its faces, in its tangent plane, then
  // onto the input surface; a move that would fold a face is not done.
  void relax_and_project()
  {
    for(vertex_descriptor v : vertices(tm_))
    {
      if(feature_degree(v) != 0 || is_border(v, tm_)) continue;
      const Point p = point(v);
      Vector c = CGAL::NULL_VECTOR, n = CGAL::NULL_VECTOR;
      double w = 0.;
      for(halfedge_descriptor h : halfedges_around_target(v, tm_))
      {
        const Point& q = point(source(h, tm_));
        const Point& r = point(target(next(h, tm_), tm_));
        const Vector fn = normal(p, r, q); // h: q -> v, next: v -> r
        const double a = std::sqrt(CGAL::to_double(fn * fn));
        c = c + a * ((p - CGAL::ORIGIN) + (q - CGAL::ORIGIN) + (r - CGAL::ORIGIN)) / 3.;
        n = n + fn;
        w += a;
      }
      const double nl = std::sqrt(CGAL::to_double(n * n));
      if(!(w > 0.) || !(nl > 0.)) continue;
      n = n / nl;
      Vector d = (CGAL::ORIGIN + c / w) - p;
      d = d - (d * n) * n;
      const Point moved = p + d;
      const Point q = ref_.surface.closest_point(moved, p); // the search starts from the old position
      bool ok = true;
      for(halfedge_descriptor h : halfedges_around_target(v, tm_))
      {
        const Point& a = point(source(h, tm_));
        const Point& b = point(target(next(h, tm_), tm_));
        if(cosine(normal(p, b, a), normal(q, b, a)) < 0.5) { ok = false; break; }
      }
      if(ok) put(vpm_, v, q);
    }
  }

  TriangleMesh& tm_;
  VPM vpm_;
  EFM efm_;
  VCM vcm_;
  SizeMap size_;
  const Remeshing_reference<GT>& ref_;
  double feature_tol_;
  std::size_t max_faces_;
};

// Per vertex, the largest distance measured around it: from the output to the input at the centroid
// and edge midpoints of its faces, and from the input to the output at the input vertices whose
// closest output point lies on one of its faces. Returns the largest of all. The searches on the input
// start from a vertex of the face (vertices lie on the input surface, up to the chords of feature lines).
template <typename TriangleMesh, typename VPM, typename ErrorMap, typename GT>
double measure_distances(const TriangleMesh& tm, const VPM& vpm, const Remeshing_reference<GT>& ref, ErrorMap err)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename GT::Point_3 Point;
  typedef typename GT::Triangle_3 Triangle;
  typedef typename Remeshing_reference<GT>::Tri_tree Tree;
  for(vertex_descriptor v : vertices(tm)) put(err, v, 0.);
  std::vector<face_descriptor> fs;
  std::vector<Triangle> tris;
  double worst = 0.;
  auto raise = [&](face_descriptor f, double d) {
    for(vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      if(d > get(err, v)) put(err, v, d);
    worst = (std::max)(worst, d);
  };
  for(face_descriptor f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const Point& p = get(vpm, source(h, tm));
    const Point& q = get(vpm, target(h, tm));
    const Point& r = get(vpm, target(next(h, tm), tm));
    fs.push_back(f);
    tris.emplace_back(p, q, r);
    raise(f, std::sqrt(CGAL::to_double(ref.surface.squared_distance(CGAL::centroid(p, q, r), p))));
  }
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    const Point& p = get(vpm, source(h, tm));
    const double d = std::sqrt(CGAL::to_double(ref.surface.squared_distance(CGAL::midpoint(p, get(vpm, target(h, tm))), p)));
    for(auto g : {h, opposite(h, tm)})
      if(!is_border(g, tm)) raise(face(g, tm), d);
  }
  Tree out(tris.begin(), tris.end());
  out.accelerate_distance_queries();
  for(const Point& p : ref.points)
  {
    const auto cp = out.closest_point_and_primitive(p);
    const face_descriptor f = fs[std::size_t(cp.second - tris.begin())];
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, cp.first)));
    raise(f, d);
  }
  return worst;
}

// Paper (4.2): per vertex, a multiplier of the uniform length from the radius ratio of the pass-1
// triangles (averaged over the one-ring, then over the faces' vertices), mapped linearly from
// [10th percentile, best] to [0.3, 3]; the worst 10% get 0.3.
template <typename TriangleMesh, typename VPM, typename MultiplierMap>
void radius_ratio_multipliers(const TriangleMesh& tmesh, const VPM& vpm, MultiplierMap mult)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor Face;
  auto fq = get(CGAL::dynamic_face_property_t<double>(), tmesh);
  std::vector<double> q;
  for(Face f : faces(tmesh))
  {
    auto h = halfedge(f, tmesh);
    put(fq, f, radius_ratio(get(vpm, source(h, tmesh)), get(vpm, target(h, tmesh)), get(vpm, target(next(h, tmesh), tmesh))));
  }
  for(vertex_descriptor v : vertices(tmesh))
  {
    double s = 0.;
    int n = 0;
    for(Face f : faces_around_target(halfedge(v, tmesh), tmesh))
      if(f != boost::graph_traits<TriangleMesh>::null_face()) { s += get(fq, f); ++n; }
    put(mult, v, n ? s / n : 1.);
    q.push_back(n ? s / n : 1.);
  }
  if(q.empty()) return;
  std::vector<double> sorted = q;
  const std::size_t k = sorted.size() / 10;
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  const double q10 = sorted[k];
  const double qmax = *std::max_element(q.begin(), q.end());
  for(vertex_descriptor v : vertices(tmesh))
  {
    const double x = get(mult, v);
    put(mult, v, qmax - q10 > 1e-9 ? 0.3 + 2.7 * std::max(0., std::min(1., (x - q10) / (qmax - q10))) : 1.);
  }
}

// The number of faces a remeshing at the sizing field `size` would give, up to the same constant factor
// for every field: the area of each face over that of an equilateral triangle of its mean target length.
template <typename TriangleMesh, typename VPM, typename SizeMap>
double expected_faces(const TriangleMesh& tm, const VPM& vpm, const SizeMap& size)
{
  double n = 0.;
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const auto a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
    const double area = std::sqrt(CGAL::to_double(CGAL::squared_area(get(vpm, a), get(vpm, b), get(vpm, c))));
    const double s = (get(size, a) + get(size, b) + get(size, c)) / 3.;
    if(s > 0.) n += area / (0.433 * s * s);
  }
  return n;
}

// Limits the growth of the target length: s(v) <= s(u) + gradation * |uv| over every edge.
template <typename TriangleMesh, typename VPM, typename SizeMap>
void limit_size_gradation(const TriangleMesh& tm, const VPM& vpm, SizeMap size, double gradation)
{
  for(int pass = 0; pass < 3; ++pass)
    for(auto e : edges(tm))
    {
      const auto h = halfedge(e, tm);
      const auto a = source(h, tm), b = target(h, tm);
      const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, a), get(vpm, b))));
      const double sa = get(size, a), sb = get(size, b);
      if(sa > sb + gradation * l) put(size, a, sb + gradation * l);
      else if(sb > sa + gradation * l) put(size, b, sa + gradation * l);
    }
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif
