// The real `sketchlab view` window under Xvfb, driven with xdotool.
#include <catch2/catch.hpp>

#include <filesystem>

#include "gui_driver.hpp"
#include "sketchlab/desktop/replay_controller.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/viewer/png_image.hpp"
#include "stacks.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;
using Path = std::vector<std::pair<int, int>>;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("sketchlab_view_" + name + "_" +
                                                    std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Path line(std::pair<int, int> a, std::pair<int, int> b, int steps) {
  Path p;
  for (int i = 0; i <= steps; ++i)
    p.push_back({a.first + (b.first - a.first) * i / steps, a.second + (b.second - a.second) * i / steps});
  return p;
}

bool dark(const viewer::RgbImage& img, int x, int y) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return false;
  const auto* p = img.at(x, y);
  return std::max({p[0], p[1], p[2]}) < 110;
}

bool dark_near(const viewer::RgbImage& img, int x, int y, int r) {
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (dark(img, x + dx, y + dy)) return true;
  return false;
}

std::string wait_read(const fs::path& file) {
  REQUIRE(test::wait_for([&] { return fs::exists(file); }, 60));
  return read_text_file(file);
}

}  // namespace

TEST_CASE("drawing three strokes, undo, redo and save in the real window", "[desktop][gui]") {
  test::ensure_private_display();
  const fs::path dir = fresh_dir("draw");
  const fs::path record = dir / "live.jsonl", saved = dir / "saved.jsonl";
  const int width = 900, height = 500, half = width / 2;
  std::vector<Path> strokes{line({60, 150}, {380, 150}, 24), line({220, 190}, {220, 420}, 20),
                            line({100, 390}, {350, 390}, 24)};
  {
    test::ViewerProcess view({"view", test::source_path("configs/compare.yaml"), "--record",
                              record.string(), "--save", saved.string(), "--export-dir",
                              dir.string(), "--size", "900x500", "--multisamples", "0"},
                             dir / "view.log");
    for (const Path& s : strokes) view.drag(s);
    view.key("u");
    view.key("r");
    view.key("s");
    REQUIRE(test::wait_for([&] { return fs::exists(saved); }, 60));
    view.key("j");
    view.key("p");
    REQUIRE(test::wait_for([&] { return fs::exists(dir / "screenshot-1.png"); }, 60));
    view.key("q");
    CHECK(view.wait_exit(60) == 0);
  }
  INFO(read_text_file(dir / "view.log"));

  // The saved recording: three strokes then the two commands; the live
  // recording (appended while drawing) holds the same events.
  const Recording rec = read_recording(saved);
  REQUIRE(rec.events.size() == 5);
  for (int i = 0; i < 3; ++i) {
    const auto* s = std::get_if<StrokeEvent>(&rec.events[i].payload);
    REQUIRE(s);
    CHECK(s->stroke.is_2d());
    CHECK(s->stroke.draw_plane.has_value());
    CHECK(s->stroke.samples.size() >= 15);
  }
  CHECK(std::holds_alternative<UndoEvent>(rec.events[3].payload));
  CHECK(std::holds_alternative<RedoEvent>(rec.events[4].payload));
  CHECK(read_recording(record) == rec);

  // Replaying it gives the sketch each viewport showed (exported JSON).
  const auto stacks = test::compare_stacks();
  for (const StackInstance& stack : stacks) {
    RecordingInput input(rec);
    const ReplayResult r = replay(input, stack);
    CHECK(r.session.sketch().network.curves().size() >= 3);
    CHECK(sketch_to_json(r.session.sketch()) == wait_read(dir / (stack.name + ".json")));
  }

  // Every viewport shows dark pixels along the drawn paths, none elsewhere.
  const viewer::RgbImage img = viewer::read_png(dir / "screenshot-1.png");
  REQUIRE(img.width == width);
  REQUIRE(img.height == height);
  for (int v = 0; v < 2; ++v) {
    const int offset = v * half;
    for (const Path& s : strokes)
      for (std::size_t i = 2; i + 2 < s.size(); i += 2) {
        INFO("viewport " << v << " at " << s[i].first << "," << s[i].second);
        CHECK(dark_near(img, s[i].first + offset, s[i].second, 4));
      }
    int stray = 0;
    for (int y = 200; y <= 290; ++y)
      for (int x = 300; x <= 430; ++x) stray += dark(img, x + offset, y) ? 1 : 0;
    CHECK(stray == 0);
  }
  fs::remove_all(dir);
}

TEST_CASE("replay keys step through a bundled session in the real window", "[desktop][gui]") {
  test::ensure_private_display();
  const fs::path dir = fresh_dir("replay");
  const std::string recording = test::source_path("data/recordings/01-2-1.jsonl");
  const auto stacks = test::compare_stacks();
  desktop::ReplayController reference(read_recording(recording), stacks);
  auto expect_stop = [&](std::size_t stop) {
    reference.seek_stop(stop);
    for (std::size_t s = 0; s < stacks.size(); ++s) {
      const fs::path file = dir / (stacks[s].name + ".json");
      CHECK(wait_read(file) == sketch_to_json(reference.session(s).sketch()));
      fs::remove(file);
    }
  };
  test::ViewerProcess view({"view", test::source_path("configs/compare.yaml"), recording,
                            "--record", (dir / "live.jsonl").string(), "--export-dir",
                            dir.string(), "--size", "800x450", "--multisamples", "0"},
                           dir / "view.log");
  view.key("Right");
  view.key("Right");
  view.key("period");
  view.key("j");
  expect_stop(3);
  view.key("Left");
  view.key("j");
  expect_stop(2);
  view.key("Next");  // ten strokes on
  view.key("j");
  expect_stop(12);
  view.key("Home");
  view.key("j");
  expect_stop(0);
  view.key("q");
  CHECK(view.wait_exit(60) == 0);
  CHECK(!fs::exists(dir / "live.jsonl"));  // replaying records nothing
  fs::remove_all(dir);
}
