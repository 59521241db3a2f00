#pragma once
// Feedback on every correction (issue #25): the stroke being drawn, live;
// once released it stays drawn as it was until its correction comes back
// from the worker (so nothing blinks away while the stack works), then it
// fades out over `transition_s` while the corrected curves of that stroke
// glow (a halo in `glow_colour` around them) and settle; the constraints the corrector enforced flash where they
// act for `flash_s` (and, when asked, the candidates it rejected). Schmidt
// et al. 2009 §4 ("temporary visual feedback" of right-angle markers) and
// ScaffoldSketch's users, who needed to see when and why a snap fired.
//
// Everything is in workspace coordinates (the placement is applied as the
// actors' user matrix); times are the session's display seconds.
#include <cstddef>
#include <deque>
#include <vector>

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "sketchlab/constraint.hpp"
#include "sketchlab/sketch.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::vr {

inline constexpr double transition_s = 0.35;  // raw stroke -> corrected curve
inline constexpr double flash_s = 1.5;        // constraint markers shown, fading over the last third
inline constexpr double marker_size = 0.012;  // m, workspace
inline constexpr viewer::Rgb glow_colour{0.10, 0.55, 0.95};

// Opacity factor of a flash `age` seconds old (1, then down to 0 at flash_s).
double flash_opacity(double age);

class CorrectionFeedback {
 public:
  CorrectionFeedback(vtkRenderer* renderer, const viewer::SceneStyle& style);

  // The stroke being drawn (workspace samples; empty when not drawing).
  void set_live_stroke(const std::vector<Sample>& samples);
  // A stroke the input just finished and submitted to the worker.
  void stroke_submitted(const Stroke& stroke);
  // A snapshot arrived in which `strokes_handled` stroke events have been
  // folded; `stroke` is the latest of them, `sketch` the shown stack's
  // sketch and `constraints` what its corrector considered for `stroke`.
  void corrected(std::size_t strokes_handled, StrokeId stroke, const Sketch& sketch,
                 const std::vector<Constraint>& constraints, bool show_rejected, double now);
  // Per frame: placement and fades.
  void update(vtkMatrix4x4* placement, double now);

 private:
  void clear_flash();
  vtkRenderer* renderer_;
  viewer::SceneStyle style_;
  vtkSmartPointer<vtkActor> live_, pending_actor_, fading_, glow_;
  std::deque<std::vector<Vec3>> pending_;  // submitted, not corrected yet, oldest first
  std::size_t submitted_ = 0;              // stroke events submitted so far
  double fade_start_ = -1.0, flash_start_ = -1.0;
  struct Flash {
    vtkSmartPointer<vtkActor> actor;
    double opacity;
  };
  std::vector<Flash> flash_;
};

}  // namespace sketchlab::vr
