// VR frame time: `sketchlab vr` with the cassie stack on the scripted test
// runtime (tests/fixtures/openxr_runtime), drawing strokes for a few hundred
// frames at headset and smaller eye sizes. A headset at 90 Hz allows 11.1 ms
// per frame; figures under Xvfb are software rendering (Mesa llvmpipe), so
// they bound the GPU case from above. Prints `name value unit` lines.
//
// Usage: xvfb-run -a build/bin/bench_vr_frame [frames]
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "sketchlab/heap_policy.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/vr/vr_app.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;

namespace {

// Strokes of 40 frames (circles of 10 cm in front of the head), 10 frames apart.
void write_script(const fs::path& path, int width, int height, int frames) {
  std::ofstream s(path);
  s << "option eye_size " << width << " " << height << "\noption fov 50 50\n"
    << "frame 5 head=0,1.5,0.6 left=-0.3,1.2,0.2 right=0,1.4,0\n";
  for (int f = 0; f < frames; ++f) {
    const int stroke = f / 50, k = f % 50;
    const double a = 2.0 * 3.14159265358979 * k / 40.0;
    const double cx = -0.2 + 0.1 * (stroke % 5), cy = 1.3 + 0.1 * ((stroke / 5) % 3);
    s << "frame right=" << cx + 0.05 * std::cos(a) << "," << cy + 0.05 * std::sin(a) << ",0"
      << " right/input/trigger/value=" << (k < 40 ? 0.8 : 0.0) << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  sketchlab::keep_freed_heap();  // as the sketchlab program runs (heap_policy.hpp)
  const int frames = argc > 1 ? std::atoi(argv[1]) : 300;
  if (!std::getenv("XR_RUNTIME_JSON")) setenv("XR_RUNTIME_JSON", SKETCHLAB_TEST_XR_RUNTIME_JSON, 1);
  if (!fs::exists(std::getenv("XR_RUNTIME_JSON"))) {
    std::cerr << "bench_vr_frame: no runtime manifest at " << std::getenv("XR_RUNTIME_JSON")
              << " (build sketchlab_test_xr_runtime, or set XR_RUNTIME_JSON)\n";
    return 1;
  }
  PluginHost host;
  host.load_directories(PluginHost::default_search_paths());
  const fs::path dir = fs::temp_directory_path() / ("sketchlab_bench_vr_" + std::to_string(getpid()));
  fs::create_directories(dir);
  int status = 0;
  for (const auto& [w, h] : {std::pair{1440, 1600}, std::pair{720, 800}}) {
    write_script(dir / "script.txt", w, h, frames);
    setenv("SKETCHLAB_XR_SCRIPT", (dir / "script.txt").c_str(), 1);
    vr::VrOptions options;
    options.config = fs::path(SKETCHLAB_SOURCE_DIR) / "configs/stacks/cassie.yaml";
    options.recording = dir / "bench.jsonl";
    options.overwrite = true;
    vr::VrStats stats;
    std::ostringstream out, err;
    try {
      status |= vr::run_vr(options, host, out, err, &stats);
    } catch (const std::exception& e) {
      std::cerr << "bench_vr_frame: " << e.what() << "\n";
      return 1;
    }
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    std::cout << "vr_frame_mean_" << size << " " << stats.frame_mean_ms << " ms\n"
              << "vr_frame_p95_" << size << " " << stats.frame_p95_ms << " ms\n"
              << "vr_frame_max_" << size << " " << stats.frame_max_ms << " ms\n"
              << "vr_frames_" << size << " " << stats.frames << " frames\n"
              << "vr_events_" << size << " " << stats.events << " events\n";
  }
  fs::remove_all(dir);
  return status;
}
