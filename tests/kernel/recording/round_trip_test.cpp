#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "random_recording.hpp"
#include "sketchlab/recording/event_json.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/recording/recording_writer.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

namespace {

std::string to_text(const Recording& r) {
  std::ostringstream os;
  write_recording(os, r);
  return os.str();
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A fresh scratch directory under the build tree, unique per test case.
std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = test::binary_path("tests/scratch/recording") + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("random recordings survive write -> read -> write exactly", "[recording][round_trip]") {
  for (std::uint64_t seed : {1u, 2u, 3u, 42u, 2024u}) {
    const Recording original = test::random_recording(seed, 120);
    const std::string text = to_text(original);
    std::istringstream in(text);
    const Recording read = parse_recording(in, "random");
    // Every double, flag and id comes back bit for bit.
    REQUIRE(read == original);
    CHECK(to_text(read) == text);
  }
}

TEST_CASE("one line per event, header first, newline-terminated", "[recording][round_trip]") {
  const Recording r = test::random_recording(9, 40);
  const std::string text = to_text(r);
  CHECK(std::count(text.begin(), text.end(), '\n') == 41);
  CHECK(text.back() == '\n');
  CHECK(text.rfind("{\"format\":\"sketchlab-recording\",\"version\":1,\"units\":\"m\",\"workspace\":", 0) == 0);
  const std::string second = text.substr(text.find('\n') + 1);
  CHECK(second.rfind("{\"t\":", 0) == 0);
}

TEST_CASE("samples are compact and orientation is written only when not identity", "[recording]") {
  Stroke s;
  s.id = 7;
  Sample a;
  a.position = Vec3(0.5, 1.25, -0.125);
  a.time = 1.5;
  Sample b = a;
  b.position.x() = 0.75;
  b.time = 1.75;
  b.pressure = 0.5;
  b.orientation = Quat(0.0, 1.0, 0.0, 0.0);
  s.samples = {a, b};
  const std::string line = to_json_line(Event{2.0, StrokeEvent{s}});
  CHECK(line ==
        "{\"t\":2.0,\"type\":\"stroke\",\"id\":7,\"layer\":\"auto\",\"workspace_scale\":1.0,"
        "\"samples\":[[0.5,1.25,-0.125,1.5,1.0],[0.75,1.25,-0.125,1.75,0.5,0.0,1.0,0.0,0.0]]}");
  CHECK(event_from_json_line(line) == Event{2.0, StrokeEvent{s}});
}

TEST_CASE("the bundled hat recording reads and rewrites byte for byte", "[recording][round_trip]") {
  const std::filesystem::path path = test::source_path("data/recordings/hat.jsonl");
  const std::string original = slurp(path);
  REQUIRE(!original.empty());
  const Recording r = read_recording(path);
  CHECK(to_text(r) == original);

  const std::filesystem::path copy = scratch("hat") / "hat.jsonl";
  write_recording(copy, r);
  CHECK(slurp(copy) == original);
}

TEST_CASE("RecordingWriter flushes every line and refuses to overwrite", "[recording][writer]") {
  const std::filesystem::path dir = scratch("writer");
  const std::filesystem::path path = dir / "live.jsonl";
  const Recording r = test::random_recording(5, 10);
  {
    RecordingWriter w(path, r.header);
    for (std::size_t i = 0; i < r.events.size(); ++i) {
      w.append(r.events[i]);
      // Without closing, the file already holds every finished line: a crash
      // now would lose nothing that was appended.
      const Recording partial = read_recording(path);
      CHECK(partial.events.size() == i + 1);
    }
    CHECK(w.lines_written() == r.events.size() + 1);
  }
  CHECK(read_recording(path) == r);

  CHECK_THROWS_WITH(RecordingWriter(path, r.header), Catch::Contains("already exists"));
  CHECK(read_recording(path) == r);  // untouched
  RecordingWriter replaced(path, r.header, /*overwrite=*/true);
  replaced.close();
  CHECK(read_recording(path).events.empty());
  CHECK_THROWS_AS(write_recording(path, r), std::runtime_error);
}

TEST_CASE("the writer refuses events the reader would reject, writing nothing", "[recording][writer]") {
  const std::filesystem::path path = scratch("writer_invalid") / "w.jsonl";
  RecordingWriter w(path, RecordingHeader{});
  Stroke s;
  s.id = 3;
  s.samples.resize(2);
  s.samples[1].position = Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  CHECK_THROWS_WITH(w.append(Event{1.0, StrokeEvent{s}}), Catch::Contains("non-finite position"));
  w.append(Event{2.0, UndoEvent{}});
  CHECK_THROWS_WITH(w.append(Event{1.0, RedoEvent{}}), Catch::Contains("earlier"));
  Curve open_curve;
  open_curve.control_points = {Vec3::Zero(), Vec3::UnitX()};
  CHECK_THROWS_AS(w.append(Event{3.0, ReferenceEvent{1, "x", open_curve}}), std::invalid_argument);
  w.close();
  const Recording r = read_recording(path);
  REQUIRE(r.events.size() == 1);
  CHECK(std::holds_alternative<UndoEvent>(r.events[0].payload));
}
