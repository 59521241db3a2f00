#include "sketchlab/io/sketch_json.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "recording/json_codec.hpp"
#include "sketchlab/io/text_file.hpp"

namespace sketchlab {
namespace {

using json_codec::json;
using json_codec::ojson;
using json_codec::to_json;

constexpr int sketch_format_version = 1;

std::string_view keypoint_kind_name(Keypoint::Kind k) {
  switch (k) {
    case Keypoint::Kind::start: return "start";
    case Keypoint::Kind::end: return "end";
    case Keypoint::Kind::midpoint: return "midpoint";
    case Keypoint::Kind::tick: return "tick";
    case Keypoint::Kind::other: break;
  }
  return "other";
}

Keypoint::Kind keypoint_kind_from(const std::string& s, const std::string& what) {
  for (auto k : {Keypoint::Kind::start, Keypoint::Kind::end, Keypoint::Kind::midpoint,
                 Keypoint::Kind::tick, Keypoint::Kind::other})
    if (keypoint_kind_name(k) == s) return k;
  throw std::invalid_argument(what + ": unknown keypoint kind '" + s +
                              "' (allowed: start, end, midpoint, tick, other)");
}

std::string_view ref_kind_name(ConstraintRef::Kind k) {
  switch (k) {
    case ConstraintRef::Kind::stroke: return "stroke";
    case ConstraintRef::Kind::curve: return "curve";
    case ConstraintRef::Kind::node: return "node";
    case ConstraintRef::Kind::grid: return "grid";
    case ConstraintRef::Kind::mirror: return "mirror";
    case ConstraintRef::Kind::axis: break;
  }
  return "axis";
}

ojson constraint_to_json(const Constraint& c) {
  ojson refs = ojson::array();
  for (const auto& r : c.references)
    refs.push_back(ojson{{"kind", ref_kind_name(r.kind)}, {"id", r.id}, {"t", r.parameter}});
  return ojson{{"kind", to_string(c.kind)}, {"references", refs}, {"target", to_json(c.target)},
               {"weight", c.weight},        {"hard", c.hard},     {"enforced", c.enforced},
               {"residual", c.residual}};
}

// Vertex normals (a surfacer's shading) only when the mesh has them, so
// files of meshes without normals are the bytes they were before normals
// were written.
ojson mesh_to_json(const Mesh& m) {
  ojson v = ojson::array(), f = ojson::array();
  for (const auto& p : m.vertices) v.push_back(to_json(p));
  for (const auto& t : m.faces) f.push_back({t[0], t[1], t[2]});
  ojson out{{"vertices", v}, {"faces", f}};
  if (!m.normals.empty()) {
    ojson n = ojson::array();
    for (const auto& p : m.normals) n.push_back(to_json(p));
    out["normals"] = n;
  }
  return out;
}

Vec3 vec3_from(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3) throw std::invalid_argument(what + ": expected [x, y, z]");
  Vec3 v;
  for (int i = 0; i < 3; ++i) {
    if (!j[i].is_number()) throw std::invalid_argument(what + ": expected numbers");
    v[i] = j[i].get<double>();
    if (!std::isfinite(v[i])) throw std::invalid_argument(what + ": non-finite number");
  }
  return v;
}

const json& field(const json& j, const char* name, const std::string& what) {
  if (!j.is_object() || !j.contains(name))
    throw std::invalid_argument(what + ": missing field '" + name + "'");
  return j.at(name);
}

const json& list(const json& j, const char* name, const std::string& what) {
  const json& v = field(j, name, what);
  if (!v.is_array()) throw std::invalid_argument(what + "." + name + ": expected a list");
  return v;
}

// An integer of type T, exactly. nlohmann keeps integer literals as int64 or
// uint64 and everything else as double; converting a double (1.5, 1e300,
// -1.5, 1.7e24) or an out-of-range integer to T would be undefined
// behaviour (issue 17, D7), so those are errors naming the field.
template <class T>
T integer(const json& v, const std::string& what) {
  constexpr auto lo = std::numeric_limits<T>::min();
  constexpr auto hi = std::numeric_limits<T>::max();
  const auto out_of_range = [&] {
    return std::invalid_argument(what + ": expected an integer in [" + std::to_string(lo) + ", " +
                                 std::to_string(hi) + "], got " + v.dump());
  };
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(hi)) throw out_of_range();
    return static_cast<T>(u);
  }
  if (v.is_number_integer()) {
    const auto i = v.get<std::int64_t>();
    if constexpr (std::is_unsigned_v<T>) {
      if (i < 0) throw out_of_range();
    } else {
      if (i < static_cast<std::int64_t>(lo) || i > static_cast<std::int64_t>(hi)) throw out_of_range();
    }
    return static_cast<T>(i);
  }
  throw out_of_range();
}

