// §4.1–4.3 pieces on plain data: ShortStraw, fold-over unfolding, the merge
// and join tests (eq. 1–2), types, scores (eq. 3–6) and the choice rules.
#include <catch2/catch.hpp>

#include "choice.hpp"
#include "jdi_fixture.hpp"
#include "scratch.hpp"
#include "short_straw.hpp"
#include "stroke_curve_analysis.hpp"

using namespace jdi_test;

namespace {
Points2 line2(const Vec2& a, const Vec2& b, int n = 60) {
  Points2 out;
  for (int i = 0; i < n; ++i) out.push_back(a + (b - a) * (i / double(n - 1)));
  return out;
}
Points2 cat(Points2 a, const Points2& b) {
  a.insert(a.end(), b.begin() + 1, b.end());
  return a;
}
constexpr double d = 15;
}  // namespace

TEST_CASE("ShortStraw finds the corners of a zig-zag", "[justdrawit][shortstraw]") {
  const Points2 z = cat(cat(line2({0, 0}, {200, 0}), line2({200, 0}, {200, 200})), line2({200, 200}, {400, 200}));
  const Corners c = short_straw(z);
  REQUIRE(c.index.size() == 4);  // both ends and the two corners
  CHECK((c.points[c.index[1]] - Vec2(200, 0)).norm() < 15);
  CHECK((c.points[c.index[2]] - Vec2(200, 200)).norm() < 15);
  CHECK(short_straw(line2({0, 0}, {300, 10})).index.size() == 2);
}

TEST_CASE("Fold-overs are found and unfolded, corners are not fold-overs", "[justdrawit][scratch]") {
  // Three passes back and forth along y = 0, 4 px apart.
  const Points2 s = cat(cat(line2({0, 0}, {300, 2}), line2({300, 2}, {10, 6})), line2({10, 6}, {310, 4}));
  const auto sections = fold_over_sections(resample(s, 1.5), d);
  CHECK(sections.size() == 3);
  const Points2 u = unfold_stroke(resample(s, 1.5), d);
  // Non-folding: x never runs back by more than a pixel, one pass long.
  for (std::size_t i = 1; i < u.size(); ++i) CHECK(u[i].x() > u[i - 1].x() - 1.0);
  CHECK(length(u) == Approx(310).margin(25));
  for (const Vec2& p : u) CHECK(std::abs(p.y() - 3) < 4);
  // An L-shaped stroke has a corner but no fold-over.
  const Points2 l = cat(line2({0, 0}, {200, 0}), line2({200, 0}, {200, 200}));
  CHECK(fold_over_sections(resample(l, 1.5), d).size() == 1);
  CHECK(unfold_stroke(resample(l, 1.5), d) == resample(l, 1.5));
}

TEST_CASE("Overlap fraction measures how much of a stroke lies within d", "[justdrawit][scratch]") {
  const Points2 a = line2({0, 0}, {100, 0}), b = line2({0, 5}, {100, 5});
  CHECK(overlap_fraction(a, b, d) == Approx(1.0));
  // Within d of b up to x = 100 + sqrt(15² - 5²).
  CHECK(overlap_fraction(line2({0, 0}, {200, 0}), b, d) == Approx((100 + std::sqrt(200.0)) / 200).margin(0.01));
  CHECK(overlap_fraction(a, line2({0, 50}, {100, 50}), d) == 0.0);
}

TEST_CASE("Merge test (eq. 1): along the curve yes, across it no", "[justdrawit][merge]") {
  const Projected curve = make_projected(line2({0, 0}, {300, 0}, 100), false);
  const Points2 along = line2({250, 3}, {500, 3}, 120);
  const auto cum = cumulative(along);
  const auto m = merge_test(along, cum, curve, false, d);
  REQUIRE(m);
  CHECK(m->dir == 1);
  CHECK(m->overhang);
  CHECK(m->d_a == Approx(3).margin(1e-6));
  CHECK(m->score == Approx(0.7 * 3 / d + 0.3 * m->alpha_a / (0.75 * std::numbers::pi)));
  // Backwards along the curve: dir -1.
  const Points2 back = line2({50, 3}, {-200, 3}, 120);
  const auto mb = merge_test(back, cumulative(back), curve, false, d);
  REQUIRE(mb);
  CHECK(mb->dir == -1);
  CHECK(mb->overhang);
  // Perpendicular from the middle, and too far: no merge.
  const Points2 across = line2({150, 2}, {150, 300}, 120);
  CHECK_FALSE(merge_test(across, cumulative(across), curve, false, d));
  const Points2 far = line2({50, 40}, {250, 40}, 120);
  CHECK_FALSE(merge_test(far, cumulative(far), curve, false, d));
  // A wobbling pen (1.5 px, 8 px wavelength: 1.3 px of arclength per px
  // moved) still travels along the curve; leaving the curve's end at 30° it
  // does not, however close its start.
  Points2 wobbly;
  for (int i = 0; i <= 1000; ++i) {
    const double x = 250 + 0.25 * i;
    wobbly.emplace_back(x, 1.5 * std::sin(2 * std::numbers::pi * x / 8));
  }
  const auto mw = merge_test(wobbly, cumulative(wobbly), curve, false, d);
  REQUIRE(mw);
  CHECK(mw->overhang);
  CHECK(cumulative(wobbly)[40] > 1.25 * 10);  // the arclength the wobble adds
  const double a30 = std::numbers::pi / 6;
  const Points2 leaving = line2({296, 0}, Vec2(296, 0) + 200 * Vec2(std::cos(a30), std::sin(a30)), 120);
  CHECK_FALSE(merge_test(leaving, cumulative(leaving), curve, false, d));
}

