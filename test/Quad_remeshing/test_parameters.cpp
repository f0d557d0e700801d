// Named parameters: the package's own tags compose with CGAL's (compile and run-time checks).
#include <CGAL/Quad_remeshing/parameters.h>

#include <boost/test/unit_test.hpp>

#include <functional>
#include <type_traits>

// Two parameters local to this test, declared the way every stage header declares its own.
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(qr_test_angle_t, qr_test_angle, qr_test_angle)
CGAL_QUAD_REMESHING_ADD_NAMED_PARAMETER(qr_test_weight_t, qr_test_weight, qr_test_weight)

namespace {

namespace QRP = CGAL::Quad_remeshing::parameters;
namespace QRnp = CGAL::Quad_remeshing::internal_np;

// A function written the way the stages are: defaults with choose_parameter/get_parameter.
template <typename NP>
double read_angle(const NP& np)
{
  return QRP::choose_parameter(QRP::get_parameter(np, QRnp::qr_test_angle), 35.);
}
template <typename NP>
double read_weight(const NP& np)
{
  return QRP::choose_parameter(QRP::get_parameter(np, QRnp::qr_test_weight), 1.);
}
template <typename NP>
bool read_verbose(const NP& np)
{
  return QRP::choose_parameter(QRP::get_parameter(np, CGAL::internal_np::verbose), false);
}

struct Not_copyable
{
  Not_copyable() = default;
  Not_copyable(const Not_copyable&) = delete;
  int calls = 0;
};

} // namespace

BOOST_AUTO_TEST_SUITE(parameters)

BOOST_AUTO_TEST_CASE(defaults_and_own_first_chain)
{
  BOOST_TEST(read_angle(QRP::default_values()) == 35.);
  BOOST_TEST(read_verbose(QRP::default_values()) == false);

  auto np = QRP::qr_test_angle(40.).verbose(true); // CGAL members chain after an own parameter
  BOOST_TEST(read_angle(np) == 40.);
  BOOST_TEST(read_verbose(np) == true);
  BOOST_TEST(read_weight(np) == 1.);
  static_assert(!CGAL::parameters::is_default_parameter<decltype(np), QRnp::qr_test_angle_t>::value, "");
  static_assert(CGAL::parameters::is_default_parameter<decltype(np), QRnp::qr_test_weight_t>::value, "");
}

BOOST_AUTO_TEST_CASE(append_form)
{
  auto np = QRP::qr_test_weight(CGAL::parameters::verbose(true).number_of_iterations(3), 2.5);
  BOOST_TEST(read_weight(np) == 2.5);
  BOOST_TEST(read_verbose(np) == true);
  BOOST_TEST(QRP::choose_parameter(QRP::get_parameter(np, CGAL::internal_np::number_of_iterations), 0) == 3);
}

BOOST_AUTO_TEST_CASE(combine_packs_later_wins)
{
  auto a = CGAL::parameters::verbose(true).number_of_iterations(3);
  auto b = QRP::qr_test_angle(50.).number_of_iterations(7);
  auto np = QRP::combine(a, b, QRP::qr_test_weight(4.), QRP::default_values());
  BOOST_TEST(read_angle(np) == 50.);
  BOOST_TEST(read_weight(np) == 4.);
  BOOST_TEST(read_verbose(np) == true);
  BOOST_TEST(QRP::choose_parameter(QRP::get_parameter(np, CGAL::internal_np::number_of_iterations), 0) == 7);

  auto np2 = QRP::combine(QRP::qr_test_angle(10.), QRP::qr_test_angle(20.));
  BOOST_TEST(read_angle(np2) == 20.);
}

BOOST_AUTO_TEST_CASE(objects_by_reference)
{
  Not_copyable solver;
  auto np = QRP::qr_test_weight(1.).visitor(std::ref(solver));
  Not_copyable& s = QRP::get_parameter_reference(np, CGAL::internal_np::visitor);
  ++s.calls;
  BOOST_TEST(solver.calls == 1);
}

BOOST_AUTO_TEST_SUITE_END()
