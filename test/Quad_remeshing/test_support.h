// Helpers shared by the test files.
#ifndef CGAL_QUAD_REMESHING_TEST_SUPPORT_H
#define CGAL_QUAD_REMESHING_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <string>

namespace qr_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3                                     Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;

/// path of a mesh bundled in data/meshes
inline std::string data_file(const std::string& name) { return std::string(QR_TEST_DATA_DIR) + "/" + name; }

/// a path for files written by the tests
inline std::string output_file(const std::string& name) { return std::string(QR_TEST_BINARY_DIR) + "/" + name; }

/// The quads of `q` flipped over in the surface: the normal of the quad's diagonals is turned by more than
/// 120 degrees from that of every quad across one of its edges. The scaled Jacobian, measured in the
/// quad's own plane, does not see them: a convex quad flipped over is as good as any by that measure.
inline std::size_t flipped_over_quads(const Mesh& q)
{
  auto normal = [&](Mesh::Face_index f) {
    std::vector<Point_3> c;
    for(auto v : CGAL::vertices_around_face(q.halfedge(f), q)) c.push_back(q.point(v));
    return c.size() == 4 ? CGAL::cross_product(c[2] - c[0], c[3] - c[1]) : Kernel::Vector_3(0, 0, 0);
  };
  std::size_t flipped = 0;
  for(auto f : q.faces())
  {
    const Kernel::Vector_3 n = normal(f);
    std::size_t neighbours = 0, against = 0;
    for(auto h : CGAL::halfedges_around_face(q.halfedge(f), q))
    {
      if(q.is_border(q.opposite(h))) continue;
      const Kernel::Vector_3 m = normal(q.face(q.opposite(h)));
      ++neighbours;
      if(n * m < -0.5 * std::sqrt(n.squared_length() * m.squared_length())) ++against;
    }
    if(neighbours > 0 && against == neighbours) ++flipped;
  }
  return flipped;
}

/// A unit square plate with a square hole (0.2..0.5 x 0.3..0.6) and a cap triangle P Q R: P = (0.5, 0.6) and
/// Q = (0.5, 0.3) are the hole's right corners, R = (0.504, 0.1) lies almost on the line PQ beyond Q (the angle
/// at Q is about 177 degrees). Q is lifted by `lift`, which tilts the cap so that its three edges are sharp:
/// PQ is a border, PR and QR have dihedral angles of about 65 degrees. It reproduces truck's sliver next to a
/// window (input vertices 1972, 1976 and 1982, a cap 0.0018 wide whose edges are all features).
inline Mesh cap_plate(double lift = 0.005)
{
  Mesh m;
  const Point_3 p[9] = {Point_3(0, 0, 0),   Point_3(1, 0, 0),      Point_3(1, 1, 0),
                        Point_3(0, 1, 0),   Point_3(0.2, 0.3, 0),  Point_3(0.5, 0.3, lift),
                        Point_3(0.5, 0.6, 0), Point_3(0.2, 0.6, 0), Point_3(0.504, 0.1, 0)};
  Mesh::Vertex_index v[9];
  for(int i = 0; i < 9; ++i) v[i] = m.add_vertex(p[i]);
  const int f[10][3] = {{6, 5, 8}, {8, 1, 2}, {8, 2, 6}, {6, 2, 3}, {6, 3, 7},
                        {7, 3, 0}, {7, 0, 4}, {4, 0, 8}, {0, 1, 8}, {4, 8, 5}};
  for(const auto& t : f) m.add_face(v[t[0]], v[t[1]], v[t[2]]);
  return m;
}

/// Two parts: fandisk and, 0.1 beside it along x, truck's steering wheel (a rim with three spokes 0.03 wide,
/// 0.21 across: 7% of the whole diagonal; at fandisk's quad edge length, 0.09, its spokes are one quad wide).
inline Mesh fandisk_and_steering_wheel()
{
  Mesh m, wheel;
  if(!CGAL::IO::read_polygon_mesh(data_file("fandisk.off"), m) ||
     !CGAL::IO::read_polygon_mesh(data_file("truck_steering_wheel.off"), wheel))
    throw std::runtime_error("fandisk_and_steering_wheel: cannot read the bundled meshes");
  const CGAL::Bbox_3 a = CGAL::Polygon_mesh_processing::bbox(m), b = CGAL::Polygon_mesh_processing::bbox(wheel);
  const Kernel::Vector_3 shift(a.xmax() + 0.1 - b.xmin(), -b.ymin(), -b.zmin());
  for(auto v : wheel.vertices()) wheel.point(v) = wheel.point(v) + shift;
  CGAL::copy_face_graph(wheel, m);
  return m;
}

} // namespace qr_test

#endif
