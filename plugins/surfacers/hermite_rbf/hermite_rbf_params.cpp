#include "hermite_rbf_params.hpp"

namespace sketchlab::hermite_rbf {

std::vector<ParamSpec> hermite_rbf_param_specs() {
  const HermiteRbfParams d;
  auto integer = [](int v) { return ParamValue{std::int64_t{v}}; };
  return {
      {"sample_spacing", ParamType::real, d.sampling.sample_spacing, 1e-5, 10.0, {}, "m",
       "spacing of the curve samples the §6 rules count (JustDrawIt's polyline points)"},
      {"max_samples", ParamType::integer, integer(d.sampling.max_samples), 10.0, 100000.0, {}, "",
       "curve samples at most; the spacing grows on large sketches"},
      {"point_stride", ParamType::integer, integer(d.sampling.point_stride), 1.0, 1000.0, {}, "",
       "a point constraint at least every this many samples (§6: 6)"},
      {"deviation_factor", ParamType::real, d.sampling.deviation_factor, 0.0, 100.0, {}, "",
       "a point constraint where skipped samples leave their fitted line by more than this × the "
       "average sample distance (§6: 1)"},
      {"tangent_stride", ParamType::integer, integer(d.sampling.tangent_stride), 1.0, 1000.0, {}, "",
       "a tangent constraint at least every this many samples (§6: 12)"},
      {"tangent_change", ParamType::real, d.sampling.tangent_change, 0.0, 2.0, {}, "",
       "a tangent constraint where 1 - dot(tangent, last constrained tangent) exceeds this (§6: 0.4)"},
      {"normal_stride", ParamType::integer, integer(d.sampling.normal_stride), 1.0, 1000.0, {}, "",
       "a normal constraint at least every this many samples (§6: as tangents, 12)"},
      {"normal_change", ParamType::real, d.sampling.normal_change, 0.0, 2.0, {}, "",
       "a normal constraint where 1 - dot(normal, last constrained normal) exceeds this (§6: 0.1)"},
      {"planarity", ParamType::real, d.normals.planarity, 0.0, 1.0, {}, "",
       "a curve is planar when no sample leaves its fitted plane by more than this × its length"},
      {"intersection_window", ParamType::integer, integer(d.normals.intersection_window), 2.0, 1000.0, {}, "",
       "samples each side of an intersection fitted by the plane giving its normal (§6: 10)"},
      {"regularizer", ParamType::real, d.solve.regularizer, 0.0, 1.0, {}, "",
       "λ added to the kernel matrix diagonal (normalised coordinates); raised ×100 if the "
       "factorisation fails; the value used is reported"},
      {"resolution", ParamType::integer, integer(d.mesh.resolution), 8.0, 1024.0, {}, "",
       "marching-cubes grid cells along the longest side of the box"},
      {"padding", ParamType::real, d.mesh.padding, 0.0, 10.0, {}, "",
       "grid box margin around the constraints, × their bounding-box diagonal"},
      {"far_distance", ParamType::real, d.mesh.far_distance, 0.0, 10.0, {}, "",
       "surface farther than this × the bounding-box diagonal from every curve sample is 'far' "
       "(reported as far_area_fraction)"},
      {"trim_far_components", ParamType::boolean, d.mesh.trim_far_components, {}, {}, {}, "",
       "drop closed components of the zero set with no vertex near a curve (keeps the rest watertight)"},
      {"threads", ParamType::integer, integer(d.mesh.threads), 0.0, 256.0, {}, "",
       "grid evaluation threads (0: one per core)"},
  };
}

HermiteRbfParams hermite_rbf_params(const Params& p) {
  HermiteRbfParams r;
  r.sampling.sample_spacing = p.real("sample_spacing");
  r.sampling.max_samples = static_cast<int>(p.integer("max_samples"));
  r.sampling.point_stride = static_cast<int>(p.integer("point_stride"));
  r.sampling.deviation_factor = p.real("deviation_factor");
  r.sampling.tangent_stride = static_cast<int>(p.integer("tangent_stride"));
  r.sampling.tangent_change = p.real("tangent_change");
  r.sampling.normal_stride = static_cast<int>(p.integer("normal_stride"));
  r.sampling.normal_change = p.real("normal_change");
  r.normals.planarity = p.real("planarity");
  r.normals.intersection_window = static_cast<int>(p.integer("intersection_window"));
  r.solve.regularizer = p.real("regularizer");
  r.mesh.resolution = static_cast<int>(p.integer("resolution"));
  r.mesh.padding = p.real("padding");
  r.mesh.far_distance = p.real("far_distance");
  r.mesh.trim_far_components = p.boolean("trim_far_components");
  r.mesh.threads = static_cast<int>(p.integer("threads"));
  return r;
}

}  // namespace sketchlab::hermite_rbf
