#include "sketchlab/lab/cassie_import.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "sketchlab/curve.hpp"
#include "sketchlab/lab/teacher_forced.hpp"
#include "sketchlab/event.hpp"
#include "sketchlab/recording/event_json.hpp"
#include "sketchlab/stroke.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab {

namespace {

using json = nlohmann::json;

// Shortest round-trip text of a double, as in recordings.
std::string num_text(double v) { return json(v).dump(); }

// The limits of the recording format (event_json.hpp), as messages say them.
static_assert(recording_max_time == 1e9 && recording_max_coordinate == 1e6);
constexpr const char* time_range = "[0, 1e9] s";
constexpr const char* coordinate_range = "±1e6 m";

struct Source {
  std::string file;

  [[noreturn]] void fail(const std::string& where, const std::string& msg) const {
    throw std::runtime_error(file + ": " + where + ": " + msg);
  }
  const json& need(const json& obj, const char* key, const std::string& where) const {
    if (!obj.is_object()) fail(where, std::string("expected an object, got ") + obj.type_name());
    const auto it = obj.find(key);
    if (it == obj.end()) fail(where, "missing field '" + std::string(key) + "'");
    return *it;
  }
  double number(const json& v, const std::string& where, const std::string& name) const {
    if (!v.is_number()) fail(where, "field '" + name + "' must be a number, got " + v.type_name());
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(where, "field '" + name + "' is not finite");
    return x;
  }
  // A time the recording format can hold: [0, 1e9] s (event_json.hpp).
  double time(const json& v, const std::string& where, const std::string& name) const {
    const double x = number(v, where, name);
    if (x < 0.0 || x > recording_max_time) {
      fail(where, "field '" + name + "' = " + num_text(x) + " s is outside " + time_range +
                      " (seconds since the session started)");
    }
    return x;
  }
  const json& array(const json& v, const std::string& where, const std::string& name) const {
    if (!v.is_array()) fail(where, "field '" + name + "' must be an array, got " + v.type_name());
    return v;
  }
  Vec3 xyz_array(const json& v, const std::string& where, const std::string& name) const {
    array(v, where, name);
    if (v.size() != 3) fail(where, "field '" + name + "' must have 3 numbers, got " + std::to_string(v.size()));
    return {number(v[0], where, name + "[0]"), number(v[1], where, name + "[1]"),
            number(v[2], where, name + "[2]")};
  }
  // Coordinates the recording format can hold (|x| <= 1e6 m, event_json.hpp).
  static bool in_range(const Vec3& p) { return p.cwiseAbs().maxCoeff() <= recording_max_coordinate; }
  Vec3 coordinate(const json& v, const std::string& where, const std::string& name) const {
    const Vec3 p = xyz_array(v, where, name);
    if (!in_range(p)) {
      fail(where, "field '" + name + "' = (" + num_text(p.x()) + ", " + num_text(p.y()) + ", " +
                      num_text(p.z()) + ") is absurd: coordinates must be within " + coordinate_range);
    }
    return p;
  }
};

json load_json(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open (missing file?)");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(path.string() + ": malformed JSON: " + e.what());
  }
}

struct CassieStroke {
  std::uint64_t id = 0;
  std::vector<Vec3> samples;
  std::string curve_type;
  std::vector<std::vector<Vec3>> segments;
  double creation = 0.0;
  std::optional<double> deletion;
};

struct SystemState {
  double time = 0.0;
  bool mirroring = false;
  double scale = 1.0;
  int interaction = 0;     // interactionType (2 = delete stroke)
  std::int64_t element = -1;  // elementID
};

