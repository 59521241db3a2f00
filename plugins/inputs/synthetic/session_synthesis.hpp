#pragma once
// A whole synthetic session: ground-truth network -> drawing plan -> strokes,
// each followed by its ground-truth curve and the relations it completes.
#include <cstdint>
#include <string>

#include "ground_truth.hpp"
#include "mesh_features.hpp"
#include "sketchlab/recording/recording.hpp"
#include "stroke_synthesis.hpp"

namespace sketchlab::synthetic {

enum class Modality { vr, tablet };

// How the person draws: `plain` draws the model's curves only (scaffold lines
// first, then connected neighbours); `analytic` draws as the users of
// analytic drawing do (construction.hpp: construction scaffold, ground-plane
// first stroke, guidelines, ticks); `justdrawit` as JustDrawIt's users do
// (multi_view.hpp: multi-stroke curves, then every curve oversketched from a
// second view). Both tablet only.
enum class DrawingStyle { plain, analytic, justdrawit };

struct SynthesisParams {
  std::string model = "cube";  // a model_names() entry, or "mesh"
  std::string mesh;            // OFF/PLY path when model == "mesh"
  double size = 0.3;           // m: largest extent of the model
  std::uint64_t seed = 1;
  Modality modality = Modality::vr;
  DrawingStyle style = DrawingStyle::plain;
  bool draw_planes = true;     // style justdrawit: strokes on placed draw planes
  double noise = 1.0;          // global scale of every error magnitude
  NoiseModel vr_noise{0.0005, 0.004, 0.15, 2.0, 0.005, 0.2, 0.015};  // metres
  MotionModel vr_motion{0.35, 90.0, 0.25};
  NoiseModel tablet_noise{0.5, 1.5, 200.0, 1.0, 4.0, 0.1, 8.0};    // pixels
  MotionModel tablet_motion{500.0, 120.0, 0.2};
  MeshFeatureParams mesh_features;
  double pause = 1.0;  // s: mean pause between strokes (uniform in [0.6, 1.4]×)
};

// Where the models stand (m) and where the VR user's eyes are.
inline const Vec3 model_center{0.0, 1.2, 0.0};
inline const Vec3 vr_head_position{0.0, 1.6, 0.6};

// The ground-truth network named by params (built-in model or mesh features),
// not yet ordered for drawing.
GroundTruthNetwork build_network(const SynthesisParams& params);

// The head pose given to VR strokes (view matrix looking at the model).
View vr_head_view();
// The tablet camera: perspective, 35° vertical field of view, 1600×1000 px,
// looking at the model from the front-right-above at twice its size.
View tablet_view(const GroundTruthNetwork& net);
// The second view of style justdrawit: the tablet camera turned 60° about
// the vertical through the model centre (front-left-above).
View second_tablet_view(const GroundTruthNetwork& net);

// The session: header (units m or px, default workspace, source = generator
// and parameters) and, per stroke in drawing order, a StrokeEvent (id 1, 2,
// ... ; time = its last sample), a ReferenceEvent (track "ground_truth", the
// intended curve in workspace metres, also for tablet sessions) and the
// RelationEvents (track "ground_truth") whose last stroke it is. Guideline
// strokes and ticks (style analytic) have no ReferenceEvent: they are
// construction aids, not intended curves; with style justdrawit every stroke
// of a curve has it, and its relations come with the curve's first stroke.
// Throws std::invalid_argument for a style that needs the tablet in VR.
Recording synthesize_session(const SynthesisParams& params);

}  // namespace sketchlab::synthetic
