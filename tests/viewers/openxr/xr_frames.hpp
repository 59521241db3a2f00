#pragma once
// Helpers of the VR viewer's tests: scripted sessions of `sketchlab vr` on
// the test runtime and the eye images it reads back from the swapchains
// (`dump` frames: frameN_eyeE.ppm + .txt with the submitted view).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sketchlab/config/config.hpp"
#include "sketchlab/lab/stack.hpp"
#include "sketchlab/plugin/recording_input.hpp"
#include "sketchlab/types.hpp"
#include "test_paths.hpp"

namespace sketchlab::test {

inline std::filesystem::path fresh_vr_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("sketchlab_vr_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// `sketchlab vr CONFIG` on the test runtime with `script`, recording to
// DIR/vr.jsonl and the final sketch to DIR/vr_sketch.json.
inline std::string vr_command(const std::filesystem::path& script, const std::filesystem::path& dir,
                              const std::string& runtime_json,
                              const std::string& config = "configs/stacks/cassie.yaml") {
  return "XR_RUNTIME_JSON=" + runtime_json + " SKETCHLAB_XR_SCRIPT=" + script.string() + " " SKETCHLAB_CLI " vr " +
         test::source_path(config) + " -o " + (dir / "vr.jsonl").string() + " --sketch " +
         (dir / "vr_sketch.json").string();
}

inline std::string xyz(const Vec3& p) {
  std::ostringstream s;
  s.precision(17);
  s << p.x() << "," << p.y() << "," << p.z();
  return s.str();
}

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // top row first
  const unsigned char* at(int x, int y) const { return rgb.data() + 3 * (static_cast<std::size_t>(y) * width + x); }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
};

inline Image read_ppm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  REQUIRE(in);
  std::string magic;
  int max = 0;
  Image img;
  in >> magic >> img.width >> img.height >> max;
  in.get();
  REQUIRE(magic == "P6");
  img.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
  in.read(reinterpret_cast<char*>(img.rgb.data()), static_cast<std::streamsize>(img.rgb.size()));
  REQUIRE(in);
  return img;
}

// The view the application submitted for this image (pose, fov).
struct EyeFile {
  Vec3 position;
  Quat orientation;
  double left, right, up, down;
};

inline EyeFile read_eye(const std::filesystem::path& file) {
  std::ifstream in(file);
  EyeFile e;
  double qx, qy, qz, qw;
  in >> e.position.x() >> e.position.y() >> e.position.z() >> qx >> qy >> qz >> qw >> e.left >> e.right >> e.up >>
      e.down;
  REQUIRE(in);
  e.orientation = Quat(qw, qx, qy, qz).normalized();
  return e;
}

// Pixel (x right, y down from the top) where a stage point projects.
inline Vec2 project(const EyeFile& eye, const Image& img, const Vec3& p) {
  const Vec3 v = eye.orientation.conjugate() * (p - eye.position);
  const double tx = v.x() / -v.z(), ty = v.y() / -v.z();
  const double nx = (tx - std::tan(eye.left)) / (std::tan(eye.right) - std::tan(eye.left));
  const double ny = (ty - std::tan(eye.down)) / (std::tan(eye.up) - std::tan(eye.down));
  return {nx * img.width, (1.0 - ny) * img.height};
}

// One dumped eye image with its view.
struct EyeImage {
  Image image;
  EyeFile eye;
  explicit EyeImage(const std::filesystem::path& stem)
      : image(read_ppm(stem.string() + ".ppm")), eye(read_eye(stem.string() + ".txt")) {}
  Vec2 pixel(const Vec3& stage) const { return project(eye, image, stage); }
  // Largest channel difference between the pixel at `stage` and `rgb` (0..1 colour).
  int distance(const Vec3& stage, const std::array<double, 3>& rgb) const {
    const Vec2 q = pixel(stage);
    const int x = int(std::floor(q.x())), y = int(std::floor(q.y()));
    if (!image.inside(x, y)) return 1000;
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(image.at(x, y)[c]) - int(std::lround(255 * rgb[c]))));
    return d;
  }
};

// The first `events` events of `rec` replayed through the cassie stack
// (what `sketchlab vr configs/stacks/cassie.yaml` computed live).
inline ReplayResult cassie_replay(const Recording& rec, std::size_t events) {
  PluginHost host;
  host.load_directories({SKETCHLAB_BUILD_PLUGIN_DIR});
  const StackInstance stack = instantiate_stack(load_stack(test::source_path("configs/stacks/cassie.yaml")), host);
  Recording prefix = rec;
  prefix.events.resize(std::min(events, prefix.events.size()));
  RecordingInput input(prefix);
  return replay(input, stack);
}

inline std::filesystem::path dump_stem(const std::filesystem::path& dir, int frame, int eye) {
  return dir / ("frame" + std::to_string(frame) + "_eye" + std::to_string(eye));
}

}  // namespace sketchlab::test