std::vector<CassieStroke> parse_history(const json& doc, const Source& src,
                                        std::vector<std::string>& warnings) {
  if (!doc.is_array()) src.fail("top level", std::string("expected an array of strokes, got ") + doc.type_name());
  std::vector<CassieStroke> out;
  for (std::size_t i = 0; i < doc.size(); ++i) {
    const json& e = doc[i];
    std::string where = "stroke entry " + std::to_string(i);
    CassieStroke s;
    const json& id = src.need(e, "id", where);
    if (!id.is_number_unsigned()) src.fail(where, "field 'id' must be a non-negative integer");
    s.id = id.get<std::uint64_t>();
    where += " (id " + std::to_string(s.id) + ")";
    const json& samples = src.array(src.need(e, "input_samples", where), where, "input_samples");
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const std::string name = "input_samples[" + std::to_string(k) + "]";
      const Vec3 p = src.xyz_array(samples[k], where, name);
      // A tracking glitch: drop the sample, keep the stroke (its neatened
      // curve is still CASSIE's answer).
      if (!Source::in_range(p)) {
        warnings.push_back(src.file + ": " + where + ": " + name + " = (" + num_text(p.x()) + ", " +
                           num_text(p.y()) + ", " + num_text(p.z()) +
                           ") is absurd (a coordinate beyond " + coordinate_range + "); sample dropped");
        continue;
      }
      s.samples.push_back(p);
    }
    const json& type = src.need(e, "curve_type", where);
    if (!type.is_string() || (type != "line" && type != "polybezier")) {
      src.fail(where, "field 'curve_type' must be \"line\" or \"polybezier\", got " + type.dump());
    }
    s.curve_type = type.get<std::string>();
    const std::size_t per_segment = s.curve_type == "line" ? 2 : 4;
    const json& ctrl = src.array(src.need(e, "ctrl_pts", where), where, "ctrl_pts");
    if (ctrl.empty()) src.fail(where, "field 'ctrl_pts' is empty");
    for (std::size_t k = 0; k < ctrl.size(); ++k) {
      const std::string name = "ctrl_pts[" + std::to_string(k) + "]";
      src.array(ctrl[k], where, name);
      if (ctrl[k].size() != per_segment) {
        src.fail(where, "field '" + name + "' must have " + std::to_string(per_segment) +
                            " points for a " + s.curve_type + ", got " + std::to_string(ctrl[k].size()));
      }
      std::vector<Vec3> seg;
      for (std::size_t m = 0; m < per_segment; ++m) {
        seg.push_back(src.coordinate(ctrl[k][m], where, name + "[" + std::to_string(m) + "]"));
      }
      s.segments.push_back(std::move(seg));
    }
    s.creation = src.time(src.need(e, "creation_time", where), where, "creation_time");
    const json& del = src.need(e, "deletion_time", where);
    if (!del.is_null()) s.deletion = src.time(del, where, "deletion_time");
    out.push_back(std::move(s));
  }
  return out;
}

// A stroke "deleted before it was created" (a real quirk of `flower`): the
// history's deletion_time is not usable. The delete-stroke action the app
// logged for it (or for its mirrored twin: same creation time) after its
// creation is used instead; without one the stroke stays alive. Warns either
// way, naming the stroke.
void repair_deletions(std::vector<CassieStroke>& strokes, const std::vector<SystemState>& states,
                      const Source& src, std::vector<std::string>& warnings) {
  for (CassieStroke& s : strokes) {
    if (!s.deletion || *s.deletion >= s.creation) continue;
    std::vector<std::int64_t> ids{static_cast<std::int64_t>(s.id)};
    for (const CassieStroke& t : strokes)
      if (t.id != s.id && t.creation == s.creation) ids.push_back(static_cast<std::int64_t>(t.id));
    std::optional<double> logged;
    for (const SystemState& st : states) {
      if (st.interaction != 2 || st.time < s.creation) continue;
      if (std::find(ids.begin(), ids.end(), st.element) == ids.end()) continue;
      logged = st.time;
      break;
    }
    std::string msg = src.file + ": stroke id " + std::to_string(s.id) + ": deletion_time " +
                      num_text(*s.deletion) + " is before creation_time " + num_text(s.creation) + "; ";
    if (logged) {
      msg += "deleted at " + num_text(*logged) + " instead (the delete action raw_data logs for it)";
    } else {
      msg += "kept alive (raw_data logs no later delete action for it)";
    }
    warnings.push_back(msg);
    s.deletion = logged;
  }
}

