// Hostile strokes through every corrector and surfacer of the build (issue
// 17): NaN and infinity, 1 and 2 samples, duplicates, zero length, 10^6
// samples, coordinates from 1e-12 to 1e12, glitch samples kilometres away, 50
// stacked copies, self-crossing and closed strokes, degenerate cameras and
// draw planes. For each stack: handle() never throws, no event takes much
// longer than the per-event time budget, nothing non-finite reaches the
// sketch or the reports, a refused stroke carries its own error, and the rest
// of the session is kept (a stroke drawn before stays, one drawn after is
// corrected).
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "build_plugin_host.hpp"
#include "sketchlab/draw_plane.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/session.hpp"

using namespace sketchlab;

namespace {

// The per-event budget. The sanitizers slow the plugins 5-20x: there the
// budget grows likewise, or JustDrawIt's strokes after a long curve (over 1
// s there) would be refused for time, not for what they are.
#ifdef SKETCHLAB_SANITIZED
constexpr double budget_s = 10.0;
#else
constexpr double budget_s = 1.0;
#endif
// What an event may take beyond its budget: the kernel's own work around the
// plugins (validation, copies, lifting, undo records) on a 10^6-sample
// stroke, on a loaded 2-core machine, under sanitizers.
constexpr double grace_s = 8.0;
// The two long strokes the stacks must correct. Under the sanitizers (where
// the test with 10^5 samples and 50 copies did not finish in 9 min) they
// have 2·10^4 samples: every hostile kind still reaches every stack, and the
// run stays bounded (issue 17: long property runs bounded in time). The
// 10^6-sample stroke, refused before any plugin sees it, keeps its size.
// Likewise the stacked copies: 10, not 50.
#ifdef SKETCHLAB_SANITIZED
constexpr int long_stroke_samples = 20'000;
constexpr int stacked_copies = 10;
#else
constexpr int long_stroke_samples = 100'000;
constexpr int stacked_copies = 50;
#endif
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

struct Case {
  std::string name;
  Stroke stroke;
  bool may_be_corrected = true;  // false: must be refused (invalid input)
};

View tablet_view() {
  View v;
  v.view = look_at(Vec3(0.8, 0.6, 1.5), Vec3(0, 0, 0), Vec3(0, 1, 0));
  v.projection = perspective(0.9, 1.6, 0.01, 100.0);
  v.viewport = Vec4(0, 0, 1600, 1000);
  return v;
}

Vec4 plane_facing(const View& v) {
  return plane_through(Vec3::Zero(), eye_position(v));
}

// A stroke of n samples along `at(u)`, u in [0, 1], over `seconds`.
template <class At>
Stroke along(int n, double seconds, At&& at) {
  Stroke s;
  s.layer = Layer::automatic;
  for (int i = 0; i < n; ++i) {
    const double u = n == 1 ? 0.0 : double(i) / (n - 1);
    Sample smp;
    smp.position = at(u);
    smp.time = seconds * u;
    smp.pressure = 0.7;
    s.samples.push_back(smp);
  }
  return s;
}

Stroke on_tablet(Stroke s, std::optional<Vec4> plane, const View& view = tablet_view()) {
  s.view = view;
  s.samples_are_pixels = true;
  s.draw_plane = plane;
  return s;
}

// 3D strokes in metres (what VR gives) and the same shapes drawn on a tablet.
std::vector<Case> hostile_cases() {
  const auto line = [](Vec3 a, Vec3 b) { return [=](double u) -> Vec3 { return a + u * (b - a); }; };
  const auto circle = [](Vec3 c, double r) {
    return [=](double u) -> Vec3 {
      return c + r * Vec3(std::cos(2 * std::numbers::pi * u), std::sin(2 * std::numbers::pi * u), 0);
    };
  };
  const auto eight = [](double u) -> Vec3 {
    const double a = 2 * std::numbers::pi * u;
    return {0.2 * std::sin(a), 0.1 * std::sin(2 * a), 0.05};
  };
  std::vector<Case> cases;
  auto add = [&](std::string name, Stroke s, bool may = true) { cases.push_back({std::move(name), std::move(s), may}); };

  Stroke s = along(20, 0.5, line(Vec3(0, 0, 0), Vec3(0.3, 0, 0)));
  s.samples[7].position.x() = nan;
  add("NaN position", s, false);
  s.samples[7].position.x() = inf;
  add("infinite position", s, false);
  s.samples[7].position.x() = 0.1;
  s.samples[3].time = nan;
  add("NaN time", s, false);
  add("1 sample", along(1, 0.0, line(Vec3(0, 0, 0), Vec3(0, 0, 0))), false);
  add("2 samples", along(2, 0.1, line(Vec3(0, 0.1, 0), Vec3(0.2, 0.1, 0))));
  add("zero length", along(30, 0.5, line(Vec3(0.1, 0.1, 0.1), Vec3(0.1, 0.1, 0.1))), false);
  {
    Stroke d = along(40, 0.6, line(Vec3(0, 0.2, 0), Vec3(0.25, 0.2, 0)));
    for (int i = 0; i < 15; ++i) d.samples[i].position = d.samples[0].position;  // a pen resting
    for (int i = 30; i < 40; ++i) d.samples[i].position = d.samples[29].position;
    add("duplicate samples", d);
  }
  // Beyond max_stroke_samples: refused with its own error.
  add("10^6 samples", along(1'000'000, 20.0, [](double u) -> Vec3 {
        const double a = 40 * std::numbers::pi * u;
        return {0.3 * u * std::cos(a), 0.3 * u * std::sin(a), 0.001 * std::sin(977 * a)};
      }), false);
  add("long stroke", along(long_stroke_samples, 60.0, [](double u) -> Vec3 {
        const double a = 60 * std::numbers::pi * u;
        return {(0.1 + 0.2 * u) * std::cos(a), (0.1 + 0.2 * u) * std::sin(a), 0.001 * std::sin(977 * a)};
      }));
  add("1e-12 m", along(20, 0.3, line(Vec3(1e-12, 0, 0), Vec3(5e-12, 3e-12, 1e-12))));
  add("1e6 m", along(20, 0.3, line(Vec3(-1e6, 0, 0), Vec3(1e6, 5e5, 0))));
  // Beyond the recording format's 1e6 m: refused like a recording would be.
  add("1e12 m", along(20, 0.3, line(Vec3(-1e12, 0, 0), Vec3(1e12, 5e11, 0))), false);
  add("1e-12 to 1e12 m", along(20, 0.3, [](double u) -> Vec3 { return Vec3(std::pow(10.0, -12 + 24 * u), 0, 0); }),
      false);
  {
    Stroke g = along(20, 0.3, line(Vec3(0, 0, 0.1), Vec3(0.3, 0.3, 0.1)));
    g.samples[10].position = Vec3(1e4, 1e4, 1e4);
    add("glitch sample 10 km away", g);
    g.samples[10].position = Vec3(-1e6, 1e6, 1e6);
    g.samples[3].position = Vec3(1e6, 0, -1e6);
    add("glitch samples 1000 km away", g);
  }
  add("self-crossing", along(120, 1.0, eight));
  add("closed", along(100, 1.0, circle(Vec3(0, 0, 0.2), 0.1)));

  // Tablet: pixels on a draw plane, and with degenerate cameras and planes.
  const View view = tablet_view();
  const Vec4 plane = plane_facing(view);
  add("2D closed", on_tablet(along(80, 1.0, circle(Vec3(800, 500, 0), 120)), plane));
  add("2D self-crossing", on_tablet(along(80, 1.0, [](double u) -> Vec3 {
        const double a = 2 * std::numbers::pi * u;
        return {800 + 300 * std::sin(a), 500 + 150 * std::sin(2 * a), 0};
      }), plane));
  add("2D pixels near 1e6", on_tablet(along(20, 0.3, [](double u) -> Vec3 {
        return int(u * 19) % 2 ? Vec3(1e6, -1e6, 0) : Vec3(0, 0, 0);
      }), plane));
  {
    Stroke g = on_tablet(along(20, 0.3, line(Vec3(700, 300, 0), Vec3(700, 600, 0))), plane);
    g.samples[10].position = Vec3(65535, 65535, 0);
    add("2D glitch 65535 px", g);
  }
  add("2D long stroke", on_tablet(along(long_stroke_samples, 10.0, [](double u) -> Vec3 {
        const double a = 30 * std::numbers::pi * u;
        return {800 + 400 * u * std::cos(a), 500 + 400 * u * std::sin(a), 0};
      }), plane));
  const Stroke flat = along(20, 0.3, line(Vec3(400, 300, 0), Vec3(700, 450, 0)));
  add("2D without draw plane", on_tablet(flat, std::nullopt));
  View singular = view;
  singular.view.setZero();
  add("singular camera", on_tablet(flat, plane, singular), false);
  View nearly = view;
  nearly.projection(3, 2) = 1e-300;
  nearly.projection(2, 3) = 1e-300;
  add("nearly singular camera", on_tablet(flat, plane, nearly));
  View infinite = view;
  infinite.projection(0, 0) = 1e12;
  add("extreme projection", on_tablet(flat, plane, infinite));
  // The plane through the eye containing every view ray (reproducer H4).
  const Vec3 eye = eye_position(view);
  const Vec3 forward = -view.view.block<1, 3>(2, 0).transpose();
  add("draw plane containing the view rays",
      on_tablet(flat, plane_through(eye, forward.cross(Vec3(0, 1, 0)))));
  add("draw plane behind the camera", on_tablet(flat, plane_through(eye + 2.0 * (eye - Vec3::Zero()), eye)));
  add("draw plane 1e6 m away", on_tablet(flat, plane_through(1e6 * forward, forward)));
  return cases;
}

bool finite_report(const StepReport& r) {
  if (!std::isfinite(r.latency_ms)) return false;
  for (const auto& [k, v] : r.stats.extra)
    if (!std::isfinite(v)) return false;
  for (const auto& c : r.constraints)
    if (!std::isfinite(c.residual)) return false;
  return true;
}

// Every number in the sketch is finite: sketch_to_json writes NaN and
// infinity as null.
bool finite_sketch(const Sketch& sketch, const std::vector<StepReport>& steps) {
  return sketch_to_json(sketch, &steps).find("null") == std::string::npos;
}

// Every stack of `corrector_name`: alone and with each surfacer of the build.
void hostile_strokes_on_stacks_of(const std::string& corrector_name) {
  const PluginHost& host = test::build_plugin_host();
  std::vector<std::string> surfacers{""};
  for (const auto& p : host.plugins())
    if (p.descriptor->kind == PluginKind::surfacer) surfacers.push_back(p.descriptor->name);
  REQUIRE(surfacers.size() >= 3);  // none + soap film + Hermite RBF
  const std::vector<Case> cases = hostile_cases();

  for (const std::string& surfacer_name : surfacers) {
    const std::string label = corrector_name + (surfacer_name.empty() ? "" : "+" + surfacer_name);
    DYNAMIC_SECTION(label) {
    auto corrector = host.make_corrector(corrector_name, {});
    auto surfacer = surfacer_name.empty() ? nullptr : host.make_surfacer(surfacer_name, {});
    const bool pixels = corrector->stroke_space() == StrokeSpace::pixels;
    Session session(Workspace{}, corrector, surfacer, {}, budget_s);
    std::vector<StepReport> steps;
    double t = 0.0;
    StrokeId next_id = 1;
    auto handle = [&](Event e, const std::string& what) {
      e.time = t += 1.0;
      const auto start = std::chrono::steady_clock::now();
      StepReport r;
      REQUIRE_NOTHROW(r = session.handle(e));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      INFO(label << ", " << what << ": " << seconds << " s, error '" << r.error << "'");
      CHECK(seconds < budget_s + grace_s);
      CHECK(finite_report(r));
      CHECK(r.error.find("unknown exception") == std::string::npos);
      steps.push_back(r);
      return r;
    };
    auto stroke_event = [&](Stroke s) {
      s.id = next_id++;
      for (Sample& smp : s.samples) smp.time += t;
      return Event{0.0, StrokeEvent{std::move(s)}};
    };
    // A plain stroke every stack corrects, drawn before and after.
    const Stroke plain = pixels ? on_tablet(along(25, 0.4, [](double u) -> Vec3 { return {500 + 300 * u, 400 + 40 * u, 0}; }),
                                            plane_facing(tablet_view()))
                                : along(25, 0.4, [](double u) -> Vec3 { return {0.3 * u, 0.02 * u, 0.4}; });

    const StepReport first = handle(stroke_event(plain), "the plain stroke before");
    REQUIRE(first.error.empty());
    const std::size_t curves_before = session.sketch().network.curves().size();
    REQUIRE(curves_before >= 1);

    for (const Case& c : cases) {
      const StrokeId id = next_id;
      const StepReport r = handle(stroke_event(c.stroke), c.name);
      INFO(label << ", " << c.name << ": '" << r.error << "'");
      CHECK(r.stroke == id);
      if (!c.may_be_corrected) CHECK_FALSE(r.error.empty());
      CHECK(finite_sketch(session.sketch(), steps));
    }
    for (int k = 0; k < stacked_copies; ++k) handle(stroke_event(plain), "stacked copy " + std::to_string(k));
    handle(Event{0.0, AddPatchEvent{Vec3(0.1, 0.0, 0.4)}}, "add_patch");
    handle(Event{0.0, RecomputeSurfaceEvent{}}, "recompute_surface");
    CHECK(finite_sketch(session.sketch(), steps));

    // The rest of the session is kept: the first curve is still there (unless
    // a stacked copy legitimately replaced it) and a new stroke is corrected.
    const StepReport last = handle(stroke_event(plain), "the plain stroke after");
    INFO(label << ": '" << last.error << "'");
    CHECK(last.error.empty());
    CHECK(session.sketch().network.curves().size() >= 1);
    }
  }
}

// One test case per corrector, so that CTest runs them side by side; any
// other corrector of the build gets the last one.
const std::vector<std::string> named_correctors{"analytic", "cassie", "freehand", "justdrawit", "scaffoldsketch"};

}  // namespace

