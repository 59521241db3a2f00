#pragma once
// Turns one intended curve into the samples a person would produce drawing
// it, in VR (workspace metres) or on a tablet (pixels of a camera View).
//
// Motion: the hand moves along the curve with the minimum-jerk profile of
// Flash & Hogan (1985), s(τ) = s0 + (s1 - s0)(10τ³ - 15τ⁴ + 6τ⁵), τ = t/T,
// whose peak speed is 1.875× the mean; the duration is T = max(min_duration,
// path length / mean speed), sampled at `rate` Hz (τ = i/(N-1)).
// Errors, every magnitude multiplied by the global `noise` scale:
//  - endpoint over/undershoot: the path runs from -o0 to L + o1 along the
//    curve's arclength, o ~ N(0, overshoot), extrapolated along the end
//    tangents beyond the ends (negative o stops short);
//  - low-frequency wobble: an offset perpendicular to the path, a sum of
//    three sinusoids of arclength (wavelengths λ, 0.62λ, 0.38λ, random
//    phases) with RMS `wobble` per component. In VR one component is across
//    the view ray and the other along the ray from the head, scaled by
//    `depth_factor` (depth is judged worst, Arora et al. 2017); on a tablet
//    there is one component, in the image plane;
//  - hooks: with probability hook_probability at each end, a flick of
//    hook_length turning back by more than 90° (over 0.1 s);
//  - jitter: i.i.d. Gaussian per sample and axis, std `jitter` (tracking
//    noise and physiological tremor).
// With noise = 0 every sample lies exactly on the curve (VR) or is exactly
// world_to_pixel of a point of the curve (tablet).
#include <optional>
#include <vector>

#include "rng.hpp"
#include "sketchlab/curve.hpp"
#include "sketchlab/sample.hpp"
#include "sketchlab/view.hpp"

namespace sketchlab::synthetic {

// Units: metres for VR, pixels for the tablet.
struct NoiseModel {
  double jitter = 0.0;
  double wobble = 0.0;
  double wobble_wavelength = 0.15;
  double depth_factor = 1.0;  // VR only
  double overshoot = 0.0;
  double hook_probability = 0.0;
  double hook_length = 0.0;
};

struct MotionModel {
  double speed = 0.35;        // mean speed along the path (units/s)
  double rate = 90.0;         // samples per second
  double min_duration = 0.25; // s
};

// Noise model with every magnitude (not the probability) scaled by `noise`.
NoiseModel scaled(const NoiseModel& model, double noise);

// VR: samples in metres, starting at time `start`. `head` is the eye
// position the depth error is measured from.
std::vector<Sample> synthesize_vr_stroke(const Curve& curve, const Vec3& head,
                                         const NoiseModel& noise, const MotionModel& motion,
                                         double start, Rng& rng);

// Tablet: samples are pixels (x, y, 0) of `view`.
std::vector<Sample> synthesize_tablet_stroke(const Curve& curve, const View& view,
                                             const NoiseModel& noise, const MotionModel& motion,
                                             double start, Rng& rng);

}  // namespace sketchlab::synthetic
