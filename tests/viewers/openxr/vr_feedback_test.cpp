// What the headset shows (issue #25), read back from the swapchains of the
// test runtime after scripted input: the stage (ground to the horizon,
// floor grid), the brush tip at the aim pose in the mode's colour, the hand
// menu's state (active items, the hovered one), a stroke kept until its
// correction arrives, the corrected curve's transition, the enforced
// constraints flashing where they act and gone afterwards, and switching
// and comparing the stacks of an experiment from the menu.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "cli_helpers.hpp"
#include "constraint_markers.hpp"
#include "hand_actors.hpp"
#include "hand_menu.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/lab/stack.hpp"
#include "viewers/xvfb.hpp"
#include "correction_feedback.hpp"
#include "workspace_actors.hpp"
#include "xr_frames.hpp"

using namespace sketchlab;
using sketchlab::test::CliRun;
using sketchlab::test::EyeImage;
using sketchlab::test::run_captured;
using sketchlab::test::xyz;
namespace fs = std::filesystem;
using openxr::MenuItem;

namespace {

// Pitched down 25°: the floor is in view.
const std::string head_down = "head=0,1.5,0.6,-0.21644,0,0,0.97630";
const Vec3 left_hand(-0.15, 1.2, 0.1);

openxr::RigidPose left_pose() {
  openxr::RigidPose p;
  p.position = left_hand;
  return p;
}

// A point in the lower part of a menu square (the label is in the upper part).
Vec3 on_item(MenuItem item, double dx = 0.0, double dy = -0.3) {
  return openxr::menu_item_centre(left_pose(), item) + openxr::menu_cell * Vec3(dx, dy, 0.0);
}

// Lines that touch `item` with the tip, pull the trigger and let go.
std::string press(MenuItem item) {
  const std::string at = "right=" + xyz(openxr::menu_item_centre(left_pose(), item));
  return "frame " + at + "\nframe 2 " + at + " right/input/trigger/value=0.9\nframe " + at +
         " right/input/trigger/value=0\n";
}

bool red(const unsigned char* p) { return p[0] > p[1] + 50 && p[0] > p[2] + 50; }

#ifdef SKETCHLAB_TEST_XR_RUNTIME_JSON

CliRun run_vr(const fs::path& dir, const std::string& script, const std::string& config = "configs/stacks/cassie.yaml") {
  std::ofstream(dir / "script.txt") << script;
  const CliRun r =
      run_captured(test::vr_command(dir / "script.txt", dir, SKETCHLAB_TEST_XR_RUNTIME_JSON, config) + " --overwrite");
  INFO(r.output);
  REQUIRE(r.status == 0);
  return r;
}

#endif

}  // namespace

TEST_CASE("the scale bar is a round workspace length of 3 to 7.5 cm on the stage", "[openxr]") {
  for (double s : {0.05, 0.1, 0.37, 1.0, 1.5, 2.0, 7.3, 20.0}) {
    const auto [length, label] = vr::scale_bar(s);
    INFO(s << " " << length << " " << label);
    CHECK(length * s >= 0.03 - 1e-12);
    CHECK(length * s < 0.075);
    const double mantissa = length / std::pow(10.0, std::floor(std::log10(length) + 1e-9));
    CHECK((std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9));
  }
  CHECK(vr::scale_bar(1.0).second == "5 cm");
  CHECK(vr::scale_bar(0.05).second == "1 m");
  CHECK(vr::scale_bar(20.0).second == "2 mm");
  CHECK(vr::flash_opacity(0.0) == 1.0);
  CHECK(vr::flash_opacity(vr::flash_s) == 0.0);
  CHECK(vr::flash_opacity(0.9 * vr::flash_s) < 1.0);
}

#ifdef SKETCHLAB_TEST_XR_RUNTIME_JSON