TEST_CASE("Join test (eq. 2): in-line gaps join, bent or far ones do not", "[justdrawit][join]") {
  const Projected curve = make_projected(line2({0, 0}, {300, 0}, 100), false);
  const Points2 s = line2({340, 0}, {500, 0}, 80);
  const auto j = join_test(s, cumulative(s), curve, false, d);
  REQUIRE(j);
  CHECK_FALSE(j->at_curve_start);
  CHECK(j->dir == 1);
  CHECK(j->d_j == Approx(40).margin(1e-9));
  CHECK(j->alpha_t < 1e-6);
  CHECK(j->score == Approx(join_score(j->alpha_d, j->alpha_t, j->d_j, d)));
  // 30° off line, and beyond 8d: no join.
  const Points2 bent = line2({340, 0}, {340 + 160 * std::cos(0.5), 160 * std::sin(0.5)}, 80);
  CHECK_FALSE(join_test(bent, cumulative(bent), curve, false, d));
  const Points2 far = line2({430, 0}, {600, 0}, 80);
  CHECK_FALSE(join_test(far, cumulative(far), curve, false, d));
}

TEST_CASE("Join score follows eq. 3–5", "[justdrawit][score]") {
  const double qa = (0.1 / 0.2) / 4 + 3 * (0.15 / 0.3) / 4;
  CHECK(join_score(0.1, 0.15, 4 * d, d) == Approx(qa));                        // q_l = 1/2
  CHECK(join_score(0.1, 0.15, 0.8 * d, d) == Approx((1 + 0.1 / 0.25) * qa));   // q_l = 0.1
  CHECK(join_score(0.1, 0.15, 7.2 * d, d) == Approx((1 + 0.15 / 0.25) * qa));  // q_l = 0.9
}

TEST_CASE("Depth score follows eq. 6", "[justdrawit][score]") {
  CHECK(depth_score(2, 3, 1, 5, false, false) == Approx(0.25 * (2.5 - 1) / 4 + 0.75 * 1.0 / 4));
  CHECK(depth_score(2, 3, 1, 5, true, false) == Approx(0.25 * (2.5 - 1) / 4));
  CHECK(depth_score(2, 3, 1, 5, false, true) == Approx(2 * (0.25 * 1.5 / 4 + 0.75 / 4)));
  CHECK(depth_score(1, 1, 1, 1, false, false) == 0.0);
  CHECK(final_score(0.4, 0.2) == Approx(0.1 + 0.15));
}

TEST_CASE("Types: oversketch, partial oversketch, topology", "[justdrawit][type]") {
  const Projected curve = make_projected(line2({0, 0}, {400, 0}, 120), false);
  const Points2 over = line2({100, 4}, {300, 4}, 100);
  const auto m = analyze(over, curve, d);
  REQUIRE(m);
  CHECK(m->type == MatchType::oversketch);
  // Leaves the curve sideways: partial oversketch.
  const Points2 partial = cat(line2({100, 3}, {200, 3}, 50), line2({200, 3}, {300, 150}, 50));
  const auto p = analyze(partial, curve, d);
  REQUIRE(p);
  CHECK(p->type == MatchType::partial_oversketch);
  // Both ends merge but in opposite directions (a hairpin): ruled out.
  const Points2 hairpin = cat(cat(line2({100, 3}, {200, 3}, 50), line2({200, 3}, {200, 100}, 40)),
                              line2({200, 100}, {120, 4}, 40));
  const auto h = analyze(hairpin, curve, d);
  CHECK((!h || h->type != MatchType::oversketch));
}

TEST_CASE("Choice: last edited curve first, then combining, then the lowest score", "[justdrawit][choice]") {
  std::vector<Candidate> c(3);
  c[0].decision = Decision::extend;
  c[0].curve = 1;
  c[0].q = 0.3;
  c[1].decision = Decision::combine;
  c[1].curve = 2;
  c[1].curve2 = 3;
  c[1].q = 0.5;
  c[2].decision = Decision::oversketch;
  c[2].curve = 4;
  c[2].q = 0.1;
  CHECK(choose(c, 1) == 0);
  CHECK(choose(c, 9) == 1);
  c.erase(c.begin() + 1);
  CHECK(choose(c, 9) == 1);
  CHECK(choose({}, 1) == -1);
}