// The neatened curve as a kernel Curve.
Curve reference_curve(const CassieStroke& s, const Source& src) {
  const std::string where = "stroke id " + std::to_string(s.id);
  if (s.curve_type == "line" && s.segments.size() == 1) {
    return make_line(s.segments[0][0], s.segments[0][1]);
  }
  Curve c;
  c.kind = CurveKind::bezier;
  for (std::size_t k = 0; k < s.segments.size(); ++k) {
    std::vector<Vec3> seg = s.segments[k];
    if (seg.size() == 2) seg = make_line(seg[0], seg[1]).control_points;  // polyline piece
    if (k == 0) {
      c.control_points.push_back(seg[0]);
    } else if (seg[0] != c.control_points.back()) {
      src.fail(where, "ctrl_pts[" + std::to_string(k) + "] does not start where ctrl_pts[" +
                          std::to_string(k - 1) + "] ends");
    }
    c.control_points.insert(c.control_points.end(), seg.begin() + 1, seg.end());
  }
  const std::vector<Vec3>& p = c.control_points;
  const int K = c.segment_count();
  c.closed = p.front() == p.back();
  // Sharp joints: the tangent turns by more than 45° (curve.hpp).
  auto incoming = [&](int k) {  // tangent arriving at joint k (k >= 1)
    const Vec3 t = p[3 * k] - p[3 * k - 1];
    return t.norm() > 0.0 ? t : Vec3(p[3 * k] - p[3 * k - 2]);
  };
  auto outgoing = [&](int k) {  // tangent leaving joint k (k < K)
    const Vec3 t = p[3 * k + 1] - p[3 * k];
    return t.norm() > 0.0 ? t : Vec3(p[3 * k + 2] - p[3 * k]);
  };
  auto sharp = [](const Vec3& a, const Vec3& b) {
    if (!(a.norm() > 0.0) || !(b.norm() > 0.0)) return false;
    return std::atan2(a.cross(b).norm(), a.dot(b)) > std::numbers::pi / 4.0;
  };
  c.sharp.assign(static_cast<std::size_t>(K) + 1, false);
  for (int k = 1; k < K; ++k) c.sharp[k] = sharp(incoming(k), outgoing(k));
  if (c.closed) c.sharp.front() = c.sharp.back() = sharp(incoming(K), outgoing(0));
  if (const std::string why = validate(c); !why.empty()) src.fail(where, "ctrl_pts: " + why);
  return c;
}

std::string system_name(const json& v) {
  if (v.is_number_integer()) {
    switch (v.get<int>()) {
      case 0: return "freehand";
      case 1: return "armature";
      case 2: return "patch";
      default: break;
    }
  }
  return v.dump();
}

std::string model_name(const json& v) {
  if (v.is_number_integer()) {
    switch (v.get<int>()) {
      case 0: return "none";
      case 1: return "lamp";
      case 3: return "shoe";
      default: break;
    }
  }
  return v.dump();
}

std::string interaction_mode_name(const json& v) {
  if (v.is_number_integer()) {
    switch (v.get<int>()) {
      case 1: return "study";
      case 2: return "free creation";
      default: break;
    }
  }
  return v.dump();
}

}  // namespace

GridInference infer_grid(const std::vector<Vec3>& points, double tolerance) {
  GridInference best;
  best.total = points.size();
  const std::size_t needed = std::max<std::size_t>(3, (points.size() * 5 + 999) / 1000);
  auto on_lattice = [tolerance](double x, double spacing, double origin) {
    const double k = (x - origin) / spacing;
    return std::abs(k - std::round(k)) * spacing <= tolerance;
  };
  static constexpr double spacings[] = {1.0, 0.5, 0.25, 0.2, 0.125, 0.1, 0.05, 0.025};
  std::size_t best_count = 0;
  for (double spacing : spacings) {  // coarse to fine: ties keep the coarser
    for (double origin : {0.0, spacing / 2.0}) {
      std::size_t count = 0;
      for (const Vec3& p : points) {
        count += on_lattice(p.x(), spacing, origin) && on_lattice(p.y(), spacing, origin) &&
                 on_lattice(p.z(), spacing, origin);
      }
      best_count = std::max(best_count, count);
      if (count >= needed && count > best.matched) {
        best.found = true;
        best.spacing = spacing;
        best.origin = Vec3::Constant(origin);
        best.matched = count;
      }
    }
  }
  const std::string tol = num_text(tolerance);
  if (best.found) {
    const std::string o = num_text(best.origin.x());
    best.description = "spacing " + num_text(best.spacing) + " m, origin (" + o + ", " + o + ", " +
                       o + "): " + std::to_string(best.matched) + " of " +
                       std::to_string(best.total) + " reference endpoints within " + tol +
                       " m of a grid point";
  } else {
    best.description = "none: at most " + std::to_string(best_count) + " of " +
                       std::to_string(best.total) + " reference endpoints within " + tol +
                       " m of any candidate lattice (spacing 1 to 0.025 m, origin 0 or spacing/2; " +
                       std::to_string(needed) + " needed)";
  }
  return best;
}

