#include <catch2/catch.hpp>
#include <limits>
#include <string>

#include "sketchlab/stroke.hpp"

using namespace sketchlab;

namespace {
Stroke line_stroke(int n) {
  Stroke s;
  s.id = 12;
  for (int i = 0; i < n; ++i) {
    Sample smp;
    smp.position = Vec3(0.01 * i, 0, 0);
    smp.time = 0.1 * i;
    s.samples.push_back(smp);
  }
  return s;
}
}  // namespace

TEST_CASE("positions lists the sample positions in order", "[stroke]") {
  const Stroke s = line_stroke(4);
  const auto p = positions(s);
  REQUIRE(p.size() == 4);
  for (int i = 0; i < 4; ++i) CHECK(p[i] == s.samples[i].position);
}

TEST_CASE("validate accepts a good stroke and names each problem", "[stroke]") {
  CHECK(validate(line_stroke(3)).empty());
  CHECK(validate(line_stroke(0)) == "stroke 12 has no samples");
  CHECK_THAT(validate(line_stroke(1)), Catch::Contains("at least 2"));

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Stroke s = line_stroke(5);
  s.samples[4].position.y() = nan;
  CHECK(validate(s) == "stroke 12 sample 4 has a non-finite position");
  s = line_stroke(5);
  s.samples[2].time = inf;
  CHECK(validate(s) == "stroke 12 sample 2 has a non-finite time");
  s = line_stroke(5);
  s.samples[1].pressure = nan;
  CHECK(validate(s) == "stroke 12 sample 1 has a non-finite pressure");

  s = line_stroke(3);
  for (auto& smp : s.samples) smp.position = Vec3(1, 2, 3);
  CHECK_THAT(validate(s), Catch::Contains("zero length"));

  s = line_stroke(3);
  s.samples_are_pixels = true;
  CHECK_THAT(validate(s), Catch::Contains("without a view"));
  s.view = View{};
  CHECK(validate(s).empty());

  s = line_stroke(3);
  s.workspace_scale = 0.0;
  CHECK_THAT(validate(s), Catch::Contains("workspace scale"));
}
