#include "cassie_session.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "cassie_json.hpp"

namespace sketchlab::soapfilm {
namespace {

double number(const nlohmann::json& item, const char* key, const std::string& what) {
  const nlohmann::json& v = cassie_field(item, key, what);
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    throw std::invalid_argument(what + ": field '" + key + "' must be a finite number");
  return v.get<double>();
}

std::int64_t integer(const nlohmann::json& item, const char* key, const std::string& what) {
  const nlohmann::json& v = cassie_field(item, key, what);
  if (!v.is_number_integer()) throw std::invalid_argument(what + ": field '" + key + "' must be an integer");
  return v.get<std::int64_t>();
}

// Unity quaternion {x, y, z, w}.
Eigen::Quaterniond quaternion(const nlohmann::json& v, const std::string& what) {
  const Eigen::Quaterniond q(number(v, "w", what), number(v, "x", what), number(v, "y", what), number(v, "z", what));
  if (!(q.norm() > 0.5)) throw std::invalid_argument(what + ": not a rotation");
  return q.normalized();
}

struct State {
  int type = 0;
  double time = 0.0;
  std::int64_t element = -1;
  const nlohmann::json* json = nullptr;
};

}  // namespace

CassieSession load_cassie_session(const std::filesystem::path& dir, const std::string& name, bool constraint_logs) {
  const std::filesystem::path history_path = dir / "sketch_history" / (name + ".json");
  const std::filesystem::path raw_path = dir / "raw_data" / (name + ".json");
  const nlohmann::json history = read_cassie_json(history_path);
  const nlohmann::json raw = read_cassie_json(raw_path);
  CassieSession out;
  out.name = name;

  // raw_data first: the zoom at each stroke and the delete entries.
  std::vector<State> states;
  try {
    out.system = static_cast<int>(integer(raw, "sketchSystem", "the session"));
    const nlohmann::json& list = cassie_field(raw, "systemStates", "the session");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string what = "systemStates[" + std::to_string(i) + "]";
      State s;
      s.type = static_cast<int>(integer(list[i], "interactionType", what));
      s.time = number(list[i], "time", what);
      s.element = integer(list[i], "elementID", what);
      s.json = &list[i];
      states.push_back(s);
    }
  } catch (const std::exception& e) {
    throw CassieFormatError(raw_path.string() + ": " + e.what());
  }
  // Entries are logged in time order; a scale lookup needs them sorted.
  std::vector<State> by_time = states;
  std::stable_sort(by_time.begin(), by_time.end(), [](const State& a, const State& b) { return a.time < b.time; });
  auto scale_at = [&](double t) {
    auto it = std::upper_bound(by_time.begin(), by_time.end(), t,
                               [](double v, const State& s) { return v < s.time; });
    if (it == by_time.begin()) return 1.0;
    const nlohmann::json& j = *std::prev(it)->json;
    const double s = j.contains("canvasScale") && j.at("canvasScale").is_number() ? j.at("canvasScale").get<double>() : 1.0;
    return s > 0.0 && std::isfinite(s) ? s : 1.0;
  };

  try {
    if (!history.is_array()) throw std::invalid_argument("expected a list of strokes");
    std::set<std::int64_t> seen;
    for (std::size_t i = 0; i < history.size(); ++i) {
      const nlohmann::json& h = history[i];
      CassieStroke s;
      s.id = integer(h, "id", "stroke #" + std::to_string(i));
      const std::string what = "stroke " + std::to_string(s.id);
      if (s.id < 0) throw std::invalid_argument(what + ": negative id");
      if (!seen.insert(s.id).second) throw std::invalid_argument(what + " listed twice");
      append_cassie_pieces(s.curve, cassie_field(h, "ctrl_pts", what), what);
      finish_cassie_curve(s.curve);
      s.created = number(h, "creation_time", what);
      if (h.contains("deletion_time") && !h.at("deletion_time").is_null()) s.deleted = number(h, "deletion_time", what);
      if (s.deleted && *s.deleted < s.created) {
        // flower: the id was deleted, created again and deleted again; the
        // history kept the first deletion time. raw_data logs the strokes
        // drawn, not their mirrored twins (same creation time).
        std::set<std::int64_t> ids{s.id};
        for (const nlohmann::json& other : history)
          if (other.contains("id") && other.at("id").is_number_integer() && other.contains("creation_time") &&
              other.at("creation_time").is_number() && other.at("creation_time").get<double>() == s.created)
            ids.insert(other.at("id").get<std::int64_t>());
        std::optional<double> later;
        for (const State& st : states)
          if (st.type == 2 && ids.count(st.element) && st.time >= s.created && (!later || st.time < *later))
            later = st.time;
        out.warnings.push_back(history_path.string() + ": " + what + " is deleted (" + std::to_string(*s.deleted) +
                               " s) before it is created (" + std::to_string(s.created) + " s); " +
                               (later ? "using the delete entry in raw_data at " + std::to_string(*later) + " s"
                                      : std::string("raw_data has no later delete entry: kept alive")));
        s.deleted = later;
      }
      s.canvas_scale = scale_at(s.created);
      out.strokes.push_back(std::move(s));
    }
  } catch (const std::exception& e) {
    throw CassieFormatError(history_path.string() + ": " + e.what());
  }

