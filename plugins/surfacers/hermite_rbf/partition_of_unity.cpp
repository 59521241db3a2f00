#include "partition_of_unity.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "parallel_for.hpp"

namespace sketchlab::hermite_rbf {
namespace {

// FNV-1a over the bytes of doubles: equal inputs, equal keys.
struct Hash {
  std::uint64_t h = 1469598103934665603ull;
  void add(double v) {
    unsigned char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    for (unsigned char c : b) h = (h ^ c) * 1099511628211ull;
  }
  void add(const Vec3& v) { add(v.x()), add(v.y()), add(v.z()); }
};

// Direction of constraint k (zero for points).
Vec3 direction(const HermiteConstraints& c, const ConstraintIndex& index, std::size_t k) {
  if (k < index.points) return Vec3::Zero();
  if (k < index.points + index.tangents) return c.tangents[k - index.points];
  return c.normals[k - index.points - index.tangents];
}

int kind(const ConstraintIndex& index, std::size_t k) { return k < index.points ? 0 : k < index.points + index.tangents ? 1 : 2; }

std::uint64_t cell_key(const PartitionCell& cell, const HermiteConstraints& c, const ConstraintIndex& index) {
  Hash h;
  h.add(cell.center);
  h.add(cell.radius);
  h.add(cell.fit_radius);
  for (std::size_t k : cell.members) {
    h.add(double(kind(index, k)));
    h.add(index.position(c, k));
    h.add(direction(c, index, k));
  }
  return h.h;
}

bool same_cell(const PartitionCell& a, const HermiteConstraints& ca, const PartitionCell& b, const HermiteConstraints& cb) {
  if (a.center != b.center || a.radius != b.radius || a.fit_radius != b.fit_radius || a.members.size() != b.members.size())
    return false;
  const ConstraintIndex ia(ca), ib(cb);
  for (std::size_t i = 0; i < a.members.size(); ++i) {
    const std::size_t ka = a.members[i], kb = b.members[i];
    if (kind(ia, ka) != kind(ib, kb) || ia.position(ca, ka) != ib.position(cb, kb) ||
        direction(ca, ia, ka) != direction(cb, ib, kb))
      return false;
  }
  return true;
}

HermiteConstraints members_of(const PartitionCell& cell, const HermiteConstraints& c, const ConstraintIndex& index) {
  HermiteConstraints out;
  for (std::size_t k : cell.members) {
    const Vec3& p = index.position(c, k);
    switch (kind(index, k)) {
      case 0: out.points.push_back(p); break;
      case 1: out.tangent_points.push_back(p), out.tangents.push_back(direction(c, index, k)); break;
      default: out.normal_points.push_back(p), out.normals.push_back(direction(c, index, k)); break;
    }
  }
  return out;
}

// Wendland's ψ_{3,1}(t) = (1 − t)⁴ (4t + 1) and ψ'(t) / t = −20 (1 − t)³.
inline double wendland(double t) {
  const double u = 1.0 - t;
  return u * u * u * u * (4.0 * t + 1.0);
}

}  // namespace

template <bool gradient>
double PartitionOfUnity::evaluate(const Vec3& x, Vec3* g) const {
  int b[3];
  for (int a = 0; a < 3; ++a)
    b[a] = std::clamp(static_cast<int>(std::floor((x[a] - lookup_origin_[a]) / bucket_)), 0, buckets_ - 1);
  const std::size_t bucket = std::size_t(b[0]) + std::size_t(buckets_) * (std::size_t(b[1]) + std::size_t(buckets_) * std::size_t(b[2]));
  double S = 0.0, W = 0.0;
  Vec3 dS = Vec3::Zero(), dW = Vec3::Zero();
  for (std::uint32_t k = bucket_start_[bucket]; k < bucket_start_[bucket + 1]; ++k) {
    const std::size_t i = bucket_cells_[k];
    const PartitionCell& cell = cells_[i];
    const Vec3 v = x - cell.center;
    const double d2 = v.squaredNorm(), r2 = cell.radius * cell.radius;
    if (d2 >= r2) continue;
    const double t = std::sqrt(d2) / cell.radius;
    const double w = wendland(t);
    if constexpr (gradient) {
      Vec3 gi;
      const double fi = fits_[i]->value_gradient(x, gi);
      const double u = 1.0 - t;
      const Vec3 dw = (-20.0 * u * u * u / r2) * v;  // ∇ψ(‖v‖/R) = ψ'(t)/t · v / R²
      S += w * fi;
      W += w;
      dS += dw * fi + w * gi;
      dW += dw;
    } else {
      S += w * fits_[i]->value(x);
      W += w;
    }
  }
  if (!(W > 0.0)) {
    // Outside every support (only outside the domain): far outside the surface.
    if constexpr (gradient) *g = Vec3::Zero();
    return std::numeric_limits<double>::max();
  }
  const double f = S / W;
  if constexpr (gradient) *g = (dS - f * dW) / W;
  return f;
}

double PartitionOfUnity::value(const Vec3& x) const { return evaluate<false>(x, nullptr); }

double PartitionOfUnity::value_gradient(const Vec3& x, Vec3& gradient) const { return evaluate<true>(x, &gradient); }

void PartitionOfUnity::build_lookup(const Box3& domain) {
  // Buckets about the size of a typical cell.
  std::vector<double> edges;
  for (const PartitionCell& c : cells_) edges.push_back(2.0 * c.half_edge);
  std::nth_element(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(edges.size() / 2), edges.end());
  const double extent = std::max(domain.sizes().maxCoeff(), 1e-9);
  buckets_ = std::clamp(static_cast<int>(std::ceil(extent / edges[edges.size() / 2])), 1, 64);
  bucket_ = extent / buckets_;
  lookup_origin_ = domain.center() - Vec3::Constant(0.5 * extent);
  const std::size_t n = std::size_t(buckets_) * buckets_ * buckets_;
  std::vector<std::uint32_t> count(n + 1, 0);
  auto for_each_bucket = [&](const PartitionCell& c, auto&& visit) {
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::clamp(static_cast<int>(std::floor((c.center[a] - c.radius - lookup_origin_[a]) / bucket_)), 0, buckets_ - 1);
      hi[a] = std::clamp(static_cast<int>(std::floor((c.center[a] + c.radius - lookup_origin_[a]) / bucket_)), 0, buckets_ - 1);
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          // Sphere against the bucket's box; border buckets extend outwards
          // (queries outside the domain are clamped to them).
          const int idx[3] = {i, j, k};
          Vec3 nearest;
          for (int a = 0; a < 3; ++a) {
            const double lo_a = idx[a] == 0 ? -HUGE_VAL : lookup_origin_[a] + bucket_ * idx[a];
            const double hi_a = idx[a] == buckets_ - 1 ? HUGE_VAL : lookup_origin_[a] + bucket_ * (idx[a] + 1);
            nearest[a] = std::clamp(c.center[a], lo_a, hi_a);
          }
          if ((nearest - c.center).squaredNorm() >= c.radius * c.radius) continue;
          visit(std::size_t(i) + std::size_t(buckets_) * (std::size_t(j) + std::size_t(buckets_) * std::size_t(k)));
        }
  };
  for (const PartitionCell& c : cells_) for_each_bucket(c, [&](std::size_t b) { ++count[b + 1]; });
  for (std::size_t b = 0; b < n; ++b) count[b + 1] += count[b];
  bucket_start_ = count;
  bucket_cells_.assign(count[n], 0);
  for (std::size_t i = 0; i < cells_.size(); ++i)
    for_each_bucket(cells_[i], [&](std::size_t b) { bucket_cells_[count[b]++] = static_cast<std::uint32_t>(i); });
}

