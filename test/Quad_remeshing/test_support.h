// Helpers shared by the test files.
#ifndef CGAL_QUAD_REMESHING_TEST_SUPPORT_H
#define CGAL_QUAD_REMESHING_TEST_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <string>

namespace qr_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3                                     Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;

/// path of a mesh bundled in data/meshes
inline std::string data_file(const std::string& name) { return std::string(QR_TEST_DATA_DIR) + "/" + name; }

/// a path for files written by the tests
inline std::string output_file(const std::string& name) { return std::string(QR_TEST_BINARY_DIR) + "/" + name; }

} // namespace qr_test

#endif
