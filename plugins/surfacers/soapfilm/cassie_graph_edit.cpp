#include "cassie_graph_edit.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "sketchlab/geometry/closest_point.hpp"

namespace sketchlab::soapfilm {
namespace {

struct Meeting {
  double t_new = 0.0;  // on the new curve
  CurveId old = 0;
  double t_old = 0.0;
  Vec3 point;  // on the old curve
};

// Where the new curve meets alive curves within `distance` (see the
// header), by t_new.
std::vector<Meeting> meetings(const Network& network, const Curve& curve, double distance) {
  std::vector<Meeting> out;
  if (curve.kind == CurveKind::line) {
    const Vec3 a = curve.control_points.front(), b = curve.control_points.back();
    for (const CurveHit& h : network.curves_near_polyline({a, b}, distance)) {
      const ClosestPoint on_line = closest_point(curve, h.point);
      out.push_back({on_line.t, h.curve, h.t, h.point});
    }
  } else {
    const int K = curve.segment_count();
    for (int k = 0; k <= (curve.closed ? K - 1 : K); ++k)
      for (const CurveHit& h : network.curves_near(curve.control_points[static_cast<std::size_t>(3 * k)], distance))
        out.push_back({static_cast<double>(k), h.curve, h.t, h.point});
  }
  std::stable_sort(out.begin(), out.end(), [](const Meeting& a, const Meeting& b) { return a.t_new < b.t_new; });
  return out;
}

// Whether the node already holds curve c at (about) parameter t: one node
// met twice at one place (two old curves crossing there) keeps one incidence.
bool has_incidence(const Node& n, CurveId c, double t) {
  return std::any_of(n.incidences.begin(), n.incidences.end(),
                     [&](const NodeIncidence& i) { return i.curve == c && std::abs(i.t - t) < 1e-6; });
}

bool on_curve(const Node& n, CurveId c) {
  return std::any_of(n.incidences.begin(), n.incidences.end(), [&](const NodeIncidence& i) { return i.curve == c; });
}

}  // namespace

Edit cassie_graph_edit(const Network& network, StrokeId stroke, const Curve& curve, double scale,
                       const CassieGraphParams& params) {
  if (const std::string why = validate(curve); !why.empty()) throw std::invalid_argument("cassie_graph_edit: " + why);
  if (!(scale > 0.0) || !std::isfinite(scale)) throw std::invalid_argument("cassie_graph_edit: scale must be > 0");
  const double delta = params.delta / scale;
  Edit edit;
  NetworkCurve nc;
  nc.id = network.next_curve_id();
  nc.curve = curve;
  nc.layer = Layer::shape;
  nc.source_stroke = stroke;
  nc.keypoints = default_keypoints(curve);
  const CurveId c = nc.id;
  const double T = curve.t_max();
  auto own_t = [&](double t) { return curve.closed && t >= T ? 0.0 : std::clamp(t, 0.0, T); };

  // Nodes the new curve goes through: existing ones (copied, to be replaced)
  // and new ones, in the order they are met.
  std::map<NodeId, Node> reused;
  std::vector<Node> fresh;
  NodeId next = network.next_node_id();
  std::vector<std::pair<NodeId, Vec3>> on_new;  // nodes on the new curve, with positions
  auto add_to = [&](NodeId id) -> Node& {
    if (auto it = reused.find(id); it != reused.end()) return it->second;
    for (Node& n : fresh)
      if (n.id == id) return n;
    return reused.emplace(id, *network.find_node(id)).first->second;
  };

  const double meet = curve.kind == CurveKind::line ? params.line_meets * delta : params.on_curve;
  for (const Meeting& m : meetings(network, curve, meet)) {
    const double t = own_t(m.t_new);
    // 1. A node of the old curve within δ of the meeting point.
    NodeId old_node = 0;
    for (const NodeHit& h : network.nodes_near(m.point, params.reuse_old * delta))
      if (on_curve(*network.find_node(h.node), m.old)) {
        old_node = h.node;
        break;
      }
    if (old_node) {
      Node& n = add_to(old_node);
      if (!has_incidence(n, c, t)) n.incidences.push_back({c, t});
      if (std::none_of(on_new.begin(), on_new.end(), [&](const auto& p) { return p.first == old_node; }))
        on_new.emplace_back(old_node, n.position);
      continue;
    }
    // 2. A node already on the new curve within 0.5δ.
    NodeId mine = 0;
    double best = params.reuse_new * delta;
    for (const auto& [id, p] : on_new)
      if ((p - m.point).norm() <= best) best = (p - m.point).norm(), mine = id;
    if (mine) {
      Node& n = add_to(mine);
      if (!on_curve(n, m.old)) n.incidences.push_back({m.old, m.t_old});
      continue;
    }
    // 3. A new node splitting the old curve.
    Node n;
    n.id = next++;
    n.position = m.point;
    n.incidences = {{c, t}, {m.old, m.t_old}};
    on_new.emplace_back(n.id, n.position);
    fresh.push_back(std::move(n));
  }
  // Every stroke end is a node (a closed stroke has one).
  for (double t_end : curve.closed ? std::vector<double>{0.0} : std::vector<double>{0.0, T}) {
    const Vec3 p = curve.control_points[t_end == 0.0 ? 0 : curve.control_points.size() - 1];
    bool covered = false;
    for (const auto& [id, q] : on_new) covered = covered || (q - p).norm() <= params.reuse_new * delta;
    if (covered) continue;
    Node n;
    n.id = next++;
    n.position = p;
    n.incidences = {{c, t_end}};
    on_new.emplace_back(n.id, p);
    fresh.push_back(std::move(n));
  }
  edit.curves_added.push_back(std::move(nc));
  edit.nodes_added = std::move(fresh);
  for (auto& [id, n] : reused) edit.nodes_replaced.push_back(std::move(n));
  return edit;
}

}  // namespace sketchlab::soapfilm
