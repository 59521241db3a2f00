// The offscreen renderer draws what the camera sees: dark curves where they
// project, background elsewhere, the same camera in every panel, translucent
// patches, and a clear error without an X display.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "output_dir.hpp"
#include "scenes.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/viewer/display.hpp"
#include "sketchlab/viewer/png_image.hpp"
#include "sketchlab/viewer/render_png.hpp"
#include "xvfb.hpp"

using namespace sketchlab;
using namespace sketchlab::test;
using viewer::Camera;
using viewer::Panel;
using viewer::RgbImage;

namespace {

// Exact pixels (no multisampling) so that equal scenes give equal pixels.
viewer::SceneStyle exact_style() {
  viewer::SceneStyle style;
  style.multisamples = 0;
  return style;
}

Camera oblique_camera() {
  Camera cam;
  cam.position = {0.7, 0.9, 2.0};
  cam.focal_point = {0.1, 0.0, 0.0};
  cam.view_up = Vec3(0.0, 1.0, 0.0);
  cam.view_angle_deg = 30.0;
  return cam;
}

}  // namespace

TEST_CASE("a straight curve renders dark along its projection and nowhere else", "[viewer]") {
  ensure_display();
  const Vec3 a(-0.5, -0.2, 0.1), b(0.5, 0.3, -0.2);
  const Sketch sketch = line_sketch(a, b);
  const Camera cam = oblique_camera();
  const int w = 480, h = 360;
  const auto png = viewer_output_dir() / "line.png";
  viewer::render_png({Panel{"", &sketch, nullptr, ""}}, cam, w, h, png, exact_style());
  const RgbImage img = viewer::read_png(png);
  REQUIRE(img.width == w);
  REQUIRE(img.height == h);

  const Vec2 pa = project(cam, a, 0, w, h), pb = project(cam, b, 0, w, h);
  REQUIRE((pb - pa).norm() > 100.0);  // the curve spans a good part of the picture
  for (int i = 1; i < 20; ++i) {
    const Vec3 p = a + (b - a) * (i / 20.0);
    const Vec2 q = project(cam, p, 0, w, h);
    INFO("sample " << i << " projects to " << q.transpose());
    CHECK(dark_near(img, q.x(), q.y()));
  }
  int far_non_background = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (pixel_distance_to_segment(Vec2(x + 0.5, y + 0.5), pa, pb) < 8.0) continue;
      const auto* px = img.at(x, y);
      far_non_background += !(px[0] == 255 && px[1] == 255 && px[2] == 255);
    }
  CHECK(far_non_background == 0);
}

TEST_CASE("two panels share the camera: the same sketch renders identically in both",
          "[viewer]") {
  ensure_display();
  const Sketch sketch = line_sketch({-0.5, -0.2, 0.1}, {0.5, 0.3, -0.2});
  const Camera cam = oblique_camera();
  const int w = 800, h = 300, half = w / 2;
  const auto png = viewer_output_dir() / "two_panels.png";
  viewer::render_png({Panel{"same", &sketch, nullptr, "1 curve"},
                      Panel{"same", &sketch, nullptr, "1 curve"}},
                     cam, w, h, png, exact_style());
  const RgbImage img = viewer::read_png(png);
  REQUIRE(img.width == w);

  int differing = 0, dark_left = 0;
  // Skip the separator drawn at the right panel's left edge.
  for (int y = 0; y < h; ++y)
    for (int x = 4; x < half - 4; ++x) {
      const auto* l = img.at(x, y);
      const auto* r = img.at(x + half, y);
      differing += l[0] != r[0] || l[1] != r[1] || l[2] != r[2];
      dark_left += is_dark(img, x, y);
    }
  CHECK(differing == 0);
  CHECK(dark_left > 100);

  // Each panel is its own viewport: the curve lands where the camera puts it
  // within that panel (aspect 400:300), not across the whole picture.
  for (int panel = 0; panel < 2; ++panel) {
    const Vec2 q = project(cam, Vec3(0.0, 0.05, -0.05), panel * half, half, h);
    CHECK(dark_near(img, q.x(), q.y()));
  }
}

