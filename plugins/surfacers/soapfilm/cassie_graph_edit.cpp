#include "cassie_graph_edit.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>

#include "curve_graph.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/network_curve.hpp"

namespace sketchlab::soapfilm {
namespace {

struct Meeting {
  double t_new = 0.0;  // on the new curve
  CurveId old = 0;
  double t_old = 0.0;
  Vec3 point;  // on the old curve
};

// The curves of the edit so far and the nodes it made or changed, over the
// network as it was.
class Overlay {
 public:
  Overlay(const Network& network, bool closed_seam_nodes)
      : network_(&network), next_node_(network.next_node_id()), closed_seam_nodes_(closed_seam_nodes) {}

  // Alive curves within `distance` of p: the network's and the edit's own.
  std::vector<CurveHit> curves_near(const Vec3& p, double distance) const {
    std::vector<CurveHit> out = network_->curves_near(p, distance);
    for (const NetworkCurve& c : added_)
      if (const ClosestPoint cp = closest_point(c.curve, p); cp.distance <= distance)
        out.push_back({c.id, cp.t, cp.point, cp.distance});
    return out;
  }
  // The same for the closest pair between each curve and a segment [a, b].
  std::vector<CurveHit> curves_near_segment(const Vec3& a, const Vec3& b, double distance) const {
    std::vector<CurveHit> out = network_->curves_near_polyline({a, b}, distance);
    for (const NetworkCurve& c : added_)
      if (const ClosestPoint cp = closest_point_to_polyline(c.curve, {a, b}); cp.distance <= distance)
        out.push_back({c.id, cp.t, cp.point, cp.distance});
    return out;
  }
  // The node nearest p within r with an incidence on `curve`, or 0; a node
  // of the network that is no graph node (what a deleted curve left) only
  // if `left_over`. The edit's own nodes are all graph nodes.
  NodeId node_on(CurveId curve, const Vec3& p, double r, bool left_over) const {
    NodeId best = 0;
    double best_d = INFINITY;
    auto consider = [&](const Node& n) {
      const double d = (n.position - p).norm();
      if (d <= r && d < best_d && on_curve(n, curve)) best = n.id, best_d = d;
    };
    const CurveGraph graph(*network_, closed_seam_nodes_);
    for (const NodeHit& h : network_->nodes_near(p, r))
      if (!nodes_.count(h.node) && (left_over || graph.is_graph_node(h.node)))
        consider(*network_->find_node(h.node));
    for (const auto& [id, n] : nodes_) consider(n);
    return best;
  }
  Node& node(NodeId id) {
    if (auto it = nodes_.find(id); it != nodes_.end()) return it->second;
    return nodes_.emplace(id, *network_->find_node(id)).first->second;
  }
  Node& new_node(const Vec3& p) {
    Node& n = nodes_[next_node_];
    n.id = next_node_++;
    n.position = p;
    return n;
  }
  void add_curve(NetworkCurve c) { added_.push_back(std::move(c)); }
  CurveId next_curve() const { return network_->next_curve_id() + added_.size(); }

  Edit edit() const {
    Edit e;
    e.curves_added = added_;
    for (const auto& [id, n] : nodes_) (network_->find_node(id) ? e.nodes_replaced : e.nodes_added).push_back(n);
    return e;
  }

  static bool on_curve(const Node& n, CurveId c) {
    return std::any_of(n.incidences.begin(), n.incidences.end(), [&](const NodeIncidence& i) { return i.curve == c; });
  }

