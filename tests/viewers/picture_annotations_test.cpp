// What makes a report picture readable on its own: curves coloured by their
// deviation from the input stroke (viridis over [0, max]), a scale bar of a
// round length, and panels in rows.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "output_dir.hpp"
#include "scenes.hpp"
#include "sketchlab/viewer/png_image.hpp"
#include "sketchlab/viewer/render_png.hpp"
#include "xvfb.hpp"

using namespace sketchlab;
using namespace sketchlab::test;
using viewer::Camera;
using viewer::Panel;
using viewer::RgbImage;

namespace {

Camera front_camera() {
  Camera cam;
  cam.position = {0.0, 0.0, 2.0};
  cam.focal_point = {0.0, 0.0, 0.0};
  cam.view_up = Vec3(0.0, 1.0, 0.0);
  cam.view_angle_deg = 30.0;
  return cam;
}

// A horizontal shape curve along x in [-0.4, 0.4] whose input stroke runs
// `offset` metres behind it (along -z, the view direction: the curve hides it).
Sketch offset_stroke_sketch(double offset) {
  Sketch sketch;
  Stroke stroke;
  stroke.id = 7;
  for (int i = 0; i <= 40; ++i) {
    Sample sample;
    sample.position = Vec3(-0.4 + 0.02 * i, 0.0, -offset);
    stroke.samples.push_back(sample);
  }
  sketch.strokes.emplace(7, stroke);
  Edit edit;
  NetworkCurve nc = line_curve(1, {-0.4, 0.0, 0.0}, {0.4, 0.0, 0.0}, Layer::shape);
  nc.source_stroke = 7;
  edit.curves_added.push_back(nc);
  sketch.network.apply(edit);
  return sketch;
}

viewer::SceneStyle deviation_style(double max_m) {
  viewer::SceneStyle style;
  style.multisamples = 0;
  style.show_raw_strokes = false;
  style.show_nodes = false;
  style.colour_by_deviation = true;
  style.deviation_max_m = max_m;
  return style;
}

bool near_colour(const std::uint8_t* px, int r, int g, int b, int tolerance = 8) {
  return std::abs(px[0] - r) <= tolerance && std::abs(px[1] - g) <= tolerance && std::abs(px[2] - b) <= tolerance;
}

}  // namespace

TEST_CASE("deviation colours: a curve 1 cm from its stroke is viridis' middle on a 2 cm scale, its top on 1 cm",
          "[viewer][picture]") {
  ensure_display();
  const Sketch sketch = offset_stroke_sketch(0.01);
  const int w = 400, h = 300;
  const auto png = viewer_output_dir() / "deviation.png";
  // The curve's middle at the picture's centre; probe a quarter of the way along it.
  const Vec2 q = project(front_camera(), Vec3(-0.2, 0.0, 0.0), 0, w, h);
  viewer::render_png({Panel{"", &sketch, nullptr, ""}}, front_camera(), w, h, png, deviation_style(0.02));
  RgbImage img = viewer::read_png(png);
  const auto* mid = img.at(static_cast<int>(q.x()), static_cast<int>(q.y()));
  INFO("pixel " << int(mid[0]) << "," << int(mid[1]) << "," << int(mid[2]));
  CHECK(near_colour(mid, 42, 120, 142));  // viridis(0.5) = (0.164, 0.471, 0.558)

  viewer::render_png({Panel{"", &sketch, nullptr, ""}}, front_camera(), w, h, png, deviation_style(0.01));
  img = viewer::read_png(png);
  const auto* top = img.at(static_cast<int>(q.x()), static_cast<int>(q.y()));
  INFO("pixel " << int(top[0]) << "," << int(top[1]) << "," << int(top[2]));
  CHECK(near_colour(top, 253, 231, 37));  // viridis(1)
}

TEST_CASE("scale bar: a round length, drawn to scale at the focal distance", "[viewer][picture]") {
  ensure_display();
  const Sketch sketch = line_sketch({-0.4, 0.3, 0.0}, {0.4, 0.3, 0.0});
  viewer::SceneStyle style;
  style.multisamples = 0;
  style.show_scale_bar = true;
  const int w = 400, h = 300;
  const auto png = viewer_output_dir() / "scale_bar.png";
  viewer::render_png({Panel{"", &sketch, nullptr, ""}}, front_camera(), w, h, png, style);
  const RgbImage img = viewer::read_png(png);
  // 2 m away with a 30° view: 2 · 2 tan 15° / 300 m per pixel; a fifth of
  // the width is 0.286 m, so the bar is 20 cm (56 pixels), plus its two end
  // ticks in the rows probed.
  const double metres_per_pixel = 4.0 * std::tan(15.0 * std::numbers::pi / 180.0) / h;
  const double expected = 0.2 / metres_per_pixel + 2;
  const int row = h - 1 - 24;
  int dark = 0;
  for (int x = 0; x < w; ++x) dark += is_dark(img, x, row) || is_dark(img, x, row - 1) || is_dark(img, x, row + 1);
  CHECK(dark == Approx(expected).margin(3));
}

TEST_CASE("panels in rows: the third of three panels in two columns is drawn at the bottom left",
          "[viewer][picture]") {
  ensure_display();
  const Vec3 a(-0.3, -0.1, 0.0), b(0.3, 0.1, 0.0);
  const Sketch sketch = line_sketch(a, b);
  viewer::SceneStyle style;
  style.multisamples = 0;
  const int w = 400, h = 400;
  const auto png = viewer_output_dir() / "rows.png";
  viewer::render_png({Panel{"", &sketch, nullptr, ""}, Panel{"", &sketch, nullptr, ""}, Panel{"", &sketch, nullptr, ""}},
                     front_camera(), w, h, png, style, 2);
  const RgbImage img = viewer::read_png(png);
  // Each panel 200 x 200; the third at columns [0, 200), rows [200, 400).
  for (int i = 1; i < 10; ++i) {
    const Vec2 q = project(front_camera(), a + (b - a) * (i / 10.0), 0, 200, 200);
    CHECK(dark_near(img, q.x(), q.y() + 200));
    CHECK(dark_near(img, q.x() + 200, q.y()));  // the second panel, top right
  }
  int bottom_right_dark = 0;
  for (int y = 200; y < h; ++y)
    for (int x = 205; x < w; ++x) bottom_right_dark += is_dark(img, x, y);  // past the separator
  CHECK(bottom_right_dark == 0);
  CHECK_THROWS_AS(viewer::render_png({Panel{"", &sketch, nullptr, ""}}, front_camera(), w, h, png, style, -1),
                  std::invalid_argument);
}