  try {
    std::map<std::int64_t, std::size_t> index;
    const nlohmann::json& list = cassie_field(raw, "allCreatedPatches", "the session");
    for (std::size_t i = 0; i < list.size(); ++i) {
      CassiePatch p;
      p.id = integer(list[i], "id", "allCreatedPatches[" + std::to_string(i) + "]");
      const std::string what = "patch " + std::to_string(p.id);
      if (!index.emplace(p.id, out.patches.size()).second) throw std::invalid_argument(what + " listed twice");
      const nlohmann::json& automatic = cassie_field(list[i], "foundByAlgo", what);
      if (!automatic.is_boolean()) throw std::invalid_argument(what + ": field 'foundByAlgo' must be true or false");
      p.automatic = automatic.get<bool>();
      for (const auto& s : cassie_field(list[i], "strokesID", what)) {
        if (!s.is_number_integer()) throw std::invalid_argument(what + ": a stroke id is not an integer");
        p.strokes.insert(s.get<std::int64_t>());
      }
      out.patches.push_back(std::move(p));
    }
    for (std::size_t i = 0; i < states.size(); ++i) {
      const State& st = states[i];
      if (st.type != 3 && st.type != 4) continue;
      const std::string what = "systemStates[" + std::to_string(i) + "]";
      const auto it = index.find(st.element);
      if (it == index.end()) {
        out.warnings.push_back(raw_path.string() + ": " + what + " names patch " + std::to_string(st.element) +
                               ", which allCreatedPatches does not list; ignored");
        continue;
      }
      CassiePatch& p = out.patches[it->second];
      if (st.type == 4) {
        if (!p.deleted_by_hand) p.deleted_by_hand = st.time;
        continue;
      }
      if (p.created) continue;
      p.created = st.time;
      const nlohmann::json& j = *st.json;
      if (j.contains("primaryHandPos") && j.contains("canvasPos") && j.contains("canvasRot")) {
        const Vec3 hand = cassie_point(j.at("primaryHandPos"), what + ": primaryHandPos");
        const Vec3 origin = cassie_point(j.at("canvasPos"), what + ": canvasPos");
        const double scale = number(j, "canvasScale", what);
        if (!(scale > 0.0)) throw std::invalid_argument(what + ": canvasScale must be > 0");
        p.hand = quaternion(j.at("canvasRot"), what + ": canvasRot").conjugate() * (hand - origin) / scale;
      }
    }
    for (const CassiePatch& p : out.patches)
      if (!p.created)
        out.warnings.push_back(raw_path.string() + ": patch " + std::to_string(p.id) +
                               " has no add-surface entry in systemStates; it is not replayed");
  } catch (const std::exception& e) {
    throw CassieFormatError(raw_path.string() + ": " + e.what());
  }
  if (!constraint_logs) return out;
  try {
    out.logs = read_cassie_constraint_logs(raw_path);  // its messages name the file, element and field
  } catch (const std::exception& e) {
    throw CassieFormatError(e.what());
  }
  if (out.logs.empty()) return out;
  try {
    // The mirror plane and the twins come from the lab's importer, which
    // also needs each stroke's input samples (the curves above do not).
    std::vector<std::string> import_warnings;  // the quirks above, found again
    add_mirrored_twin_logs(import_cassie(history_path, raw_path, name, &import_warnings), out.logs);
  } catch (const std::exception& e) {
    out.warnings.push_back(std::string(e.what()) + "; the mirrored twins get no constraint log");
  }
  return out;
}

}  // namespace sketchlab::soapfilm
