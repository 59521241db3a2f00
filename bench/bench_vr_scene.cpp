// VR frame time with a large sketch (issue #25): 2,000 curves and 200
// patches in front of the user, at the eye size the OpenXR runtime reports
// (the test runtime, tests/fixtures/openxr_runtime, set to a Valve Index's
// 1440x1600), both eyes rendered by the viewer's scene (stage, hands, menu,
// feedback) while the dominant hand draws strokes that a CorrectionWorker
// corrects with the cassie stack on its own thread.
//
// The worker's shown sketch is the large synthetic sketch plus the curves
// the worker corrected (ids offset past it), so each correction lands in a
// 2,000-curve scene, and the worker prepares every snapshot as in
// `sketchlab vr` (vr::geometry_preparer: the scene's geometry updated
// incrementally, on the worker). Each time a correction arrives the frame
// swaps in what changed, as `sketchlab vr` does. Figures per frame, render
// thread only (input, scene, both eyes): wall and thread CPU time, p50 /
// p95 / max, separately for the frames that showed a new correction; and
// what the worker's geometry update cost per snapshot (thread CPU) and
// rebuilt (curves sampled, chunks built), and what those frames swapped
// (chunk actors given new geometry). Under Xvfb the GPU is Mesa's llvmpipe
// (software), so the figures bound a GPU's from above. The frame loop never
// waits for a correction: it only takes the latest finished snapshot
// (`latest_wait_max`: the longest that took, a mutex and a shared_ptr copy).
//
// Usage: xvfb-run -a build/bin/bench_vr_scene [frames=120] [curves=2000] [patches=200]
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include "controller_state.hpp"
#include "correction_worker.hpp"
#include "eye_renderer.hpp"
#include "sketchlab/heap_policy.hpp"
#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/viewer/display.hpp"
#include "vr_scene.hpp"
#include "xr_render_session.hpp"

namespace fs = std::filesystem;
using namespace sketchlab;

namespace {

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// Curves: cubic Béziers of 1-3 segments, 10-30 cm, in a 1.2 m box in front
// of the user; patches: 9x9-vertex curved quads of 10 cm.
Sketch large_sketch(int curves, int patches) {
  std::mt19937 rng(25);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 centre(0.0, 1.3, -0.5);
  Edit edit;
  for (int i = 0; i < curves; ++i) {
    NetworkCurve c;
    c.id = static_cast<CurveId>(i + 1);
    c.layer = i % 3 == 0 ? Layer::scaffold : Layer::shape;
    c.source_stroke = static_cast<StrokeId>(i + 1);
    const int segments = 1 + i % 3;
    Vec3 p = centre + 0.6 * Vec3(u(rng), u(rng), u(rng));
    c.curve.control_points.push_back(p);
    for (int s = 0; s < segments; ++s) {
      const Vec3 step = 0.08 * Vec3(u(rng), u(rng), u(rng));
      for (int k = 1; k <= 3; ++k) c.curve.control_points.push_back(p + step * k + 0.01 * Vec3(u(rng), u(rng), u(rng)));
      p = c.curve.control_points.back();
    }
    c.curve.sharp.assign(static_cast<std::size_t>(segments + 1), false);
    edit.curves_added.push_back(std::move(c));
  }
  for (int i = 0; i < patches; ++i) {
    Patch patch;
    patch.id = static_cast<PatchId>(i + 1);
    // Bounded by (all of) curve i + 1: what the viewer draws is the mesh.
    const Curve& rim = edit.curves_added.at(static_cast<std::size_t>(i)).curve;
    patch.boundary.push_back({static_cast<CurveId>(i + 1), 0.0, rim.t_max(), 0, 0});
    const Vec3 o = centre + 0.6 * Vec3(u(rng), u(rng), u(rng));
    const int n = 9;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const double x = 0.1 * a / (n - 1), y = 0.1 * b / (n - 1);
        patch.mesh.vertices.push_back(o + Vec3(x, y, 0.2 * (x - 0.05) * (y - 0.05) * 20.0));
        patch.mesh.normals.push_back(Vec3(0, 0, 1));
      }
    for (int a = 0; a + 1 < n; ++a)
      for (int b = 0; b + 1 < n; ++b) {
        const int v = a * n + b;
        patch.mesh.faces.push_back({v, v + n, v + 1});
        patch.mesh.faces.push_back({v + 1, v + n, v + n + 1});
      }
    edit.patches_added.push_back(std::move(patch));
  }
  Sketch sketch;
  sketch.network.apply(edit);
  return sketch;
}

