// `sketchlab vr` end to end through Debian's OpenXR loader and the test
// runtime (tests/fixtures/openxr_runtime): a scripted session draws a
// square and a line with the trigger, undoes once, grabs and zooms. The
// recording must hold exactly those events, replay to the same sketch, and
// the frames the runtime read back from the swapchains must show the
// strokes where they project (against a frame dumped before drawing: the
// stage, the hands and the menu are the same in both).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_helpers.hpp"
#include "constraint_markers.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "test_paths.hpp"
#include "viewers/xvfb.hpp"
#include "xr_frames.hpp"

#ifdef SKETCHLAB_TEST_XR_RUNTIME_JSON

using namespace sketchlab;
using sketchlab::test::CliRun;
using sketchlab::test::run_captured;
namespace fs = std::filesystem;

namespace {

constexpr double dt = 1.0 / 90.0;

using test::fresh_vr_dir;
using test::Image;
using test::vr_command;
using test::xyz;

// The scripted session; frame numbers of interest are returned.
struct Scenario {
  std::vector<Vec3> square, line;  // scripted hand positions while drawing
  int dump_reference = 0, square_start = 0, line_start = 0, dump_drawing = 0, dump_done = 0;
};

Scenario write_script(const fs::path& path, const fs::path& dump_dir) {
  Scenario sc;
  std::ofstream s(path);
  // Paced at 90 Hz like a headset, so corrections arrive within the frames
  // a user would wait.
  s << "option eye_size 320 240\noption fov 45 36\noption frame_ms 11.1\noption dump_dir " << dump_dir.string()
    << "\n";
  int frame = 0;
  auto emit = [&](const std::string& line, int count = 1) {
    s << "frame " << count << " " << line << "\n";
    frame += count;
  };
  emit("head=0,1.5,0.6 left=-0.6,1.0,0.4 right=-0.1,1.4,0", 4);
  sc.dump_reference = frame;
  emit("dump");
  const Vec3 c[5] = {{-0.1, 1.4, 0}, {0.1, 1.4, 0}, {0.1, 1.6, 0}, {-0.1, 1.6, 0}, {-0.1, 1.4, 0}};
  sc.square_start = frame;
  for (int e = 0; e < 4; ++e)
    for (int k = 0; k < 10; ++k) {
      sc.square.push_back(c[e] + (c[e + 1] - c[e]) * (k / 10.0));
      emit("right=" + xyz(sc.square.back()) + " right/input/trigger/value=0.8");
    }
  sc.square.push_back(c[4]);
  emit("right=" + xyz(c[4]));
  emit("right/input/trigger/value=0");
  emit("", 5);
  sc.line_start = frame;
  for (int k = 0; k <= 20; ++k) {
    sc.line.push_back(Vec3(-0.15 + 0.3 * k / 20.0, 1.3, 0.0));
    const bool dump = k == 12;
    if (dump) sc.dump_drawing = frame;
    emit("right=" + xyz(sc.line.back()) + " right/input/trigger/value=0.6" + (dump ? " dump" : ""));
  }
  emit("right/input/trigger/value=0");
  // Long enough for the correction's transition and flashes to be over.
  emit("", 199);
  sc.dump_done = frame;
  emit("dump");
  emit("left/input/x/click=1", 3);  // undo (Touch: left X)
  emit("left/input/x/click=0", 5);
  // One-hand grab: the workspace follows the left hand.
  emit("left/input/squeeze/value=1");
  for (int k = 1; k <= 10; ++k) emit("left=" + xyz(Vec3(-0.6 + 0.01 * k, 1.0, 0.4)));
  emit("left/input/squeeze/value=0", 5);
  // Two-hand zoom from 0.4 m to 0.6 m between the hands: s = 1.5.
  for (int k = 0; k <= 10; ++k)
    emit("left=" + xyz(Vec3(-0.2 - 0.01 * k, 1.4, -0.1)) + " right=" + xyz(Vec3(0.2 + 0.01 * k, 1.4, -0.1)) +
         " left/input/squeeze/value=1 right/input/squeeze/value=1");
  emit("left/input/squeeze/value=0 right/input/squeeze/value=0", 5);
  return sc;
}

// Differs from the reference frame (same pixel) by more than 30 of 255.
bool drawn(const Image& img, const Image& reference, int x, int y) {
  if (!img.inside(x, y)) return false;
  const unsigned char *p = img.at(x, y), *q = reference.at(x, y);
  int diff = 0;
  for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(int(p[c]) - int(q[c])));
  return diff > 30;
}

