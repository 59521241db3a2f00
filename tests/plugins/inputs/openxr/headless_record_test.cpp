// The openxr input on its own (headless OpenXR session) through the real
// loader and the test runtime: `sketchlab record --input openxr`.
#include <catch2/catch.hpp>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "cli_helpers.hpp"
#include "sketchlab/recording/recording_reader.hpp"

#ifdef SKETCHLAB_TEST_XR_RUNTIME_JSON

using namespace sketchlab;
using sketchlab::test::CliRun;
using sketchlab::test::run_captured;

namespace {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("sketchlab_xr_input_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string env(const std::filesystem::path& script) {
  return std::string("XR_RUNTIME_JSON=") + SKETCHLAB_TEST_XR_RUNTIME_JSON + " SKETCHLAB_XR_SCRIPT=" + script.string() + " ";
}

}  // namespace

TEST_CASE("record --input openxr reads the scripted controllers through the loader", "[openxr]") {
  const auto dir = fresh_dir("record");
  const auto script = dir / "script.txt";
  {
    std::ofstream s(script);
    s << "frame 3 right=0,1.2,-0.3\n";
    for (int i = 0; i <= 10; ++i) s << "frame right=" << 0.02 * i << ",1.2,-0.3 right/input/trigger/value=0.5\n";
    s << "frame 2 right/input/trigger/value=0\n"
         "frame 2 left/input/x/click=1\n"
         "frame 2 left/input/x/click=0\n";
  }
  const auto out = dir / "rec.jsonl";
  const CliRun r = run_captured(env(script) + SKETCHLAB_CLI " record --input openxr -o " + out.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  const Recording rec = read_recording(out);
  CHECK(rec.header.source.at("input") == "openxr");
  CHECK(rec.header.source.at("runtime") == "sketchlab test runtime");
  REQUIRE(rec.events.size() == 2);
  const auto& stroke = std::get<StrokeEvent>(rec.events[0].payload).stroke;
  REQUIRE(stroke.samples.size() == 11);
  for (int i = 0; i <= 10; ++i) {
    CHECK((stroke.samples[i].position - Vec3(0.02 * i, 1.2, -0.3)).norm() < 1e-6);
    CHECK(stroke.samples[i].pressure == Approx(0.5));
  }
  CHECK(std::holds_alternative<UndoEvent>(rec.events[1].payload));
  std::filesystem::remove_all(dir);
}

TEST_CASE("on a Monado-like headless runtime record skips the frame functions and uses its clock",
          "[openxr][reliability]") {
  // Issue 17: Monado returns from xrWaitFrame at once with display time 0 in
  // headless sessions, and its xrBeginFrame fails without a counted wait:
  // record used to fail on its first frame.
  const auto dir = fresh_dir("monado");
  const auto script = dir / "script.txt";
  {
    std::ofstream s(script);
    s << "option monado_headless 1\nframe 3 right=0,1.2,-0.3\n";
    for (int i = 0; i <= 10; ++i) s << "frame right=" << 0.02 * i << ",1.2,-0.3 right/input/trigger/value=0.5\n";
    s << "frame 2 right/input/trigger/value=0\n";
  }
  const auto out = dir / "rec.jsonl";
  const CliRun r = run_captured(env(script) + SKETCHLAB_CLI " record --input openxr --param headless_poll_hz=1000 -o " +
                                out.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  const Recording rec = read_recording(out);
  CHECK(rec.header.source.at("timing") == "runtime clock");
  REQUIRE(rec.events.size() == 1);
  const auto& stroke = std::get<StrokeEvent>(rec.events[0].payload).stroke;
  REQUIRE(stroke.samples.size() == 11);
  for (int i = 0; i <= 10; ++i) {
    CHECK((stroke.samples[i].position - Vec3(0.02 * i, 1.2, -0.3)).norm() < 1e-6);
    // One 90 Hz tick of the runtime's clock per poll, from the first poll.
    CHECK(stroke.samples[i].time == Approx((3 + i) / 90.0).margin(1e-9));
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("SIGTERM stops record cleanly: the stroke being drawn is kept", "[openxr][reliability]") {
  const auto dir = fresh_dir("sigterm");
  const auto script = dir / "script.txt";
  {
    // About 100 s of drawing at 1000 polls per second: it must be stopped.
    std::ofstream s(script);
    s << "option monado_headless 1\nframe 3 right=0,1.2,-0.3\n";
    // The signal goes when frame `mark` begins: five positions are drawn by
    // then, whatever the machine's speed (a fixed delay was flaky).
    for (int i = 0; i < 2000; ++i)
      s << "frame 50 right=" << 0.2 * std::cos(0.01 * i) << ",1.2," << 0.2 * std::sin(0.01 * i)
        << " right/input/trigger/value=0.5" << (i == 5 ? " mark" : "") << "\n";
  }
  const auto out = dir / "rec.jsonl";
  const auto log = dir / "log.txt";
  const CliRun r = test::run_until_then_signal(
      env(script) + SKETCHLAB_CLI " record --input openxr --param headless_poll_hz=1000 -o " + out.string(), log,
      "test runtime: mark", SIGTERM, 60.0);
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK_THAT(r.output, Catch::Contains("stopping (signal 15)") && Catch::Contains("1 events"));
  const Recording rec = read_recording(out);
  REQUIRE(rec.events.size() == 1);
  CHECK(std::get<StrokeEvent>(rec.events[0].payload).stroke.samples.size() > 2);
  std::filesystem::remove_all(dir);
}

TEST_CASE("without XR_MND_headless the input says to use `sketchlab vr`", "[openxr]") {
  const auto dir = fresh_dir("noheadless");
  const auto script = dir / "script.txt";
  std::ofstream(script) << "option headless 0\nframe 2\n";
  const CliRun r = run_captured(env(script) + SKETCHLAB_CLI " record --input openxr -o " + (dir / "rec.jsonl").string());
  CHECK(r.status == 1);
  CHECK_THAT(r.output, Catch::Contains("XR_MND_headless") && Catch::Contains("sketchlab vr"));
  std::filesystem::remove_all(dir);
}

#endif
