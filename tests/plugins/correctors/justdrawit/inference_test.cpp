// End-to-end behaviour of the stroke inference engine (§4) folded through a
// Session: multi-stroke curves (Figure 2), extend / join / close and their
// negative cases, blending of repeated strokes, and oversketch from a second
// view (§4.4, §5).
#include <catch2/catch.hpp>

#include "choice.hpp"
#include "jdi_fixture.hpp"

using namespace jdi_test;

namespace {
constexpr Decision new_curve = Decision::new_curve;
constexpr Decision new_closed = Decision::new_closed_curve;
constexpr Decision oversketch = Decision::oversketch;
constexpr Decision extend = Decision::extend;
constexpr Decision extend_close = Decision::extend_close;
constexpr Decision combine = Decision::combine;

const View front = ortho_view(Vec3(0, 0, 3));

// The network's curves projected into `v` (pixels), by id.
std::vector<Vec2> projected(const Drawer& dr, CurveId id, const View& v) {
  return to_pixels(v, dr.points(id));
}

double min_x(const std::vector<Vec2>& p) {
  double m = 1e300;
  for (const Vec2& q : p) m = std::min(m, q.x());
  return m;
}
double max_x(const std::vector<Vec2>& p) {
  double m = -1e300;
  for (const Vec2& q : p) m = std::max(m, q.x());
  return m;
}

// Back-and-forth scratch along y = y0 from x0 to x1, `passes` passes.
std::vector<Vec2> scratch(double x0, double x1, double y0, int passes) {
  std::vector<Vec2> out;
  for (int k = 0; k < passes; ++k) {
    const bool fwd = k % 2 == 0;
    const double off = (k % 2 ? 3.0 : -2.0);
    // Each pass starts where the last ended and runs a little further.
    const double a = fwd ? x0 + 10 * k : x1 + 10 * k, b = fwd ? x1 + 10 * (k + 1) : x0 + 10 * (k + 1);
    for (int i = 0; i < 40; ++i) {
      const double u = i / 39.0;
      out.emplace_back(a + u * (b - a), y0 + off + 1.5 * std::sin(7 * u));
    }
  }
  return out;
}

}  // namespace

TEST_CASE("Figure 2: overlapping, skipping and scratched strokes build one curve", "[justdrawit][fig2]") {
  Drawer dr;
  REQUIRE(decision(dr.draw(front, line_px({100, 500}, {400, 505}))) == new_curve);
  // Overlap: starts on the curve's end and runs on.
  CHECK(decision(dr.draw(front, line_px({360, 504}, {600, 498}))) == extend);
  // Skip: a small gap, same direction.
  CHECK(decision(dr.draw(front, line_px({625, 498}, {800, 502}))) == extend);
  // Back-and-forth scratch continuing the curve after another small gap.
  CHECK(decision(dr.draw(front, scratch(820, 950, 502, 3))) == extend);
  // Back-and-forth: a stroke drawn backwards over the start and past it.
  CHECK(decision(dr.draw(front, line_px({160, 501}, {20, 497}))) == extend);
  REQUIRE(dr.net().curves().size() == 1);
  const auto px = projected(dr, dr.net().curves().begin()->first, front);
  CHECK(min_x(px) < 40);
  CHECK(max_x(px) > 930);
  // A smooth curve: no point strays more than d from the line drawn.
  for (const Vec2& p : px) CHECK(std::abs(p.y() - 500) < 15);
}

