// The Report record: building, writing and parsing JSON.
#include <CGAL/Quad_remeshing/Report.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace QR = CGAL::Quad_remeshing;

BOOST_AUTO_TEST_SUITE(report)

BOOST_AUTO_TEST_CASE(build_write_parse_round_trip)
{
  QR::Report r;
  r["status"] = "ok";
  r["count"] = 42;
  r["ratio"] = 0.125;
  r["flag"] = true;
  r["name"] = "quote \" backslash \\ newline \n tab \t";
  r["nested"]["a"] = 1;
  r["list"].push_back(1.5);
  r["list"].push_back("x");
  r["list"].push_back(QR::Report::object());
  r["nan"] = std::numeric_limits<double>::quiet_NaN();
  r["count"] = 43; // overwrites, keeps the position

  BOOST_TEST(r.keys().size() == 8u);
  BOOST_TEST(r.keys()[1] == "count");

  for(int indent : {-1, 2})
  {
    const std::string json = r.to_json(indent);
    const QR::Report p = QR::Report::parse(json);
    BOOST_TEST(p.find("status")->string() == "ok");
    BOOST_TEST(p.find("count")->number() == 43.);
    BOOST_TEST(p.find("ratio")->number() == 0.125);
    BOOST_TEST(p.find("flag")->boolean());
    BOOST_TEST(p.find("name")->string() == r["name"].string());
    BOOST_TEST(p.find("nested")->find("a")->number() == 1.);
    BOOST_TEST(p.find("list")->elements().size() == 3u);
    BOOST_TEST(p.find("list")->elements()[1].string() == "x");
    BOOST_TEST(p.find("nan")->is_null()); // JSON has no NaN
    BOOST_TEST(p.to_json(indent) == QR::Report::parse(p.to_json(indent)).to_json(indent));
  }
  BOOST_TEST(r.to_json(-1).find('\n') == std::string::npos);
}

BOOST_AUTO_TEST_CASE(malformed_text_throws)
{
  BOOST_CHECK_THROW(QR::Report::parse("{\"a\": }"), std::runtime_error);
  BOOST_CHECK_THROW(QR::Report::parse("[1, 2"), std::runtime_error);
  BOOST_CHECK_THROW(QR::Report::parse("\"open"), std::runtime_error);
  BOOST_CHECK_THROW(QR::Report::parse("{} x"), std::runtime_error);
  BOOST_CHECK_THROW(QR::Report::parse(""), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(type_errors_are_reported)
{
  QR::Report a = QR::Report::array();
  BOOST_CHECK_THROW(a["key"], std::logic_error);
  QR::Report o = QR::Report::object();
  BOOST_CHECK_THROW(o.push_back(1), std::logic_error);
}

BOOST_AUTO_TEST_SUITE_END()
