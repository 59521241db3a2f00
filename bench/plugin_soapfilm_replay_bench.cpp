// End-to-end replay of a bundled CASSIE session (default vintage_car, 809
// strokes) through the cassie corrector (loaded as a plugin, mirror: plane as
// in configs/stacks/cassie-soapfilm.yaml) and this surfacer, on one core.
// Built from plugins/surfacers/soapfilm as soapfilm_replay_bench.
//
// Prints "name value unit" lines: the whole replay (wall, CPU of the thread),
// per event p50/p95/max (wall and CPU), the surfacer's share (its update and
// command calls) per event and in total, and the per-patch meshing CPU.
// Targets (issue #16): whole replay <= 3 s, per-event p95 <= 8 ms, meshing
// CPU p95 <= 5 ms per patch.
//
// soapfilm_replay_bench [SESSION] [--param NAME=VALUE]...  (soapfilm parameters)
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sketchlab/heap_policy.hpp"
#include "sketchlab/lab/cassie_import.hpp"
#include "sketchlab/lab/distribution.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/session.hpp"
#include "timed_soapfilm.hpp"

using namespace sketchlab;
using namespace sketchlab::soapfilm;

namespace {

void print(const std::string& name, const std::vector<double>& ms) {
  const Distribution d = distribution(ms);
  std::cout << name << "_p50 " << d.median << " ms\n"
            << name << "_p95 " << d.p95 << " ms\n"
            << name << "_max " << d.max << " ms\n";
}

double sum(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  sketchlab::keep_freed_heap();  // as the sketchlab program runs (heap_policy.hpp)
  std::string name = "vintage_car";
  std::map<std::string, ParamValue> given;
  const std::vector<ParamSpec> specs = soapfilm_param_specs();
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--param" && i + 1 < argc) {
        parse_param_assignment(argv[++i], given);
      } else if (a.rfind("--", 0) == 0) {
        std::cerr << "usage: soapfilm_replay_bench [SESSION] [--param NAME=VALUE]...\n";
        return 2;
      } else {
        name = a;
      }
    }
    const std::filesystem::path dir = SKETCHLAB_SOURCE_DIR;
    const auto path = dir / "data/recordings" / (name + ".jsonl");
    const Recording rec = std::filesystem::exists(path) ? read_recording(path)
                                                        : import_cassie_session(dir / "data/cassie", name);
    PluginHost host;
    host.load_directories(PluginHost::default_search_paths());
    auto corrector = host.make_corrector("cassie", {{"mirror", std::string("plane")}});
    auto surfacer = std::make_shared<TimedSoapfilm>(soapfilm_params(validate_params(specs, given)));
    Session session(rec.header.workspace, corrector, surfacer);

    std::vector<double> wall, cpu, s_wall, s_cpu, mesh;
    int strokes = 0, errors = 0, patches = 0;
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_ms();
    for (const Event& e : rec.events) {
      const auto ew = std::chrono::steady_clock::now();
      const double ec = thread_cpu_ms();
      const StepReport r = session.handle(e);
      cpu.push_back(thread_cpu_ms() - ec);
      wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - ew).count());
      const SurfacerCost cost = surfacer->take();
      s_wall.push_back(cost.wall_ms);
      s_cpu.push_back(cost.cpu_ms);
      for (const PatchMeshTimings& t : cost.meshed) mesh.push_back(t.fill_ms + t.remesh_ms + t.smooth_ms + t.output_ms);
      strokes += r.event == EventKind::stroke;
      errors += !r.error.empty();
      patches += r.patches_added;
    }
    const double total_cpu = thread_cpu_ms() - c0;
    const double total_wall =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count();
    const std::string p = "replay." + name + ".";
    std::cout << p << "events " << rec.events.size() << " events\n"
              << p << "strokes " << strokes << " strokes\n"
              << p << "event_errors " << errors << " events\n"
              << p << "patches_added " << patches << " patches\n"
              << p << "total_wall " << total_wall / 1e3 << " s\n"
              << p << "total_cpu " << total_cpu / 1e3 << " s\n"
              << p << "surfacer_total_wall " << sum(s_wall) / 1e3 << " s\n"
              << p << "surfacer_total_cpu " << sum(s_cpu) / 1e3 << " s\n";
    print(p + "event_wall", wall);
    print(p + "event_cpu", cpu);
    print(p + "surfacer_event_wall", s_wall);
    print(p + "surfacer_event_cpu", s_cpu);
    print(p + "mesh_per_patch_cpu", mesh);
  } catch (const std::exception& e) {
    std::cerr << "soapfilm_replay_bench: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
