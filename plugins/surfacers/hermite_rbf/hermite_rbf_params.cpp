#include "hermite_rbf_params.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "sketchlab/plugin/param_table.hpp"

namespace sketchlab::hermite_rbf {
namespace {

// Angles are shown in degrees rounded to 1e-6 (the stored radians are
// rounded constants) and read back in radians.
const RealConversion degrees{
    [](double radians) { return std::round(radians * 180.0 / std::numbers::pi * 1e6) / 1e6; },
    [](double shown) { return shown * std::numbers::pi / 180.0; }};

const ParamTable<HermiteRbfParams>& parameters() {
  using P = HermiteRbfParams;
  auto sampling = [](auto field) { return nested_field(&P::sampling, field); };
  auto normals = [](auto field) { return nested_field(&P::normals, field); };
  auto partition = [](auto field) { return nested_field(&P::partition, field); };
  auto mesh = [](auto field) { return nested_field(&P::mesh, field); };
  static const auto table =
      ParamTable<P>()
          .real("sample_spacing", sampling(&SamplingParams::sample_spacing), 1e-5, 10.0, "m",
                "spacing of the curve samples the §6 rules count (JustDrawIt's polyline points)")
          .integer("max_samples", sampling(&SamplingParams::max_samples), 10.0, 100000.0, "",
                   "curve samples at most; the spacing grows on large sketches")
          .integer("point_stride", sampling(&SamplingParams::point_stride), 1.0, 1000.0, "",
                   "a point constraint at least every this many samples (§6: 6)")
          .real("deviation_factor", sampling(&SamplingParams::deviation_factor), 0.0, 100.0, "",
                "a point constraint where skipped samples leave their fitted line by more than this × the "
                "average sample distance (§6: 1)")
          .integer("tangent_stride", sampling(&SamplingParams::tangent_stride), 1.0, 1000.0, "",
                   "a tangent constraint at least every this many samples (§6: 12)")
          .real("tangent_change", sampling(&SamplingParams::tangent_change), 0.0, 2.0, "",
                "a tangent constraint where 1 - dot(tangent, last constrained tangent) exceeds this (§6: 0.4)")
          .integer("normal_stride", sampling(&SamplingParams::normal_stride), 1.0, 1000.0, "",
                   "a normal constraint at least every this many samples (§6: as tangents, 12)")
          .real("normal_change", sampling(&SamplingParams::normal_change), 0.0, 2.0, "",
                "a normal constraint where 1 - dot(normal, last constrained normal) exceeds this (§6: 0.1)")
          .real("planarity", normals(&NormalParams::planarity), 0.0, 1.0, "",
                "a curve is planar when no sample leaves its fitted plane by more than this × its length")
          .integer("intersection_window", normals(&NormalParams::intersection_window), 2.0, 1000.0, "",
                   "samples each side of an intersection fitted by the plane giving its normal (§6: 10)")
          .choice("normal_rule", normals(&NormalParams::network_rule),
                  std::vector<std::pair<std::string, bool>>{{"network", true}, {"paper", false}},
                  "network: intersection normals oriented consistently across the network and used along every curve "
                  "through them (the default rules only where a curve meets no other); paper: §6 as written (default "
                  "rules wherever no intersection is within intersection_window samples)")
          .real("regularizer", nested_field(&P::solve, &SolveParams::regularizer), 0.0, 1.0, "",
                "λ added to the kernel matrix diagonal (normalised coordinates); raised ×100 if the "
                "factorisation fails; the value used is reported")
          .choice("solver", &P::solver,
                  std::vector<std::pair<std::string, Solver>>{{"partition", Solver::partition},
                                                              {"dense", Solver::dense}},
                  "partition: local Hermite RBF fits blended by a partition of unity (Ohtake et al. 2003; linear "
                  "memory and time); dense: one global system (exact, cubic time; the reference)")
          .integer("pu_max_rows", partition(&PartitionParams::max_rows), 20.0, 5000.0, "",
                   "partition of unity: a cell is split while its support holds more rows than this")
          .integer("pu_min_rows", partition(&PartitionParams::min_rows), 5.0, 5000.0, "",
                   "partition of unity: a leaf's support grows until it holds this many rows")
          .integer("pu_min_normals", partition(&PartitionParams::min_normals), 1.0, 1000.0, "",
                   "partition of unity: ... and this many normal constraints")
          .real("pu_overlap", partition(&PartitionParams::overlap), 1.0, 4.0, "",
                "partition of unity: support radius / cell half diagonal (Ohtake et al. 2003: 1.5)")
          .integer("resolution", mesh(&MeshParams::resolution), 8.0, 1024.0, "",
                   "marching-cubes grid cells along the longest side of the box")
          .real("padding", mesh(&MeshParams::padding), 0.0, 10.0, "",
                "grid box margin around the constraints, × their bounding-box diagonal")
          .real("far_distance", mesh(&MeshParams::far_distance), 0.0, 10.0, "",
                "surface farther than this × the bounding-box diagonal from every curve sample is 'far' "
                "(reported as far_area_fraction)")
          .choice("trim", mesh(&MeshParams::trim),
                  std::vector<std::pair<std::string, Trim>>{{"enclosed", Trim::enclosed},
                                                            {"far_components", Trim::far_components},
                                                            {"none", Trim::none}},
                  "enclosed: drop components far from the curves and cut the surface where no curves enclose it "
                  "(opens instead of ballooning); far_components: only drop those components (closed, watertight); "
                  "none: the whole zero set (JustDrawIt §6: watertight)")
          .real("trim_reach", mesh(&MeshParams::trim_reach), 0.01, 10.0, "",
                "trim: curves within this × the bounding-box diagonal can enclose a surface point")
          .real("trim_elevation", mesh(&MeshParams::trim_elevation), 1.0, 90.0, "deg",
                "trim: curves seen more steeply than this from a point's tangent plane do not enclose it", degrees)
          .real("trim_gap", mesh(&MeshParams::trim_gap), 10.0, 360.0, "deg",
                "trim: a point is enclosed when no angle around its normal wider than this is free of curves", degrees)
          .integer("threads", mesh(&MeshParams::threads), 0.0, 256.0, "", "grid evaluation threads (0: one per core)");
  return table;
}

}  // namespace

std::vector<ParamSpec> hermite_rbf_param_specs() { return parameters().specs(); }

HermiteRbfParams hermite_rbf_params(const Params& p) { return parameters().read(p); }

}  // namespace sketchlab::hermite_rbf