double distance_to_polyline(const Vec2& q, const std::vector<Vec2>& line) {
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const Vec2 a = line[i], b = line[i + 1], ab = b - a;
    const double t = ab.squaredNorm() > 0 ? std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * ab - q).norm());
  }
  if (line.size() == 1) best = (line[0] - q).norm();
  return best;
}

struct FrameCheck {
  double visible = 0;   // fraction of `must_show` points with a drawn pixel within 2 px
  double explained = 0; // fraction of drawn pixels within 6 px of `allowed` strokes or the hand
  int drawn_pixels = 0;
};

// `around` are points (hands then and in the reference, constraint markers)
// whose neighbourhood may change too.
FrameCheck check_frame(const fs::path& stem, const fs::path& reference_stem,
                       const std::vector<std::vector<Vec3>>& must_show, const std::vector<std::vector<Vec3>>& allowed,
                       const std::vector<Vec3>& around) {
  const test::EyeImage frame(stem), reference(reference_stem);
  const Image& img = frame.image;
  FrameCheck r;
  int shown = 0, total = 0;
  for (const auto& stroke : must_show)
    for (const Vec3& p : stroke) {
      const Vec2 q = frame.pixel(p);
      bool hit = false;
      for (int dy = -2; dy <= 2 && !hit; ++dy)
        for (int dx = -2; dx <= 2 && !hit; ++dx)
          hit = drawn(img, reference.image, int(std::lround(q.x())) + dx, int(std::lround(q.y())) + dy);
      shown += hit;
      ++total;
    }
  r.visible = total ? double(shown) / total : 0.0;
  std::vector<std::vector<Vec2>> lines;
  for (const auto& stroke : allowed) {
    lines.emplace_back();
    for (const Vec3& p : stroke) lines.back().push_back(frame.pixel(p));
  }
  std::vector<Vec2> spots;
  for (const Vec3& p : around) spots.push_back(frame.pixel(p));
  int explained = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (!drawn(img, reference.image, x, y)) continue;
      ++r.drawn_pixels;
      const Vec2 q(x + 0.5, y + 0.5);
      bool ok = false;
      for (const Vec2& s : spots) ok = ok || (q - s).norm() < 25.0;
      for (const auto& l : lines) ok = ok || distance_to_polyline(q, l) < 6.0;
      explained += ok;
    }
  r.explained = r.drawn_pixels ? double(explained) / r.drawn_pixels : 0.0;
  return r;
}

// The stack's sketch after the first `events` events of `rec`.
Sketch replay_prefix(const Recording& rec, std::size_t events) {
  return test::cassie_replay(rec, events).session.sketch();
}

// Where the constraints enforced on the first `events` events act (their
// markers may still be flashing).
std::vector<Vec3> constraint_points(const Recording& rec, std::size_t events) {
  const ReplayResult result = test::cassie_replay(rec, events);
  std::vector<Vec3> out;
  for (const StepReport& step : result.steps)
    for (const Constraint& c : step.constraints)
      if (c.enforced)
        for (const Vec3& p : viewer::constraint_anchors(c, result.session.sketch())) out.push_back(p);
  return out;
}

// Each corrected curve as a polyline (stage = workspace before any grab).
std::vector<std::vector<Vec3>> curve_polylines(const Sketch& sketch) {
  std::vector<std::vector<Vec3>> out;
  for (const auto& [id, c] : sketch.network.curves()) {
    out.emplace_back();
    const int n = 50 * c.curve.segment_count();
    for (int i = 0; i <= n; ++i) out.back().push_back(evaluate(c.curve, c.curve.t_max() * i / n));
  }
  return out;
}

}  // namespace