TEST_CASE("Extend by overlap and by join, not on perpendicular or distant strokes", "[justdrawit][extend]") {
  SECTION("extend (merge with overhang)") {
    Drawer dr;
    dr.draw(front, line_px({200, 500}, {500, 500}));
    const StepReport r = dr.draw(front, line_px({470, 501}, {700, 503}));
    CHECK(decision(r) == extend);
    CHECK(r.curves_replaced == 1);
    REQUIRE(dr.net().curves().size() == 1);
    CHECK(max_x(projected(dr, 1, front)) > 690);
    CHECK(min_x(projected(dr, 1, front)) < 205);
  }
  SECTION("join (a gap, tangents in line)") {
    Drawer dr;
    dr.draw(front, line_px({200, 500}, {500, 500}));
    const StepReport r = dr.draw(front, line_px({540, 500}, {700, 500}));
    CHECK(decision(r) == extend);
    REQUIRE(dr.net().curves().size() == 1);
    const auto px = projected(dr, 1, front);
    // The join fills the gap: consecutive points stay close.
    for (std::size_t i = 1; i < px.size(); ++i) CHECK((px[i] - px[i - 1]).norm() < 10);
  }
  SECTION("join at the curve's start, stroke drawn towards it") {
    Drawer dr;
    dr.draw(front, line_px({400, 500}, {700, 500}));
    CHECK(decision(dr.draw(front, line_px({200, 500}, {370, 500}))) == extend);
    REQUIRE(dr.net().curves().size() == 1);
    CHECK(min_x(projected(dr, 1, front)) < 205);
  }
  SECTION("perpendicular from the middle is a new curve") {
    Drawer dr;
    dr.draw(front, line_px({200, 500}, {500, 500}));
    const Points3 before = dr.points(1);
    CHECK(decision(dr.draw(front, line_px({350, 505}, {350, 750}))) == new_curve);
    CHECK(dr.net().curves().size() == 2);
    CHECK(dr.points(1) == before);
  }
  SECTION("perpendicular at the end is a new curve") {
    Drawer dr;
    dr.draw(front, line_px({200, 500}, {500, 500}));
    CHECK(decision(dr.draw(front, line_px({502, 510}, {502, 750}))) == new_curve);
    CHECK(dr.net().curves().size() == 2);
  }
  SECTION("in line but far beyond 8d is a new curve") {
    Drawer dr;
    dr.draw(front, line_px({200, 500}, {500, 500}));
    CHECK(decision(dr.draw(front, line_px({640, 500}, {900, 500}))) == new_curve);
    CHECK(dr.net().curves().size() == 2);
  }
  SECTION("parallel but 5d away is a new curve") {
    Drawer dr;
    dr.draw(front, line_px({200, 500}, {500, 500}));
    CHECK(decision(dr.draw(front, line_px({250, 575}, {450, 575}))) == new_curve);
    CHECK(dr.net().curves().size() == 2);
  }
}

TEST_CASE("Close: extend-and-close and a new closed stroke, not when open", "[justdrawit][close]") {
  SECTION("extend and close") {
    Drawer dr;
    std::vector<Vec2> u = line_px({300, 300}, {300, 600});
    for (const Vec2& p : line_px({300, 600}, {600, 600})) u.push_back(p);
    for (const Vec2& p : line_px({600, 600}, {600, 300})) u.push_back(p);
    dr.draw(front, u);
    std::vector<Vec2> s = line_px({601, 380}, {601, 301}, 30);
    for (const Vec2& p : line_px({600, 300}, {300, 299})) s.push_back(p);
    for (const Vec2& p : line_px({299, 300}, {299, 380}, 30)) s.push_back(p);
    const StepReport r = dr.draw(front, s);
    CHECK(decision(r) == extend_close);
    REQUIRE(dr.net().curves().size() == 1);
    const Curve& c = dr.net().curves().begin()->second.curve;
    CHECK(c.closed);
    CHECK((c.control_points.front() - c.control_points.back()).norm() < 1e-12);
  }
  SECTION("a stroke coming back over its start makes a closed curve") {
    Drawer dr;
    std::vector<Vec2> circle;
    for (int i = 0; i <= 200; ++i) {
      const double a = 2.2 * std::numbers::pi * i / 200;  // 396°: overlaps its start
      circle.emplace_back(600 + 200 * std::cos(a), 500 + 200 * std::sin(a));
    }
    CHECK(decision(dr.draw(front, circle)) == new_closed);
    REQUIRE(dr.net().curves().size() == 1);
    CHECK(dr.net().curves().begin()->second.curve.closed);
  }
  SECTION("a loop ending back on its own stem stays open: its start meets nothing") {
    // §4.3 (1) closes a stroke when *each* end merges or joins with the
    // other. This one's end runs 150 px along its first 400 px (a merge
    // with its start's third), but its start is 100 px from the stroke's
    // last third and points away from it (neither merge nor join).
    Drawer dr;
    std::vector<Vec2> s;
    const std::vector<Vec2> corners = {{300, 500}, {700, 500}, {750, 600}, {700, 700},
                                       {400, 700}, {350, 600}, {400, 500}, {550, 500}};
    for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
      std::vector<Vec2> leg = line_px(corners[k], corners[k + 1]);
      if (k > 0) leg.erase(leg.begin());
      s.insert(s.end(), leg.begin(), leg.end());
    }
    CHECK(decision(dr.draw(front, s)) == new_curve);
    REQUIRE(dr.net().curves().size() == 1);
    CHECK_FALSE(dr.net().curves().begin()->second.curve.closed);
  }
  SECTION("an open arc stays open") {
    Drawer dr;
    std::vector<Vec2> arc;
    for (int i = 0; i <= 200; ++i) {
      const double a = 1.5 * std::numbers::pi * i / 200;
      arc.emplace_back(600 + 200 * std::cos(a), 500 + 200 * std::sin(a));
    }
    CHECK(decision(dr.draw(front, arc)) == new_curve);
    CHECK_FALSE(dr.net().curves().begin()->second.curve.closed);
  }
}

