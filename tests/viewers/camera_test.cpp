// fit_camera frames every given sketch tightly, from the requested side,
// identically for all panels.
#include <catch2/catch.hpp>

#include "scenes.hpp"
#include "sketchlab/viewer/camera.hpp"

using namespace sketchlab;
using namespace sketchlab::test;
using viewer::Camera;
using viewer::ViewDirection;

namespace {

// Points in normalized device coordinates ([-1, 1]^2 is the viewport).
std::vector<Vec2> to_ndc(const Camera& cam, const std::vector<Vec3>& points, double aspect) {
  const int h = 1000, w = static_cast<int>(aspect * h);
  std::vector<Vec2> out;
  for (const Vec3& p : points) {
    const Vec2 px = project(cam, p, 0, w, h);
    out.emplace_back(2.0 * px.x() / w - 1.0, 1.0 - 2.0 * px.y() / h);
  }
  return out;
}

}  // namespace

TEST_CASE("fit_camera keeps every sketch in view and fills the frame", "[viewer][camera]") {
  const Sketch a = line_sketch({-1.0, 0.0, 0.0}, {1.0, 0.5, 0.2});
  const Sketch b = square_sketch(0.3, true);
  const Box3 box = viewer::scene_bounds({&a, &b});
  REQUIRE(box.min().isApprox(Vec3(-1.0, -0.3, 0.0)));
  REQUIRE(box.max().isApprox(Vec3(1.0, 0.5, 0.2)));
  // Denser than fit_camera's own sampling: points between its samples must
  // be in view too.
  const std::vector<Vec3> drawn = viewer::scene_points({&a, &b}, 0.001);
  REQUIRE(drawn.size() > 2000);
  for (ViewDirection view :
       {ViewDirection::iso, ViewDirection::front, ViewDirection::top, ViewDirection::side})
    for (double aspect : {0.6, 1.0, 16.0 / 9.0}) {
      INFO("view " << viewer::to_string(view) << " aspect " << aspect);
      const Camera cam = viewer::fit_camera({&a, &b}, view, aspect);
      CHECK(cam.focal_point.isApprox(box.center(), 1e-9));
      CHECK(std::abs(cam.view_up.norm() - 1.0) < 1e-12);
      CHECK(std::abs(cam.view_up.dot(cam.focal_point - cam.position)) < 1e-9);
      double extent = 0.0;
      bool inside = true;
      for (const Vec2& q : to_ndc(cam, drawn, aspect)) {
        inside = inside && std::abs(q.x()) <= 1.0 && std::abs(q.y()) <= 1.0;
        extent = std::max({extent, std::abs(q.x()), std::abs(q.y())});
      }
      CHECK(inside);
      // Tight: the content reaches the margin (1/1.1 = 0.91) on some side;
      // perspective brings it a little inside.
      CHECK(extent > 0.85);
    }
}

TEST_CASE("fit_camera looks from the named side of the workspace", "[viewer][camera]") {
  const Sketch s = square_sketch(0.5, false);  // up = +Y by default
  const auto dir = [&](ViewDirection v) {
    const Camera c = viewer::fit_camera({&s}, v);
    return Vec3((c.position - c.focal_point).normalized());
  };
  CHECK(dir(ViewDirection::front).isApprox(Vec3::UnitZ()));
  CHECK(dir(ViewDirection::side).isApprox(Vec3::UnitX()));
  CHECK(dir(ViewDirection::top).isApprox(Vec3::UnitY()));
  CHECK(dir(ViewDirection::iso).isApprox(Vec3(1, 1, 1).normalized()));
  // Top view: the front of the workspace (+Z) is at the bottom of the picture.
  CHECK(viewer::fit_camera({&s}, ViewDirection::top).view_up.isApprox(-Vec3::UnitZ()));

  Sketch z_up = s;
  z_up.workspace.up = Vec3::UnitZ();
  const Camera front = viewer::fit_camera({&z_up}, ViewDirection::front);
  CHECK(Vec3((front.position - front.focal_point).normalized()).isApprox(-Vec3::UnitY()));
  CHECK(front.view_up.isApprox(Vec3::UnitZ()));
}

TEST_CASE("fit_camera handles empty scenes and rejects bad arguments", "[viewer][camera]") {
  const Sketch empty;
  const Camera c = viewer::fit_camera({&empty, nullptr}, ViewDirection::iso);
  CHECK(c.position.allFinite());
  CHECK((c.position - c.focal_point).norm() > 0.5);
  CHECK(viewer::fit_camera({}, ViewDirection::front).position.allFinite());
  CHECK_THROWS_AS(viewer::fit_camera({&empty}, ViewDirection::iso, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(viewer::fit_camera({&empty}, ViewDirection::iso, std::nan("")),
                  std::invalid_argument);
  CHECK(viewer::view_direction_from_string("top") == ViewDirection::top);
  CHECK_THROWS_WITH(viewer::view_direction_from_string("back"),
                    Catch::Contains("iso, front, top, side"));
}