template <class T>
T number(const json& j, const char* name, const std::string& what) {
  const json& v = field(j, name, what);
  const std::string where = what + "." + name;
  if constexpr (std::is_floating_point_v<T>) {
    if (!v.is_number()) throw std::invalid_argument(where + ": expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw std::invalid_argument(where + ": non-finite number");
    return x;
  } else {
    return integer<T>(v, where);
  }
}

std::string text(const json& j, const char* name, const std::string& what) {
  const json& v = field(j, name, what);
  if (!v.is_string()) throw std::invalid_argument(what + "." + name + ": expected a string");
  return v.get<std::string>();
}

bool boolean(const json& j, const char* name, const std::string& what) {
  const json& v = field(j, name, what);
  if (!v.is_boolean()) throw std::invalid_argument(what + "." + name + ": expected true or false");
  return v.get<bool>();
}

}  // namespace

std::string sketch_to_json(const Sketch& sketch, const std::vector<StepReport>* steps) {
  const Network& net = sketch.network;
  ojson curves = ojson::array();
  for (const auto& [id, c] : net.curves()) {
    ojson keypoints = ojson::array(), normals = ojson::array();
    for (const auto& k : c.keypoints)
      keypoints.push_back(ojson{{"kind", keypoint_kind_name(k.kind)}, {"t", k.t}, {"position", to_json(k.position)}});
    for (const auto& n : c.normals) normals.push_back(ojson{{"t", n.t}, {"normal", to_json(n.normal)}});
    curves.push_back(ojson{{"id", id},
                           {"layer", to_string(c.layer)},
                           {"source_stroke", c.source_stroke},
                           {"curve", to_json(c.curve)},
                           {"keypoints", keypoints},
                           {"normals", normals}});
  }
  ojson nodes = ojson::array();
  for (const auto& [id, n] : net.nodes()) {
    ojson inc = ojson::array();
    for (const auto& i : n.incidences) inc.push_back(ojson{{"curve", i.curve}, {"t", i.t}});
    nodes.push_back(ojson{{"id", id}, {"position", to_json(n.position)}, {"incidences", inc}});
  }
  ojson segments = ojson::array();
  for (const auto& s : net.segments())
    segments.push_back(ojson{{"curve", s.curve}, {"t0", s.t0}, {"t1", s.t1}, {"nodes", {s.node0, s.node1}}});
  ojson patches = ojson::array();
  for (const auto& [id, p] : net.patches()) {
    ojson boundary = ojson::array();
    for (const auto& b : p.boundary)
      boundary.push_back(ojson{{"curve", b.curve}, {"t_from", b.t_from}, {"t_to", b.t_to},
                               {"node_from", b.node_from}, {"node_to", b.node_to}});
    patches.push_back(ojson{{"id", id}, {"automatic", p.automatic}, {"boundary", boundary},
                            {"mesh", mesh_to_json(p.mesh)}});
  }
  ojson strokes = ojson::array();
  for (const auto& [id, s] : sketch.strokes) strokes.push_back(id);
  ojson constraints = ojson::array();
  if (steps)
    for (const auto& step : *steps) {
      if (!step.stroke || step.constraints.empty() || step.event != EventKind::stroke) continue;
      ojson list = ojson::array();
      for (const auto& c : step.constraints) list.push_back(constraint_to_json(c));
      constraints.push_back(ojson{{"stroke", *step.stroke}, {"constraints", list}});
    }
  const IdCounters& k = net.counters();
  ojson root{{"format", "sketchlab-sketch"},
             {"version", sketch_format_version},
             {"workspace", to_json(sketch.workspace)},
             {"counters", {{"next_curve", k.next_curve}, {"next_node", k.next_node}, {"next_patch", k.next_patch}}},
             {"curves", curves},
             {"nodes", nodes},
             {"segments", segments},
             {"patches", patches},
             {"strokes", strokes},
             {"constraints", constraints}};
  return root.dump(1) + "\n";
}

namespace {

// A recording's first line is its header (recording/event_json.hpp): given
// where a sketch is expected, say so rather than report line 2 as bad JSON.
bool is_recording(std::string_view text) {
  const json header = json::parse(text.substr(0, text.find('\n')), nullptr, false);
  return header.is_object() && header.value("format", json()) == "sketchlab-recording";
}

}  // namespace