TEST_CASE("A stroke combining two curves joins them into one", "[justdrawit][combine]") {
  Drawer dr;
  dr.draw(front, line_px({100, 500}, {400, 500}));
  dr.draw(front, line_px({700, 500}, {1000, 500}));
  dr.draw(front, line_px({100, 800}, {300, 850}));  // the last edited curve is elsewhere
  const StepReport r = dr.draw(front, line_px({370, 501}, {730, 501}));
  CHECK(decision(r) == combine);
  CHECK(r.curves_removed == 1);
  CHECK(dr.net().curves().size() == 2);
  const auto px = projected(dr, 1, front);
  CHECK(min_x(px) < 105);
  CHECK(max_x(px) > 995);
}

TEST_CASE("The same stroke twice blends instead of overriding", "[justdrawit][blend]") {
  Drawer dr;
  std::vector<Vec2> a, b;
  for (int i = 0; i < 80; ++i) {
    const double x = 200 + 5 * i;
    a.emplace_back(x, 500 + 4 * std::sin(x / 40));
    b.emplace_back(x + 1, 508 + 4 * std::sin(x / 40));
  }
  dr.draw(front, a);
  const StepReport r = dr.draw(front, b);
  CHECK(r.stats.extra.at("blended_strokes") == 1);
  REQUIRE(dr.net().curves().size() == 1);
  CHECK(r.curves_replaced == 1);
  // The middle of the curve lies between the two strokes, not on the second.
  const auto px = projected(dr, 1, front);
  double mean_offset = 0;
  int n = 0;
  for (const Vec2& p : px)
    if (p.x() > 300 && p.x() < 500) {
      mean_offset += p.y() - (500 + 4 * std::sin(p.x() / 40));
      ++n;
    }
  REQUIRE(n > 10);
  mean_offset /= n;
  CHECK(mean_offset > 2.0);
  CHECK(mean_offset < 6.0);
  // Undo restores the first stroke's curve exactly.
  const Points3 blended = dr.points(1);
  Event undo;
  undo.payload = UndoEvent{};
  dr.session.handle(undo);
  REQUIRE(dr.net().curves().size() == 1);
  CHECK(dr.points(1) != blended);
}