 private:
  const Network* network_;
  std::vector<NetworkCurve> added_;
  std::map<NodeId, Node> nodes_;  // new ones (ids >= the network's next) and changed copies
  NodeId next_node_;
  bool closed_seam_nodes_;
};

// Which alive curves a point of the new curve meets: those within `base`
// (on_curve for a Bézier joint, line_meets·δ for a line), or, on a logged
// stroke, as its log says (CassieGraphParams::logged_meets).
class JointTest {
 public:
  JointTest(const Overlay& alive, const CassieCurve& in, const CassieGraphParams& params, double delta)
      : alive_(&alive), params_(&params), reach_(params.logged_meets * delta) {
    if (!in.log || !(reach_ > 0.0)) return;
    logged_ = true;
    // CASSIE app, item 21: "applied" = bound in the best subset; item 22:
    // those onto a curve or a node are the graph's intersections.
    const CassieConstraintLog& log = *in.log;
    for (std::size_t i = 0; i < log.applied.size(); ++i) {
      const std::optional<bool> flag = i < log.applied_intersection.size() ? log.applied_intersection[i] : std::nullopt;
      if (flag.value_or(true)) targets_.push_back(log.applied[i]);
    }
  }

  // The alive curves the point p meets, base being the test without a log.
  std::vector<CurveHit> hits(const Vec3& p, double base) const {
    if (!logged_) return alive_->curves_near(p, base);
    const std::vector<const Vec3*> near = targets_near(p);
    if (near.empty()) return params_->logged_only ? std::vector<CurveHit>{} : alive_->curves_near(p, base);
    std::vector<CurveHit> out = alive_->curves_near(p, std::max(base, reach_));
    std::erase_if(out, [&](const CurveHit& h) {
      return h.distance > base && std::none_of(near.begin(), near.end(), [&](const Vec3* q) { return passes(h.curve, *q); });
    });
    return out;
  }
  // Whether a point of a line's interior may meet (logged_only).
  bool may_meet(const Vec3& p) const {
    return !logged_ || !params_->logged_only || !targets_near(p).empty();
  }
  const Overlay& alive() const { return *alive_; }

