#pragma once
// Selection of scaffold keypoints and tangents for a shape stroke
// (ScaffoldSketch §4.2.1).
#include <cstddef>
#include <vector>

#include "scaffold_params.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::scaffoldsketch {

struct ShapeKeypoints {
  std::vector<Vec3> points;         // Q: keypoint positions, consecutive repeats removed
  std::vector<Vec3> tangents;       // D: unit tangent at each, oriented along the stroke
  std::vector<CurveId> keypoint_curve;  // a scaffold line owning the keypoint
  std::vector<double> keypoint_t;       // and the keypoint's parameter on it
  std::vector<CurveId> tangent_curve;   // scaffold line giving the tangent (0: stroke direction)
  std::vector<std::size_t> sample;      // index of the selecting sample in the input
  bool closed = false;  // Q returns to its first keypoint after >= 2 others: closed
};

// `samples`: the stroke resampled uniformly in arclength (n x 3, metres;
// §4.2.1 uses 1 cm). For each sample, the nearest keypoint of a scaffold line
// within keypoint_distance/s; keypoints sharing a position are one keypoint
// (ties: lowest curve id). At each selected keypoint the tangent is the
// direction of the scaffold line through it that makes the smallest angle
// (below tangent_angle) with the forward difference d = (p_{i+1} - p_i) /
// |p_{i+1} - p_i|, else the local average direction of the stroke
// (p_{i+2} - p_{i-2}, clamped to the ends). For a run of samples selecting
// the same keypoint, i is the sample closest to it; with tangent_sample best,
// the smallest angle is taken over the forward differences of every sample
// of the run (the local direction still comes from the closest).
ShapeKeypoints select_shape_keypoints(const std::vector<Vec3>& samples, const Network& network,
                                      const ShapeParams& params, double scale);

}  // namespace sketchlab::scaffoldsketch