MirrorInference infer_mirror_plane(
    const std::vector<std::pair<std::vector<Vec3>, std::vector<Vec3>>>& twins, double tolerance) {
  MirrorInference out;
  int axis = -1;
  std::vector<double> mids;
  std::size_t stroke_pairs = 0;
  for (const auto& [a, b] : twins) {
    if (a.size() != b.size()) continue;
    ++stroke_pairs;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Vec3 d = a[i] - b[i];
      if (d.norm() <= tolerance) continue;  // a sample on the plane itself
      int ax = 0;
      d.cwiseAbs().maxCoeff(&ax);
      const bool aligned = (d.cwiseAbs().sum() - std::abs(d[ax])) <= 2.0 * tolerance;
      if (!aligned || (axis >= 0 && ax != axis)) {
        out.description = "none: mirrored stroke pairs are not reflections across one axis plane";
        return out;
      }
      axis = ax;
      mids.push_back((a[i][ax] + b[i][ax]) / 2.0);
    }
  }
  if (mids.empty()) {
    out.description = "none: no mirrored stroke pairs";
    return out;
  }
  std::sort(mids.begin(), mids.end());
  out.found = true;
  out.normal = Vec3::Unit(axis);
  out.offset = mids[mids.size() / 2];
  out.pairs = mids.size();
  out.description = std::string("plane ") + "xyz"[axis] + " = " + num_text(out.offset) +
                    " (median of " + std::to_string(mids.size()) + " sample pairs of " +
                    std::to_string(stroke_pairs) + " mirrored stroke pairs)";
  return out;
}

std::map<StrokeId, CassieConstraintLog> read_cassie_constraint_logs(const std::filesystem::path& raw_data_json) {
  const Source src{raw_data_json.string()};
  const json raw = load_json(raw_data_json);
  std::map<StrokeId, CassieConstraintLog> out;
  if (!raw.is_object() || !raw.contains("allSketchedStrokes")) return out;
  const json& strokes = src.array(raw["allSketchedStrokes"], "top level", "allSketchedStrokes");
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    const std::string where = "allSketchedStrokes[" + std::to_string(i) + "]";
    const json& jid = src.need(strokes[i], "id", where);
    if (!jid.is_number_integer() || jid.get<std::int64_t>() < 0) src.fail(where, "field 'id' must be an integer >= 0");
    CassieConstraintLog& log = out[static_cast<StrokeId>(jid.get<std::int64_t>())];
    for (const auto& [key, list] : {std::pair{"appliedPositionConstraints", &log.applied},
                                    std::pair{"rejectedPositionConstraints", &log.rejected}}) {
      if (!strokes[i].contains(key)) continue;
      const json& a = src.array(strokes[i][key], where, key);
      for (std::size_t j = 0; j < a.size(); ++j) {
        // Older exports log the point, newer ones {position, isIntersection, ...}.
        const bool wrapped = a[j].is_object() && a[j].contains("position");
        const std::string at = where + "." + key + "[" + std::to_string(j) + "]" + (wrapped ? ".position" : "");
        const json& q = wrapped ? a[j]["position"] : a[j];
        list->push_back({src.number(src.need(q, "x", at), at, "x"), src.number(src.need(q, "y", at), at, "y"),
                         src.number(src.need(q, "z", at), at, "z")});
        if (list != &log.applied) continue;
        std::optional<bool>& intersection = log.applied_intersection.emplace_back();
        if (!wrapped || !a[j].contains("isIntersection")) continue;
        if (!a[j]["isIntersection"].is_boolean())
          src.fail(where + "." + key + "[" + std::to_string(j) + "]", "field 'isIntersection' must be true or false");
        intersection = a[j]["isIntersection"].get<bool>();
      }
    }
    for (const auto& [key, flag] : {std::pair{"planar", &log.planar}, std::pair{"closedLoop", &log.closed_loop},
                                    std::pair{"onSurface", &log.on_surface}}) {
      if (!strokes[i].contains(key)) continue;
      if (!strokes[i][key].is_boolean()) src.fail(where, std::string("field '") + key + "' must be true or false");
      *flag = strokes[i][key].get<bool>();
    }
  }
  return out;
}

