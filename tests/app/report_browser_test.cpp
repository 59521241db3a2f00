// The report in a real browser: `sketchlab run` on a synthetic sketch with
// two stacks, then headless Chromium (Debian's `chromium`, scripts/setup.sh)
// opens report.html from the run folder (file://, no network, no server):
// both 3D views must draw pixels other than the background, and the page
// must log nothing to the console (no error, no warning).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "cli_helpers.hpp"
#include "sketchlab/io/text_file.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;

namespace {

std::string body_attribute(const std::string& dom, const std::string& name) {
  std::smatch m;
  const std::regex re("<body[^>]*\\b" + name + "=\"([^\"]*)\"");
  return std::regex_search(dom, m, re) ? m[1].str() : "";
}

}  // namespace

TEST_CASE("report in headless Chromium: every 3D view renders, nothing on the console", "[app][report][browser]") {
  const fs::path chromium = "/usr/bin/chromium";
  INFO("headless Chromium is the Debian package chromium (scripts/setup.sh installs it)");
  REQUIRE(fs::exists(chromium));

  const fs::path dir = test::fresh_dir("report_browser");
  const fs::path exp = dir / "experiment.yaml";
  std::ofstream(exp) << "experiment: browser\n"
                     << "recordings: [" << test::source_path("data/synthetic/cube.jsonl") << "]\n"
                     << "stacks:\n  - name: freehand\n    corrector: {plugin: freehand}\n"
                     << "  - name: cassie\n    corrector: {plugin: cassie}\n"
                     << "outputs: {dir: " << (dir / "runs").string() << ", timestamp: false, report: true}\n";
  REQUIRE(test::run_cli("run " + exp.string(), dir / "run.txt") == 0);
  const fs::path run = dir / "runs/browser";
  for (const char* stack : {"freehand", "cassie"}) {
    INFO(stack);
    const auto gltf = nlohmann::json::parse(read_text_file(run / "cube" / stack / "scene.gltf"));
    CHECK(gltf.at("asset").at("version") == "2.0");
    CHECK(gltf.at("meshes").size() > 0);
  }

  const auto out = test::run_captured(
      "timeout 60 " + chromium.string() +
      " --headless --no-sandbox --user-data-dir=" + (dir / "chromium").string() +
      " --use-angle=swiftshader --enable-unsafe-swiftshader --window-size=1400,1000"
      " --virtual-time-budget=10000 --enable-logging=stderr --v=0 --dump-dom file://" +
      fs::absolute(run / "report.html").string());
  REQUIRE(out.status == 0);
  const std::string& dom = out.output;
  INFO(dom.substr(0, 2000));
  CHECK(body_attribute(dom, "data-scene-done") == "1");
  CHECK(body_attribute(dom, "data-scene-views") == "2");
  CHECK(body_attribute(dom, "data-scene-nonblank") == "2");
  CHECK(body_attribute(dom, "data-scene-errors").empty());
  // Chromium logs every console message of the page as INFO:CONSOLE. One is
  // Chromium's own performance hint, not the page's: "GPU stall due to
  // ReadPixels" when the non-blank check reads pixels back on a loaded
  // machine (software GL); it says nothing about the report.
  std::istringstream lines(dom);
  for (std::string line; std::getline(lines, line);)
    if (line.find("GPU stall due to ReadPixels") == std::string::npos)
      CHECK_THAT(line, !Catch::Contains(":CONSOLE"));
}