TEST_CASE("the stage, the brush tip at the aim pose and the menu's state are drawn", "[openxr][viewer]") {
  test::ensure_display();
  const auto dir = test::fresh_vr_dir("stage");
  const Vec3 tip(0.08, 1.35, 0.25);
  std::ostringstream s;
  // 640 x 480: a menu square is about 16 px across.
  s << "option eye_size 640 480\noption fov 45 36\noption dump_dir " << dir.string() << "\n"
    << "frame 3 " << head_down << " left=" << xyz(left_hand) << " right=" << xyz(tip) << "\nframe dump\n"  // 3
    << "frame right=" << xyz(openxr::menu_item_centre(left_pose(), MenuItem::undo)) << " dump\n"            // 4
    << press(MenuItem::shape) << "frame 2 right=" << xyz(tip) << "\nframe dump\n";                          // 11
  const CliRun r = run_vr(dir, s.str());
  // Menu picks record what they change and nothing else: one mode event.
  const Recording rec = read_recording(dir / "vr.jsonl");
  REQUIRE(rec.events.size() == 1);
  CHECK(std::get<ModeEvent>(rec.events[0].payload).mode == Layer::shape);

  const EyeImage first(test::dump_stem(dir, 3, 0)), hover(test::dump_stem(dir, 4, 0)),
      picked(test::dump_stem(dir, 11, 0));
  SECTION("ground to the horizon under the sky, floor grid lines") {
    for (const Vec3& p : {Vec3(0, 0, -1.25), Vec3(0, 0, -1.75), Vec3(0.25, 0, -1.0), Vec3(-0.25, 0, -1.0)}) {
      INFO(p.transpose());
      int best = 1000;
      for (double e : {-0.004, 0.0, 0.004})  // the line is 1-2 px wide
        best = std::min({best, first.distance(p + Vec3(e, 0, 0), vr::floor_line_colour),
                         first.distance(p + Vec3(0, 0, e), vr::floor_line_colour)});
      CHECK(best <= 12);
    }
    for (const Vec3& p : {Vec3(0.25, 0, -1.25), Vec3(-0.25, 0, -1.75), Vec3(0.75, 0, -2.25), Vec3(0, 0, -30)}) {
      INFO(p.transpose());
      CHECK(first.distance(p, vr::ground_colour) <= 3);
    }
    CHECK(first.distance(Vec3(0, 1.9, -5), vr::sky_colour) <= 3);
  }
  SECTION("the brush tip is at the aim point, in the mode's colour once a mode is picked") {
    const auto at = [](const EyeImage& img, const Vec3& p) {
      const Vec2 q = img.pixel(p);
      return img.image.at(int(q.x()), int(q.y()));
    };
    CHECK_FALSE(red(at(first, tip)));  // auto mode: grey
    CHECK(red(at(picked, tip)));       // shape: red
    CHECK_FALSE(red(at(picked, tip + Vec3(0.02, 0, 0))));
    CHECK_FALSE(red(at(picked, tip + Vec3(-0.02, 0, 0))));
    CHECK_FALSE(red(at(picked, tip + Vec3(0, 0.02, 0))));
  }
  SECTION("menu items: correction and raw strokes on, the hovered item highlighted, the picked mode lit") {
    CHECK(first.distance(on_item(MenuItem::correction), vr::menu_active_colour) <= 3);
    CHECK(first.distance(on_item(MenuItem::raw_strokes), vr::menu_active_colour) <= 3);
    for (MenuItem item : {MenuItem::scaffold, MenuItem::shape, MenuItem::undo, MenuItem::compare, MenuItem::rejected})
      CHECK(first.distance(on_item(item), vr::menu_item_colour) <= 3);
    // The tip covers the middle of the hovered square: look around it.
    int lit = 0;
    const std::pair<double, double> around[] = {{-0.3, -0.3}, {0.0, -0.3}, {0.3, -0.3}, {-0.3, 0.3}, {0.3, 0.3}};
    for (const auto& [dx, dy] : around)
      lit += hover.distance(on_item(MenuItem::undo, dx, dy), vr::menu_hover_colour) <= 3;
    CHECK(lit >= 3);
    CHECK(hover.distance(on_item(MenuItem::redo), vr::menu_item_colour) <= 3);
    CHECK(picked.distance(on_item(MenuItem::shape), vr::menu_active_colour) <= 3);
    CHECK(picked.distance(on_item(MenuItem::scaffold), vr::menu_item_colour) <= 3);
    CHECK(picked.distance(on_item(MenuItem::undo), vr::menu_item_colour) <= 3);
  }
  fs::remove_all(dir);
}