TEST_CASE("a scripted VR session records exactly what was done and replays identically", "[openxr][viewer]") {
  test::ensure_display();
  const auto dir = fresh_vr_dir("session");
  const auto dumps = dir / "frames";
  fs::create_directories(dumps);
  const Scenario sc = write_script(dir / "script.txt", dumps);
  const CliRun r = run_captured(vr_command(dir / "script.txt", dir, SKETCHLAB_TEST_XR_RUNTIME_JSON));
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("4 events recorded"));

  const Recording rec = read_recording(dir / "vr.jsonl");
  CHECK(rec.header.units == "m");
  CHECK(rec.header.source.at("input") == "openxr");
  REQUIRE(rec.events.size() == 4);
  const auto& square = std::get<StrokeEvent>(rec.events[0].payload).stroke;
  const auto& line = std::get<StrokeEvent>(rec.events[1].payload).stroke;
  CHECK(std::holds_alternative<UndoEvent>(rec.events[2].payload));
  const auto& ws = std::get<WorkspaceEvent>(rec.events[3].payload).workspace;

  SECTION("strokes are the scripted hand positions, pressures and times") {
    REQUIRE(square.samples.size() == sc.square.size());
    REQUIRE(line.samples.size() == sc.line.size());
    for (std::size_t i = 0; i < sc.square.size(); ++i) {
      CHECK((square.samples[i].position - sc.square[i]).norm() < 1e-6);
      CHECK(square.samples[i].pressure == Approx(0.8).margin(1e-6));
      CHECK(square.samples[i].time == Approx((sc.square_start + int(i)) * dt).margin(1e-9));
    }
    for (std::size_t i = 0; i < sc.line.size(); ++i) {
      CHECK((line.samples[i].position - sc.line[i]).norm() < 1e-6);
      CHECK(line.samples[i].pressure == Approx(0.6).margin(1e-6));
    }
    CHECK(square.id == 1);
    CHECK(line.id == 2);
    CHECK(square.view.has_value());
    CHECK(square.workspace_scale == 1.0);
  }
  SECTION("the zoom is recorded as the workspace scale (hands 0.4 m -> 0.6 m apart)") {
    CHECK(ws.scale == Approx(1.5).epsilon(1e-6));
    for (std::size_t i = 1; i < rec.events.size(); ++i) CHECK(rec.events[i].time >= rec.events[i - 1].time);
  }
  SECTION("the corrected curves equal those of replaying the recording") {
    const Sketch replayed = replay_prefix(rec, rec.events.size());
    std::ifstream live(dir / "vr_sketch.json");
    std::stringstream text;
    text << live.rdbuf();
    CHECK(text.str() == sketch_to_json(replayed));
    // The undo took the line back: only the square's curves remain.
    REQUIRE_FALSE(replayed.network.curves().empty());
    for (const auto& [id, c] : replayed.network.curves()) CHECK(c.source_stroke == 1);
    CHECK(replayed.workspace.scale == Approx(1.5).epsilon(1e-6));
    // And through `sketchlab run` (its sketch.json adds the constraints each
    // stroke considered; everything else must match byte for byte).
    std::ofstream(dir / "replay.yaml") << "experiment: vr-replay\nrecordings: [vr.jsonl]\n"
                                          "stacks:\n  - name: cassie\n    corrector: {plugin: cassie, params: {mirror: plane}}\n"
                                          "outputs: {dir: runs, timestamp: false, pictures: false}\n";
    const CliRun ran = run_captured("cd " + dir.string() + " && " SKETCHLAB_CLI " run replay.yaml --no-timings");
    INFO(ran.output);
    REQUIRE(ran.status == 0);
    std::ifstream cli_file(dir / "runs/vr-replay/vr/cassie/sketch.json");
    const auto from_run = nlohmann::json::parse(cli_file);
    const auto from_vr = nlohmann::json::parse(text.str());
    for (const char* key : {"workspace", "counters", "curves", "nodes", "segments", "patches", "strokes"}) {
      INFO(key);
      CHECK(from_run.at(key) == from_vr.at(key));
    }
  }
  SECTION("frames read back from the swapchains show the strokes where they project") {
    // Drawn pixels must be raw strokes or the corrected curves (as replay
    // computes them), nothing else but the controller.
    auto allowed_during = curve_polylines(replay_prefix(rec, 1));
    auto allowed_after = curve_polylines(replay_prefix(rec, 2));
    const Vec3 hand_at_reference(-0.1, 1.4, 0);
    for (int eye = 0; eye < 2; ++eye) {
      const auto reference = dumps / ("frame" + std::to_string(sc.dump_reference) + "_eye" + std::to_string(eye));
      // While drawing the line: the stroke in progress is drawn by the
      // render thread itself (the square may or may not be corrected yet).
      std::vector<Vec3> drawn_so_far;
      for (const auto& s : line.samples)
        if (s.time <= sc.dump_drawing * dt + 1e-9) drawn_so_far.push_back(s.position);
      REQUIRE(drawn_so_far.size() == 13);
      const auto stem1 = dumps / ("frame" + std::to_string(sc.dump_drawing) + "_eye" + std::to_string(eye));
      auto allowed = allowed_during;
      allowed.push_back(drawn_so_far);
      allowed.push_back(sc.square);
      std::vector<Vec3> around = constraint_points(rec, 1);
      around.push_back(drawn_so_far.back());
      around.push_back(hand_at_reference);
      const FrameCheck during = check_frame(stem1, reference, {drawn_so_far}, allowed, around);
      CHECK(during.drawn_pixels > 50);
      CHECK(during.visible >= 0.9);
      CHECK(during.explained >= 0.97);
      // 200 frames after the line: both strokes are corrected and shown.
      const auto stem2 = dumps / ("frame" + std::to_string(sc.dump_done) + "_eye" + std::to_string(eye));
      allowed = allowed_after;
      allowed.push_back(sc.square);
      allowed.push_back(sc.line);
      const FrameCheck after = check_frame(stem2, reference, {sc.square, sc.line}, allowed, {sc.line.back(), hand_at_reference});
      CHECK(after.drawn_pixels > 100);
      CHECK(after.visible >= 0.9);
      CHECK(after.explained >= 0.97);
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("focus loss and session loss keep what was drawn", "[openxr][viewer]") {
  test::ensure_display();
  const auto dir = fresh_vr_dir("states");
  const auto script = dir / "script.txt";
  auto write = [&](const std::string& option) {
    std::ofstream s(script);
    s << option << "\nframe 5 head=0,1.5,0.6 right=0,1.4,0\n";
    for (int f = 5; f <= 30; ++f)
      s << "frame right=" << 0.005 * f << ",1.4,0 right/input/trigger/value=0.7" << (f >= 20 ? " left/input/x/click=1" : "")
        << "\n";
    s << "frame 5 right/input/trigger/value=0 left/input/x/click=0\n";
  };
  SECTION("focus lost mid-stroke: the stroke ends there, a button held across the loss does not fire") {
    // Input goes away from frame 15 to 25 (the runtime reports VISIBLE).
    write("option unfocus_at 15\noption refocus_at 25");
    const CliRun r = run_captured(vr_command(script, dir, SKETCHLAB_TEST_XR_RUNTIME_JSON));
    INFO(r.output);
    REQUIRE(r.status == 0);
    const Recording rec = read_recording(dir / "vr.jsonl");
    REQUIRE(rec.events.size() == 2);
    const auto& first = std::get<StrokeEvent>(rec.events[0].payload).stroke;
    const auto& second = std::get<StrokeEvent>(rec.events[1].payload).stroke;
    REQUIRE(first.samples.size() == 10);  // frames 5..14
    CHECK(first.samples.front().time == Approx(5 * dt).margin(1e-9));
    CHECK(first.samples.back().time == Approx(14 * dt).margin(1e-9));
    CHECK(second.samples.front().time > 25 * dt - 1e-9);
  }
  SECTION("session lost: exit status 1 with a message, the recording keeps the stroke") {
    write("option lose_at 20");
    const CliRun r = run_captured(vr_command(script, dir, SKETCHLAB_TEST_XR_RUNTIME_JSON));
    INFO(r.output);
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains("lost the session") && Catch::Contains("vr.jsonl"));
    const Recording rec = read_recording(dir / "vr.jsonl");
    REQUIRE(rec.events.size() == 1);
    CHECK(std::get<StrokeEvent>(rec.events[0].payload).stroke.samples.size() == 15);  // frames 5..19
  }
  fs::remove_all(dir);
}

TEST_CASE("the grid near the hand and the mirror plane are drawn when the workspace enables them",
          "[openxr][viewer]") {
  test::ensure_display();
  const auto dir = fresh_vr_dir("helpers");
  // The same frame with and without them: what differs is theirs.
  auto frame = [&](const std::string& flags, const std::string& name) {
    const auto dumps = dir / name;
    fs::create_directories(dumps);
    std::ofstream(dir / "script.txt") << "option eye_size 320 240\noption fov 45 36\noption dump_dir " << dumps.string()
                                      << "\nframe 3 head=0.5,1.5,0.6 left=-0.6,1.0,0.4 right=0.1,1.45,0\nframe dump\n";
    const CliRun r = run_captured(vr_command(dir / "script.txt", dir, SKETCHLAB_TEST_XR_RUNTIME_JSON) + " --overwrite" +
                                  flags);
    INFO(r.output);
    REQUIRE(r.status == 0);
    return test::EyeImage(dumps / "frame3_eye0");
  };
  const test::EyeImage plain = frame("", "plain");
  const test::EyeImage shown = frame(" --grid 0.1 --mirror", "helpers");
  const Recording rec = read_recording(dir / "vr.jsonl");
  CHECK(rec.header.workspace.grid_enabled);
  CHECK(rec.header.workspace.grid_spacing == 0.1);
  CHECK(rec.header.workspace.mirror_enabled);
  const Image& img = shown.image;
  auto differs = [&](const Vec3& p, int margin, int radius) {
    const Vec2 q = shown.pixel(p);
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const int x = int(std::lround(q.x())) + dx, y = int(std::lround(q.y())) + dy;
        if (!img.inside(x, y)) continue;
        for (int c = 0; c < 3; ++c)
          if (std::abs(int(img.at(x, y)[c]) - int(plain.image.at(x, y)[c])) > margin) return true;
      }
    return false;
  };
  // Grid points within two cells of the hand (cell (1, 14, 0) of 0.1 m).
  int shown_points = 0, total = 0;
  for (int i = -1; i <= 3; ++i)
    for (int j = 12; j <= 16; ++j) {
      const Vec3 p(0.1 * i, 0.1 * j, 0.0);
      const Vec2 q = shown.pixel(p);
      if (q.x() < 3 || q.y() < 3 || q.x() > img.width - 3 || q.y() > img.height - 3) continue;
      ++total;
      shown_points += differs(p, 30, 2);
    }
  CHECK(total >= 10);
  // (The pen in front of the hand hides up to three of them.)
  CHECK(shown_points >= total - 3);
  // The mirror plane x = 0 tints what lies behind it, away from grid points.
  CHECK(differs(Vec3(0.0, 1.45, -0.45), 8, 0));
  CHECK_FALSE(differs(Vec3(0.45, 1.75, -0.45), 8, 0));  // beyond the plane's edge, off the grid
  fs::remove_all(dir);
}

