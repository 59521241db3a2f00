// The `tablet` input plugin: a PointerInput fed by the desktop viewer's
// window (XInput2 pen or mouse events).
#include "sketchlab/plugin/plugin_api.hpp"
#include "tablet_input.hpp"

namespace {

using namespace sketchlab;

tablet::TabletParams from_params(const Params& p) {
  tablet::TabletParams t;
  t.min_length_px = p.real("min_length");
  t.min_spacing_px = p.real("min_spacing");
  t.dpi = p.real("dpi");
  t.up = p.string("up") == "z" ? Vec3::UnitZ() : Vec3::UnitY();
  return t;
}

class TabletPlugin : public tablet::TabletInput {
 public:
  explicit TabletPlugin(const Params& p) : TabletInput(from_params(p)) {}
};

PluginDescriptor describe() {
  std::vector<ParamSpec> specs{
      {"min_length", ParamType::real, 3.0, 0.0, 1000.0, {}, "px",
       "strokes shorter than this are clicks and are dropped"},
      {"min_spacing", ParamType::real, 0.5, 0.0, 100.0, {}, "px",
       "pointer moves closer than this to the previous sample are skipped"},
      {"dpi", ParamType::real, 96.0, 1.0, 10000.0, {}, "px/in",
       "pixels per inch of the drawing surface, stored in each stroke's View"},
      {"up", ParamType::choice, std::string("y"), {}, {}, {"y", "z"}, "",
       "workspace up axis written in the recording header"},
  };
  return pointer_input_descriptor<TabletPlugin>(
      "tablet", "1.0",
      "live pen/mouse strokes pushed by a window (2D pixels + View, pressure from XInput2)",
      std::move(specs));
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
