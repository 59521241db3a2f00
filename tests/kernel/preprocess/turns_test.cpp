// Direction turns of the CASSIE app's hook and corner rules (reference items
// 3–4): the two readings of "the averaged direction turns at a sample".
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "sketchlab/preprocess/hooks.hpp"
#include "sketchlab/preprocess/turns.hpp"

using namespace sketchlab;

namespace {

constexpr double pi = std::numbers::pi;

// A 3-sample hook arriving along −u, turning by `phi` at sample 2 into +x,
// then a straight body of `body` samples: spacing s everywhere.
std::vector<Vec3> hooked(double phi, double s, int body) {
  const Vec3 u(std::cos(pi - phi), std::sin(pi - phi), 0.0);  // from the corner back up the hook
  std::vector<Vec3> p{2 * s * u, s * u, Vec3::Zero()};
  for (int i = 1; i <= body; ++i) p.push_back(Vec3(i * s, 0, 0));
  return p;
}

}  // namespace

TEST_CASE("sample_turns: consecutive and across readings on a right angle", "[preprocess][turns]") {
  // Averaged directions (chords of the neighbours): x, 2x, 2x, x+y, 2y, 2y, y.
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {3, 2, 0}, {3, 3, 0}};
  const std::vector<double> across = sample_turns(p, TurnSpan::across);
  const std::vector<double> consecutive = sample_turns(p, TurnSpan::consecutive);
  const std::vector<double> want_across{0, 0, pi / 4, pi / 2, pi / 4, 0, 0};
  const std::vector<double> want_consecutive{0, 0, 0, pi / 4, pi / 4, 0, 0};
  REQUIRE(across.size() == p.size());
  REQUIRE(consecutive.size() == p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    CHECK(across[i] == Approx(want_across[i]).margin(1e-12));
    CHECK(consecutive[i] == Approx(want_consecutive[i]).margin(1e-12));
  }
  CHECK(sample_turns({}, TurnSpan::consecutive).empty());
  CHECK(sample_turns({Vec3::Zero(), Vec3::UnitX()}, TurnSpan::consecutive) == std::vector<double>{0, 0});
}

TEST_CASE("Item 3: a hook is cut where the averaged direction turns more than π/6 between samples",
          "[preprocess][hooks]") {
  TurnHookParams hp;  // 3δ = 6 cm, 15 %, π/6, more than 4 samples left
  REQUIRE(hp.span == TurnSpan::consecutive);
  const double s = 0.005;
  SECTION("a 50° turn: half of it per sample, under π/6: kept") {
    // Consecutive turns 25° at samples 2 and 3; across, 50° at sample 2.
    const std::vector<Vec3> p = hooked(50.0 * pi / 180.0, s, 30);
    CHECK(sample_turns(p, TurnSpan::consecutive)[2] == Approx(25.0 * pi / 180.0).margin(1e-12));
    CHECK(find_hookless_range_by_turns(p, hp).first == 0);
    TurnHookParams across = hp;
    across.span = TurnSpan::across;
    CHECK(find_hookless_range_by_turns(p, across).first == 2);
  }
  SECTION("an 80° turn: 40° at samples 2 and 3, cut at the last, 3") {
    const std::vector<Vec3> p = hooked(80.0 * pi / 180.0, s, 30);
    const IndexRange r = find_hookless_range_by_turns(p, hp);
    CHECK(r.first == 3);
    CHECK(r.last == p.size() - 1);
  }
}
