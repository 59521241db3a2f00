// The plugin through the PluginHost: the surface is built at the end of a
// replay (not after every stroke), and on recompute_surface events.
#include <catch2/catch.hpp>
#include <filesystem>

#include "build_plugin_host.hpp"
#include "mesh_topology.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

TEST_CASE("the hermite_rbf plugin loads with the paper's defaults", "[hermite_rbf][plugin]") {
  const LoadedPlugin* p = test::build_plugin_host().find(PluginKind::surfacer, "hermite_rbf");
  REQUIRE(p);
  auto param = [&](const std::string& name) {
    for (const ParamSpec& s : p->descriptor->params)
      if (s.name == name) return s.default_value;
    FAIL("no parameter " << name);
    return ParamValue{};
  };
  CHECK(std::get<std::int64_t>(param("point_stride")) == 6);
  CHECK(std::get<std::int64_t>(param("tangent_stride")) == 12);
  CHECK(std::get<double>(param("tangent_change")) == 0.4);
  CHECK(std::get<double>(param("normal_change")) == 0.1);
  CHECK(std::get<std::int64_t>(param("intersection_window")) == 10);
  CHECK_THROWS(test::build_plugin_host().make_surfacer("hermite_rbf", {{"resolution", std::int64_t{2}}}));
}

TEST_CASE("replaying a CASSIE session builds the surface once at the end", "[hermite_rbf][plugin][slow]") {
  const StackInstance stack = instantiate_stack(
      load_stack(test::source_path("configs/stacks/cassie-hermite_rbf.yaml")), test::build_plugin_host());
  RecordingInput input(read_recording(test::source_path("data/recordings/hat.jsonl")));
  const ReplayResult r = replay(input, stack);
  REQUIRE(!r.steps.empty());
  for (std::size_t i = 0; i + 1 < r.steps.size(); ++i) CHECK(r.steps[i].patches_added == 0);
  const StepReport& last = r.steps.back();
  CHECK(last.event == EventKind::recompute_surface);
  INFO(last.error);
  REQUIRE(last.error.empty());
  CHECK(last.patches_added == 1);
  CHECK(last.stats.extra.at("surfacer.residual_point_max") <= 1e-6);
  CHECK(last.stats.extra.at("surfacer.residual_normal_max") <= 1e-6);
  const auto& patches = r.session.sketch().network.patches();
  REQUIRE(patches.size() == 1);
  const Mesh& mesh = patches.begin()->second.mesh;
  CHECK(mesh.faces.size() > 100);
  // Trimmed to where the curves enclose it (the default): open, but a
  // consistently oriented manifold, near the network and not ballooning past
  // it (before trimming and network-wide normals: 42 % of the area outside
  // the network's box, 95th percentile 0.33 × the diagonal from the curves).
  const hermite_rbf::MeshTopology t = hermite_rbf::mesh_topology(mesh);
  CHECK(t.nonmanifold_edges == 0);
  CHECK(t.inconsistent_edges == 0);
  CHECK(last.stats.extra.at("surfacer.outside_area_fraction") <= 0.03);
  CHECK(last.stats.extra.at("surfacer.curve_distance_p95") <= 0.06 * last.stats.extra.at("surfacer.diagonal"));
}
