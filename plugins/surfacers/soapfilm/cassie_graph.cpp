#include "cassie_graph.hpp"

#include <algorithm>
#include <stdexcept>

#include "cassie_breaks.hpp"
#include "cassie_json.hpp"
#include "curve_graph.hpp"
#include "patch_upkeep.hpp"
#include "sketchlab/network_curve.hpp"

namespace sketchlab::soapfilm {
namespace {

std::int64_t id_of(const nlohmann::json& item, const std::string& what) {
  if (!item.is_object() || !item.contains("id") || !item.at("id").is_number_integer())
    throw std::invalid_argument(what + " without an integer id");
  return item.at("id").get<std::int64_t>();
}

// One of the graph's three lists; anything else is refused naming the field
// (iterating a number or an object would report its items as bad elements).
const nlohmann::json& graph_list(const nlohmann::json& graph, const char* key) {
  const nlohmann::json& list = cassie_field(graph, key, "the graph");
  if (!list.is_array()) throw std::invalid_argument(std::string("the graph: field '") + key + "' is not a list");
  return list;
}

}  // namespace

CassieNetwork load_cassie_network(const std::filesystem::path& path) {
  const nlohmann::json j = read_cassie_json(path);
  try {
    // Index the segments and nodes (ids unique), then build one curve per
    // stroke from its segments in order.
    std::map<std::int64_t, const nlohmann::json*> segments;
    for (const auto& s : graph_list(j, "segments")) {
      const std::int64_t id = id_of(s, "a segment");
      if (!segments.emplace(id, &s).second) throw std::invalid_argument("segment " + std::to_string(id) + " listed twice");
    }
    std::map<std::int64_t, Vec3> node_pos;
    for (const auto& n : graph_list(j, "nodes")) {
      const std::int64_t id = id_of(n, "a node");
      const std::string at = "node " + std::to_string(id);
      if (!node_pos.emplace(id, cassie_point(cassie_field(n, "position", at), at + ": position")).second)
        throw std::invalid_argument("node " + std::to_string(id) + " listed twice");
    }

    CassieNetwork out;
    Edit edit;
    std::map<std::int64_t, Node> nodes;
    std::map<std::int64_t, std::int64_t> owner;  // segment -> stroke using it
    for (const auto& stroke : graph_list(j, "strokes")) {
      const std::int64_t sid = id_of(stroke, "a stroke");
      const std::string where = "stroke " + std::to_string(sid);
      if (sid < 0) throw std::invalid_argument(where + ": negative id");
      if (out.stroke_of.count(static_cast<CurveId>(sid + 1))) throw std::invalid_argument(where + " listed twice");
      const nlohmann::json& seg_ids = cassie_field(stroke, "segments", where);
      if (!seg_ids.is_array() || seg_ids.empty()) {
        // Real data (02-2-1, hmd_sutherland): a stroke the graph export kept
        // without its geometry. It bounds nothing; the rest still loads.
        out.warnings.push_back(path.string() + ": " + where + " has no segments; skipped");
        continue;
      }
      Curve curve;
      std::vector<std::pair<std::int64_t, double>> incidences;
      for (const auto& seg_id : seg_ids) {
        if (!seg_id.is_number_integer()) throw std::invalid_argument(where + ": a segment id is not an integer");
        const std::int64_t gid = seg_id.get<std::int64_t>();
        const std::string at = where + ": segment " + std::to_string(gid);
        const auto found = segments.find(gid);
        if (found == segments.end()) throw std::invalid_argument(at + " does not exist");
        if (const auto [it, fresh] = owner.emplace(gid, sid); !fresh)
          throw std::invalid_argument(at + " already belongs to stroke " + std::to_string(it->second));
        const nlohmann::json& seg = *found->second;
        // The segment names its stroke too (sketch_graph schema); a graph
        // where the two disagree is not CASSIE's (none of the bundled ones).
        if (seg.contains("stroke_id") &&
            !(seg["stroke_id"].is_number_integer() && seg["stroke_id"].get<std::int64_t>() == sid))
          throw std::invalid_argument(at + ": its stroke_id " + seg["stroke_id"].dump() + " is not stroke " +
                                      std::to_string(sid) + ", which lists it");
        std::vector<Vec3>& cp = curve.control_points;
        const double t_start = cp.empty() ? 0.0 : static_cast<double>((cp.size() - 1) / 3);
        const nlohmann::json& pieces = cassie_field(seg, "ctrl_pts", at);
        append_cassie_pieces(curve, pieces, at);
        const Vec3 a = cassie_point(pieces.at(0).at(0), at + ": first point");
        // Consecutive segments of a stroke share their joint.
        if (t_start > 0.0 && (a - cp[static_cast<std::size_t>(3 * t_start)]).norm() > 1e-3)
          throw std::invalid_argument(at + " starts " +
                                      std::to_string((a - cp[static_cast<std::size_t>(3 * t_start)]).norm()) +
                                      " m from where the previous segment ends");
        const double t_end = static_cast<double>((cp.size() - 1) / 3);
        const Vec3 b = cp.back();
        const auto& ends = cassie_field(seg, "nodes", at);
        if (!ends.is_array() || ends.size() != 2) throw std::invalid_argument(at + ": needs 2 nodes");
        if (!ends.at(0).is_number_integer() || !ends.at(1).is_number_integer())
          throw std::invalid_argument(at + ": node ids must be integers");
        const std::int64_t n0 = ends.at(0).get<std::int64_t>(), n1 = ends.at(1).get<std::int64_t>();
        for (std::int64_t n : {n0, n1})
          if (!node_pos.count(n)) throw std::invalid_argument(at + ": node " + std::to_string(n) + " does not exist");
        // Which listed node is at the segment start: the closer one.
        const bool swap = (node_pos.at(n0) - a).norm() + (node_pos.at(n1) - b).norm() >
                          (node_pos.at(n1) - a).norm() + (node_pos.at(n0) - b).norm();
        incidences.emplace_back(swap ? n1 : n0, t_start);
        incidences.emplace_back(swap ? n0 : n1, t_end);
      }
      finish_cassie_curve(curve);
      NetworkCurve nc = make_network_curve(static_cast<CurveId>(sid + 1), std::move(curve), Layer::shape,
                                           static_cast<StrokeId>(sid + 1));
      for (const auto& [n, t] : incidences) {
        Node& node = nodes[n];
        node.id = static_cast<NodeId>(n + 1);
        node.position = node_pos.at(n);
        const double tt = nc.curve.closed && t == nc.curve.t_max() ? 0.0 : t;
        const NodeIncidence inc{nc.id, tt};
        if (std::find(node.incidences.begin(), node.incidences.end(), inc) == node.incidences.end())
          node.incidences.push_back(inc);
      }
      out.stroke_of[nc.id] = sid;
      edit.curves_added.push_back(std::move(nc));
    }
    for (auto& [id, node] : nodes) {
      if (id < 0) throw std::invalid_argument("node " + std::to_string(id) + ": negative id");
      edit.nodes_added.push_back(std::move(node));
    }
    out.network.apply(edit);
    return out;
  } catch (const CassieFormatError&) {
    throw;
  } catch (const std::exception& e) {
    throw CassieFormatError(path.string() + ": " + e.what());
  }
}

FidelityReport& FidelityReport::operator+=(const FidelityReport& o) {
  cassie_automatic += o.cassie_automatic;
  cassie_manual += o.cassie_manual;
  ours += o.ours;
  found += o.found;
  missed += o.missed;
  missed_not_closed += o.missed_not_closed;
  missed_not_found += o.missed_not_found;
  extra += o.extra;
  extra_matching_manual += o.extra_matching_manual;
  warnings.insert(warnings.end(), o.warnings.begin(), o.warnings.end());
  return *this;
}

FidelityReport compare_with_cassie(const std::filesystem::path& sketch_graph_json, const CassieSession& session,
                                   const CycleSearchParams& params) {
  const CassieNetwork net = load_cassie_network(sketch_graph_json);
  std::set<std::int64_t> alive;
  for (const auto& [c, s] : net.stroke_of) alive.insert(s);
  std::set<StrokeSet> automatic, manual;
  const std::map<std::int64_t, double> broken = inferred_breaks(session);
  for (const CassiePatch& p : session.patches) {
    if (p.deleted_by_hand || p.strokes.empty() || broken.count(p.id)) continue;
    if (!std::all_of(p.strokes.begin(), p.strokes.end(), [&](std::int64_t s) { return alive.count(s); })) continue;
    (p.automatic ? automatic : manual).insert(p.strokes);
  }
  std::set<StrokeSet> ours;
  for (const auto& cycle : detect_all_cycles(net.network, params)) {
    StrokeSet s;
    for (const OrientedSegment& piece : cycle) s.insert(net.stroke_of.at(piece.curve));
    ours.insert(s);
  }
  FidelityReport r;
  r.warnings = net.warnings;
  r.cassie_automatic = static_cast<int>(automatic.size());
  r.cassie_manual = static_cast<int>(manual.size());
  r.ours = static_cast<int>(ours.size());
  std::map<std::int64_t, CurveId> curve_of;
  for (const auto& [c, s] : net.stroke_of) curve_of[s] = c;
  for (const StrokeSet& s : automatic) {
    if (ours.count(s)) {
      ++r.found;
      continue;
    }
    ++r.missed;
    const MissingCycle why = classify_missing(net.network, curve_of, s, params);
    if (why == MissingCycle::not_closed) ++r.missed_not_closed;
    if (why == MissingCycle::not_found) ++r.missed_not_found;
  }
  for (const StrokeSet& s : ours)
    if (!automatic.count(s)) {
      ++r.extra;
      if (manual.count(s)) ++r.extra_matching_manual;
    }
  return r;
}

NodeAgreement& NodeAgreement::operator+=(const NodeAgreement& o) {
  cassie += o.cassie;
  ours += o.ours;
  cassie_matched += o.cassie_matched;
  ours_matched += o.ours_matched;
  return *this;
}

NodeAgreement compare_graph_nodes(const Network& cassie, const Network& ours, double tolerance) {
  NodeAgreement a;
  const CurveGraph graph(ours);
  for (const auto& [id, n] : cassie.nodes()) {
    const std::vector<NodeHit> hits = ours.nodes_near(n.position, tolerance);
    ++a.cassie;
    a.cassie_matched +=
        std::any_of(hits.begin(), hits.end(), [&](const NodeHit& h) { return graph.is_graph_node(h.node); });
  }
  for (const auto& [id, n] : ours.nodes()) {
    if (!graph.is_graph_node(id)) continue;
    ++a.ours;
    a.ours_matched += !cassie.nodes_near(n.position, tolerance).empty();
  }
  return a;
}

}  // namespace sketchlab::soapfilm
