#pragma once
// Random curves, valid random edits and networks for the network tests. All
// randomness comes from the caller's seeded std::mt19937_64.
#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "sketchlab/curve.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::test {

inline double uniform(std::mt19937_64& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}
inline int uniform_int(std::mt19937_64& rng, int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }
inline bool chance(std::mt19937_64& rng, double p) { return uniform(rng, 0.0, 1.0) < p; }

inline Vec3 random_point(std::mt19937_64& rng, double lo = 0.0, double hi = 1.0) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}
inline Vec3 random_direction(std::mt19937_64& rng) {
  Vec3 d;
  do d = random_point(rng, -1.0, 1.0);
  while (d.norm() < 1e-3 || d.norm() > 1.0);
  return d.normalized();
}

template <class T>
T pick(std::mt19937_64& rng, const std::vector<T>& v) {
  return v[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(v.size()) - 1))];
}

// A random curve starting at `start` with `segments` cubic pieces, each about
// `size` metres: a line (1 in 4 single-piece curves), a closed loop (1 in 6
// when segments >= 2) or an open poly-Bézier.
inline Curve random_curve(std::mt19937_64& rng, const Vec3& start, double size, int segments) {
  const int kind = uniform_int(rng, 0, 11);
  if (kind < 3 && segments == 1) return make_line(start, start + size * uniform(rng, 0.5, 3.0) * random_direction(rng));
  Curve c;
  Vec3 p = start;
  c.control_points.push_back(p);
  for (int k = 0; k < segments; ++k)
    for (int j = 0; j < 3; ++j) {
      p += random_point(rng, -1.0, 1.0) * (size / 2.0);
      c.control_points.push_back(p);
    }
  c.sharp.assign(static_cast<std::size_t>(segments) + 1, false);
  for (std::size_t i = 0; i < c.sharp.size(); ++i) c.sharp[i] = chance(rng, 0.25);
  if (kind < 5 && segments >= 2) {
    c.control_points.back() = c.control_points.front();
    c.closed = true;
  }
  return c;
}

inline NetworkCurve random_network_curve(std::mt19937_64& rng, CurveId id, int segments = 0) {
  NetworkCurve nc;
  nc.id = id;
  nc.curve = random_curve(rng, random_point(rng), uniform(rng, 0.02, 0.12),
                          segments > 0 ? segments : (chance(rng, 0.4) ? 1 : uniform_int(rng, 2, 4)));
  nc.layer = static_cast<Layer>(uniform_int(rng, 0, 3));
  nc.source_stroke = static_cast<StrokeId>(uniform_int(rng, 1, 50));
  nc.keypoints = default_keypoints(nc.curve);
  if (chance(rng, 0.3)) {
    const double t = uniform(rng, 0.0, nc.curve.t_max());
    nc.keypoints.push_back(Keypoint{Keypoint::Kind::tick, t, evaluate(nc.curve, t)});
  }
  if (chance(rng, 0.25)) nc.normals.push_back(CurveNormal{uniform(rng, 0.0, nc.curve.t_max()), Vec3::UnitY()});
  return nc;
}

inline double random_t(std::mt19937_64& rng, double t_max) {
  const int k = uniform_int(rng, 0, 9);
  if (k == 0) return 0.0;
  if (k == 1) return t_max;
  return uniform(rng, 0.0, t_max);
}

// A node on 1..3 of the given curves (ids with their t_max).
inline Node random_node(std::mt19937_64& rng, NodeId id, const std::map<CurveId, double>& t_max) {
  Node n;
  n.id = id;
  n.position = random_point(rng);
  std::vector<CurveId> ids;
  for (const auto& [c, tm] : t_max) ids.push_back(c);
  const int count = uniform_int(rng, 1, 3);
  for (int i = 0; i < count; ++i) {
    const CurveId c = pick(rng, ids);
    n.incidences.push_back(NodeIncidence{c, random_t(rng, t_max.at(c))});
  }
  return n;
}

inline Patch random_patch(std::mt19937_64& rng, PatchId id, const std::map<CurveId, double>& t_max) {
  Patch p;
  p.id = id;
  std::vector<CurveId> ids;
  for (const auto& [c, tm] : t_max) ids.push_back(c);
  const int count = uniform_int(rng, 1, 4);
  for (int i = 0; i < count; ++i) {
    const CurveId c = pick(rng, ids);
    p.boundary.push_back(OrientedSegment{c, random_t(rng, t_max.at(c)), random_t(rng, t_max.at(c)),
                                         static_cast<NodeId>(uniform_int(rng, 1, 9)),
                                         static_cast<NodeId>(uniform_int(rng, 1, 9))});
  }
  p.mesh.vertices = {random_point(rng), random_point(rng), random_point(rng)};
  p.mesh.faces = {{0, 1, 2}};
  p.automatic = chance(rng, 0.5);
  return p;
}

