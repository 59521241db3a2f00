// The plugin as the host loads it: descriptor, parameter defaults, the
// bundled stack file, and 2D (pixel) strokes.
#include <catch2/catch.hpp>

#include "build_plugin_host.hpp"
#include "jdi_fixture.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "test_paths.hpp"

using namespace jdi_test;

TEST_CASE("The justdrawit plugin loads with its defaults and the bundled stack", "[justdrawit][plugin]") {
  const LoadedPlugin* p = test::build_plugin_host().find(PluginKind::corrector, "justdrawit");
  REQUIRE(p);
  const Params defaults = validate_params(p->descriptor->params, {});
  const JdiParams jp = jdi_params_from(defaults);
  CHECK(jp.d == 15.0);
  CHECK(jp.smoothing == 2);
  CHECK(jp.surface == SurfaceKind::view_plane);
  CHECK_THROWS_AS(validate_params(p->descriptor->params, {{"surface", std::string("sphere")}}), ParamError);

  const StackInstance stack =
      instantiate_stack(load_stack(test::source_path("configs/stacks/justdrawit.yaml")), test::build_plugin_host());
  REQUIRE(stack.corrector);
  CHECK(stack.corrector->stroke_space() == StrokeSpace::pixels);
  Sketch sketch;
  const Stroke s = pixel_stroke(1, ortho_view(Vec3(0, 0, 3)), line_px({100, 100}, {400, 300}));
  const Correction c = stack.corrector->correct(s, sketch);
  CHECK(c.error.empty());
  CHECK(c.edit.curves_added.size() == 1);
}