 private:
  std::vector<const Vec3*> targets_near(const Vec3& p) const {
    std::vector<const Vec3*> out;
    for (const Vec3& q : targets_)
      if ((q - p).norm() <= reach_) out.push_back(&q);
    return out;
  }
  bool passes(CurveId c, const Vec3& q) const {
    const std::vector<CurveHit> at = alive_->curves_near(q, params_->logged_on_curve);
    return std::any_of(at.begin(), at.end(), [&](const CurveHit& h) { return h.curve == c; });
  }
  const Overlay* alive_;
  const CassieGraphParams* params_;
  double reach_;
  bool logged_ = false;
  std::vector<Vec3> targets_;  // logged applied intersections (or unflagged positions)
};

// Where the new curve meets alive curves with `base` as the test distance
// (see the header), by t_new.
std::vector<Meeting> meetings(const JointTest& test, const Curve& curve, double base) {
  std::vector<Meeting> out;
  if (curve.kind == CurveKind::line) {
    // Its ends, then where it passes closest to each curve (a line may meet
    // one curve at both ends, or at an end and inside).
    const Vec3 a = curve.control_points.front(), b = curve.control_points.back();
    for (const double t : {0.0, curve.t_max()})
      for (const CurveHit& h : test.hits(t == 0.0 ? a : b, base)) out.push_back({t, h.curve, h.t, h.point});
    const double length = (b - a).norm();
    for (const CurveHit& h : test.alive().curves_near_segment(a, b, base)) {
      const ClosestPoint on_line = closest_point(curve, h.point);
      const bool at_end = std::any_of(out.begin(), out.end(), [&](const Meeting& m) {
        return m.old == h.curve && std::abs(m.t_new - on_line.t) * length <= 2.0 * base;
      });
      if (!at_end && test.may_meet(on_line.point)) out.push_back({on_line.t, h.curve, h.t, h.point});
    }
  } else {
    const int K = curve.segment_count();
    for (int k = 0; k <= (curve.closed ? K - 1 : K); ++k)
      for (const CurveHit& h : test.hits(curve.control_points[static_cast<std::size_t>(3 * k)], base))
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

void add_curve(Overlay& overlay, const CassieCurve& in, const CassieGraphParams& params) {
  const Curve& curve = in.curve;
  if (const std::string why = validate(curve); !why.empty()) throw std::invalid_argument("cassie_graph_edit: " + why);
  if (!(in.scale > 0.0) || !std::isfinite(in.scale)) throw std::invalid_argument("cassie_graph_edit: scale must be > 0");
  const double delta = params.delta / in.scale;
  const CurveId c = overlay.next_curve();
  const double T = curve.t_max();
  auto own_t = [&](double t) { return curve.closed && t >= T ? 0.0 : std::clamp(t, 0.0, T); };

  std::vector<std::pair<NodeId, Vec3>> on_new;  // nodes on the new curve, with positions
  const double meet = curve.kind == CurveKind::line ? params.line_meets * delta : params.on_curve;
  // A node the new curve already has at parameter t: it is the new curve's
  // only node there, whatever the distances (two nodes at one t of a curve
  // would leave no segment between them, cutting the network there).
  auto node_at = [&](double t) -> NodeId {
    for (const auto& [id, p] : on_new)
      if (has_incidence(overlay.node(id), c, t)) return id;
    return 0;
  };
  for (const Meeting& m : meetings(JointTest(overlay, in, params, delta), curve, meet)) {
    const double t = own_t(m.t_new);
    // 0. The new curve's node at this parameter (a joint meeting two curves).
    if (const NodeId here = node_at(t)) {
      Node& n = overlay.node(here);
      if (!Overlay::on_curve(n, m.old)) n.incidences.push_back({m.old, m.t_old});
      continue;
    }
    // 1. A node already on the new curve within 0.5δ; 2. a node of the old
    // curve within δ of the meeting point (item 22 names the new stroke
    // first; with reuse_new_first unset, the old curve's node comes first).
    const auto reuse_mine = [&] {
      NodeId mine = 0;
      double best = params.reuse_new * delta;
      for (const auto& [id, p] : on_new)
        if ((p - m.point).norm() <= best) best = (p - m.point).norm(), mine = id;
      if (!mine) return false;
      Node& n = overlay.node(mine);
      if (!Overlay::on_curve(n, m.old)) n.incidences.push_back({m.old, m.t_old});
      return true;
    };
    const auto reuse_old = [&] {
      const NodeId old_node = overlay.node_on(m.old, m.point, params.reuse_old * delta, params.reuse_left_over);
      if (!old_node) return false;
      Node& n = overlay.node(old_node);
      if (!has_incidence(n, c, t)) n.incidences.push_back({c, t});
      if (std::none_of(on_new.begin(), on_new.end(), [&](const auto& p) { return p.first == old_node; }))
        on_new.emplace_back(old_node, n.position);
      return true;
    };
    if (params.reuse_new_first ? reuse_mine() || reuse_old() : reuse_old() || reuse_mine()) continue;
    // 3. A new node splitting the old curve.
    Node& n = overlay.new_node(m.point);
    n.incidences = {{c, t}, {m.old, m.t_old}};
    on_new.emplace_back(n.id, n.position);
  }
  // Every stroke end is a node (a closed stroke has one).
  for (double t_end : curve.closed ? std::vector<double>{0.0} : std::vector<double>{0.0, T}) {
    const Vec3 p = curve.control_points[t_end == 0.0 ? 0 : curve.control_points.size() - 1];
    // An intersection at the end made its node already (an old curve's node
    // within δ may lie farther than 0.5δ from the end point).
    if (node_at(t_end)) continue;
    if (std::any_of(on_new.begin(), on_new.end(),
                    [&](const auto& q) { return (q.second - p).norm() <= params.reuse_new * delta; }))
      continue;
    Node& n = overlay.new_node(p);
    n.incidences = {{c, t_end}};
    on_new.emplace_back(n.id, p);
  }
  overlay.add_curve(make_network_curve(c, curve, Layer::shape, in.stroke));
}

}  // namespace

Edit cassie_graph_edit(const Network& network, const std::vector<CassieCurve>& curves,
                       const CassieGraphParams& params) {
  Overlay overlay(network, params.closed_seam_nodes);
  for (const CassieCurve& c : curves) add_curve(overlay, c, params);
  return overlay.edit();
}

}  // namespace sketchlab::soapfilm
