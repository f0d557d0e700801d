// Reading and repairing input meshes: bundled meshes (clean and nasty) and malformed files.
#include "test_support.h"

#include <CGAL/Quad_remeshing/IO.h>

#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

namespace {

namespace QR = CGAL::Quad_remeshing;
using qr_test::Mesh;

std::string write_text(const std::string& name, const std::string& content)
{
  const std::string path = qr_test::output_file(name);
  std::ofstream out(path);
  out << content;
  return path;
}

// reads `path`, which must give a tetrahedron (a closed mesh of four vertices and four faces)
QR::Repair_statistics read_tetrahedron(const std::string& path)
{
  Mesh m;
  const QR::Repair_statistics s = QR::read_and_repair(path, m);
  BOOST_TEST(num_vertices(m) == 4u);
  BOOST_TEST(num_faces(m) == 4u);
  BOOST_TEST(CGAL::is_closed(m));
  return s;
}

bool throws_bad_input(const std::string& path, const std::string& expected_part)
{
  Mesh m;
  try {
    QR::read_and_repair(path, m);
  } catch(const QR::Bad_input& e) {
    const std::string msg = e.what();
    BOOST_TEST_MESSAGE(msg);
    return msg.find(expected_part) != std::string::npos;
  }
  return false;
}

} // namespace

BOOST_AUTO_TEST_SUITE(io)

BOOST_AUTO_TEST_CASE(clean_mesh_is_unchanged)
{
  Mesh m;
  const QR::Repair_statistics s = QR::read_and_repair(qr_test::data_file("fandisk.off"), m);
  BOOST_TEST(s.input_vertices == 6475u);
  BOOST_TEST(s.input_faces == 12946u);
  BOOST_TEST(!s.repaired());
  BOOST_TEST(num_faces(m) == 12946u);
  BOOST_TEST(s.components == 1u);
  BOOST_TEST(s.boundary_cycles == 0u);
  BOOST_TEST(CGAL::is_triangle_mesh(m));
  BOOST_TEST(CGAL::is_closed(m));
  BOOST_TEST(s.report().find("V")->number() == 6475.);
}

BOOST_AUTO_TEST_CASE(nasty_meshes_are_repaired)
{
  // draco_test_nm: 2 non-manifold vertices and 17 unreferenced vertices.
  Mesh m;
  QR::Repair_statistics s = QR::read_and_repair(qr_test::data_file("draco_test_nm.off"), m);
  BOOST_TEST(s.removed_isolated_points == 17u);
  BOOST_TEST(s.duplicated_points >= 2u);
  BOOST_TEST(s.repaired());
  BOOST_TEST(m.is_valid());
  BOOST_TEST(CGAL::is_triangle_mesh(m));

  // angle_block: 33 non-manifold vertices, slivers.
  Mesh a;
  s = QR::read_and_repair(qr_test::data_file("angle_block.off"), a);
  BOOST_TEST(s.duplicated_points >= 33u);
  BOOST_TEST(a.is_valid());
  BOOST_TEST(num_faces(a) > 600u);
}

BOOST_AUTO_TEST_CASE(every_bundled_mesh_loads)
{
  for(const char* name : {"abc_00000005.off", "abc_00000008.off", "plate_holes.off", "spot.off", "fertility.off",
                          "hemisphere.off", "xyz_cube_20mm.off", "lego.off"})
  {
    Mesh m;
    const QR::Repair_statistics s = QR::read_and_repair(qr_test::data_file(name), m);
    BOOST_TEST_INFO(name);
    BOOST_TEST(m.is_valid());
    BOOST_TEST(num_faces(m) > 0u);
    BOOST_TEST(s.components == 1u);
  }
}