TEST_CASE("Oversketch from a second view changes depth only where it should", "[justdrawit][oversketch]") {
  // amplitude 0: a straight curve, the depth correspondence is exact and only
  // the 2 + N ray-projected smoothing rounds move points (µm); with a wavy
  // curve the closest-point correspondence (§4.4.1) slides along the sloped
  // projection by about slope x bump (≤ 0.1 x 27 px here), i.e. ~2 mm
  // along the screen's x axis, sin 50° of it in z.
  const double amplitude = GENERATE(0.0, 0.05);
  const double tolerance = amplitude == 0 ? 1e-5 : 3e-3;
  auto curve_y = [&](double x) { return amplitude * std::sin(3.0 * (x + 0.4) / 0.8); };
  Drawer dr;
  // A curve drawn from the front: on the view plane z = 0.
  std::vector<Vec3> line;
  for (int i = 0; i <= 120; ++i) {
    const double x = -0.4 + 0.8 * i / 120.0;
    line.emplace_back(x, curve_y(x), 0);
  }
  dr.draw(front, to_pixels(front, line));
  REQUIRE(dr.net().curves().size() == 1);
  const Points3 before = dr.points(1);
  for (const Vec3& p : before) REQUIRE(std::abs(p.z()) < 1e-9);

  // Second view: rotated 50° about the up axis. Over-sketch the middle
  // half with a bump in screen y (world y).
  const double a = 50 * std::numbers::pi / 180;
  const View side = ortho_view(Vec3(3 * std::sin(a), 0, 3 * std::cos(a)));
  std::vector<Vec2> stroke;
  for (int i = 0; i <= 80; ++i) {
    const double u = i / 80.0, x = -0.2 + 0.4 * u;
    Vec2 px = world_to_pixel(side, Vec3(x, curve_y(x), 0)).head<2>();
    px.y() += 40 * std::pow(std::sin(std::numbers::pi * u), 2);
    stroke.push_back(px);
  }
  const StepReport r = dr.draw(side, stroke);
  REQUIRE(decision(r) == oversketch);
  REQUIRE(dr.net().curves().size() == 1);
  const Points3 after = dr.points(1);
  // Seen from the up direction (the x–z plane) nothing moved: every point
  // is still on the line z = 0 and within the old x range.
  double worst = 0;
  Vec3 worst_at = Vec3::Zero();
  for (const Vec3& p : after) {
    if (std::abs(p.z()) > worst) worst_at = p;
    worst = std::max(worst, std::abs(p.z()));
    CHECK(p.x() > -0.4 - 1e-9);
    CHECK(p.x() < 0.4 + 1e-9);
  }
  INFO("worst at x = " << worst_at.x() << ", y = " << worst_at.y());
  CHECK(worst < tolerance);
  // The bump is there (40 px = 4 cm at 1000 px/m).
  double lift = 0;
  for (const Vec3& p : after) lift = std::max(lift, p.y() - curve_y(p.x()));
  CHECK(lift > 0.03);
  // Outside the over-sketched part the curve is untouched, point for point.
  int kept = 0, outside = 0;
  for (const Vec3& p : before) {
    if (std::abs(p.x()) < 0.3) continue;
    ++outside;
    for (const Vec3& q : after)
      if ((p - q).norm() == 0) {
        ++kept;
        break;
      }
  }
  CHECK(outside > 10);
  CHECK(kept == outside);
}

TEST_CASE("Oversketching a closed curve from its seam keeps the whole loop", "[justdrawit][oversketch][close]") {
  // A circle of radius 0.2 m in the view plane z = 0, closed by running on
  // over its start; then oversketched whole from a second view, starting and
  // ending at its seam. The stroke's start merges across the seam (curve
  // arclength from near the end on past 0): the middle of that merge is at
  // the seam, not halfway round (which cut a chord across the loop).
  Drawer dr;
  std::vector<Vec3> circle;
  for (int i = 0; i <= 220; ++i) {
    const double a = 2.2 * std::numbers::pi * i / 200;
    circle.emplace_back(0.2 * std::cos(a), 0.2 * std::sin(a), 0);
  }
  REQUIRE(decision(dr.draw(front, to_pixels(front, circle))) == new_closed);
  const Points3 loop = dr.points(1);
  const double a = 50 * std::numbers::pi / 180;
  const View side = ortho_view(Vec3(3 * std::sin(a), 0, 3 * std::cos(a)));
  Points3 around;
  for (std::size_t i = 0; i < loop.size(); i += 4) around.push_back(loop[i]);
  around.push_back(loop.back());
  REQUIRE(decision(dr.draw(side, to_pixels(side, around))) == oversketch);
  REQUIRE(dr.net().curves().size() == 1);
  CHECK(dr.net().curves().begin()->second.curve.closed);
  double worst = 0;
  for (const Vec3& p : dr.points(1)) worst = std::max({worst, std::abs(p.head<2>().norm() - 0.2), std::abs(p.z())});
  CHECK(worst < 2e-3);
}

