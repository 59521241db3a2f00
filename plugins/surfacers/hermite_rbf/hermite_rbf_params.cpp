#include "hermite_rbf_params.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace sketchlab::hermite_rbf {
namespace {

double degrees(double radians) { return std::round(radians * 180.0 / std::numbers::pi * 1e6) / 1e6; }

}  // namespace

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
      {"normal_rule", ParamType::choice, std::string("network"), {}, {}, {"network", "paper"}, "",
       "network: intersection normals oriented consistently across the network and used along every curve "
       "through them (the default rules only where a curve meets no other); paper: §6 as written (default "
       "rules wherever no intersection is within intersection_window samples)"},
      {"regularizer", ParamType::real, d.solve.regularizer, 0.0, 1.0, {}, "",
       "λ added to the kernel matrix diagonal (normalised coordinates); raised ×100 if the "
       "factorisation fails; the value used is reported"},
      {"solver", ParamType::choice, std::string("partition"), {}, {}, {"partition", "dense"}, "",
       "partition: local Hermite RBF fits blended by a partition of unity (Ohtake et al. 2003; linear "
       "memory and time); dense: one global system (exact, cubic time; the reference)"},
      {"pu_max_rows", ParamType::integer, integer(d.partition.max_rows), 20.0, 5000.0, {}, "",
       "partition of unity: a cell is split while its support holds more rows than this"},
      {"pu_min_rows", ParamType::integer, integer(d.partition.min_rows), 5.0, 5000.0, {}, "",
       "partition of unity: a leaf's support grows until it holds this many rows"},
      {"pu_min_normals", ParamType::integer, integer(d.partition.min_normals), 1.0, 1000.0, {}, "",
       "partition of unity: ... and this many normal constraints"},
      {"pu_overlap", ParamType::real, d.partition.overlap, 1.0, 4.0, {}, "",
       "partition of unity: support radius / cell half diagonal (Ohtake et al. 2003: 1.5)"},
      {"resolution", ParamType::integer, integer(d.mesh.resolution), 8.0, 1024.0, {}, "",
       "marching-cubes grid cells along the longest side of the box"},
      {"padding", ParamType::real, d.mesh.padding, 0.0, 10.0, {}, "",
       "grid box margin around the constraints, × their bounding-box diagonal"},
      {"far_distance", ParamType::real, d.mesh.far_distance, 0.0, 10.0, {}, "",
       "surface farther than this × the bounding-box diagonal from every curve sample is 'far' "
       "(reported as far_area_fraction)"},
      {"trim", ParamType::choice, std::string("enclosed"), {}, {}, {"enclosed", "far_components", "none"}, "",
       "enclosed: drop components far from the curves and cut the surface where no curves enclose it "
       "(opens instead of ballooning); far_components: only drop those components (closed, watertight); "
       "none: the whole zero set (JustDrawIt §6: watertight)"},
      {"trim_reach", ParamType::real, d.mesh.trim_reach, 0.01, 10.0, {}, "",
       "trim: curves within this × the bounding-box diagonal can enclose a surface point"},
      {"trim_elevation", ParamType::real, degrees(d.mesh.trim_elevation), 1.0, 90.0, {}, "deg",
       "trim: curves seen more steeply than this from a point's tangent plane do not enclose it"},
      {"trim_gap", ParamType::real, degrees(d.mesh.trim_gap), 10.0, 360.0, {}, "deg",
       "trim: a point is enclosed when no angle around its normal wider than this is free of curves"},
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
  r.normals.network_rule = p.string("normal_rule") == "network";
  r.solve.regularizer = p.real("regularizer");
  r.solver = p.string("solver") == "dense" ? Solver::dense : Solver::partition;
  r.partition.max_rows = static_cast<int>(p.integer("pu_max_rows"));
  r.partition.min_rows = static_cast<int>(p.integer("pu_min_rows"));
  r.partition.min_normals = static_cast<int>(p.integer("pu_min_normals"));
  r.partition.overlap = p.real("pu_overlap");
  r.mesh.resolution = static_cast<int>(p.integer("resolution"));
  r.mesh.padding = p.real("padding");
  r.mesh.far_distance = p.real("far_distance");
  const std::string& trim = p.string("trim");
  r.mesh.trim = trim == "none" ? Trim::none : trim == "far_components" ? Trim::far_components : Trim::enclosed;
  r.mesh.trim_reach = p.real("trim_reach");
  r.mesh.trim_elevation = p.real("trim_elevation") * std::numbers::pi / 180.0;
  r.mesh.trim_gap = p.real("trim_gap") * std::numbers::pi / 180.0;
  r.mesh.threads = static_cast<int>(p.integer("threads"));
  return r;
}

}  // namespace sketchlab::hermite_rbf