Sketch parse_sketch_json(std::string_view text_in, const std::string& name) {
  if (is_recording(text_in))
    throw std::runtime_error(name + ": a sketchlab recording (one event per line), not a sketch (format "
                             "\"sketchlab-sketch\"); replay it first: `sketchlab run` writes each case's sketch.json");
  try {
    const json root = json::parse(text_in);
    if (!root.is_object() || root.value("format", "") != "sketchlab-sketch")
      throw std::invalid_argument("format: expected \"sketchlab-sketch\"");
    if (number<std::int64_t>(root, "version", "sketch") != sketch_format_version)
      throw std::invalid_argument("version: only version " + std::to_string(sketch_format_version) +
                                  " is supported");
    Sketch sketch;
    sketch.workspace = json_codec::workspace_from_json(field(root, "workspace", "sketch"), "workspace");
    Edit edit;
    for (const json& c : list(root, "curves", "sketch")) {
      NetworkCurve nc;
      const std::string what = "curve " + field(c, "id", "curve").dump();
      nc.id = number<CurveId>(c, "id", what);
      nc.layer = layer_from_string(text(c, "layer", what));
      nc.source_stroke = number<StrokeId>(c, "source_stroke", what);
      nc.curve = json_codec::curve_from_json(field(c, "curve", what), what + ".curve");
      for (const json& k : list(c, "keypoints", what))
        nc.keypoints.push_back({keypoint_kind_from(text(k, "kind", what), what), number<double>(k, "t", what),
                                vec3_from(field(k, "position", what), what)});
      for (const json& n : list(c, "normals", what))
        nc.normals.push_back({number<double>(n, "t", what), vec3_from(field(n, "normal", what), what)});
      edit.curves_added.push_back(std::move(nc));
    }
    for (const json& n : list(root, "nodes", "sketch")) {
      Node node;
      const std::string what = "node " + field(n, "id", "node").dump();
      node.id = number<NodeId>(n, "id", what);
      node.position = vec3_from(field(n, "position", what), what + ".position");
      for (const json& i : list(n, "incidences", what))
        node.incidences.push_back({number<CurveId>(i, "curve", what), number<double>(i, "t", what)});
      edit.nodes_added.push_back(std::move(node));
    }
    for (const json& p : list(root, "patches", "sketch")) {
      Patch patch;
      const std::string what = "patch " + field(p, "id", "patch").dump();
      patch.id = number<PatchId>(p, "id", what);
      patch.automatic = boolean(p, "automatic", what);
      for (const json& b : list(p, "boundary", what))
        patch.boundary.push_back({number<CurveId>(b, "curve", what), number<double>(b, "t_from", what),
                                  number<double>(b, "t_to", what), number<NodeId>(b, "node_from", what),
                                  number<NodeId>(b, "node_to", what)});
      const json& mesh = field(p, "mesh", what);
      for (const json& v : list(mesh, "vertices", what)) patch.mesh.vertices.push_back(vec3_from(v, what));
      const int vertices = static_cast<int>(patch.mesh.vertices.size());
      for (const json& f : list(mesh, "faces", what)) {
        if (!f.is_array() || f.size() != 3) throw std::invalid_argument(what + ": faces must be triangles");
        std::array<int, 3> face{};
        for (int k = 0; k < 3; ++k) {
          face[k] = integer<int>(f[k], what + ".faces");
          if (face[k] < 0 || face[k] >= vertices)
            throw std::invalid_argument(what + ".faces: vertex index " + std::to_string(face[k]) +
                                        " outside [0, " + std::to_string(vertices) + ")");
        }
        patch.mesh.faces.push_back({face[0], face[1], face[2]});
      }
      // Optional (files written before normals were kept have none).
      if (mesh.contains("normals")) {
        for (const json& n : list(mesh, "normals", what))
          patch.mesh.normals.push_back(vec3_from(n, what + ".normals"));
        if (patch.mesh.normals.size() != patch.mesh.vertices.size())
          throw std::invalid_argument(what + ".normals: " + std::to_string(patch.mesh.normals.size()) +
                                      " normals for " + std::to_string(vertices) +
                                      " vertices (one per vertex, or the key left out)");
      }
      edit.patches_added.push_back(std::move(patch));
    }
    const json& k = field(root, "counters", "sketch");
    edit.counters = IdCounters{number<CurveId>(k, "next_curve", "counters"),
                               number<NodeId>(k, "next_node", "counters"),
                               number<PatchId>(k, "next_patch", "counters")};
    sketch.network.apply(edit);
    return sketch;
  } catch (const json::exception& e) {
    throw std::runtime_error(name + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(name + ": " + e.what());
  }
}

Sketch read_sketch_json(const std::filesystem::path& file) {
  return parse_sketch_json(read_text_file(file), file.string());
}

}  // namespace sketchlab
