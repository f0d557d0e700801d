// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// After the fidelity refinement: quad vertices are put onto the tips of the input surface that the quads
// cut off (an ear, a tusk), and the result is kept if it is closer (quad_remesh() and the command line
// share it).

#ifndef CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_TIP_SNAPPING_H
#define CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_TIP_SNAPPING_H

#include <CGAL/Quad_remeshing/quad_mesh_quality.h>
#include <CGAL/Quad_remeshing/Report.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Bbox_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_remeshing {
namespace internal {

// at most this many quad vertices are put onto tips in one call
constexpr std::size_t max_tip_snaps = 64;
// the smoothing iterations after the quad vertices are put onto the tips
constexpr unsigned tip_smoothing_iterations = 10;
// the vertices within this many rings of the quad vertices put onto tips are smoothed again, the others held
constexpr unsigned tip_smoothing_rings = 6;
// at most this many rounds of tips, each on the quads the round before kept
constexpr unsigned max_tip_rounds = 3;
// a round is tried again at most this many times without the tips whose quads around strayed from the input
constexpr unsigned max_tip_retries = 2;

// Copies `from` into the empty `to`, and the flags of `from_feature` into `to_feature`. (No mesh holding
// a dynamic property map that is used afterwards is cleared: CGAL::clear() removes the property maps of
// a Surface_mesh, and a new map made afterwards can take the removed one's address, which the old map's
// handle then removes when it goes.)
template <typename QuadMesh, typename FromFeature, typename ToFeature>
void copy_quad_mesh(const QuadMesh& from, const FromFeature& from_feature, QuadMesh& to, const ToFeature& to_feature)
{
  typedef typename boost::graph_traits<QuadMesh>::halfedge_descriptor halfedge_descriptor;
  std::map<halfedge_descriptor, halfedge_descriptor> h2h;
  CGAL::copy_face_graph(from, to, CGAL::parameters::halfedge_to_halfedge_output_iterator(std::inserter(h2h, h2h.end())));
  for(auto e : edges(to)) put(to_feature, e, false);
  for(const auto& hh : h2h)
    if(get(from_feature, edge(hh.first, from))) put(to_feature, edge(hh.second, to), true);
}

struct Tip_snapping_statistics
{
  std::size_t candidates = 0; // input vertices farther than the tolerance from the quads
  std::size_t snapped = 0;    // quad vertices put onto one of them (in every round tried)
  std::size_t dropped = 0;    // tips left out because the quads around them strayed from the input
  std::size_t rounds = 0;     // rounds kept
  bool smoothed_all = false;  // whether the last smoothing of all the quads (tips held) was kept
  std::size_t pulled = 0;     // quad vertices still far from the input moved onto it at the end
  bool pulled_kept = false;   // whether they were kept
  bool kept = false;          // whether the snapped, smoothed quads replaced the old ones
  double distance_before = 0., distance_after = 0.; // the largest measured distance (absolute)
  double seconds = 0.;

