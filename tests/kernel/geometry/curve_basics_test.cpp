#include <catch2/catch.hpp>

#include <cmath>

#include "sketchlab/curve.hpp"

using namespace sketchlab;

TEST_CASE("make_line builds a valid linear cubic", "[geometry][curve]") {
  const Curve l = make_line(Vec3(0, 0, 0), Vec3(3, 6, 9));
  REQUIRE(l.kind == CurveKind::line);
  REQUIRE(l.segment_count() == 1);
  REQUIRE(validate(l).empty());
  REQUIRE((l.control_points[1] - Vec3(1, 2, 3)).norm() < 1e-15);
  REQUIRE((l.control_points[2] - Vec3(2, 4, 6)).norm() < 1e-15);
}

TEST_CASE("validate names what is wrong with a curve", "[geometry][curve]") {
  Curve c = make_line(Vec3::Zero(), Vec3::UnitX());
  c.control_points.pop_back();
  REQUIRE(validate(c).find("control points") != std::string::npos);
  c = make_line(Vec3::Zero(), Vec3::UnitX());
  c.control_points[2].x() = std::nan("");
  REQUIRE(validate(c).find("not finite") != std::string::npos);
  c = make_line(Vec3::Zero(), Vec3::UnitX());
  c.sharp.push_back(true);
  REQUIRE(validate(c).find("sharp flags") != std::string::npos);
  c = make_line(Vec3::Zero(), Vec3::UnitX());
  c.closed = true;
  REQUIRE(validate(c).find("closed") != std::string::npos);
  REQUIRE_FALSE(validate(Curve{}).empty());
}