TEST_CASE("hostile strokes never hang, crash or poison a session: analytic stacks", "[adversarial][reliability][slow]") {
  hostile_strokes_on_stacks_of("analytic");
}
TEST_CASE("hostile strokes never hang, crash or poison a session: cassie stacks", "[adversarial][reliability][slow]") {
  hostile_strokes_on_stacks_of("cassie");
}
TEST_CASE("hostile strokes never hang, crash or poison a session: freehand stacks", "[adversarial][reliability][slow]") {
  hostile_strokes_on_stacks_of("freehand");
}
TEST_CASE("hostile strokes never hang, crash or poison a session: justdrawit stacks",
          "[adversarial][reliability][slow]") {
  hostile_strokes_on_stacks_of("justdrawit");
}
TEST_CASE("hostile strokes never hang, crash or poison a session: scaffoldsketch stacks",
          "[adversarial][reliability][slow]") {
  hostile_strokes_on_stacks_of("scaffoldsketch");
}
TEST_CASE("hostile strokes never hang, crash or poison a session: every other corrector's stacks",
          "[adversarial][reliability][slow]") {
  for (const auto& p : test::build_plugin_host().plugins())
    if (p.descriptor->kind == PluginKind::corrector &&
        std::find(named_correctors.begin(), named_correctors.end(), p.descriptor->name) == named_correctors.end())
      hostile_strokes_on_stacks_of(p.descriptor->name);
}