BOOST_AUTO_TEST_CASE(other_formats_round_trip)
{
  Mesh m;
  QR::read_and_repair(qr_test::data_file("xyz_cube_20mm.off"), m);
  for(const char* ext : {"obj", "ply", "off"})
  {
    const std::string path = qr_test::output_file(std::string("io_round_trip.") + ext);
    QR::write_mesh(path, m);
    Mesh r;
    const QR::Repair_statistics s = QR::read_and_repair(path, r);
    BOOST_TEST_INFO(ext);
    BOOST_TEST(num_faces(r) == num_faces(m));
    BOOST_TEST(num_vertices(r) == num_vertices(m));
    BOOST_TEST(!s.repaired());
  }
  // STL is a soup: reading welds the points back into the same mesh.
  const std::string stl = qr_test::output_file("io_round_trip.stl");
  BOOST_TEST(CGAL::IO::write_polygon_mesh(stl, m, CGAL::parameters::stream_precision(17)));
  Mesh r;
  const QR::Repair_statistics s = QR::read_and_repair(stl, r);
  BOOST_TEST(num_faces(r) == num_faces(m));
  BOOST_TEST(num_vertices(r) == num_vertices(m));
  BOOST_TEST(s.components == 1u);
}

BOOST_AUTO_TEST_CASE(doubled_faces_are_merged)
{
  // A tetrahedron whose every face also appears reversed (like chair_doublesided).
  const std::string path = write_text("io_doubled.off",
    "OFF\n4 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"
    "3 0 1 2\n3 0 3 1\n3 1 3 2\n3 0 2 3\n");
  BOOST_TEST(read_tetrahedron(path).removed_duplicate_faces == 4u);
}

