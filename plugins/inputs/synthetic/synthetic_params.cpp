#include "synthetic_params.hpp"

#include <numbers>

#include "models.hpp"

namespace sketchlab::synthetic {

std::vector<ParamSpec> synthetic_param_specs() {
  const SynthesisParams d;
  std::vector<std::string> models = model_names();
  models.push_back("mesh");
  auto real = [](std::string name, double def, double lo, std::optional<double> hi, std::string unit,
                 std::string doc) {
    return ParamSpec{std::move(name), ParamType::real, def, lo, hi, {}, std::move(unit), std::move(doc)};
  };
  return {
      {"model", ParamType::choice, d.model, {}, {}, models, "",
       "ground-truth curve network: a built-in model, or 'mesh' for the sharp feature curves of "
       "the 'mesh' file"},
      {"mesh", ParamType::string, d.mesh, {}, {}, {}, "", "triangle/polygon mesh (OFF or PLY) for model=mesh"},
      real("size", d.size, 0.01, 10.0, "m", "largest extent of the model"),
      {"seed", ParamType::integer, static_cast<std::int64_t>(d.seed), 0.0, {}, {}, "",
       "random seed: the same seed gives the same session byte for byte"},
      {"modality", ParamType::choice, std::string("vr"), {}, {}, {"vr", "tablet"}, "",
       "vr: 3D samples in metres at 90 Hz; tablet: pixels of a camera view"},
      {"style", ParamType::choice, std::string("plain"), {}, {}, {"plain", "analytic", "justdrawit"}, "",
       "plain: the model's curves only; analytic (tablet): construction scaffold, ground-plane "
       "first stroke, guidelines toward the vanishing points and ticks, as in analytic drawing; "
       "justdrawit (tablet): multi-stroke curves, then every curve oversketched from a second view"},
      real("noise", d.noise, 0.0, 10.0, "",
           "global scale of every error magnitude below (0: perfect strokes)"),
      real("vr_jitter", d.vr_noise.jitter, 0.0, 0.1, "m", "per-sample Gaussian noise, std per axis (tracking + tremor)"),
      real("vr_wobble", d.vr_noise.wobble, 0.0, 0.1, "m", "RMS low-frequency lateral deviation across the view ray"),
      real("vr_wobble_wavelength", d.vr_noise.wobble_wavelength, 0.01, 10.0, "m", "longest wavelength of the wobble along the stroke"),
      real("vr_depth_factor", d.vr_noise.depth_factor, 0.0, 10.0, "", "wobble along the view ray / across it (depth is judged worst)"),
      real("vr_overshoot", d.vr_noise.overshoot, 0.0, 0.2, "m", "std of the over/undershoot at each end along the end tangent"),
      real("vr_hook_probability", d.vr_noise.hook_probability, 0.0, 1.0, "", "chance of a hook at each end"),
      real("vr_hook_length", d.vr_noise.hook_length, 0.0, 0.2, "m", "length of a hook"),
      real("vr_speed", d.vr_motion.speed, 0.01, 10.0, "m/s", "mean hand speed along a stroke"),
      real("vr_rate", d.vr_motion.rate, 1.0, 1000.0, "Hz", "controller sampling rate"),
      real("tablet_jitter", d.tablet_noise.jitter, 0.0, 100.0, "px", "per-sample Gaussian noise, std per axis"),
      real("tablet_wobble", d.tablet_noise.wobble, 0.0, 100.0, "px", "RMS low-frequency lateral deviation"),
      real("tablet_wobble_wavelength", d.tablet_noise.wobble_wavelength, 1.0, 1e5, "px", "longest wavelength of the wobble"),
      real("tablet_overshoot", d.tablet_noise.overshoot, 0.0, 1000.0, "px", "std of the over/undershoot at each end"),
      real("tablet_hook_probability", d.tablet_noise.hook_probability, 0.0, 1.0, "", "chance of a hook at each end"),
      real("tablet_hook_length", d.tablet_noise.hook_length, 0.0, 1000.0, "px", "length of a hook"),
      real("tablet_speed", d.tablet_motion.speed, 1.0, 1e5, "px/s", "mean pen speed along a stroke"),
      real("tablet_rate", d.tablet_motion.rate, 1.0, 1000.0, "Hz", "pen sampling rate"),
      real("feature_angle", d.mesh_features.feature_angle, 0.0, std::numbers::pi, "rad",
           "model=mesh: an edge is a feature when its faces' normals differ by more than this"),
      real("corner_angle", d.mesh_features.corner_angle, 0.0, std::numbers::pi, "rad",
           "model=mesh: feature chains are split where they turn by more than this"),
      real("pause", d.pause, 0.0, 60.0, "s", "mean pause between strokes"),
  };
}

SynthesisParams synthesis_params(const Params& p) {
  SynthesisParams s;
  s.model = p.string("model");
  s.mesh = p.string("mesh");
  s.size = p.real("size");
  s.seed = static_cast<std::uint64_t>(p.integer("seed"));
  s.modality = p.string("modality") == "tablet" ? Modality::tablet : Modality::vr;
  const std::string style = p.string("style");
  s.style = style == "analytic" ? DrawingStyle::analytic
            : style == "justdrawit" ? DrawingStyle::justdrawit
                                    : DrawingStyle::plain;
  s.noise = p.real("noise");
  s.vr_noise = {p.real("vr_jitter"),   p.real("vr_wobble"),           p.real("vr_wobble_wavelength"),
                p.real("vr_depth_factor"), p.real("vr_overshoot"), p.real("vr_hook_probability"),
                p.real("vr_hook_length")};
  s.vr_motion = {p.real("vr_speed"), p.real("vr_rate"), s.vr_motion.min_duration};
  s.tablet_noise = {p.real("tablet_jitter"),   p.real("tablet_wobble"),
                    p.real("tablet_wobble_wavelength"), 1.0,
                    p.real("tablet_overshoot"), p.real("tablet_hook_probability"),
                    p.real("tablet_hook_length")};
  s.tablet_motion = {p.real("tablet_speed"), p.real("tablet_rate"), s.tablet_motion.min_duration};
  s.mesh_features = {p.real("feature_angle"), p.real("corner_angle")};
  s.pause = p.real("pause");
  return s;
}

}  // namespace sketchlab::synthetic