TEST_CASE("Extending from the front extrapolates the curve's depth", "[justdrawit][depth]") {
  // A curve leaving the z = 0 plane linearly (dz/dx = 0.5), seeded directly.
  Sketch sketch;
  std::vector<Vec3> pts;
  for (int i = 0; i <= 60; ++i) pts.emplace_back(-0.3 + 0.3 * i / 60.0, 0, 0.5 * (0.3 * i / 60.0));
  Edit e;
  NetworkCurve nc;
  nc.id = 1;
  nc.curve = polyline_curve(pts, false);
  e.curves_added.push_back(nc);
  sketch.network.apply(e);
  // From the front, continue the curve to the right.
  std::vector<Vec3> ext;
  for (int i = 0; i <= 60; ++i) ext.emplace_back(-0.05 + 0.3 * i / 60.0, 0, 0);
  const Stroke s = pixel_stroke(2, front, to_pixels(front, ext));
  const Correction c = justdrawit_correct(s, sketch, JdiParams{});
  REQUIRE(c.error.empty());
  REQUIRE(decision_from_string(c.stats.outcomes.at("decision")) == extend);
  REQUIRE(c.edit.curves_replaced.size() == 1);
  const Points3 after = curve_points(c.edit.curves_replaced[0].curve, 1e-3);
  // The far end keeps rising in z at the curve's slope (0.5 per metre), and
  // still projects onto the stroke.
  const Vec3 tip = after.back().x() > after.front().x() ? after.back() : after.front();
  CHECK(tip.x() > 0.2);
  CHECK(tip.z() == Approx(0.5 * (tip.x() + 0.3)).margin(0.02));
  CHECK(std::abs(tip.y()) < 1e-9);
}

TEST_CASE("Bad input gives a clear error, never a crash", "[justdrawit][errors]") {
  const JdiParams p;
  Sketch sketch;
  Stroke s3d;
  s3d.id = 1;
  s3d.samples.resize(5);
  for (int i = 0; i < 5; ++i) s3d.samples[i].position = Vec3(i, 0, 0);
  CHECK(justdrawit_correct(s3d, sketch, p).error.find("2D") != std::string::npos);
  const Stroke dot = pixel_stroke(2, front, {{100, 100}, {100, 100}, {100, 100}});
  CHECK(justdrawit_correct(dot, sketch, p).error.find("zero length") != std::string::npos);
  const Stroke two = pixel_stroke(3, front, {{100, 100}, {103, 100}});
  const Correction c = justdrawit_correct(two, sketch, p);
  CHECK(c.error.empty());
  CHECK(c.edit.curves_added.size() == 1);
}

TEST_CASE("A curve on the visible draw plane is not behind it, one farther than d is", "[justdrawit][extend]") {
  // §4.3 rules out curves behind a visible draw plane. The first stroke lies
  // on z = 0; the second, on a plane `offset` nearer the eye, continues it.
  // Within d (15 px = 15 mm here) the curve counts as on the plane.
  const auto second = [](double offset) {
    Drawer dr;
    dr.draw(front, line_px({200, 500}, {500, 500}), Layer::automatic, Vec4(0, 0, 1, 0));
    const StepReport r = dr.draw(front, line_px({470, 500}, {700, 500}), Layer::automatic, Vec4(0, 0, 1, offset));
    return std::make_pair(decision(r), dr.net().curves().size());
  };
  using Outcome = std::pair<std::optional<Decision>, std::size_t>;
  CHECK(second(0.0) == Outcome{extend, 1});
  CHECK(second(0.005) == Outcome{extend, 1});
  CHECK(second(0.05) == Outcome{new_curve, 2});
}