void add_mirrored_twin_logs(const Recording& recording, std::map<StrokeId, CassieConstraintLog>& logs) {
  const Workspace& ws = recording.header.workspace;
  if (!(ws.mirror_normal.norm() > 0)) return;
  const auto reflect = [&](std::vector<Vec3> points) {
    for (Vec3& p : points) p = mirror_point(ws, p);
    return points;
  };
  std::map<double, std::vector<StrokeId>> by_time;
  for (const Event& e : recording.events)
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) by_time[e.time].push_back(s->stroke.id);
  for (const auto& [t, ids] : by_time) {
    if (ids.size() != 2) continue;
    for (int i = 0; i < 2; ++i) {
      const auto drawn = logs.find(ids[i]);
      if (drawn == logs.end() || logs.count(ids[1 - i])) continue;
      CassieConstraintLog twin = drawn->second;  // planarity, closure and the flags are the same in a reflection
      twin.applied = reflect(twin.applied);
      twin.rejected = reflect(twin.rejected);
      twin.mirrored_twin = true;
      logs[ids[1 - i]] = std::move(twin);
    }
  }
}

std::vector<CassiePatchLog> read_cassie_patches(const std::filesystem::path& raw_data_json) {
  const Source src{raw_data_json.string()};
  const json raw = load_json(raw_data_json);
  std::vector<CassiePatchLog> out;
  if (!raw.is_object() || !raw.contains("allCreatedPatches")) return out;
  const json& patches = src.array(raw["allCreatedPatches"], "top level", "allCreatedPatches");
  std::map<std::int64_t, std::size_t> index;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const std::string where = "allCreatedPatches[" + std::to_string(i) + "]";
    CassiePatchLog p;
    const json& jid = src.need(patches[i], "id", where);
    if (!jid.is_number_integer()) src.fail(where, "field 'id' must be an integer");
    p.id = jid.get<std::int64_t>();
    if (!index.emplace(p.id, out.size()).second) src.fail(where, "patch " + std::to_string(p.id) + " listed twice");
    const json& automatic = src.need(patches[i], "foundByAlgo", where);
    if (!automatic.is_boolean()) src.fail(where, "field 'foundByAlgo' must be true or false");
    p.automatic = automatic.get<bool>();
    const json& ids = src.array(src.need(patches[i], "strokesID", where), where, "strokesID");
    for (const json& s : ids) {
      if (!s.is_number_integer() || s.get<std::int64_t>() < 0) src.fail(where, "field 'strokesID' must hold integers >= 0");
      p.strokes.push_back(static_cast<StrokeId>(s.get<std::int64_t>()));
    }
    std::sort(p.strokes.begin(), p.strokes.end());
    p.strokes.erase(std::unique(p.strokes.begin(), p.strokes.end()), p.strokes.end());
    out.push_back(std::move(p));
  }
  if (!raw.contains("systemStates")) return out;
  const json& states = src.array(raw["systemStates"], "top level", "systemStates");
  for (std::size_t i = 0; i < states.size(); ++i) {
    const json a = states[i].is_object() ? states[i].value("interactionType", json()) : json();
    if (!a.is_number_integer() || (a.get<int>() != 3 && a.get<int>() != 4)) continue;
    const std::string where = "systemStates[" + std::to_string(i) + "]";
    const json& element = src.need(states[i], "elementID", where);
    if (!element.is_number_integer()) src.fail(where, "field 'elementID' must be an integer");
    const auto it = index.find(element.get<std::int64_t>());
    if (it == index.end()) continue;  // a patch the export does not list: nothing to rebuild
    const double t = src.time(src.need(states[i], "time", where), where, "time");
    std::optional<double>& when = a.get<int>() == 3 ? out[it->second].created : out[it->second].deleted;
    if (!when || t < *when) when = t;
  }
  return out;
}

