// A fitted curve never leaves its stroke's neighbourhood (issue #15): the
// two-sided (Hausdorff) distance between every bundled 3D stroke and its
// preprocessed curve, under both rule sets.
#include <catch2/catch.hpp>

#include <filesystem>
#include <numbers>

#include "sketchlab/geometry/hausdorff.hpp"
#include "sketchlab/geometry/polyline.hpp"
#include "sketchlab/preprocess/preprocess.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

namespace {

std::vector<std::filesystem::path> bundled_recordings() {
  std::vector<std::filesystem::path> out;
  for (const char* dir : {"data/recordings", "data/synthetic"})
    for (const auto& e : std::filesystem::directory_iterator(test::source_path(dir)))
      if (e.path().extension() == ".jsonl") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Vec3> stroke_points(const Stroke& s) {
  std::vector<Vec3> p;
  for (const Sample& x : s.samples) p.push_back(x.position);
  return p;
}

const Stroke& stroke_of(const Recording& rec, StrokeId id) {
  for (const Event& e : rec.events)
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload); s && s->stroke.id == id) return s->stroke;
  throw std::runtime_error("no stroke " + std::to_string(id));
}

}  // namespace

TEST_CASE("hausdorff_distance measures both ways", "[preprocess][hausdorff]") {
  const Curve line = make_line({0, 0, 0}, {1, 0, 0});
  const HausdorffDistance h = hausdorff_distance(line, {{0, 0.1, 0}, {0.5, 0.1, 0}});
  CHECK(h.polyline_to_curve == Approx(0.1));
  CHECK(h.curve_to_polyline == Approx(std::hypot(0.5, 0.1)));  // the line's far end
  CHECK(h.max() == h.curve_to_polyline);
  CHECK_THROWS(hausdorff_distance(line, {}));
}

TEST_CASE("every bundled stroke's fitted curve stays within a few δ of it, both ways",
          "[preprocess][hausdorff]") {
  PreprocessParams app = cassie_app_preprocess();
  PreprocessParams app_no_hooks = cassie_app_preprocess();
  app_no_hooks.remove_hooks = false;
  const std::pair<const char*, PreprocessParams> rule_sets[] = {
      {"sketchlab", PreprocessParams{}}, {"cassie_app", app}, {"cassie_app, no hooks", app_no_hooks}};
  std::size_t strokes = 0;
  for (const auto& file : bundled_recordings()) {
    const Recording rec = read_recording(file);
    for (const Event& e : rec.events) {
      const auto* se = std::get_if<StrokeEvent>(&e.payload);
      if (!se || se->stroke.samples_are_pixels) continue;
      const Stroke& s = se->stroke;
      const std::vector<Vec3> pts = stroke_points(s);
      const double d = 0.02 / s.workspace_scale;
      const double length = polyline_length(pts);
      ++strokes;
      for (const auto& [name, params] : rule_sets) {
        INFO(file.filename().string() << " stroke " << s.id << ", rules " << name);
        const Preprocessed p = preprocess_stroke(s, params);
        const HausdorffDistance h = hausdorff_distance(p.curve, pts);
        if (p.is_line) {
          // A line accepts a bow of up to ~9 % of its length (line_detection.hpp).
          CHECK(h.max() <= std::max(1.0 * d, 0.1 * length));
        } else {
          CHECK(h.curve_to_polyline <= 2.0 * d);
          CHECK(h.polyline_to_curve <= 3.5 * d);  // a hook spans at most 3δ
        }
      }
    }
  }
  CHECK(strokes > 2900);  // the 18 sessions and the synthetic VR sketches
}

TEST_CASE("the strokes that used to fly away stay put", "[preprocess][hausdorff]") {
  // Before: 01-2-1 stroke 7 (3 samples, 7 cm) reached 0.78 m away; 02-1-2
  // strokes 89/90 (3 samples) 0.22 m; the synthetic mug's rim (closed, ends
  // 5 mm apart) became a 1.31 m curve with a 0.30 m spike: least-squares
  // handles longer than the points they fit.
  const struct {
    const char* file;
    StrokeId id;
  } cases[] = {{"data/recordings/01-2-1.jsonl", 7},
               {"data/recordings/02-1-2.jsonl", 89},
               {"data/recordings/02-1-2.jsonl", 90},
               {"data/synthetic/mug.jsonl", 1}};
  for (const auto& c : cases) {
    const Recording rec = read_recording(test::source_path(c.file));
    const Stroke& s = stroke_of(rec, c.id);
    const std::vector<Vec3> pts = stroke_points(s);
    for (const PreprocessParams& params : {PreprocessParams{}, cassie_app_preprocess()}) {
      INFO(c.file << " stroke " << c.id);
      const Preprocessed p = preprocess_stroke(s, params);
      CHECK(hausdorff_distance(p.curve, pts).curve_to_polyline < 0.02);
    }
  }
}
