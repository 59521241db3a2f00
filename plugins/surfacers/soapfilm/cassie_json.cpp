#include "cassie_json.hpp"

#include <cmath>
#include <fstream>

#include "sketchlab/recording/event_json.hpp"

namespace sketchlab::soapfilm {

nlohmann::json read_cassie_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw CassieFormatError(path.string() + ": cannot open");
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw CassieFormatError(path.string() + ": " + e.what());
  }
}

const nlohmann::json& cassie_field(const nlohmann::json& item, const char* key, const std::string& what) {
  if (!item.is_object() || !item.contains(key)) throw std::invalid_argument(what + ": missing field '" + key + "'");
  return item.at(key);
}

Vec3 cassie_point(const nlohmann::json& v, const std::string& what) {
  Vec3 p;
  if (v.is_array() && v.size() == 3) {
    for (int i = 0; i < 3; ++i) {
      if (!v[static_cast<std::size_t>(i)].is_number())
        throw std::invalid_argument(what + ": coordinate " + std::to_string(i) + " is not a number");
      p(i) = v[static_cast<std::size_t>(i)].get<double>();
    }
  } else if (v.is_object() && v.contains("x") && v.contains("y") && v.contains("z")) {
    const char* names[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      if (!v.at(names[i]).is_number()) throw std::invalid_argument(what + ": " + names[i] + " is not a number");
      p(i) = v.at(names[i]).get<double>();
    }
  } else {
    throw std::invalid_argument(what + ": expected a point [x, y, z] or {x, y, z}");
  }
  if (!p.allFinite()) throw std::invalid_argument(what + ": non-finite coordinate");
  // The recordings' bound: far beyond it lengths overflow (a 1e300 m control
  // point hung soapfilm_compare in the arclength quadrature).
  if (p.cwiseAbs().maxCoeff() > recording_max_coordinate)
    throw std::invalid_argument(what + ": coordinate of magnitude above " +
                                std::to_string(static_cast<long long>(recording_max_coordinate)) + " m (absurd)");
  return p;
}

void append_cassie_pieces(Curve& curve, const nlohmann::json& pieces, const std::string& what) {
  if (!pieces.is_array() || pieces.empty()) throw std::invalid_argument(what + ": no curve pieces");
  std::vector<Vec3>& cp = curve.control_points;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const nlohmann::json& piece = pieces[k];
    const std::string at = what + ": piece " + std::to_string(k);
    if (!piece.is_array() || (piece.size() != 4 && piece.size() != 2))
      throw std::invalid_argument(at + " has " + std::to_string(piece.is_array() ? piece.size() : 0) +
                                  " control points; need 4 (cubic) or 2 (line)");
    std::vector<Vec3> q;
    for (std::size_t i = 0; i < piece.size(); ++i)
      q.push_back(cassie_point(piece[i], at + ", point " + std::to_string(i)));
    if (q.size() == 2) q = {q[0], q[0] + (q[1] - q[0]) / 3.0, q[0] + 2.0 * (q[1] - q[0]) / 3.0, q[1]};
    for (std::size_t i = cp.empty() ? 0 : 1; i < 4; ++i) cp.push_back(q[i]);
  }
  if (pieces.size() == 1 && pieces[0].size() == 2 && cp.size() == 4) curve.kind = CurveKind::line;
}

void finish_cassie_curve(Curve& curve, double tolerance) {
  const int K = curve.segment_count();
  curve.sharp.assign(static_cast<std::size_t>(K + 1), false);
  if (K >= 1 && curve.kind != CurveKind::line &&
      (curve.control_points.front() - curve.control_points.back()).norm() < tolerance) {
    curve.control_points.back() = curve.control_points.front();
    curve.closed = true;
  }
}

}  // namespace sketchlab::soapfilm