TEST_CASE("SIGTERM ends a VR session like Ctrl-C: recording closed, figures printed", "[openxr][viewer][reliability]") {
  // Issue 17: vr handled SIGINT only; SIGTERM killed it with no figures.
  test::ensure_display();
  const auto dir = fresh_vr_dir("sigterm");
  const auto script = dir / "script.txt";
  {
    std::ofstream s(script);
    for (int i = 0; i < 1000; ++i)
      s << "frame 10 right=" << 0.001 * i << ",1.2,-0.3 right/input/trigger/value=0.5" << (i == 20 ? " mark" : "")
        << "\n";
  }
  // Signalled mid-stroke, once frame `mark` begins (not after a guessed delay).
  const CliRun r = test::run_until_then_signal(vr_command(script, dir, SKETCHLAB_TEST_XR_RUNTIME_JSON),
                                               dir / "log.txt", "test runtime: mark", SIGTERM, 120.0);
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("events recorded in") && Catch::Contains(" frames, "));
  const Recording rec = read_recording(dir / "vr.jsonl");
  CHECK(rec.events.size() >= 1);  // the stroke being drawn
  fs::remove_all(dir);
}

TEST_CASE("vr warns at start when the stack's corrector corrects 2D strokes only", "[openxr][viewer]") {
  test::ensure_display();
  const auto dir = fresh_vr_dir("warn2d");
  const auto script = dir / "script.txt";
  std::ofstream(script) << "frame 5\n";
  const CliRun r = run_captured("XR_RUNTIME_JSON=" SKETCHLAB_TEST_XR_RUNTIME_JSON " SKETCHLAB_XR_SCRIPT=" +
                                script.string() + " " SKETCHLAB_CLI " vr " +
                                test::source_path("configs/stacks/justdrawit.yaml") + " -o " +
                                (dir / "vr.jsonl").string());
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("warning: ") && Catch::Contains("corrector 'justdrawit' corrects 2D (tablet) "
                                                                          "strokes only"));
  fs::remove_all(dir);
}

