#include "cassie_graph.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "patch_upkeep.hpp"

namespace sketchlab::soapfilm {
namespace {

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

Vec3 vec(const nlohmann::json& a) { return {a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()}; }

}  // namespace

CassieNetwork load_cassie_network(const std::filesystem::path& path) {
  const nlohmann::json j = read_json(path);
  try {
    std::map<std::int64_t, const nlohmann::json*> segments;
    for (const auto& s : j.at("segments")) segments[s.at("id").get<std::int64_t>()] = &s;
    std::map<std::int64_t, Vec3> node_pos;
    for (const auto& n : j.at("nodes")) node_pos[n.at("id").get<std::int64_t>()] = vec(n.at("position"));

    CassieNetwork out;
    Edit edit;
    std::map<std::int64_t, Node> nodes;
    for (const auto& stroke : j.at("strokes")) {
      const std::int64_t sid = stroke.at("id").get<std::int64_t>();
      NetworkCurve nc;
      nc.id = static_cast<CurveId>(sid + 1);
      nc.source_stroke = static_cast<StrokeId>(sid + 1);
      nc.layer = Layer::shape;
      std::vector<Vec3>& cp = nc.curve.control_points;
      std::vector<std::pair<std::int64_t, double>> incidences;
      for (const auto& seg_id : stroke.at("segments")) {
        const nlohmann::json& seg = *segments.at(seg_id.get<std::int64_t>());
        const double t_start = cp.empty() ? 0.0 : static_cast<double>((cp.size() - 1) / 3);
        for (const auto& piece : seg.at("ctrl_pts")) {
          // A cubic piece (4 points) or a straight one (2 points, stored as a
          // cubic with inner points at thirds, like the kernel's lines).
          std::vector<Vec3> q;
          if (piece.size() == 4) {
            for (const auto& x : piece) q.push_back(vec(x));
          } else if (piece.size() == 2) {
            const Vec3 a0 = vec(piece.at(0)), a1 = vec(piece.at(1));
            q = {a0, a0 + (a1 - a0) / 3.0, a0 + 2.0 * (a1 - a0) / 3.0, a1};
          } else {
            throw std::runtime_error("a curve piece needs 4 (cubic) or 2 (line) control points");
          }
          for (std::size_t i = cp.empty() ? 0 : 1; i < 4; ++i) cp.push_back(q[i]);
        }
        const double t_end = static_cast<double>((cp.size() - 1) / 3);
        const Vec3 a = vec(seg.at("ctrl_pts").front().at(0)), b = cp.back();
        const auto& ends = seg.at("nodes");
        const std::int64_t n0 = ends.at(0).get<std::int64_t>(), n1 = ends.at(1).get<std::int64_t>();
        // Which listed node is at the segment start: the closer one.
        const bool swap = (node_pos.at(n0) - a).norm() + (node_pos.at(n1) - b).norm() >
                          (node_pos.at(n1) - a).norm() + (node_pos.at(n0) - b).norm();
        incidences.emplace_back(swap ? n1 : n0, t_start);
        incidences.emplace_back(swap ? n0 : n1, t_end);
      }
      const int K = static_cast<int>((cp.size() - 1) / 3);
      nc.curve.sharp.assign(static_cast<std::size_t>(K + 1), false);
      if (K >= 1 && (cp.front() - cp.back()).norm() < 1e-6) {
        cp.back() = cp.front();
        nc.curve.closed = true;
      }
      nc.keypoints = default_keypoints(nc.curve);
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
    for (auto& [id, node] : nodes) edit.nodes_added.push_back(std::move(node));
    out.network.apply(edit);
    return out;
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": malformed sketch graph (" + e.what() + ")");
  }
}

CassiePatches load_cassie_patches(const std::filesystem::path& path, const std::set<std::int64_t>& alive) {
  const nlohmann::json j = read_json(path);
  CassiePatches out;
  try {
    std::set<std::int64_t> deleted;  // interactionType 4: surface deleted by hand
    for (const auto& s : j.at("systemStates"))
      if (s.at("interactionType").get<int>() == 4) deleted.insert(s.at("elementID").get<std::int64_t>());
    for (const auto& p : j.at("allCreatedPatches")) {
      const bool automatic = p.at("foundByAlgo").get<bool>();
      if (automatic) ++out.created_automatic;
      if (deleted.count(p.at("id").get<std::int64_t>())) continue;
      StrokeSet strokes;
      bool ok = true;
      for (const auto& s : p.at("strokesID")) {
        strokes.insert(s.get<std::int64_t>());
        ok = ok && alive.count(s.get<std::int64_t>());
      }
      if (!ok || strokes.empty()) continue;
      (automatic ? out.automatic : out.manual).insert(strokes);
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": malformed raw data (" + e.what() + ")");
  }
  return out;
}

FidelityReport compare_with_cassie(const std::filesystem::path& sketch_graph_json,
                                   const std::filesystem::path& raw_data_json,
                                   const CycleSearchParams& params) {
  const CassieNetwork net = load_cassie_network(sketch_graph_json);
  std::set<std::int64_t> alive;
  for (const auto& [c, s] : net.stroke_of) alive.insert(s);
  const CassiePatches cassie = load_cassie_patches(raw_data_json, alive);
  std::set<StrokeSet> ours;
  for (const auto& cycle : detect_all_cycles(net.network, params)) {
    StrokeSet s;
    for (const OrientedSegment& piece : cycle) s.insert(net.stroke_of.at(piece.curve));
    ours.insert(s);
  }
  FidelityReport r;
  r.cassie_automatic = static_cast<int>(cassie.automatic.size());
  r.cassie_manual = static_cast<int>(cassie.manual.size());
  r.ours = static_cast<int>(ours.size());
  for (const StrokeSet& s : cassie.automatic) (ours.count(s) ? r.found : r.missed)++;
  for (const StrokeSet& s : ours)
    if (!cassie.automatic.count(s)) {
      ++r.extra;
      if (cassie.manual.count(s)) ++r.extra_matching_manual;
    }
  return r;
}

}  // namespace sketchlab::soapfilm
