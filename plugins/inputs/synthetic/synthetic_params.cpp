#include "synthetic_params.hpp"

#include <numbers>

#include "models.hpp"
#include "sketchlab/plugin/param_table.hpp"

namespace sketchlab::synthetic {

namespace {

const ParamTable<SynthesisParams>& parameters() {
  using S = SynthesisParams;
  using N = NoiseModel;
  using M = MotionModel;
  std::vector<std::string> models = model_names();
  models.push_back("mesh");
  static const auto table =
      ParamTable<S>()
          .choice("model", &S::model, models,
                  "ground-truth curve network: a built-in model, or 'mesh' for the sharp feature curves of "
                  "the 'mesh' file")
          .string("mesh", &S::mesh, "triangle/polygon mesh (OFF or PLY) for model=mesh")
          .real("size", &S::size, 0.01, 10.0, "m", "largest extent of the model")
          .integer("seed", &S::seed, 0.0, {}, "", "random seed: the same seed gives the same session byte for byte")
          .choice("modality", &S::modality,
                  std::vector<std::pair<std::string, Modality>>{{"vr", Modality::vr}, {"tablet", Modality::tablet}},
                  "vr: 3D samples in metres at 90 Hz; tablet: pixels of a camera view")
          .choice("style", &S::style,
                  std::vector<std::pair<std::string, DrawingStyle>>{{"plain", DrawingStyle::plain},
                                                                    {"analytic", DrawingStyle::analytic},
                                                                    {"justdrawit", DrawingStyle::justdrawit}},
                  "plain: the model's curves only; analytic (tablet): construction scaffold, ground-plane "
                  "first stroke, guidelines toward the vanishing points and ticks, as in analytic drawing; "
                  "justdrawit (tablet): multi-stroke curves, then every curve oversketched from a second view")
          .boolean("draw_planes", &S::draw_planes,
                   "style=justdrawit: each curve drawn on the draw plane placed for it (its own plane; a line's "
                   "plane facing the eye), as JustDrawIt's users give curves depth (§5.1); false: on the view plane")
          .real("noise", &S::noise, 0.0, 10.0, "", "global scale of every error magnitude below (0: perfect strokes)")
          .real("vr_jitter", nested_field(&S::vr_noise, &N::jitter), 0.0, 0.1, "m", "per-sample Gaussian noise, std per axis (tracking + tremor)")
          .real("vr_wobble", nested_field(&S::vr_noise, &N::wobble), 0.0, 0.1, "m", "RMS low-frequency lateral deviation across the view ray")
          .real("vr_wobble_wavelength", nested_field(&S::vr_noise, &N::wobble_wavelength), 0.01, 10.0, "m", "longest wavelength of the wobble along the stroke")
          .real("vr_depth_factor", nested_field(&S::vr_noise, &N::depth_factor), 0.0, 10.0, "", "wobble along the view ray / across it (depth is judged worst)")
          .real("vr_overshoot", nested_field(&S::vr_noise, &N::overshoot), 0.0, 0.2, "m", "std of the over/undershoot at each end along the end tangent")
          .real("vr_hook_probability", nested_field(&S::vr_noise, &N::hook_probability), 0.0, 1.0, "", "chance of a hook at each end")
          .real("vr_hook_length", nested_field(&S::vr_noise, &N::hook_length), 0.0, 0.2, "m", "length of a hook")
          .real("vr_speed", nested_field(&S::vr_motion, &M::speed), 0.01, 10.0, "m/s", "mean hand speed along a stroke")
          .real("vr_rate", nested_field(&S::vr_motion, &M::rate), 1.0, 1000.0, "Hz", "controller sampling rate")
          .real("tablet_jitter", nested_field(&S::tablet_noise, &N::jitter), 0.0, 100.0, "px", "per-sample Gaussian noise, std per axis")
          .real("tablet_wobble", nested_field(&S::tablet_noise, &N::wobble), 0.0, 100.0, "px", "RMS low-frequency lateral deviation")
          .real("tablet_wobble_wavelength", nested_field(&S::tablet_noise, &N::wobble_wavelength), 1.0, 1e5, "px", "longest wavelength of the wobble")
          .real("tablet_overshoot", nested_field(&S::tablet_noise, &N::overshoot), 0.0, 1000.0, "px", "std of the over/undershoot at each end")
          .real("tablet_hook_probability", nested_field(&S::tablet_noise, &N::hook_probability), 0.0, 1.0, "", "chance of a hook at each end")
          .real("tablet_hook_length", nested_field(&S::tablet_noise, &N::hook_length), 0.0, 1000.0, "px", "length of a hook")
          .real("tablet_speed", nested_field(&S::tablet_motion, &M::speed), 1.0, 1e5, "px/s", "mean pen speed along a stroke")
          .real("tablet_rate", nested_field(&S::tablet_motion, &M::rate), 1.0, 1000.0, "Hz", "pen sampling rate")
          .real("feature_angle", nested_field(&S::mesh_features, &MeshFeatureParams::feature_angle), 0.0, std::numbers::pi, "rad",
                "model=mesh: an edge is a feature when its faces' normals differ by more than this")
          .real("corner_angle", nested_field(&S::mesh_features, &MeshFeatureParams::corner_angle), 0.0, std::numbers::pi, "rad",
                "model=mesh: feature chains are split where they turn by more than this")
          .real("pause", &S::pause, 0.0, 60.0, "s", "mean pause between strokes");
  return table;
}

}  // namespace

std::vector<ParamSpec> synthetic_param_specs() { return parameters().specs(); }

SynthesisParams synthesis_params(const Params& p) { return parameters().read(p); }

}  // namespace sketchlab::synthetic