TEST_CASE("VR failures print one message saying what is missing and exit cleanly", "[openxr][viewer]") {
  test::ensure_display();
  const auto dir = fresh_vr_dir("failures");
  const auto script = dir / "script.txt";
  auto expect = [&](const std::string& options, const std::string& runtime, const std::string& message) {
    std::ofstream(script) << options << "frame 5\n";
    const CliRun r = run_captured(vr_command(script, dir, runtime));
    INFO(r.output);
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains(message));
    CHECK_THAT(r.output, !Catch::Contains("terminate") && !Catch::Contains("Segmentation"));
    CHECK_FALSE(fs::exists(dir / "vr.jsonl"));  // nothing half-made is left
  };
  SECTION("no runtime") { expect("", (dir / "missing_runtime.json").string(), "XR_RUNTIME_JSON"); }
  SECTION("runtime refuses the session") {
    expect("option refuse_session 1\n", SKETCHLAB_TEST_XR_RUNTIME_JSON, "refused the session");
  }
  SECTION("runtime without OpenGL") {
    expect("option no_opengl 1\n", SKETCHLAB_TEST_XR_RUNTIME_JSON, "XR_KHR_opengl_enable");
  }
  SECTION("no headset") { expect("option no_headset 1\n", SKETCHLAB_TEST_XR_RUNTIME_JSON, "reports no headset"); }
  fs::remove_all(dir);
}

#endif
