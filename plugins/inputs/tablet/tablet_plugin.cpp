// The `tablet` input plugin: a PointerInput fed by the desktop viewer's
// window (XInput2 pen or mouse events).
#include "sketchlab/plugin/param_table.hpp"
#include "sketchlab/plugin/plugin_api.hpp"
#include "tablet_input.hpp"

namespace {

using namespace sketchlab;

const ParamTable<tablet::TabletParams>& parameters() {
  using T = tablet::TabletParams;
  static const auto table =
      ParamTable<T>()
          .real("min_length", &T::min_length_px, 0.0, 1000.0, "px",
                "strokes shorter than this are clicks and are dropped")
          .real("min_spacing", &T::min_spacing_px, 0.0, 100.0, "px",
                "pointer moves closer than this to the previous sample are skipped")
          .real("dpi", &T::dpi, 1.0, 10000.0, "px/in",
                "pixels per inch of the drawing surface, stored in each stroke's View")
          .choice("up", &T::up, std::vector<std::pair<std::string, Vec3>>{{"y", Vec3::UnitY()}, {"z", Vec3::UnitZ()}},
                  "workspace up axis written in the recording header");
  return table;
}

class TabletPlugin : public tablet::TabletInput {
 public:
  explicit TabletPlugin(const Params& p) : TabletInput(parameters().read(p)) {}
};

PluginDescriptor describe() {
  return pointer_input_descriptor<TabletPlugin>(
      "tablet", "1.0",
      "live pen/mouse strokes pushed by a window (2D pixels + View, pressure from XInput2)",
      parameters().specs());
}

}  // namespace

SKETCHLAB_PLUGIN(describe)