TEST_CASE("a stroke stays until corrected, then the snapped curve glows in and its constraints flash and go",
          "[openxr][viewer]") {
  test::ensure_display();
  const auto dir = test::fresh_vr_dir("feedback");
  std::ostringstream s;
  // Paced at 90 Hz: the worker's wall time and the display time go together.
  s << "option eye_size 320 240\noption fov 45 36\noption frame_ms 11.1\noption dump_dir " << dir.string() << "\n"
    << "frame 4 head=0,1.5,0.6 left=-0.6,1.0,0.4 right=-0.15,1.4,0\nframe dump\n";  // 4: reference
  int frame = 5;
  std::vector<Vec3> first, second;
  for (int k = 0; k <= 20; ++k, ++frame) {
    first.emplace_back(-0.15 + 0.01 * k, 1.4, 0.0);
    s << "frame right=" << xyz(first.back()) << " right/input/trigger/value=0.8\n";
  }
  s << "frame 30 right/input/trigger/value=0\n";
  frame += 30;
  // The second stroke starts 6 mm from the first one's curve, which ends
  // 0.02 s of motion before its last sample (cassie's default
  // trim_last_end): at 1 cm a frame, 1.8 cm short of x = 0.05. A snap.
  for (int k = 0; k <= 20; ++k, ++frame) {
    second.emplace_back(0.038, 1.404 + 0.01 * k, 0.0);
    s << "frame right=" << xyz(second.back()) << " right/input/trigger/value=0.8\n";
  }
  const int release = frame;
  s << "frame right/input/trigger/value=0 right=0.3,1.3,0\n";  // released (hand away)
  const std::vector<int> dumps{release + 1, release + 12, release + 40, release + 80, release + 400};
  int at = release + 1;
  for (int d : dumps) {
    if (d > at) s << "frame " << d - at << "\n";
    s << "frame dump\n";
    at = d + 1;
  }
  run_vr(dir, s.str());
  const Recording rec = read_recording(dir / "vr.jsonl");
  REQUIRE(rec.events.size() == 2);

  // What cassie did with the second stroke (replaying the recording).
  const ReplayResult replayed = test::cassie_replay(rec, rec.events.size());
  const Sketch& sketch = replayed.session.sketch();
  std::vector<Vec3> snaps;  // where the enforced point constraints of the second stroke act (their markers)
  for (const Constraint& c : replayed.steps.at(1).constraints)
    if (c.enforced && (c.kind == ConstraintKind::coincident_point || c.kind == ConstraintKind::point_on_curve ||
                       c.kind == ConstraintKind::intersection))
      for (const Vec3& p : viewer::constraint_anchors(c, sketch)) snaps.push_back(p);
  REQUIRE_FALSE(snaps.empty());
  std::vector<Vec3> corrected;  // the second stroke's curves
  for (const auto& [id, c] : sketch.network.curves())
    if (c.source_stroke == 2)
      for (int i = 0; i <= 40; ++i) corrected.push_back(evaluate(c.curve, c.curve.t_max() * i / 40));
  REQUIRE_FALSE(corrected.empty());

  const auto image = [&](int i) { return EyeImage(test::dump_stem(dir, dumps[static_cast<std::size_t>(i)], 0)); };
  const auto count = [](const EyeImage& img, const std::vector<Vec3>& points, auto&& wanted, int radius) {
    int n = 0;
    for (const Vec3& p : points) {
      const Vec2 q = img.pixel(p);
      bool hit = false;
      for (int dy = -radius; dy <= radius && !hit; ++dy)
        for (int dx = -radius; dx <= radius && !hit; ++dx) {
          const int x = int(q.x()) + dx, y = int(q.y()) + dy;
          hit = img.image.inside(x, y) && wanted(img.image.at(x, y));
        }
      n += hit;
    }
    return n;
  };
  const auto dark = [](const unsigned char* p) { return p[0] < 90 && p[1] < 90 && p[2] < 100; };
  const auto glowing = [](const unsigned char* p) { return p[2] > p[0] + 60 && p[2] > 150; };
  const auto marker = [](const unsigned char* p) { return p[1] > p[0] + 60 && p[1] > p[2] + 40; };
  // One frame after release the raw stroke is drawn as it was (pending or
  // just starting to fade): nothing blinks away while the stack works.
  const EyeImage just_released = image(0);
  CHECK(count(just_released, second, dark, 1) >= int(0.9 * second.size()));
  // Within the next second the corrected curve glows and the snap flashes
  // at the point it joined.
  int glow = 0, flashed = 0;
  for (int i = 1; i <= 3; ++i) {
    const EyeImage img = image(i);
    // The glow is a halo two pixels wider than the curve, which stays on top.
    glow = std::max(glow, count(img, corrected, glowing, 3));
    flashed = std::max(flashed, count(img, snaps, marker, 4));
  }
  CHECK(glow >= int(0.5 * corrected.size()));
  CHECK(flashed == int(snaps.size()));
  // Long after: the curve is drawn plainly, nothing flashes.
  const EyeImage settled = image(4);
  CHECK(count(settled, corrected, glowing, 3) == 0);
  CHECK(count(settled, snaps, marker, 6) == 0);
  CHECK(count(settled, corrected, dark, 1) >= int(0.9 * corrected.size()));
  fs::remove_all(dir);
}