  Report report(double diagonal) const
  {
    Report r = Report::object();
    r["candidates"] = candidates;
    r["snapped"] = snapped;
    r["dropped"] = dropped;
    r["rounds"] = rounds;
    r["smoothed_all"] = smoothed_all;
    r["pulled"] = pulled;
    r["pulled_kept"] = pulled_kept;
    r["kept"] = kept;
    r["distance_before"] = diagonal > 0. ? distance_before / diagonal : 0.;
    r["distance_after"] = diagonal > 0. ? distance_after / diagonal : 0.;
    r["seconds"] = seconds;
    return r;
  }
};

/*
  The triangle mesh `input`'s tips that the quad mesh cuts off: the quads are a sampling of a surface at
  their own size, and where the input narrows to a point smaller than a quad (an ear, a tusk, the tip of
  a nose) no quad vertex lies on it and the quads pass beside it (camelhead: 1.2% of the diagonal).

  In a round, the input vertices (those on a face) farther than `tolerance` from the quads are taken
  farthest first; each takes the nearest quad vertex within two mean quad edge lengths that is not on a
  constrained edge (`qfeature`) or the border, not taken yet, whose normal (of its quads) agrees with the
  input vertex's (the other side of a thin sheet is left alone), and not within one mean quad edge length
  of a tip already taken in the round; at most `max_tip_snaps` in all. Those vertices are moved onto their
  tips in a copy of the quads, which `smooth(copy, copy_feature, fixed)` smooths with them held (it must
  not move the vertices of `fixed`), and with them every vertex farther than `tip_smoothing_rings` rings
  from all of them, so that only the quads around the tips change. The copy is kept if the largest
  distance between the input and the quads, both ways (input vertices to the quads; quad vertices,
  centres, edge midpoints and triangle centroids to the input), falls and no more quads are inverted
  (scaled Jacobian <= 0) than in `qmesh`; if not, the round is tried again with tips two edge lengths
  apart. Before that, each tip is judged on its own: the samples of the quads (as above) farther than
  `tolerance` from the input belong to the nearest tip within `tip_smoothing_rings` mean quad edge lengths;
  a tip whose samples end farther from the input than the tip itself was from the quads and than its
  samples were before the round pulled its quads off the surface, and the round is tried again without it
  (at most `max_tip_retries` times, and only while other tips are left).
  Then the next round (at most `max_tip_rounds`) does the same on the kept
  copy, with the tips of the rounds before still held: an ear is a blade rather than a point, and the
  points of its rim near the tip taken first, left out then, get vertices of their own (camelhead, qmeval:
  0.71% -> 0.43% in 3 rounds). If the quads are still farther than `tolerance` from the input, the free
  quad vertices (not held) farther than half of it are pulled onto the input, as far as the quads around
  them allow (see below), kept if closer. The last copy kept replaces `qmesh` (through
  `keep(copy, copy_feature)`).
*/
template <typename TriangleMesh, typename QuadMesh, typename QuadFeatureMap, typename Smooth, typename Keep>
Tip_snapping_statistics snap_quads_to_input_tips(const TriangleMesh& input, const QuadMesh& qmesh,
                                                 const QuadFeatureMap& qfeature, double tolerance,
                                                 const Smooth& smooth, const Keep& keep, bool verbose)
{
  typedef boost::graph_traits<QuadMesh> QTr;
  typedef typename QTr::vertex_descriptor qvertex;
  typedef typename QTr::halfedge_descriptor qhalfedge;
  typedef typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef typename K::Vector_3 Vector;
  typedef typename K::Triangle_3 Triangle;
  typedef CGAL::AABB_triangle_primitive<K, typename std::vector<Triangle>::const_iterator> Quad_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Quad_primitive>> Quad_tree;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh> Tri_primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Tri_primitive>> Tri_tree;

  Tip_snapping_statistics st;
  CGAL::Real_timer timer;
  timer.start();
  if(!(tolerance > 0.) || faces(input).first == faces(input).second || is_empty(qmesh)) return st;
  const auto ivpm = get(CGAL::vertex_point, input);
  Tri_tree surface(faces(input).first, faces(input).second, input);
  surface.accelerate_distance_queries();

  // the largest distance both ways between `input` and `m`, and the input vertices farther than
  // `tolerance` from `m` with their distances
  // a quad mesh as the measures below see it: its polygon soup and that soup's triangles (made once per
  // mesh, for both measures)
  struct Soup
  {
    std::vector<Point> points;
    quality::Index_polygons polygons;
    std::vector<Triangle> triangles;
  };
  auto soup_of = [](const QuadMesh& m) {
    Soup s;
    quality::mesh_to_soup(m, get(CGAL::vertex_point, m), s.points, s.polygons);
    s.triangles = quality::triangulate_soup<K>(s.points, s.polygons);
    return s;
  };
  // (and where it is attained, into `worst_at`: an input vertex or a sample of the quads)
  Point worst_at = CGAL::ORIGIN;
  auto measure = [&](const Soup& m, std::vector<std::pair<double, Point>>* far) {
    const std::vector<Triangle>& triangles = m.triangles;
    double worst = 0.;
    if(triangles.empty()) return worst;
    Quad_tree quads(triangles.begin(), triangles.end());
    quads.accelerate_distance_queries();
    Point at = CGAL::ORIGIN;
    for(auto v : vertices(input))
    {
      if(halfedge(v, input) == boost::graph_traits<TriangleMesh>::null_halfedge()) continue; // isolated: no surface
      const double d = std::sqrt(CGAL::to_double(quads.squared_distance(get(ivpm, v))));
      if(d > worst) { worst = d; at = get(ivpm, v); }
      if(far != nullptr && d > tolerance) far->emplace_back(d, get(ivpm, v));
    }
    quality::for_each_soup_sample(m.points, m.polygons, triangles, [&](const Point& s) {
      const double d = std::sqrt(CGAL::to_double(surface.squared_distance(s)));
      if(d > worst) { worst = d; at = s; }
    });
    worst_at = at;
    return worst;
  };
  // for each of `tips`, the largest distance to the input of the samples of `m` (as in `measure`) farther
  // than `tolerance` whose nearest tip it is, within `radius`
  auto stray_near_tips = [&](const Soup& m, const std::vector<Point>& tips, double radius) {
    std::vector<double> worst(tips.size(), 0.);
    quality::for_each_soup_sample(m.points, m.polygons, m.triangles, [&](const Point& s) {
      std::size_t nearest = tips.size();
      double nearest_d = radius * radius;
      for(std::size_t i = 0; i < tips.size(); ++i) {
        const double d = CGAL::to_double(CGAL::squared_distance(s, tips[i]));
        if(d < nearest_d) { nearest_d = d; nearest = i; }
      }
      if(nearest == tips.size()) return;
      const double d = std::sqrt(CGAL::to_double(surface.squared_distance(s)));
      if(d > tolerance) worst[nearest] = (std::max)(worst[nearest], d);
    });
    return worst;
  };
  std::vector<std::pair<double, Point>> far;
  Soup start_soup = soup_of(qmesh); // of the quads a round starts from (`qmesh`, then the last round kept)
  st.distance_before = st.distance_after = measure(start_soup, &far);
  Point best_at = worst_at; // where the distance of the quads kept is attained
  st.candidates = far.size();
  // farthest first; ties by position, so that the order does not depend on the sort
  auto farther = [](const std::pair<double, Point>& a, const std::pair<double, Point>& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  };
  std::sort(far.begin(), far.end(), farther);

  // the quads of a round, with their constrained edges and held vertices (the maps are made once the mesh
  // has its address, and go before it)
  typedef decltype(get(CGAL::dynamic_edge_property_t<bool>(), std::declval<QuadMesh&>())) Edge_flags;
  typedef decltype(get(CGAL::dynamic_vertex_property_t<bool>(), std::declval<QuadMesh&>())) Vertex_flags;
  struct Round_mesh
  {
    QuadMesh mesh;
    std::optional<Edge_flags> feature;
    std::optional<Vertex_flags> fixed;
  };
  // the normal of the input at a point of it (of the face nearest to it)
  auto input_normal = [&](const Point& p) {
    const auto f = surface.closest_point_and_primitive(p).second;
    const auto h = halfedge(f, input);
    return CGAL::cross_product(get(ivpm, target(h, input)) - get(ivpm, source(h, input)),
                               get(ivpm, target(next(h, input), input)) - get(ivpm, source(h, input)));
  };
  const std::size_t inverted_before = quad_mesh_quality(qmesh).non_positive_scaled_jacobian;
  std::unique_ptr<Round_mesh> best; // the last round kept
  std::set<Point> held;             // the tips of the rounds kept
  std::set<Point> dropped;          // the tips whose quads strayed from the input
  unsigned retries = 0;             // of the current round
  double best_distance = st.distance_before;
  // a round first takes tips one mean quad edge length apart; if that is not closer, two
  unsigned round = 0;
  bool sparse = false;
  // a copy of the last quads kept (at first `qmesh`), its vertices on the tips kept so far held
  auto start_attempt = [&]() {
    auto attempt = std::make_unique<Round_mesh>();
    QuadMesh& copy = attempt->mesh;
    attempt->feature.emplace(get(CGAL::dynamic_edge_property_t<bool>(), copy));
    attempt->fixed.emplace(get(CGAL::dynamic_vertex_property_t<bool>(), copy));
    if(best) copy_quad_mesh(best->mesh, *best->feature, copy, *attempt->feature);
    else copy_quad_mesh(qmesh, qfeature, copy, *attempt->feature);
    auto cvpm = get(CGAL::vertex_point, copy);
    for(qvertex v : vertices(copy)) put(*attempt->fixed, v, held.count(get(cvpm, v)) > 0);
    return attempt;
  };
  while(round < max_tip_rounds && !far.empty())
  {
    std::unique_ptr<Round_mesh> attempt = start_attempt();
    QuadMesh& copy = attempt->mesh;
    const Edge_flags& copy_feature = *attempt->feature;
    const Vertex_flags& fixed = *attempt->fixed;
    auto cvpm = get(CGAL::vertex_point, copy);

    // the quad vertices that may move onto a tip, with their normals
    double length = 0.;
    std::size_t edge_count = 0;
    for(auto e : edges(copy))
    {
      length += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(cvpm, source(e, copy)), get(cvpm, target(e, copy)))));
      ++edge_count;
    }
    const double reach = 2. * length / double((std::max)(edge_count, std::size_t(1)));
    const double separation = sparse ? reach : 0.5 * reach;
    std::vector<std::pair<qvertex, Vector>> movable;
    for(qvertex v : vertices(copy))
    {
      bool free = !is_border(v, copy) && !get(fixed, v);
      const Point& p = get(cvpm, v);
      Vector normal = NULL_VECTOR;
      for(qhalfedge h : halfedges_around_target(v, copy))
      {
        if(get(copy_feature, edge(h, copy))) free = false;
        if(is_border(h, copy)) continue;
        normal = normal + CGAL::cross_product(get(cvpm, target(next(h, copy), copy)) - p, get(cvpm, source(h, copy)) - p);
      }
      if(free) movable.emplace_back(v, normal);
    }

    std::vector<Point> tips;
    std::vector<double> tip_distances; // from the quads before the round
    std::vector<qvertex> snapped_vertices;
    for(const auto& candidate : far)
    {
      if(held.size() + tips.size() >= max_tip_snaps) break;
      const Point& tip = candidate.second;
      if(dropped.count(tip) > 0) continue;
      bool close = false;
      for(const Point& t : tips)
        if(CGAL::to_double(CGAL::squared_distance(t, tip)) < separation * separation) { close = true; break; }
      if(close) continue;
      const Vector n = input_normal(tip);
      std::size_t best_vertex = movable.size();
      double best_d = reach * reach;
      for(std::size_t i = 0; i < movable.size(); ++i)
      {
        if(get(fixed, movable[i].first) || CGAL::to_double(movable[i].second * n) <= 0.) continue;
        const double d = CGAL::to_double(CGAL::squared_distance(get(cvpm, movable[i].first), tip));
        if(d < best_d) { best_d = d; best_vertex = i; }
      }
      if(best_vertex == movable.size()) continue;
      snapped_vertices.push_back(movable[best_vertex].first);
      put(cvpm, movable[best_vertex].first, tip);
      put(fixed, movable[best_vertex].first, true);
      tips.push_back(tip);
      tip_distances.push_back(candidate.first);
    }
    st.snapped += tips.size();
    if(tips.empty()) break; // (then none at a larger separation either)
    // Only the quads near the tips are smoothed again: the vertices farther than `tip_smoothing_rings`
    // rings from every tip are held, so the rest of the quads stay as they were (smoothed again
    // everywhere, they could get worse anywhere: truck, with --refine-layout, had an inverted quad a
    // unit away from its two tips, and the round was refused for it).
    {
      std::set<qvertex> near;
      std::vector<qvertex> ring;
      for(qvertex v : snapped_vertices)
        if(near.insert(v).second) ring.push_back(v);
      for(unsigned r = 0; r < tip_smoothing_rings && !ring.empty(); ++r)
      {
        std::vector<qvertex> next_ring;
        for(qvertex v : ring)
          for(qhalfedge h : halfedges_around_target(v, copy))
            if(near.insert(source(h, copy)).second) next_ring.push_back(source(h, copy));
        ring.swap(next_ring);
      }
      for(qvertex v : vertices(copy))
        if(near.count(v) == 0) put(fixed, v, true);
    }
    smooth(copy, copy_feature, fixed);
    Soup copy_soup = soup_of(copy);

    // the tips whose quads around now stray farther from the input than before are left out
    if(retries < max_tip_retries)
    {
      const double radius = 0.5 * reach * double(tip_smoothing_rings);
      const std::vector<double> stray_before = stray_near_tips(start_soup, tips, radius);
      const std::vector<double> stray_after = stray_near_tips(copy_soup, tips, radius);
      std::vector<Point> strayed;
      for(std::size_t i = 0; i < tips.size(); ++i)
        if(stray_after[i] > (std::max)(stray_before[i], tip_distances[i])) strayed.push_back(tips[i]);
      if(!strayed.empty() && strayed.size() < tips.size())
      {
        if(verbose)
          std::cerr << "[tips] round " << round + 1 << (sparse ? " (sparse)" : "") << ": the quads around "
                    << strayed.size() << " of " << tips.size()
                    << " tips strayed from the input; tried again without them" << std::endl;
        dropped.insert(strayed.begin(), strayed.end());
        st.dropped += strayed.size();
        ++retries;
        continue;
      }
    }

    std::vector<std::pair<double, Point>> next_far;
    const double after = measure(copy_soup, &next_far);
    const std::size_t inverted_after = quad_mesh_quality(copy).non_positive_scaled_jacobian;
    const bool closer = after < best_distance && inverted_after <= inverted_before;
    if(verbose)
      std::cerr << "[tips] round " << round + 1 << (sparse ? " (sparse)" : "") << ": " << far.size()
                << " input vertices farther than " << tolerance << " from the quads, " << tips.size()
                << " quad vertices put onto tips: distance " << best_distance << " -> " << after << ", "
                << inverted_after << " quads inverted (" << inverted_before << " before)"
                << (closer ? ", kept" : ", not kept") << std::endl;
    retries = 0;
    if(!closer)
    {
      if(sparse) break;
      sparse = true;
      continue;
    }
    ++round;
    sparse = false;
    ++st.rounds;
    best_distance = after;
    best_at = worst_at;
    held.insert(tips.begin(), tips.end());
    best = std::move(attempt);
    start_soup = std::move(copy_soup);
    far = std::move(next_far);
    std::sort(far.begin(), far.end(), farther);
  }
  // The rounds smoothed the quads around their tips only; all the quads are then smoothed once more with
  // the tips held, which the rest of the mesh gains from (the mean scaled Jacobian and angle deviation of
  // the 8 development meshes with tips), kept only with no more inverted quads (it can invert a quad
  // anywhere, which must not cost the tips) and within the tolerance of the input or at most 1% farther
  // than without it (any smoothing moves the largest distance at the samples a little: spot 3.7%, truck
  // 0.01%).
  if(best)
  {
    std::unique_ptr<Round_mesh> attempt = start_attempt();
    QuadMesh& copy = attempt->mesh;
    smooth(copy, *attempt->feature, *attempt->fixed);
    const double after = measure(soup_of(copy), nullptr);
    const std::size_t inverted_after = quad_mesh_quality(copy).non_positive_scaled_jacobian;
    st.smoothed_all = after <= (std::max)(tolerance, 1.01 * best_distance) && inverted_after <= inverted_before;
    if(verbose)
      std::cerr << "[tips] all the quads smoothed again: distance " << best_distance << " -> " << after << ", "
                << inverted_after << " quads inverted (" << inverted_before << " before)"
                << (st.smoothed_all ? ", kept" : ", not kept") << std::endl;
    if(st.smoothed_all)
    {
      best_distance = after;
      best_at = worst_at;
      best = std::move(attempt);
    }
  }
  // Last, where the quads still stray farther than the tolerance from the input: the smoothing projects
  // them onto the remeshed triangles, which can themselves be that far from the input where it bends
  // tightly (elephant's toes: 0.52% of the diagonal). The free quad vertices farther than half the
  // tolerance from the input move onto their nearest point of it, farthest first, or a part of the way
  // (3/4, 1/2, 1/4) if the whole would turn a quad around over (its normal against the one before) or
  // leave one with a scaled Jacobian under half of what it had and under 0.2; kept if closer, with no
  // more inverted quads (measured only if the largest distance is attained near a vertex moved).
  if(best_distance > tolerance)
  {
    std::unique_ptr<Round_mesh> attempt = start_attempt();
    QuadMesh& copy = attempt->mesh;
    auto cvpm = get(CGAL::vertex_point, copy);
    typedef typename QTr::face_descriptor qface;
    auto corners = [&](qface f, std::array<Point, 4>& q) {
      std::size_t k = 0;
      for(qvertex w : vertices_around_face(halfedge(f, copy), copy)) {
        if(k == 4) return false;
        q[k++] = get(cvpm, w);
      }
      return k == 4;
    };
    auto quad_normal = [](const std::array<Point, 4>& q) { return CGAL::cross_product(q[2] - q[0], q[3] - q[1]); };
    // the candidates, farthest first (a pulled vertex changes the quads of its neighbours)
    struct Pull { double distance; qvertex v; Point target; }; // the target: the closest input point
    std::vector<Pull> pulls;
    for(qvertex v : vertices(copy))
    {
      if(is_border(v, copy) || get(*attempt->fixed, v)) continue;
      bool free = true;
      for(qhalfedge h : halfedges_around_target(v, copy)) free = free && !get(*attempt->feature, edge(h, copy));
      if(!free) continue;
      const Point target = surface.closest_point(get(cvpm, v));
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(cvpm, v), target)));
      if(d > 0.5 * tolerance) pulls.push_back(Pull{d, v, target});
    }
    std::sort(pulls.begin(), pulls.end(), [](const Pull& x, const Pull& y) {
      return x.distance != y.distance ? x.distance > y.distance : x.v < y.v; });
    std::vector<CGAL::Bbox_3> changed; // around the vertices pulled, grown by the largest distance
    for(const Pull& pull : pulls)
    {
      const qvertex v = pull.v;
      const Point p = get(cvpm, v); // (only v moves in its turn: its closest input point is still `target`)
      const Point& target = pull.target;
      std::vector<std::pair<Vector, double>> before; // of the quads around v: normal, scaled Jacobian
      std::array<Point, 4> q;
      bool quads = true;
      for(qhalfedge h : halfedges_around_target(v, copy)) {
        if(is_border(h, copy)) continue;
        if(!corners(face(h, copy), q)) { quads = false; break; }
        before.emplace_back(quad_normal(q), quality::quad_scaled_jacobian(q));
      }
      if(!quads) continue;
      // all the way if the quads around allow it, else a part of it
      bool fine = false;
      for(double t : {1., 0.75, 0.5, 0.25})
      {
        put(cvpm, v, p + t * (target - p));
        std::size_t i = 0;
        fine = true;
        for(qhalfedge h : halfedges_around_target(v, copy)) {
          if(is_border(h, copy)) continue;
          corners(face(h, copy), q);
          fine = fine && CGAL::to_double(quad_normal(q) * before[i].first) > 0. &&
                 quality::quad_scaled_jacobian(q) >= (std::min)(0.5 * before[i].second, 0.2);
          ++i;
        }
        if(fine) break;
      }
      if(!fine) { put(cvpm, v, p); continue; }
      ++st.pulled;
      // where the distances can change: the quads around v, before and after, and as far again as the
      // largest distance (an input vertex that far may come closer to them)
      CGAL::Bbox_3 box = p.bbox();
      for(qhalfedge h : halfedges_around_target(v, copy))
        if(!is_border(h, copy))
          for(qvertex w : vertices_around_face(h, copy)) box += get(cvpm, w).bbox();
      const double r = best_distance;
      changed.emplace_back(box.xmin() - r, box.ymin() - r, box.zmin() - r, box.xmax() + r, box.ymax() + r, box.zmax() + r);
    }
    // only if the largest distance is attained where something changed can it fall
    const CGAL::Bbox_3 worst = best_at.bbox();
    const bool may_fall = std::any_of(changed.begin(), changed.end(), [&](const CGAL::Bbox_3& b) {
      return CGAL::do_overlap(b, worst); });
    if(st.pulled > 0 && !may_fall && verbose)
      std::cerr << "[tips] " << st.pulled << " quad vertices farther than " << 0.5 * tolerance
                << " from the input could be pulled onto it, none near the largest distance: left" << std::endl;
    if(st.pulled > 0 && may_fall)
    {
      const double after = measure(soup_of(copy), nullptr);
      const std::size_t inverted_after = quad_mesh_quality(copy).non_positive_scaled_jacobian;
      st.pulled_kept = after < best_distance && inverted_after <= inverted_before;
      if(verbose)
        std::cerr << "[tips] " << st.pulled << " quad vertices farther than " << 0.5 * tolerance
                  << " from the input pulled onto it: distance " << best_distance << " -> " << after << ", "
                  << inverted_after << " quads inverted (" << inverted_before << " before)"
                  << (st.pulled_kept ? ", kept" : ", not kept") << std::endl;
      if(st.pulled_kept)
      {
        best_distance = after;
        best = std::move(attempt);
      }
    }
  }
  if(best)
  {
    st.kept = true;
    st.distance_after = best_distance;
    keep(best->mesh, *best->feature);
  }
  st.seconds = timer.time();
  if(verbose)
    std::cerr << "[tips] " << st.candidates << " input vertices farther than " << tolerance << " from the quads, "
              << st.rounds << " round(s) kept, " << held.size() << " quad vertices on tips: distance "
              << st.distance_before << " -> " << st.distance_after << " (" << st.seconds << " s)" << std::endl;
  return st;
}

} // namespace internal
} // namespace Quad_remeshing
} // namespace CGAL

#endif // CGAL_QUAD_REMESHING_INTERNAL_PIPELINE_TIP_SNAPPING_H
