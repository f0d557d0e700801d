// libFuzzer target over the mesh readers: the first byte picks the format, the rest is the file.
// Any input must end in a repaired mesh or a Bad_input exception: never a crash, a hang or a leak.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Quad_remeshing/IO.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  if(size < 1 || size > 20000) return 0;
  static const char* extensions[] = {"off", "obj", "ply", "stl"};
  const std::string path = "/tmp/qr_fuzz_" + std::to_string(getpid()) + "." + extensions[data[0] % 4];
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  Mesh m;
  try {
    CGAL::Quad_remeshing::read_and_repair(path, m);
    if(!m.is_valid(false)) __builtin_trap(); // a repaired mesh must be a valid halfedge structure
  } catch(const CGAL::Quad_remeshing::Bad_input&) {
  }
  std::remove(path.c_str());
  return 0;
}
