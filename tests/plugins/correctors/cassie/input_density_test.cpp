// Dense input for the app's turn rules (input_density.hpp): points inserted in
// long gaps lie on the thinned polyline, keep every sample and its order, and
// change nothing when the samples are already dense enough.
#include <catch2/catch.hpp>

#include "input_density.hpp"

using namespace sketchlab;
using namespace sketchlab::cassie;

namespace {

Stroke thinned() {
  Stroke s;
  s.id = 7;
  const Vec3 p[] = {{0, 0, 0}, {0.05, 0, 0}, {0.05, 0.013, 0}, {0.0501, 0.0131, 0.001}};
  const double t[] = {0.0, 0.5, 0.6, 0.61};
  for (int i = 0; i < 4; ++i) {
    Sample x;
    x.position = p[i];
    x.time = t[i];
    x.pressure = 0.5 + 0.1 * i;
    s.samples.push_back(x);
  }
  return s;
}

}  // namespace

TEST_CASE("densify_stroke keeps the samples and fills long gaps on the polyline", "[cassie]") {
  const Stroke in = thinned();
  const Stroke out = densify_stroke(in, 0.002);
  // 0.05 m -> 25 pieces, 0.013 m -> 7 pieces, the last gap (1.4 mm) untouched.
  REQUIRE(out.samples.size() == 4 + 24 + 6);
  std::size_t next = 0;
  for (std::size_t i = 0; i < out.samples.size(); ++i) {
    if (next < in.samples.size() && out.samples[i] == in.samples[next]) ++next;
    if (i > 0) {
      const Sample& a = out.samples[i - 1];
      const Sample& b = out.samples[i];
      CHECK((b.position - a.position).norm() <= 0.002 + 1e-12);
      CHECK(b.time >= a.time);
    }
  }
  CHECK(next == in.samples.size());  // every sample, in order
  // An inserted point is on its segment, with time and pressure in step.
  const Sample& mid = out.samples[1];
  CHECK(mid.position.isApprox(Vec3(0.002, 0, 0), 1e-12));
  CHECK(mid.time == Approx(0.02).margin(1e-12));
  CHECK(mid.pressure == Approx(0.504).margin(1e-12));
  CHECK(out.id == in.id);
}

TEST_CASE("densify_stroke is the identity when off or when samples are dense", "[cassie]") {
  const Stroke in = thinned();
  CHECK(densify_stroke(in, 0.0) == in);
  CHECK(densify_stroke(in, -1.0) == in);
  CHECK(densify_stroke(in, 0.06) == in);
}