TEST_CASE("different sketches in two panels each render with the common camera", "[viewer]") {
  ensure_display();
  const Vec3 a1(-0.4, 0.3, 0.0), b1(0.4, 0.3, 0.0);    // upper horizontal line
  const Vec3 a2(0.0, -0.4, 0.0), b2(0.0, -0.05, 0.0);  // lower vertical line
  const Sketch left = line_sketch(a1, b1), right = line_sketch(a2, b2);
  Camera cam;
  cam.position = {0.0, 0.0, 2.5};
  const int w = 640, h = 320, half = w / 2;
  const auto png = viewer_output_dir() / "two_sketches.png";
  viewer::render_png({Panel{"", &left, nullptr, ""}, Panel{"", &right, nullptr, ""}}, cam, w, h,
                     png, exact_style());
  const RgbImage img = viewer::read_png(png);
  const Vec2 l = project(cam, 0.5 * (a1 + b1), 0, half, h);
  const Vec2 r = project(cam, 0.5 * (a2 + b2), half, half, h);
  CHECK(dark_near(img, l.x(), l.y()));
  CHECK(dark_near(img, r.x(), r.y()));
  // And not the other's curve.
  const Vec2 l_in_right = project(cam, 0.5 * (a1 + b1), half, half, h);
  const Vec2 r_in_left = project(cam, 0.5 * (a2 + b2), 0, half, h);
  CHECK_FALSE(dark_near(img, l_in_right.x(), l_in_right.y(), 6));
  CHECK_FALSE(dark_near(img, r_in_left.x(), r_in_left.y(), 6));
}

TEST_CASE("a translucent patch tints the pixels inside its projection only", "[viewer]") {
  ensure_display();
  const Sketch frame = square_sketch(0.4, false), filled = square_sketch(0.4, true);
  REQUIRE(filled.network.patches().size() == 1);
  const Camera cam = oblique_camera();
  const int w = 400, h = 300;
  const auto png_frame = viewer_output_dir() / "square_frame.png";
  const auto png_filled = viewer_output_dir() / "square_patch.png";
  viewer::render_png({Panel{"", &frame, nullptr, ""}}, cam, w, h, png_frame, exact_style());
  viewer::render_png({Panel{"", &filled, nullptr, ""}}, cam, w, h, png_filled, exact_style());
  const RgbImage a = viewer::read_png(png_frame), b = viewer::read_png(png_filled);

  for (const Vec3& inside : {Vec3(0, 0, 0), Vec3(0.2, -0.15, 0), Vec3(-0.25, 0.2, 0)}) {
    const Vec2 q = project(cam, inside, 0, w, h);
    const int x = static_cast<int>(q.x()), y = static_cast<int>(q.y());
    const auto* pa = a.at(x, y);
    const auto* pb = b.at(x, y);
    INFO("inside point projects to " << q.transpose());
    CHECK((pa[0] == 255 && pa[1] == 255 && pa[2] == 255));  // empty frame: background
    CHECK(pb[2] > pb[0] + 20);  // tinted towards the patch colour (blue)
    CHECK(pb[0] > 100);         // translucent, not the opaque patch colour
    CHECK(pb[0] < 250);
  }
  // Well outside the square nothing changes.
  const Vec2 out = project(cam, Vec3(0.65, 0.0, 0.0), 0, w, h);
  REQUIRE((out.x() >= 0 && out.x() < w && out.y() >= 0 && out.y() < h));
  const auto* pa = a.at(static_cast<int>(out.x()), static_cast<int>(out.y()));
  const auto* pb = b.at(static_cast<int>(out.x()), static_cast<int>(out.y()));
  CHECK((pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2]));
  // The boundary curves still read dark over the patch.
  const Vec2 edge = project(cam, Vec3(0.0, -0.4, 0.0), 0, w, h);
  CHECK(dark_near(b, edge.x(), edge.y()));
}