struct Figures {
  std::vector<double> wall, cpu;
  void add(double w, double c) {
    wall.push_back(w);
    cpu.push_back(c);
  }
};

void print(const std::string& name, std::vector<double> v, const std::string& unit = "ms") {
  if (v.empty()) return;
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) { return v[std::min(v.size() - 1, static_cast<std::size_t>(q * v.size()))]; };
  std::cout << name << "_p50 " << at(0.50) << " " << unit << "\n"
            << name << "_p95 " << at(0.95) << " " << unit << "\n"
            << name << "_max " << v.back() << " " << unit << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  sketchlab::keep_freed_heap();  // as the sketchlab program runs (heap_policy.hpp)
  const int frames = argc > 1 ? std::atoi(argv[1]) : 120;
  const int curves = argc > 2 ? std::atoi(argv[2]) : 2000;
  const int patches = argc > 3 ? std::atoi(argv[3]) : 200;
  if (!std::getenv("XR_RUNTIME_JSON")) setenv("XR_RUNTIME_JSON", SKETCHLAB_TEST_XR_RUNTIME_JSON, 1);
  const fs::path dir = fs::temp_directory_path() / ("sketchlab_bench_vr_scene_" + std::to_string(getpid()));
  fs::create_directories(dir);
  {
    std::ofstream s(dir / "script.txt");
    s << "option eye_size 1440 1600\noption fov 50 52\nframe " << frames + 20 << " head=0,1.5,0.4\n";
  }
  setenv("SKETCHLAB_XR_SCRIPT", (dir / "script.txt").c_str(), 1);
  try {
    PluginHost host;
    host.load_directories(PluginHost::default_search_paths());
    const StackConfig config = load_stack(fs::path(SKETCHLAB_SOURCE_DIR) / "configs/stacks/cassie.yaml");
    viewer::require_display();
    const viewer::DisplayConnection display;
    std::unique_ptr<vr::EyeRenderer> eyes;
    vr::XrRenderSession xr;
    eyes = std::make_unique<vr::EyeRenderer>(xr.eye_width(), xr.eye_height());
    xr.start(eyes->glx_handles());
    RecordingHeader header;
    header.units = "m";
    const Sketch big = large_sketch(curves, patches);
    const CurveId offset = big.network.next_curve_id();
    // Worker thread only (read after finish()).
    std::vector<double> geometry_cpu;
    std::vector<std::size_t> curves_sampled, chunks_built;
    const vr::CorrectionWorker::Prepare geometry = vr::geometry_preparer(vr::vr_style());
    const auto prepare = [&](vr::SketchSnapshot& snap) {
      Edit drawn;
      for (const auto& [id, nc] : snap.stacks[0].sketch.network.curves()) {
        NetworkCurve c = nc;
        c.id += offset;
        drawn.curves_added.push_back(std::move(c));
      }
      Sketch shown = big;
      shown.network.apply(drawn);
      shown.strokes = snap.stacks[0].sketch.strokes;
      snap.stacks[0].sketch = std::move(shown);
      const double cpu0 = thread_cpu_ms();
      geometry(snap);
      geometry_cpu.push_back(thread_cpu_ms() - cpu0);
      curves_sampled.push_back(snap.geometry[0]->work.curves_sampled);
      chunks_built.push_back(snap.geometry[0]->work.chunks_built);
    };
    vr::CorrectionWorker worker(std::make_unique<LiveSession>(header, std::vector<StackInstance>{instantiate_stack(config, host)},
                                                              dir / "bench.jsonl", true),
                                prepare);
    openxr::InputSettings settings;
    settings.hand_menu = true;
    openxr::GestureInterpreter input(settings, header.workspace);
    vr::VrScene scene(eyes->renderer(), vr::vr_style(), {config.name});
    std::uint64_t shown_version = ~std::uint64_t{0};
    std::vector<double> swapped;

    Figures all, rebuilt;
    int frame = 0, corrections_shown = 0;
    double latest_wait_max = 0.0;
    bool lost = false;
    double seconds = 0.0;
    while (frame < frames && xr.poll(lost)) {
      if (!xr.running()) continue;
      bool rebuild = false;
      const auto wall0 = std::chrono::steady_clock::now();
      const double cpu0 = thread_cpu_ms();
      xr.frame(
          [&](XrTime) {
            seconds = frame / 90.0;
            // The right hand draws a 40-frame circle every 60 frames, the
            // left holds the menu up.
            openxr::ControllerFrame f;
            f.time = seconds;
            f.head_tracked = true;
            f.head.position = {0, 1.5, 0.4};
            const int k = frame % 60;
            const double a = 2.0 * 3.14159265358979 * k / 40.0;
            f.hands[1].tracked = f.hands[0].tracked = true;
            f.hands[1].aim.position = {0.1 + 0.06 * std::cos(a), 1.35 + 0.06 * std::sin(a), -0.1};
            f.hands[0].aim.position = {-0.2, 1.2, 0.0};
            f.draw_value = k < 40 ? 0.8 : 0.0;
            for (Event& e : input.step(f)) {
              if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) scene.stroke_submitted(s->stroke);
              worker.submit(std::move(e));
            }
            const auto before = std::chrono::steady_clock::now();
            const auto snap = worker.latest();
            latest_wait_max = std::max(
                latest_wait_max, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - before).count());
            scene.show(*snap, input.menu_view(), seconds);
            if (snap->version != shown_version) {
              rebuild = shown_version != ~std::uint64_t{0};
              shown_version = snap->version;
              if (rebuild) {
                ++corrections_shown;
                swapped.push_back(static_cast<double>(scene.chunks_swapped()));
              }
            }
            scene.update(openxr::controller_state(input, f, settings), seconds);
          },
          [&](int, const vr::EyeView& view, std::uint32_t texture) {
            eyes->render(view.position, view.orientation, view.fov, texture);
          });
      const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall0).count();
      const double cpu = thread_cpu_ms() - cpu0;
      // The first frame builds everything (shaders, the first scene).
      if (frame > 0) (rebuild ? rebuilt : all).add(wall, cpu);
      ++frame;
    }
    worker.finish();
    eyes->make_current();
    std::cout << "vr_scene_eye_size " << eyes->width() << "x" << eyes->height() << " px\n"
              << "vr_scene_curves " << big.network.curves().size() << " curves\n"
              << "vr_scene_patches " << big.network.patches().size() << " patches\n"
              << "vr_scene_frames " << frame << " frames\n"
              << "vr_scene_corrections_shown " << corrections_shown << " frames\n"
              << "vr_scene_latest_wait_max " << latest_wait_max << " ms\n";
    print("vr_scene_frame_wall", all.wall);
    print("vr_scene_frame_cpu", all.cpu);
    print("vr_scene_rebuild_frame_wall", rebuilt.wall);
    print("vr_scene_rebuild_frame_cpu", rebuilt.cpu);
    // The first snapshot (made before the loop) builds the whole scene.
    const auto tail = [](const auto& v) { return std::vector<double>(v.begin() + (v.empty() ? 0 : 1), v.end()); };
    if (!geometry_cpu.empty())
      std::cout << "vr_scene_geometry_first_cpu " << geometry_cpu.front() << " ms\n"
                << "vr_scene_geometry_first_curves_sampled " << curves_sampled.front() << " curves\n";
    print("vr_scene_geometry_update_cpu", tail(geometry_cpu));
    print("vr_scene_geometry_update_curves_sampled", tail(curves_sampled), "curves");
    print("vr_scene_geometry_update_chunks_built", tail(chunks_built), "chunks");
    print("vr_scene_rebuild_frame_chunks_swapped", swapped, "chunks");
  } catch (const std::exception& e) {
    std::cerr << "bench_vr_scene: " << e.what() << "\n";
    fs::remove_all(dir);
    return 1;
  }
  fs::remove_all(dir);
  return 0;
}
