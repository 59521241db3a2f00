// sketch_to_gltf: a valid glTF 2.0 document holding the sketch's geometry
// where it is, one primitive per drawing class, without a display.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>

#include "scenes.hpp"
#include "sketchlab/viewer/export_gltf.hpp"

using namespace sketchlab;

namespace {

// Modes of every primitive, and the POSITION bounds over all of them.
struct Summary {
  std::multiset<int> modes;
  Vec3 min = Vec3::Constant(1e300), max = Vec3::Constant(-1e300);
};

Summary summarize(const nlohmann::json& g) {
  Summary s;
  for (const auto& mesh : g.value("meshes", nlohmann::json::array()))
    for (const auto& p : mesh.at("primitives")) {
      s.modes.insert(p.value("mode", 4));
      const auto& acc = g.at("accessors").at(p.at("attributes").at("POSITION").get<std::size_t>());
      for (int k = 0; k < 3; ++k) {
        s.min[k] = std::min(s.min[k], acc.at("min")[k].get<double>());
        s.max[k] = std::max(s.max[k], acc.at("max")[k].get<double>());
      }
    }
  return s;
}

}  // namespace

TEST_CASE("glTF export: a square with nodes and a patch gives lines, points and triangles in place",
          "[viewers][gltf]") {
  // No display is needed: nothing is rendered.
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display ? display : "";
  unsetenv("DISPLAY");
  const Sketch sketch = test::square_sketch(0.25, true);
  const auto g = nlohmann::json::parse(viewer::sketch_to_gltf(sketch));
  if (!saved.empty()) setenv("DISPLAY", saved.c_str(), 1);

  CHECK(g.at("asset").at("version") == "2.0");
  // Buffers inline: the document stands alone.
  for (const auto& b : g.at("buffers")) CHECK(b.at("uri").get<std::string>().rfind("data:", 0) == 0);
  const Summary s = summarize(g);
  // Shape curves (lines: mode 1), nodes (points: 0), the patch (triangles: 4).
  CHECK(s.modes == std::multiset<int>{0, 1, 4});
  // Everything lies in the square [-0.25, 0.25]^2 x {0} and reaches its corners (float precision).
  for (int k = 0; k < 2; ++k) {
    CHECK(s.min[k] == Approx(-0.25).margin(1e-6));
    CHECK(s.max[k] == Approx(0.25).margin(1e-6));
  }
  CHECK(s.min[2] == Approx(0.0).margin(1e-6));
  CHECK(s.max[2] == Approx(0.0).margin(1e-6));
}

TEST_CASE("glTF export: an empty sketch is still a valid document", "[viewers][gltf]") {
  const auto g = nlohmann::json::parse(viewer::sketch_to_gltf(Sketch{}));
  CHECK(g.at("asset").at("version") == "2.0");
  CHECK(summarize(g).modes.empty());
}
