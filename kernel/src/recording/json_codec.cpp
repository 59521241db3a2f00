#include "json_codec.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "sketchlab/constraint.hpp"
#include "sketchlab/stroke.hpp"

namespace sketchlab::json_codec {

namespace {

[[noreturn]] void fail(const std::string& msg) { throw std::invalid_argument(msg); }

std::string join(std::initializer_list<const char*> names) {
  std::string s;
  for (const char* n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

// Shortest text that reads back to v, as in recordings.
std::string format_number(double v) { return json(v).dump(); }

// An object whose fields must be exactly `allowed` (optional ones may be
// absent). `what` names the object in messages.
void check_object(const json& j, const std::string& what, std::initializer_list<const char*> allowed) {
  if (!j.is_object()) fail(what + " must be a JSON object, got " + j.type_name());
  for (const auto& item : j.items()) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || item.key() == a;
    if (!ok) fail("unknown field '" + item.key() + "' in " + what + " (allowed: " + join(allowed) + ")");
  }
}

const json& field(const json& j, const char* name, const std::string& what) {
  const auto it = j.find(name);
  if (it == j.end()) fail("missing field '" + std::string(name) + "' in " + what);
  return *it;
}

double number(const json& v, const std::string& name, double limit) {
  if (!v.is_number()) {
    fail("field '" + name + "' must be a number, got " + v.type_name() +
         (v.is_null() ? " (JSON has no NaN or infinity)" : ""));
  }
  const double x = v.get<double>();
  // Overflowing literals such as 1e999 parse to infinity.
  if (!std::isfinite(x)) fail("field '" + name + "' is not finite");
  if (std::abs(x) > limit) {
    fail("field '" + name + "' = " + format_number(x) + " is absurd (magnitude above " +
         format_number(limit) + ")");
  }
  return x;
}

double positive(const json& v, const std::string& name, double limit) {
  const double x = number(v, name, limit);
  if (!(x > 0.0)) fail("field '" + name + "' = " + format_number(x) + " must be > 0");
  return x;
}

double time_value(const json& v, const std::string& name) {
  const double x = number(v, name, max_time);
  if (x < 0.0) fail("field '" + name + "' = " + format_number(x) + " is negative (times are seconds since the session started)");
  return x;
}

std::uint64_t unsigned_integer(const json& v, const std::string& name) {
  if (!v.is_number_unsigned()) {
    fail("field '" + name + "' must be a non-negative integer, got " +
         (v.is_number() ? std::string("a ") + (v.is_number_integer() ? "negative integer" : "fraction") : std::string(v.type_name())));
  }
  return v.get<std::uint64_t>();
}

bool boolean(const json& v, const std::string& name) {
  if (!v.is_boolean()) fail("field '" + name + "' must be true or false, got " + v.type_name());
  return v.get<bool>();
}

std::string string(const json& v, const std::string& name) {
  if (!v.is_string()) fail("field '" + name + "' must be a string, got " + v.type_name());
  return v.get<std::string>();
}

const json& array(const json& v, const std::string& name) {
  if (!v.is_array()) fail("field '" + name + "' must be an array, got " + v.type_name());
  return v;
}

const json& fixed_array(const json& v, const std::string& name, std::size_t n) {
  array(v, name);
  if (v.size() != n) {
    fail("field '" + name + "' must have " + std::to_string(n) + " entries, got " + std::to_string(v.size()));
  }
  return v;
}

Vec3 vec3(const json& v, const std::string& name, double limit = max_coordinate) {
  fixed_array(v, name, 3);
  return {number(v[0], name + "[0]", limit), number(v[1], name + "[1]", limit),
          number(v[2], name + "[2]", limit)};
}

Vec3 direction(const json& v, const std::string& name) {
  const Vec3 d = vec3(v, name);
  if (!(d.norm() > 0.0)) fail("field '" + name + "' must be a non-zero vector");
  return d;
}

Layer layer(const json& v, const std::string& name) {
  try {
    return layer_from_string(string(v, name));
  } catch (const std::invalid_argument& e) {
    fail("field '" + name + "': " + e.what());
  }
}

Mat4 mat4(const json& v, const std::string& name) {
  fixed_array(v, name, 4);
  Mat4 m;
  for (int r = 0; r < 4; ++r) {
    const std::string row = name + "[" + std::to_string(r) + "]";
    fixed_array(v[r], row, 4);
    for (int c = 0; c < 4; ++c) m(r, c) = number(v[r][c], row + "[" + std::to_string(c) + "]", 1e12);
  }
  return m;
}

ojson mat4_json(const Mat4& m) {
  ojson rows = ojson::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
  return rows;
}

constexpr std::array<const char*, 13> type_names{
    "stroke",    "undo",       "redo",      "delete_near",  "delete_stroke", "mode",
    "workspace", "correction", "add_patch", "delete_patch", "reference",     "relation",
    "recompute_surface"};

std::string allowed_types() {
  std::string s;
  for (const char* t : type_names) s += (s.empty() ? "" : ", ") + std::string(t);
  return s;
}

Stroke stroke_from_json(const json& j) {
  const std::string what = "stroke event";
  check_object(j, what, {"t", "type", "id", "layer", "workspace_scale", "pixels", "view", "draw_plane", "samples"});
  Stroke s;
  s.id = unsigned_integer(field(j, "id", what), "id");
  s.layer = layer(field(j, "layer", what), "layer");
  s.workspace_scale = positive(field(j, "workspace_scale", what), "workspace_scale", 1e6);
  if (j.contains("pixels")) {
    s.samples_are_pixels = boolean(j["pixels"], "pixels");
  }
  if (j.contains("view")) s.view = view_from_json(j["view"], "view");
  if (j.contains("draw_plane")) {
    const json& p = array(j["draw_plane"], "draw_plane");
    if (p.size() != 4) fail("field 'draw_plane' must have 4 numbers [nx,ny,nz,d]");
    Vec4 plane;
    for (std::size_t k = 0; k < 4; ++k)
      plane[static_cast<int>(k)] =
          number(p[k], "draw_plane[" + std::to_string(k) + "]", max_coordinate);
    s.draw_plane = plane;
  }
  const json& samples = array(field(j, "samples", what), "samples");
  s.samples.reserve(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const std::string name = "samples[" + std::to_string(i) + "]";
    const json& a = samples[i];
    array(a, name);
    if (a.size() != 5 && a.size() != 9) {
      fail("field '" + name + "' must have 5 numbers [x,y,z,t,pressure] or 9 with the orientation "
           "[...,qw,qx,qy,qz], got " + std::to_string(a.size()));
    }
    auto at = [&](std::size_t k) { return name + "[" + std::to_string(k) + "]"; };
    Sample smp;
    smp.position = {number(a[0], at(0), max_coordinate), number(a[1], at(1), max_coordinate),
                    number(a[2], at(2), max_coordinate)};
    smp.time = time_value(a[3], at(3));
    smp.pressure = number(a[4], at(4), 1e6);
    if (smp.pressure < 0.0 || smp.pressure > 1.0) {
      fail("field '" + at(4) + "' (pressure) = " + format_number(smp.pressure) + " is outside [0, 1]");
    }
    if (a.size() == 9) {
      smp.orientation = Quat(number(a[5], at(5), 2.0), number(a[6], at(6), 2.0),
                             number(a[7], at(7), 2.0), number(a[8], at(8), 2.0));
      if (std::abs(smp.orientation.norm() - 1.0) > 1e-3) {
        fail("field '" + name + "' has an orientation that is not a unit quaternion (norm " +
             format_number(smp.orientation.norm()) + ")");
      }
    }
    // Correctors measure speeds and durations along the stroke (line
    // detection, hooks): times running backwards would be refused by each of
    // them, so the reader names the sample instead.
    if (!s.samples.empty() && smp.time < s.samples.back().time) {
      fail("field '" + at(3) + "' (time) = " + format_number(smp.time) + " is earlier than the " +
           "previous sample's " + format_number(s.samples.back().time) +
           "; sample times must not decrease along a stroke");
    }
    s.samples.push_back(smp);
  }
  if (const std::string why = validate(s); !why.empty()) fail(why);
  return s;
}

}  // namespace

ojson to_json(const Vec3& v) { return ojson::array({v.x(), v.y(), v.z()}); }

ojson to_json(const Workspace& ws) {
  ojson j = ojson::object();
  j["up"] = to_json(ws.up);
  j["grid_enabled"] = ws.grid_enabled;
  j["grid_spacing"] = ws.grid_spacing;
  j["grid_origin"] = to_json(ws.grid_origin);
  j["mirror_enabled"] = ws.mirror_enabled;
  j["mirror_normal"] = to_json(ws.mirror_normal);
  j["mirror_offset"] = ws.mirror_offset;
  j["scale"] = ws.scale;
  return j;
}

Workspace workspace_from_json(const json& j, const std::string& what) {
  check_object(j, what, {"up", "grid_enabled", "grid_spacing", "grid_origin", "mirror_enabled",
                         "mirror_normal", "mirror_offset", "scale"});
  const std::string p = what + ".";
  Workspace ws;
  ws.up = direction(field(j, "up", what), p + "up");
  ws.grid_enabled = boolean(field(j, "grid_enabled", what), p + "grid_enabled");
  ws.grid_spacing = positive(field(j, "grid_spacing", what), p + "grid_spacing", max_coordinate);
  ws.grid_origin = vec3(field(j, "grid_origin", what), p + "grid_origin");
  ws.mirror_enabled = boolean(field(j, "mirror_enabled", what), p + "mirror_enabled");
  ws.mirror_normal = direction(field(j, "mirror_normal", what), p + "mirror_normal");
  ws.mirror_offset = number(field(j, "mirror_offset", what), p + "mirror_offset", max_coordinate);
  ws.scale = positive(field(j, "scale", what), p + "scale", 1e6);
  return ws;
}

ojson to_json(const Curve& curve) {
  ojson j = ojson::object();
  j["kind"] = curve.kind == CurveKind::line ? "line" : "bezier";
  ojson pts = ojson::array();
  for (const Vec3& p : curve.control_points) pts.push_back(to_json(p));
  j["points"] = std::move(pts);
  ojson sharp = ojson::array();
  for (bool b : curve.sharp) sharp.push_back(b);
  j["sharp"] = std::move(sharp);
  j["closed"] = curve.closed;
  return j;
}

Curve curve_from_json(const json& j, const std::string& what) {
  check_object(j, what, {"kind", "points", "sharp", "closed"});
  const std::string p = what + ".";
  Curve c;
  const std::string kind = string(field(j, "kind", what), p + "kind");
  if (kind == "bezier") {
    c.kind = CurveKind::bezier;
  } else if (kind == "line") {
    c.kind = CurveKind::line;
  } else {
    fail("field '" + p + "kind' = '" + kind + "' is not a curve kind (allowed: bezier, line)");
  }
  const json& pts = array(field(j, "points", what), p + "points");
  for (std::size_t i = 0; i < pts.size(); ++i) {
    c.control_points.push_back(vec3(pts[i], p + "points[" + std::to_string(i) + "]"));
  }
  const json& sharp = array(field(j, "sharp", what), p + "sharp");
  for (std::size_t i = 0; i < sharp.size(); ++i) {
    c.sharp.push_back(boolean(sharp[i], p + "sharp[" + std::to_string(i) + "]"));
  }
  c.closed = boolean(field(j, "closed", what), p + "closed");
  if (const std::string why = validate(c); !why.empty()) fail(what + ": " + why);
  return c;
}

ojson to_json(const View& view) {
  ojson j = ojson::object();
  j["view"] = mat4_json(view.view);
  j["projection"] = mat4_json(view.projection);
  j["viewport"] = ojson::array({view.viewport[0], view.viewport[1], view.viewport[2], view.viewport[3]});
  j["dpi"] = view.dpi;
  return j;
}

View view_from_json(const json& j, const std::string& what) {
  check_object(j, what, {"view", "projection", "viewport", "dpi"});
  const std::string p = what + ".";
  View v;
  v.view = mat4(field(j, "view", what), p + "view");
  v.projection = mat4(field(j, "projection", what), p + "projection");
  const json& vp = fixed_array(field(j, "viewport", what), p + "viewport", 4);
  for (int i = 0; i < 4; ++i) {
    v.viewport[i] = number(vp[i], p + "viewport[" + std::to_string(i) + "]", max_coordinate);
  }
  if (!(v.viewport[2] > 0.0 && v.viewport[3] > 0.0)) {
    fail("field '" + p + "viewport' must have width and height > 0");
  }
  v.dpi = positive(field(j, "dpi", what), p + "dpi", 1e6);
  return v;
}

ojson to_json(const Stroke& s) {
  ojson j = ojson::object();
  j["id"] = s.id;
  j["layer"] = std::string(to_string(s.layer));
  j["workspace_scale"] = s.workspace_scale;
  if (s.samples_are_pixels) j["pixels"] = true;
  if (s.view) j["view"] = to_json(*s.view);
  if (s.draw_plane) {
    const Vec4& p = *s.draw_plane;
    j["draw_plane"] = ojson::array({p[0], p[1], p[2], p[3]});
  }
  ojson samples = ojson::array();
  for (const Sample& smp : s.samples) {
    ojson a = ojson::array({smp.position.x(), smp.position.y(), smp.position.z(), smp.time, smp.pressure});
    if (smp.orientation.coeffs() != Quat::Identity().coeffs()) {
      a.push_back(smp.orientation.w());
      a.push_back(smp.orientation.x());
      a.push_back(smp.orientation.y());
      a.push_back(smp.orientation.z());
    }
    samples.push_back(std::move(a));
  }
  j["samples"] = std::move(samples);
  return j;
}

ojson to_json(const Event& e) {
  ojson j = ojson::object();
  j["t"] = e.time;
  j["type"] = std::string(event_type_name(e.payload));
  std::visit(
      [&j](const auto& p) {
        using T = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<T, StrokeEvent>) {
          ojson fields = to_json(p.stroke);
          for (auto& [k, v] : fields.items()) j[k] = std::move(v);
        } else if constexpr (std::is_same_v<T, DeleteNearEvent>) {
          j["point"] = to_json(p.point);
          j["radius"] = p.radius;
        } else if constexpr (std::is_same_v<T, DeleteStrokeEvent>) {
          j["stroke"] = p.stroke;
        } else if constexpr (std::is_same_v<T, ModeEvent>) {
          j["mode"] = std::string(to_string(p.mode));
        } else if constexpr (std::is_same_v<T, WorkspaceEvent>) {
          j["workspace"] = to_json(p.workspace);
        } else if constexpr (std::is_same_v<T, CorrectionEvent>) {
          j["enabled"] = p.enabled;
        } else if constexpr (std::is_same_v<T, AddPatchEvent> || std::is_same_v<T, DeletePatchEvent>) {
          j["point"] = to_json(p.point);
        } else if constexpr (std::is_same_v<T, ReferenceEvent>) {
          j["stroke"] = p.stroke;
          j["track"] = p.track;
          j["curve"] = to_json(p.curve);
        } else if constexpr (std::is_same_v<T, RelationEvent>) {
          j["track"] = p.track;
          j["kind"] = std::string(to_string(p.kind));
          j["strokes"] = p.strokes;
          j["parameters"] = p.parameters;
        }
      },
      e.payload);
  return j;
}

Event event_from_json(const json& j) {
  if (!j.is_object()) fail(std::string("an event must be a JSON object, got ") + j.type_name());
  const std::string type = string(field(j, "type", "event"), "type");
  Event e;
  e.time = time_value(field(j, "t", type + " event"), "t");
  const std::string what = type + " event";
  if (type == "stroke") {
    e.payload = StrokeEvent{stroke_from_json(j)};
  } else if (type == "undo") {
    check_object(j, what, {"t", "type"});
    e.payload = UndoEvent{};
  } else if (type == "redo") {
    check_object(j, what, {"t", "type"});
    e.payload = RedoEvent{};
  } else if (type == "delete_near") {
    check_object(j, what, {"t", "type", "point", "radius"});
    DeleteNearEvent d;
    d.point = vec3(field(j, "point", what), "point");
    d.radius = positive(field(j, "radius", what), "radius", max_coordinate);
    e.payload = d;
  } else if (type == "delete_stroke") {
    check_object(j, what, {"t", "type", "stroke"});
    e.payload = DeleteStrokeEvent{unsigned_integer(field(j, "stroke", what), "stroke")};
  } else if (type == "mode") {
    check_object(j, what, {"t", "type", "mode"});
    e.payload = ModeEvent{layer(field(j, "mode", what), "mode")};
  } else if (type == "workspace") {
    check_object(j, what, {"t", "type", "workspace"});
    e.payload = WorkspaceEvent{workspace_from_json(field(j, "workspace", what), "workspace")};
  } else if (type == "correction") {
    check_object(j, what, {"t", "type", "enabled"});
    e.payload = CorrectionEvent{boolean(field(j, "enabled", what), "enabled")};
  } else if (type == "add_patch") {
    check_object(j, what, {"t", "type", "point"});
    e.payload = AddPatchEvent{vec3(field(j, "point", what), "point")};
  } else if (type == "delete_patch") {
    check_object(j, what, {"t", "type", "point"});
    e.payload = DeletePatchEvent{vec3(field(j, "point", what), "point")};
  } else if (type == "recompute_surface") {
    check_object(j, what, {"t", "type"});
    e.payload = RecomputeSurfaceEvent{};
  } else if (type == "reference") {
    check_object(j, what, {"t", "type", "stroke", "track", "curve"});
    ReferenceEvent r;
    r.stroke = unsigned_integer(field(j, "stroke", what), "stroke");
    r.track = string(field(j, "track", what), "track");
    if (r.track.empty()) fail("field 'track' must not be empty");
    r.curve = curve_from_json(field(j, "curve", what), "curve");
    e.payload = std::move(r);
  } else if (type == "relation") {
    check_object(j, what, {"t", "type", "track", "kind", "strokes", "parameters"});
    RelationEvent r;
    r.track = string(field(j, "track", what), "track");
    if (r.track.empty()) fail("field 'track' must not be empty");
    const std::string kind = string(field(j, "kind", what), "kind");
    try {
      r.kind = constraint_kind_from_string(kind);
    } catch (const std::exception& ex) {
      fail("field 'kind': " + std::string(ex.what()));
    }
    const json& strokes = array(field(j, "strokes", what), "strokes");
    if (strokes.empty()) fail("field 'strokes' must name at least one stroke");
    for (std::size_t i = 0; i < strokes.size(); ++i)
      r.strokes.push_back(unsigned_integer(strokes[i], "strokes[" + std::to_string(i) + "]"));
    const json& params = array(field(j, "parameters", what), "parameters");
    for (std::size_t i = 0; i < params.size(); ++i)
      r.parameters.push_back(number(params[i], "parameters[" + std::to_string(i) + "]", max_coordinate));
    e.payload = std::move(r);
  } else {
    fail("unknown event type '" + type + "' (allowed: " + allowed_types() + ")");
  }
  return e;
}

ojson to_json(const RecordingHeader& h) {
  ojson j = ojson::object();
  j["format"] = "sketchlab-recording";
  j["version"] = h.version;
  j["units"] = h.units;
  j["workspace"] = to_json(h.workspace);
  ojson src = ojson::object();
  for (const auto& [k, v] : h.source) src[k] = v;
  j["source"] = std::move(src);
  return j;
}

RecordingHeader header_from_json(const json& j) {
  const std::string what = "header";
  if (!j.is_object()) fail(std::string("the header must be a JSON object, got ") + j.type_name());
  const auto fmt = j.find("format");
  if (fmt == j.end()) {
    fail("missing field 'format' in header: not a sketchlab recording (expected "
         "{\"format\":\"sketchlab-recording\",...} on line 1)");
  }
  if (!fmt->is_string() || fmt->get<std::string>() != "sketchlab-recording") {
    fail("not a sketchlab recording: field 'format' is " + fmt->dump() +
         " (expected \"sketchlab-recording\")");
  }
  const json& ver = field(j, "version", what);
  if (!ver.is_number_integer() || ver.get<long long>() != recording_format_version) {
    fail("unsupported recording version " + ver.dump() + " (supported: " +
         std::to_string(recording_format_version) + ")");
  }
  check_object(j, what, {"format", "version", "units", "workspace", "source"});
  RecordingHeader h;
  h.version = recording_format_version;
  h.units = string(field(j, "units", what), "units");
  if (h.units != "m" && h.units != "px") {
    fail("field 'units' = '" + h.units + "' is not allowed (allowed: m, px)");
  }
  h.workspace = workspace_from_json(field(j, "workspace", what), "workspace");
  const json& src = field(j, "source", what);
  if (!src.is_object()) fail(std::string("field 'source' must be an object, got ") + src.type_name());
  for (const auto& item : src.items()) {
    h.source[item.key()] = string(item.value(), "source." + item.key());
  }
  return h;
}

json parse_line(std::string_view line) {
  try {
    return json::parse(line);
  } catch (const json::exception& e) {  // parse_error, or out_of_range for 1e999
    std::string msg = e.what();
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix.
    if (const auto p = msg.find("] "); msg.rfind("[json.exception", 0) == 0 && p != std::string::npos) {
      msg = msg.substr(p + 2);
    }
    fail("bad JSON: " + msg);
  }
}

}  // namespace sketchlab::json_codec
