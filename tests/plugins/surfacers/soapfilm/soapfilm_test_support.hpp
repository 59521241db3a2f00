#pragma once
// Helpers for the soapfilm tests: a trivial corrector that adds prepared
// curves and joins them at given parameters to whatever lies there (existing
// node or curve), and the plugin's own surfacer object.
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

#include "cassie_replay.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/network_curve.hpp"
#include "sketchlab/plugin/plugin_api.hpp"
#include "sketchlab/session.hpp"

extern "C" const sketchlab::PluginHeader* sketchlab_plugin_entry();

namespace sketchlab::soapfilm_test {

struct PreparedCurve {
  Curve curve;
  std::vector<double> junctions;  // parameters on the new curve where it meets others
};

// Returns, for stroke id k, the edit adding prepared curve k: at each
// junction, the existing node there gets an incidence, or a new node joins
// the curve passing there (1e-9 m), or a new node starts there.
class PreparedCorrector : public Corrector {
 public:
  explicit PreparedCorrector(std::map<StrokeId, PreparedCurve> curves) : curves_(std::move(curves)) {}
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    const PreparedCurve& pc = curves_.at(stroke.id);
    const Network& net = sketch.network;
    Correction c;
    const NetworkCurve nc = make_network_curve(net.next_curve_id(), pc.curve, Layer::free, stroke.id);
    c.edit.curves_added.push_back(nc);
    NodeId next = net.next_node_id();
    for (double t : pc.junctions) {
      const Vec3 p = evaluate(pc.curve, t);
      const double tt = pc.curve.closed && t == pc.curve.t_max() ? 0.0 : t;
      if (auto nodes = net.nodes_near(p, 1e-9); !nodes.empty()) {
        Node n = *net.find_node(nodes.front().node);
        // Several junctions may hit one node: extend the replaced copy.
        auto it = std::find_if(c.edit.nodes_replaced.begin(), c.edit.nodes_replaced.end(),
                               [&](const Node& m) { return m.id == n.id; });
        if (it == c.edit.nodes_replaced.end()) {
          c.edit.nodes_replaced.push_back(n);
          it = std::prev(c.edit.nodes_replaced.end());
        }
        it->incidences.push_back({nc.id, tt});
        continue;
      }
      Node n;
      n.id = next++;
      n.position = p;
      n.incidences.push_back({nc.id, tt});
      for (const CurveHit& h : net.curves_near(p, 1e-9)) n.incidences.push_back({h.curve, h.t});
      c.edit.nodes_added.push_back(n);
    }
    return c;
  }

 private:
  std::map<StrokeId, PreparedCurve> curves_;
};

// The soapfilm plugin's surfacer, made through its exported descriptor.
inline std::shared_ptr<Surfacer> make_soapfilm(const std::map<std::string, ParamValue>& given = {}) {
  const auto* header = sketchlab_plugin_entry();
  const auto* d = static_cast<const PluginDescriptor*>(header->descriptor);
  std::string error;
  auto s = d->make_surfacer(validate_params(d->params, given), error);
  if (!s) throw std::runtime_error(error);
  return std::shared_ptr<Surfacer>(std::move(s));
}

// A session over prepared curves (stroke ids 1..n in order).
struct PreparedSession {
  std::shared_ptr<Surfacer> surfacer;
  Session session;
  std::vector<StepReport> steps;
  explicit PreparedSession(const std::vector<PreparedCurve>& curves,
                           std::shared_ptr<Surfacer> s = make_soapfilm())
      : surfacer(s), session(Workspace{}, make_corrector(curves), s) {}
  StepReport draw(StrokeId id) {
    steps.push_back(session.handle(Event{0.0, StrokeEvent{soapfilm::placeholder_stroke(id)}}));
    return steps.back();
  }
  StepReport handle(const EventPayload& payload) {
    steps.push_back(session.handle(Event{0.0, payload}));
    return steps.back();
  }
  void draw_all(std::size_t n) {
    for (StrokeId id = 1; id <= n; ++id) draw(id);
  }
  const Network& network() const { return session.sketch().network; }

 private:
  static std::shared_ptr<Corrector> make_corrector(const std::vector<PreparedCurve>& curves) {
    std::map<StrokeId, PreparedCurve> m;
    for (std::size_t i = 0; i < curves.size(); ++i) m[i + 1] = curves[i];
    return std::make_shared<PreparedCorrector>(std::move(m));
  }
};

// Test shapes.
inline std::vector<Vec3> cube_corners(double a) {
  std::vector<Vec3> c;
  for (int i = 0; i < 8; ++i) c.emplace_back(a * (i & 1), a * ((i >> 1) & 1), a * ((i >> 2) & 1));
  return c;
}

inline std::vector<PreparedCurve> cube_edges(double a) {
  const auto c = cube_corners(a);
  std::vector<PreparedCurve> out;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) out.push_back({make_line(c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(i | bit)]), {0.0, 1.0}});
  return out;
}

// Closed circle of 4 cubic pieces, radius r at height z, t = k at angle kπ/2.
inline Curve circle(double r, double z) {
  const double k = 0.5522847498307936 * r;
  Curve c;
  for (int q = 0; q < 4; ++q) {
    const double a0 = q * 1.5707963267948966, a1 = (q + 1) * 1.5707963267948966;
    const Vec3 p0(r * std::cos(a0), r * std::sin(a0), z), p1(r * std::cos(a1), r * std::sin(a1), z);
    const Vec3 d0(-std::sin(a0), std::cos(a0), 0.0), d1(-std::sin(a1), std::cos(a1), 0.0);
    if (q == 0) c.control_points.push_back(p0);
    c.control_points.push_back(p0 + k * d0);
    c.control_points.push_back(p1 - k * d1);
    c.control_points.push_back(q == 3 ? c.control_points.front() : p1);
  }
  c.sharp.assign(5, false);
  c.closed = true;
  return c;
}

// Two circles then four vertical sides at angles kπ/2.
inline std::vector<PreparedCurve> cylinder(double r, double h) {
  std::vector<PreparedCurve> out{{circle(r, 0.0), {}}, {circle(r, h), {}}};
  for (int q = 0; q < 4; ++q) {
    const double a = q * 1.5707963267948966;
    const Vec3 p(r * std::cos(a), r * std::sin(a), 0.0);
    out.push_back({make_line(p, p + Vec3(0, 0, h)), {0.0, 1.0}});
  }
  return out;
}

}  // namespace sketchlab::soapfilm_test