// A random edit that is valid for `net`, exercising every field: removals
// (with the implied stripping of incidences and patches), replacements that
// change a curve's parameter range (and fix the nodes and patches it
// invalidates), re-adding a removed id, node and patch additions.
inline Edit random_edit(std::mt19937_64& rng, const Network& net) {
  Edit e;
  std::vector<CurveId> curve_ids;
  for (const auto& [id, c] : net.curves()) curve_ids.push_back(id);
  std::vector<NodeId> node_ids;
  for (const auto& [id, n] : net.nodes()) node_ids.push_back(id);
  std::vector<PatchId> patch_ids;
  for (const auto& [id, p] : net.patches()) patch_ids.push_back(id);

  std::set<PatchId> patches_removed;
  std::set<NodeId> nodes_removed;
  std::set<CurveId> curves_removed;
  if (!patch_ids.empty() && chance(rng, 0.3)) patches_removed.insert(pick(rng, patch_ids));
  if (!node_ids.empty())
    for (int i = uniform_int(rng, 0, 2); i > 0; --i) nodes_removed.insert(pick(rng, node_ids));
  if (!curve_ids.empty())
    for (int i = uniform_int(rng, 0, 2); i > 0; --i) curves_removed.insert(pick(rng, curve_ids));

  // Final parameter ranges.
  std::map<CurveId, double> t_max;
  for (const auto& [id, c] : net.curves())
    if (!curves_removed.count(id)) t_max[id] = c.curve.t_max();
  std::set<CurveId> replaced;
  if (!curve_ids.empty())
    for (int i = uniform_int(rng, 0, 2); i > 0; --i) {
      const CurveId id = pick(rng, curve_ids);
      if (curves_removed.count(id) || replaced.count(id)) continue;
      const int old_k = net.find_curve(id)->curve.segment_count();
      NetworkCurve nc = random_network_curve(rng, id, chance(rng, 0.5) ? old_k : uniform_int(rng, 1, 4));
      t_max[id] = nc.curve.t_max();
      replaced.insert(id);
      e.curves_replaced.push_back(nc);
    }
  CurveId next = net.next_curve_id();
  for (int i = uniform_int(rng, 0, 3); i > 0; --i) {
    NetworkCurve nc = random_network_curve(rng, next++);
    t_max[nc.id] = nc.curve.t_max();
    e.curves_added.push_back(nc);
  }
  if (!curves_removed.empty() && chance(rng, 0.2)) {
    // Re-use a removed id in the same edit (allowed: it is absent by step 5).
    NetworkCurve nc = random_network_curve(rng, *curves_removed.begin());
    t_max[nc.id] = nc.curve.t_max();
    e.curves_added.push_back(nc);
  }

  // Existing nodes: stripped incidences, and those a replacement put out of
  // range, force a node replacement; some are replaced at random anyway.
  for (const auto& [id, node] : net.nodes()) {
    if (nodes_removed.count(id)) continue;
    Node n = node;
    std::erase_if(n.incidences, [&](const NodeIncidence& inc) { return curves_removed.count(inc.curve) > 0; });
    if (n.incidences.empty()) continue;  // removed with its last curve
    bool must = false;
    for (NodeIncidence& inc : n.incidences)
      if (inc.t > t_max.at(inc.curve)) {
        inc.t = t_max.at(inc.curve) * uniform(rng, 0.0, 1.0);
        must = true;
      }
    if (must || chance(rng, 0.02)) {
      if (!must) n = random_node(rng, id, t_max);
      e.nodes_replaced.push_back(n);
    }
  }
  if (!t_max.empty()) {
    NodeId next_node = net.next_node_id();
    for (int i = uniform_int(rng, 0, 3); i > 0; --i) e.nodes_added.push_back(random_node(rng, next_node++, t_max));
  }
  // Existing patches: one whose boundary a replacement put out of range must go.
  for (const auto& [id, patch] : net.patches())
    for (const OrientedSegment& s : patch.boundary)
      if (!curves_removed.count(s.curve) && (s.t_from > t_max.at(s.curve) || s.t_to > t_max.at(s.curve)))
        patches_removed.insert(id);
  if (!t_max.empty() && chance(rng, 0.4)) e.patches_added.push_back(random_patch(rng, net.next_patch_id(), t_max));
  if (!patches_removed.empty() && !t_max.empty() && chance(rng, 0.2)) {
    e.patches_added.push_back(random_patch(rng, *patches_removed.begin(), t_max));
  }

  e.patches_removed.assign(patches_removed.begin(), patches_removed.end());
  e.nodes_removed.assign(nodes_removed.begin(), nodes_removed.end());
  e.curves_removed.assign(curves_removed.begin(), curves_removed.end());
  std::shuffle(e.curves_removed.begin(), e.curves_removed.end(), rng);
  return e;
}

// Grows a network by `count` random curves, with some nodes among them.
inline Network random_network(std::mt19937_64& rng, int count) {
  Network net;
  const int batch = 100;
  for (int done = 0; done < count; done += batch) {
    Edit e;
    std::map<CurveId, double> t_max;
    for (int i = 0; i < std::min(batch, count - done); ++i) {
      e.curves_added.push_back(random_network_curve(rng, net.next_curve_id() + static_cast<CurveId>(i)));
      t_max[e.curves_added.back().id] = e.curves_added.back().curve.t_max();
    }
    for (int i = 0; i < batch / 4; ++i)
      e.nodes_added.push_back(random_node(rng, net.next_node_id() + static_cast<NodeId>(i), t_max));
    net.apply(e);
  }
  return net;
}

}  // namespace sketchlab::test