BOOST_AUTO_TEST_CASE(coloured_off_reads_without_its_colours)
{
  // COFF whose second vertex has no colour: CGAL 5.5's scanner read that colour past the end of the line's
  // numbers (a heap overflow, found by fuzzing). Colours are not used: the mesh is the tetrahedron.
  const std::string path = write_text("io_coff.off",
    "# a tetrahedron\nCOFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0\n0 1 0 0 0 255 255\n0 0 1 9 9 9 255\n"
    "3 0 2 1 10 10 10\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  Mesh m;
  const QR::Repair_statistics s = QR::read_and_repair(path, m);
  BOOST_TEST(s.input_vertices == 4u);
  BOOST_TEST(s.input_faces == 4u);
  BOOST_TEST(num_faces(m) == 4u);
  BOOST_TEST(CGAL::is_closed(m));
  bool has_second_vertex = false;
  for(auto v : vertices(m)) has_second_vertex = has_second_vertex || m.point(v) == qr_test::Point_3(1, 0, 0);
  BOOST_TEST(has_second_vertex);
}

namespace {

void append_be32(std::string& s, std::uint32_t x)
{
  for(int k = 3; k >= 0; --k) s.push_back(char((x >> (8 * k)) & 0xff));
}

void append_float(std::string& s, float f)
{
  std::uint32_t x;
  std::memcpy(&x, &f, 4);
  append_be32(s, x);
}

// a binary OFF tetrahedron (big-endian); with `normals` the keyword is NOFF and every vertex carries one,
// so that the face scan of the reader's guard must step over them to find the faces
std::string binary_tetrahedron(bool normals, std::uint32_t first_face_count = 3)
{
  std::string s = normals ? "NOFF BINARY\n" : "OFF BINARY\n";
  for(std::uint32_t x : {4u, 4u, 0u}) append_be32(s, x);
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for(const auto& q : p) {
    for(float c : q) append_float(s, c);
    if(normals) for(float c : q) append_float(s, c - 0.25f);
  }
  const std::uint32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  for(int i = 0; i < 4; ++i) {
    append_be32(s, i == 0 ? first_face_count : 3u);
    for(std::uint32_t v : f[i]) append_be32(s, v);
  }
  return s;
}

} // namespace

BOOST_AUTO_TEST_CASE(binary_off_reads_and_its_face_counts_are_checked)
{
  for(bool normals : {false, true})
    BOOST_TEST(read_tetrahedron(write_text(normals ? "io_binary_normals.off" : "io_binary.off",
                                           binary_tetrahedron(normals))).input_faces == 4u);
  // the reader allocates a face's vertex count before reading its indices: 2^31 - 16 of them made it take
  // 16 GiB for this 135-byte file
  BOOST_TEST(throws_bad_input(write_text("io_binary_huge_face.off", binary_tetrahedron(false, 0x7ffffff0u)),
                              "face 0 of the binary OFF file claims 2147483632"));
  BOOST_TEST(throws_bad_input(write_text("io_binary_huge_face_normals.off", binary_tetrahedron(true, 0x7ffffff0u)),
                              "face 0 of the binary OFF file claims"));
  BOOST_TEST(throws_bad_input(write_text("io_binary_negative_face.off", binary_tetrahedron(false, 0xfffffffdu)),
                              "face 0 of the binary OFF file claims -3"));
  // found by fuzzing: the reader takes a face count cut short by the end of the file as it comes
  BOOST_TEST(throws_bad_input(write_text("io_binary_cut_count.off", binary_tetrahedron(true).substr(0, 122)),
                              "ends before the vertex count of face 0"));
  BOOST_TEST(throws_bad_input(write_text("io_binary_cut_count2.off", binary_tetrahedron(false).substr(0, 120)),
                              "ends before the vertex count of face 3"));
  // found by fuzzing: the header parser ends the keyword at any character that is not a letter or a digit
  // and consumes it, so NOFF"BINARY is binary and "cte" 1.7 billion vertices
  BOOST_TEST(throws_bad_input(write_text("io_binary_after_quote.off", std::string("NOFF\"BINARY\ncte\0\0\0\0\4\0\0\0\0", 24)),
                              "cannot fit"));
}

BOOST_AUTO_TEST_CASE(textured_off_reads_without_its_texture_coordinates)
{
  // STOFF whose first vertex has no texture coordinates: CGAL 5.5's ASCII scanner read them past the end
  // of the line's numbers (found by fuzzing). They are not used: the mesh is the tetrahedron.
  const std::string path = write_text("io_stoff.off",
    "STOFF\n4 4 0\n0 0 0\n1 0 0 0.5 0.5\n0 1 0 0 1\n0 0 1 1 0\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  BOOST_TEST(read_tetrahedron(path).input_vertices == 4u);
  // the parser refuses STSTOFF; leaving out its first ST would make a keyword it takes, with the problem
  // above (found by fuzzing)
  BOOST_TEST(throws_bad_input(write_text("io_ststoff.off", "STSTOFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                                           "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"),
                              "cannot parse"));
}

BOOST_AUTO_TEST_CASE(bad_files_are_refused_with_a_message)
{
  BOOST_TEST(throws_bad_input(qr_test::output_file("does_not_exist.off"), "cannot open"));
  BOOST_TEST(throws_bad_input(write_text("io_empty.off", ""), "empty"));
  BOOST_TEST(throws_bad_input(write_text("io_garbage.off", "this is not a mesh\n"), "cannot parse"));
  BOOST_TEST(throws_bad_input(write_text("io_noface.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), "no face"));
  BOOST_TEST(throws_bad_input(write_text("io_nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"), "non-finite"));
  BOOST_TEST(throws_bad_input(write_text("io_inf.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"), ""));
  BOOST_TEST(throws_bad_input(write_text("io_quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
                              "triangle"));
  BOOST_TEST(throws_bad_input(write_text("io_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"), ""));
  BOOST_TEST(throws_bad_input(write_text("io_degenerate.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n"),
                              "degenerate"));
  // a closed tetrahedron with a vertex on an opposite edge: the face on that edge has three collinear
  // corners that no collapse can remove (found by the pipeline fuzz target)
  BOOST_TEST(throws_bad_input(write_text("io_collinear.off", "OFF\n4 4 0\n7 7 15\n7 7 0\n7 7 7\n15 15 6\n"
                                                             "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
                              "three collinear corners"));
  BOOST_TEST(throws_bad_input(write_text("io_mesh.xyz", "0 0 0\n"), "unsupported"));
  // found by fuzzing: CGAL's reader takes the face count "170835621" out of "170835621+0.7" and allocates
  // 4 GB for it; a negative count wraps to a huge unsigned one
  BOOST_TEST(throws_bad_input(write_text("io_fuzz_count.off", std::string("\0OFF\n114 170835621+0.707107 -0 0\n0 0 0\n", 39)),
                              "cannot fit"));
  BOOST_TEST(throws_bad_input(write_text("io_fuzz_keyword.off", std::string("\0OFF\xc7\n14 170835621+0.7 -0 0\n0 0 0\n", 34)),
                              "cannot fit"));
  // found by a long fuzzing run: CGAL reads the word after the keyword as letters and digits, so
  // "BINARY\x03..." switches to binary counts after the end of that line (here "& 1 " is 639 million
  // vertices, 1.9 GB before the reader failed)
  BOOST_TEST(throws_bad_input(write_text("io_fuzz_binary.off",
                                         std::string("OFF\n\x0c" "BINARY\x03solid 3 4\n& 1 4 \xe4\xe4\xe4\xe4\n\n", 34)),
                              "cannot fit"));
  BOOST_TEST(throws_bad_input(write_text("io_binary_negative.off", std::string("OFF BINARY\n\xff\xff\xff\xfd\0\0\0\1\0\0\0\0", 23)),
                              "negative count"));
  BOOST_TEST(throws_bad_input(write_text("io_negative_count.off", "OFF\n-3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                              "negative count"));
  // found by fuzzing: a property before any element crashed CGAL 5.5's PLY reader
  BOOST_TEST(throws_bad_input(write_text("io_fuzz1.ply",
                                         std::string("ply\nformat ascii 1.0\nel eevtmnertexj3\0\0\0y float x\n", 50)
                                           + "property float y\nproperty float z\nelement face 1\n"
                                             "property list uchar int vertex_indices\nend_header\n0 0 0\n"),
                              "PLY"));
  BOOST_TEST(throws_bad_input(write_text("io_fuzz2.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
                              "before any element"));
  BOOST_TEST(throws_bad_input(write_text("io_fuzz3.ply", "ply\nformat ascii 1.0\nelement vertex 99999999999\n"
                                                        "property float x\nend_header\n"), "exceeds"));
  // found by fuzzing: CGAL 5.5's OFF reader allocated the 170835621 faces of this header (4 GB)
  BOOST_TEST(throws_bad_input(write_text("io_fuzz4.off", "OFF\n114 170835621 0.707107 -0 0\n0.382683 0.92388 0\n"),
                              "cannot fit"));
  BOOST_TEST(throws_bad_input(write_text("io_fuzz5.off", "# comment\nCOFF\n# another\n99999999 1 0\n0 0 0\n"),
                              "cannot fit"));
  // found by fuzzing: the reader allocates each face's vertex count too, here 36666666666666 (293 TB)
  BOOST_TEST(throws_bad_input(write_text("io_fuzz_face_count.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n# c\n\n0 1 0\n"
                                                                   "3 0 1 2\n36666666666666 0 1 2\n"),
                              "face 1 of the OFF file claims 36666666666666"));
  BOOST_TEST(throws_bad_input(write_text("io_negative_face_count.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n"),
                              "face 0"));
  {
    // binary OFF: big-endian counts
    std::string bin = "OFF BINARY\n";
    for(std::uint32_t x : {3u, 2000000000u, 0u}) append_be32(bin, x);
    BOOST_TEST(throws_bad_input(write_text("io_fuzz6.off", bin), "cannot fit"));
  }
}

BOOST_AUTO_TEST_SUITE_END()