TEST_CASE("the menu switches the shown stack and overlays the other one", "[openxr][viewer]") {
  test::ensure_display();
  const auto dir = test::fresh_vr_dir("stacks");
  std::ostringstream s;
  s << "option eye_size 320 240\noption fov 45 36\noption frame_ms 11.1\noption dump_dir " << dir.string() << "\n"
    << "frame 3 " << head_down << " left=" << xyz(left_hand) << " right=0.05,1.3,0\n";
  std::vector<Vec3> stroke;
  for (int k = 0; k <= 30; ++k) {
    const double a = 2.0 * 3.14159265358979 * k / 30.0;
    stroke.emplace_back(0.08 + 0.06 * std::cos(a), 1.3 + 0.06 * std::sin(a), -0.05);
    s << "frame right=" << xyz(stroke.back()) << " right/input/trigger/value=0.8\n";
  }
  s << "frame 60 right/input/trigger/value=0 right=0.3,1.1,0.2\n"
    << press(MenuItem::compare) << "frame 20 right=0.3,1.1,0.2\nframe dump\n"
    << press(MenuItem::next_stack) << press(MenuItem::compare) << "frame 20 right=0.3,1.1,0.2\nframe dump\n";
  const CliRun r = run_vr(dir, s.str(), "configs/compare.yaml");
  CHECK_THAT(r.output, Catch::Contains("drawing with stacks 'freehand', 'cassie'"));
  CHECK_THAT(r.output, Catch::Contains("showing stack 'freehand' with 'cassie' overlaid"));
  CHECK_THAT(r.output, Catch::Contains("showing stack 'cassie' with 'freehand' overlaid"));
  CHECK_THAT(r.output, Catch::Contains("showing stack 'cassie'\n"));
  // Both stacks saw the one stroke; the menu's view changes are not events.
  const Recording rec = read_recording(dir / "vr.jsonl");
  CHECK(rec.events.size() == 1);
  CHECK(rec.header.source.at("stack") == "freehand");

  // Frames: 3 still, 31 drawing, 60 waiting, a press is 4, 20 still, dump.
  const int compare_frame = 3 + 31 + 60 + 4 + 20, single_frame = compare_frame + 1 + 2 * 4 + 20;
  // The overlay's colour through the tube shading (dark edges, highlights).
  const auto orange = [](const unsigned char* p) { return p[0] > 120 && p[0] > p[1] + 40 && p[1] > p[2] + 30 && p[2] < 90; };
  const auto orange_near_stroke = [&](int f) {
    const EyeImage img(test::dump_stem(dir, f, 0));
    int n = 0;
    for (const Vec3& p : stroke) {
      const Vec2 q = img.pixel(p);
      bool hit = false;
      for (int dy = -4; dy <= 4 && !hit; ++dy)
        for (int dx = -4; dx <= 4 && !hit; ++dx) {
          const int x = int(q.x()) + dx, y = int(q.y()) + dy;
          hit = img.image.inside(x, y) && orange(img.image.at(x, y));
        }
      n += hit;
    }
    return n;
  };
  CHECK(orange_near_stroke(compare_frame) >= int(0.8 * stroke.size()));
  CHECK(orange_near_stroke(single_frame) == 0);
  fs::remove_all(dir);
}

#endif