TEST_CASE("a patch with vertex normals draws the same from sketch.json as from memory", "[viewer]") {
  ensure_display();
  Sketch shaded = square_sketch(0.4, true);
  // Normals bent away from the plane's, as a surfacer's smooth shading gives:
  // the lighting, and so the pixels, depend on them.
  Patch p = shaded.network.patches().at(1);
  p.mesh.normals = {Vec3(-0.6, -0.3, 0.7).normalized(), Vec3(0.6, -0.3, 0.7).normalized(),
                    Vec3(0.6, 0.3, 0.7).normalized(), Vec3(-0.6, 0.3, 0.7).normalized()};
  Edit swap;
  swap.patches_removed = {1};
  swap.patches_added = {p};
  shaded.network.apply(swap);
  const Sketch read_back = parse_sketch_json(sketch_to_json(shaded), "sketch.json");
  Sketch flat = shaded;  // what reading a file without normals used to give
  p.mesh.normals.clear();
  swap.patches_added = {p};
  flat.network.apply(swap);

  const Camera cam = oblique_camera();
  const int w = 200, h = 150;
  const auto png_memory = viewer_output_dir() / "normals_memory.png";
  const auto png_file = viewer_output_dir() / "normals_file.png";
  const auto png_flat = viewer_output_dir() / "normals_flat.png";
  viewer::render_png({Panel{"", &shaded, nullptr, ""}}, cam, w, h, png_memory, exact_style());
  viewer::render_png({Panel{"", &read_back, nullptr, ""}}, cam, w, h, png_file, exact_style());
  viewer::render_png({Panel{"", &flat, nullptr, ""}}, cam, w, h, png_flat, exact_style());
  const RgbImage memory = viewer::read_png(png_memory), file = viewer::read_png(png_file),
                 without = viewer::read_png(png_flat);
  CHECK(file.pixels == memory.pixels);
  CHECK(without.pixels != memory.pixels);
}

TEST_CASE("nodes are drawn as dots in the node colour", "[viewer]") {
  ensure_display();
  const Sketch sketch = square_sketch(0.4, false);
  const Camera cam = oblique_camera();
  const int w = 400, h = 300;
  const auto png = viewer_output_dir() / "nodes.png";
  viewer::render_png({Panel{"", &sketch, nullptr, ""}}, cam, w, h, png, exact_style());
  const RgbImage img = viewer::read_png(png);
  for (const auto& [id, node] : sketch.network.nodes()) {
    const Vec2 q = project(cam, node.position, 0, w, h);
    const auto* p = img.at(static_cast<int>(q.x()), static_cast<int>(q.y()));
    INFO("node " << id);
    CHECK(p[0] > 150);  // orange: red high, blue low
    CHECK(p[2] < 80);
  }
}

TEST_CASE("no X display gives a clear error and writes nothing", "[viewer]") {
  const char* old = std::getenv("DISPLAY");
  const std::optional<std::string> saved = old ? std::optional<std::string>(old) : std::nullopt;
  const Sketch sketch = line_sketch({0, 0, 0}, {1, 0, 0});
  const auto png = viewer_output_dir() / "never_written.png";
  std::filesystem::remove(png);

  unsetenv("DISPLAY");
  CHECK_THAT(viewer::display_problem(), Catch::Contains("no X display") &&
                                            Catch::Contains("xvfb-run"));
  CHECK_THROWS_WITH(
      viewer::render_png({Panel{"", &sketch, nullptr, ""}}, viewer::Camera{}, 64, 64, png),
      Catch::Contains("no X display: run under xvfb-run"));
  // A display nobody serves (VTK itself would abort the process here).
  setenv("DISPLAY", ":4097", 1);
  CHECK_THAT(viewer::display_problem(), Catch::Contains("cannot connect to DISPLAY=:4097"));
  CHECK_THROWS_AS(
      viewer::render_png({Panel{"", &sketch, nullptr, ""}}, viewer::Camera{}, 64, 64, png),
      std::runtime_error);
  CHECK_FALSE(std::filesystem::exists(png));

  if (saved)
    setenv("DISPLAY", saved->c_str(), 1);
  else
    unsetenv("DISPLAY");
}

TEST_CASE("bad arguments are rejected before rendering", "[viewer]") {
  const Sketch sketch = line_sketch({0, 0, 0}, {1, 0, 0});
  const auto png = viewer_output_dir() / "bad.png";
  CHECK_THROWS_WITH(viewer::render_png({}, viewer::Camera{}, 100, 100, png),
                    Catch::Contains("no panels"));
  CHECK_THROWS_WITH(
      viewer::render_png({Panel{"", &sketch, nullptr, ""}}, viewer::Camera{}, 8, 100, png),
      Catch::Contains("too small"));
  viewer::Camera degenerate;
  degenerate.position = degenerate.focal_point;
  CHECK_THROWS_WITH(
      viewer::render_png({Panel{"", &sketch, nullptr, ""}}, degenerate, 100, 100, png),
      Catch::Contains("camera"));
  CHECK_THROWS_WITH(viewer::render_png({Panel{"", &sketch, nullptr, ""}}, viewer::Camera{}, 100,
                                       100, viewer_output_dir() / "no_such_dir" / "x.png"),
                    Catch::Contains("does not exist"));
  CHECK_THROWS_WITH(viewer::read_png(viewer_output_dir() / "missing.png"), Catch::Contains("no such file"));
}