std::vector<ReferencePatch> reference_patches(const std::vector<CassiePatchLog>& log) {
  std::vector<ReferencePatch> out;
  for (const CassiePatchLog& p : log)
    if (p.created) out.push_back({p.id, p.strokes, *p.created, p.deleted, p.automatic});
  return out;
}

Recording import_cassie(const std::filesystem::path& sketch_history_json,
                        const std::filesystem::path& raw_data_json, const std::string& session,
                        std::vector<std::string>* warnings_out) {
  const Source hsrc{sketch_history_json.string()};
  const Source rsrc{raw_data_json.string()};
  std::vector<std::string> warnings;
  std::vector<CassieStroke> strokes = parse_history(load_json(sketch_history_json), hsrc, warnings);

  const json raw = load_json(raw_data_json);
  std::vector<SystemState> states;
  const json& jstates = rsrc.array(rsrc.need(raw, "systemStates", "top level"), "top level", "systemStates");
  for (std::size_t i = 0; i < jstates.size(); ++i) {
    const std::string where = "systemStates[" + std::to_string(i) + "]";
    SystemState st;
    st.time = rsrc.time(rsrc.need(jstates[i], "time", where), where, "time");
    const json& m = rsrc.need(jstates[i], "mirroring", where);
    if (!m.is_boolean()) rsrc.fail(where, "field 'mirroring' must be true or false");
    st.mirroring = m.get<bool>();
    st.scale = rsrc.number(rsrc.need(jstates[i], "canvasScale", where), where, "canvasScale");
    if (!(st.scale > 0.0) || st.scale > 1e6) rsrc.fail(where, "field 'canvasScale' must be in (0, 1e6]");
    // Optional (older exports): which action, on which element.
    if (const json a = jstates[i].value("interactionType", json()); a.is_number_integer()) st.interaction = a.get<int>();
    if (const json a = jstates[i].value("elementID", json()); a.is_number_integer()) st.element = a.get<std::int64_t>();
    states.push_back(st);
  }
  std::stable_sort(states.begin(), states.end(),
                   [](const SystemState& a, const SystemState& b) { return a.time < b.time; });
  repair_deletions(strokes, states, hsrc, warnings);

  // Workspace: Unity is y-up; grid and mirror plane inferred from the data.
  std::vector<Vec3> endpoints;
  for (const CassieStroke& s : strokes) {
    endpoints.push_back(s.segments.front().front());
    endpoints.push_back(s.segments.back().back());
  }
  const GridInference grid = infer_grid(endpoints);
  std::map<double, std::vector<std::size_t>> by_creation;
  for (std::size_t i = 0; i < strokes.size(); ++i) by_creation[strokes[i].creation].push_back(i);
  std::vector<std::pair<std::vector<Vec3>, std::vector<Vec3>>> twins;
  for (const auto& [t, idx] : by_creation) {
    if (idx.size() == 2) twins.emplace_back(strokes[idx[0]].samples, strokes[idx[1]].samples);
  }
  const MirrorInference mirror = infer_mirror_plane(twins);

  Recording rec;
  RecordingHeader& h = rec.header;
  h.units = "m";
  Workspace& ws = h.workspace;
  ws.up = Vec3::UnitY();
  ws.grid_enabled = grid.found;
  if (grid.found) {
    ws.grid_spacing = grid.spacing;
    ws.grid_origin = grid.origin;
  }
  if (mirror.found) {
    ws.mirror_normal = mirror.normal;
    ws.mirror_offset = mirror.offset;
  }
  ws.mirror_enabled = !states.empty() && states.front().mirroring;
  ws.scale = states.empty() ? 1.0 : states.front().scale;
  h.source = {
      {"dataset", "CASSIE (Yu et al., CHI 2021)"},
      {"license", "MIT"},
      {"session", session},
      {"system", system_name(raw.value("sketchSystem", json()))},
      {"model", model_name(raw.value("sketchModel", json()))},
      {"interaction_mode", interaction_mode_name(raw.value("interactionMode", json()))},
      {"grid", grid.description},
      {"mirror", mirror.found ? mirror.description
                              : mirror.description + "; default plane x = 0"},
      {"sample_times", "not recorded by CASSIE: spread by arclength from the last logged system "
                       "state before creation (else 1 s before) to creation_time"},
  };
  if (!warnings.empty()) {
    // The header names the files without their directory, so a recording
    // imported from any checkout is the same bytes.
    const auto bare = [&](std::string w) {
      for (const auto& f : {sketch_history_json, raw_data_json})
        if (const std::string full = f.string(); w.rfind(full, 0) == 0)
          w = f.filename().string() + w.substr(full.size());
      return w;
    };
    std::string all;
    for (const std::string& w : warnings) all += (all.empty() ? "" : "; ") + bare(w);
    h.source["import_warnings"] = all;
  }

  std::vector<Event> events;
  for (std::size_t i = 1; i < states.size(); ++i) {
    if (states[i].mirroring == states[i - 1].mirroring) continue;
    Workspace w = ws;
    w.mirror_enabled = states[i].mirroring;
    w.scale = states[i].scale;
    events.push_back({states[i].time, WorkspaceEvent{w}});
  }
  for (const CassieStroke& cs : strokes) {
    const double end = cs.creation;
    const auto after = std::lower_bound(states.begin(), states.end(), end,
                                        [](const SystemState& s, double t) { return s.time < t; });
    double start = after == states.begin() ? std::max(0.0, end - 1.0) : std::prev(after)->time;
    const auto upto = std::upper_bound(states.begin(), states.end(), end,
                                       [](double t, const SystemState& s) { return t < s.time; });
    Stroke s;
    s.id = cs.id;
    s.layer = Layer::automatic;
    s.workspace_scale = upto == states.begin() ? 1.0 : std::prev(upto)->scale;
    std::vector<double> arclength(cs.samples.size(), 0.0);
    for (std::size_t k = 1; k < cs.samples.size(); ++k) {
      arclength[k] = arclength[k - 1] + (cs.samples[k] - cs.samples[k - 1]).norm();
    }
    const double total = arclength.empty() ? 0.0 : arclength.back();
    for (std::size_t k = 0; k < cs.samples.size(); ++k) {
      Sample smp;
      smp.position = cs.samples[k];
      smp.time = total > 0.0 ? start + (end - start) * (arclength[k] / total) : end;
      if (k + 1 == cs.samples.size()) smp.time = end;
      s.samples.push_back(smp);
    }
    if (const std::string why = validate(s); !why.empty()) {
      hsrc.fail("stroke id " + std::to_string(cs.id), "input_samples: " + why);
    }
    events.push_back({end, StrokeEvent{std::move(s)}});
    events.push_back({end, ReferenceEvent{cs.id, "cassie", reference_curve(cs, hsrc)}});
  }
  for (const CassieStroke& cs : strokes) {
    if (cs.deletion) events.push_back({*cs.deletion, DeleteStrokeEvent{cs.id}});
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& a, const Event& b) { return a.time < b.time; });
  rec.events = std::move(events);
  if (warnings_out) *warnings_out = std::move(warnings);
  return rec;
}

Recording import_cassie_session(const std::filesystem::path& dataset_dir, const std::string& session,
                                std::vector<std::string>* warnings) {
  return import_cassie(dataset_dir / "sketch_history" / (session + ".json"),
                       dataset_dir / "raw_data" / (session + ".json"), session, warnings);
}

}  // namespace sketchlab
