// libFuzzer target over the whole pipeline on tiny meshes. The bytes make a triangle soup: the first
// byte gives the number of vertices (4 to 12), then 3 bytes per vertex (coordinates on a 16^3 integer
// grid, so coplanar, collinear and coincident points are frequent), then 3 bytes per triangle (vertex
// indices modulo the number of vertices, at most 24 triangles). The soup goes through read_and_repair()
// and quad_remesh() at a coarse density (a tenth of the bounding-box diagonal).
// Allowed outcomes: a Bad_input refusal, a documented stage failure (std::invalid_argument or
// std::runtime_error with a reason), or a valid, non-empty, pure-quad mesh. Anything else (a crash, a
// sanitizer report, another exception such as std::logic_error, a hang, a leak) is a finding.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Quad_remeshing/IO.h>
#include <CGAL/Quad_remeshing/internal/bbox_diagonal.h>
#include <CGAL/Quad_remeshing/quad_remesh.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  if(size < 1) return 0;
  const std::size_t n = 4 + data[0] % 9;
  if(size < 1 + 3 * n + 3) return 0;
  const std::size_t triangles = (std::min)(std::size_t(24), (size - 1 - 3 * n) / 3);
  const std::string path = "/tmp/qr_fuzz_pipeline_" + std::to_string(getpid()) + ".off";
  {
    std::ofstream out(path);
    out << "OFF\n" << n << ' ' << triangles << " 0\n";
    for(std::size_t i = 0; i < n; ++i)
      out << int(data[1 + 3 * i] % 16) << ' ' << int(data[2 + 3 * i] % 16) << ' ' << int(data[3 + 3 * i] % 16) << '\n';
    const std::uint8_t* t = data + 1 + 3 * n;
    for(std::size_t f = 0; f < triangles; ++f)
      out << "3 " << t[3 * f] % n << ' ' << t[3 * f + 1] % n << ' ' << t[3 * f + 2] % n << '\n';
  }
  Mesh m;
  bool refused = false;
  try {
    CGAL::Quad_remeshing::read_and_repair(path, m);
  } catch(const CGAL::Quad_remeshing::Bad_input&) {
    refused = true;
  }
  std::remove(path.c_str());
  if(refused) return 0;
  const double diagonal = CGAL::Quad_remeshing::internal::bbox_diagonal(CGAL::Polygon_mesh_processing::bbox(m));
  Mesh q;
  try {
    CGAL::Quad_remeshing::quad_remesh(m, q, CGAL::Quad_remeshing::parameters::quad_edge_length(0.1 * diagonal));
  } catch(const std::invalid_argument&) {
    return 0;
  } catch(const std::runtime_error&) {
    return 0;
  }
  if(num_faces(q) == 0 || !q.is_valid(false)) __builtin_trap();
  for(auto f : faces(q))
    if(degree(f, q) != 4) __builtin_trap();
  return 0;
}
