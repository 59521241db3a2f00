// `sketchlab render` end to end: sketch files in, a side-by-side PNG out.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "cli_helpers.hpp"
#include "scenes.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/viewer/png_image.hpp"
#include "xvfb.hpp"

using namespace sketchlab;
using namespace sketchlab::test;

namespace {

int dark_pixels(const viewer::RgbImage& img, int x0, int x1) {
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = x0; x < x1; ++x) n += is_dark(img, x, y);
  return n;
}

}  // namespace

TEST_CASE("sketchlab render writes one panel per sketch", "[viewer][cli]") {
  ensure_display();
  const auto dir = std::filesystem::temp_directory_path() / "sketchlab_test_cli_render";
  std::filesystem::create_directories(dir / "rec" / "a");
  std::filesystem::create_directories(dir / "rec" / "b");
  write_text_file(dir / "rec" / "a" / "sketch.json", sketch_to_json(square_sketch(0.3, true)));
  write_text_file(dir / "rec" / "b" / "sketch.json",
                  sketch_to_json(line_sketch({-0.3, -0.3, 0}, {0.3, 0.3, 0})));
  const auto png = dir / "out.png";
  std::filesystem::remove(png);

  const std::string cli = SKETCHLAB_CLI;
  const CliRun ok = run_captured(cli + " render " + (dir / "rec/a/sketch.json").string() + " " +
                     (dir / "rec/b/sketch.json").string() + " -o " + png.string() +
                     " --size 640x360 --view front");
  INFO(ok.output);
  REQUIRE(ok.status == 0);
  CHECK_THAT(ok.output, Catch::Contains("2 panel(s), 640x360"));
  const viewer::RgbImage img = viewer::read_png(png);
  CHECK(img.width == 640);
  CHECK(img.height == 360);
  // Both panels hold curves (titles are dark too, so compare the middle band).
  CHECK(dark_pixels(img, 20, 300) > 200);
  CHECK(dark_pixels(img, 340, 620) > 100);

  const CliRun bad_size = run_captured(cli + " render " + (dir / "rec/a/sketch.json").string() + " -o " +
                           png.string() + " --size 640by360");
  CHECK(bad_size.status != 0);
  CHECK_THAT(bad_size.output, Catch::Contains("WIDTHxHEIGHT"));

  const CliRun no_display = run_captured("env -u DISPLAY " + cli + " render " +
                             (dir / "rec/a/sketch.json").string() + " -o " +
                             (dir / "never.png").string());
  CHECK(no_display.status != 0);
  CHECK_THAT(no_display.output, Catch::Contains("no X display: run under xvfb-run"));
  CHECK_FALSE(std::filesystem::exists(dir / "never.png"));
}