PartitionOfUnity fit_partition_of_unity(const HermiteConstraints& constraints, const Box3& domain,
                                        const PartitionParams& params, const SolveParams& solve, int threads,
                                        PartitionReport& report, const PartitionOfUnity* previous) {
  check_constraints(constraints);
  PartitionOfUnity pu;
  pu.constraints_ = std::make_shared<const HermiteConstraints>(constraints);
  pu.cells_ = partition_cells(*pu.constraints_, domain, params);
  const ConstraintIndex index(*pu.constraints_);
  const std::size_t n = pu.cells_.size();
  pu.keys_.resize(n);
  pu.fits_.resize(n);
  pu.regularizers_.resize(n);

  std::unordered_multimap<std::uint64_t, std::size_t> before;
  std::vector<char> reused_before;
  if (previous) {
    for (std::size_t i = 0; i < previous->cells_.size(); ++i) before.emplace(previous->keys_[i], i);
    reused_before.assign(previous->cells_.size(), 0);
  }
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < n; ++i) {
    pu.keys_[i] = cell_key(pu.cells_[i], *pu.constraints_, index);
    const auto [lo, hi] = before.equal_range(pu.keys_[i]);
    for (auto it = lo; it != hi && !pu.fits_[i]; ++it)
      if (same_cell(pu.cells_[i], *pu.constraints_, previous->cells_[it->second], *previous->constraints_)) {
        pu.fits_[i] = previous->fits_[it->second];
        pu.regularizers_[i] = previous->regularizers_[it->second];
        reused_before[it->second] = 1;
      }
    if (!pu.fits_[i]) todo.push_back(i);
  }

  std::vector<SolveReport> solves(todo.size());
  std::vector<std::exception_ptr> errors(todo.size());
  parallel_for(todo.size(), threads, [&](std::size_t t) {
    const PartitionCell& cell = pu.cells_[todo[t]];
    try {
      pu.fits_[todo[t]] = std::make_shared<const HermiteInterpolant>(
          solve_hermite_rbf(members_of(cell, *pu.constraints_, index), cell.center, 2.0 * cell.fit_radius, solve, solves[t]));
      pu.regularizers_[todo[t]] = solves[t].regularizer;
    } catch (...) {
      errors[t] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);

  report = PartitionReport{};
  report.cells = n;
  report.cells_fitted = todo.size();
  for (const PartitionCell& c : pu.cells_) {
    report.max_rows = std::max(report.max_rows, c.rows);
    report.mean_rows += c.rows;
  }
  report.mean_rows /= double(std::max<std::size_t>(1, n));
  for (double l : pu.regularizers_) report.regularizer = std::max(report.regularizer, l);
  for (std::size_t i : todo) report.changed.push_back({pu.cells_[i].center, pu.cells_[i].radius});
  if (previous)
    for (std::size_t i = 0; i < previous->cells_.size(); ++i)
      if (!reused_before[i]) report.changed.push_back({previous->cells_[i].center, previous->cells_[i].radius});
  pu.build_lookup(domain);
  return pu;
}

}  // namespace sketchlab::hermite_rbf
