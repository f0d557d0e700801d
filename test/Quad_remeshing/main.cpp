// Entry point of the test suite: the module is defined once, every test_*.cpp adds a suite.
#define BOOST_TEST_MODULE CGAL_Quad_remeshing
#include <boost/test/unit_test.hpp>
