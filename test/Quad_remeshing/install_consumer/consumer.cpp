// Uses the installed headers: reads and repairs a mesh, writes the report.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/quad_remeshing.h>

#include <iostream>

int main(int argc, char** argv)
{
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  if(argc < 2) return 2;
  Mesh m;
  const auto stats = CGAL::Quad_remeshing::read_and_repair(argv[1], m);
  stats.report().write_json(std::cout, -1);
  std::cout << "\n";
  return num_faces(m) > 0 ? 0 : 1;
}
