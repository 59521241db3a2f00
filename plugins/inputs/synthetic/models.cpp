#include "models.hpp"

#include <array>
#include <stdexcept>

namespace sketchlab::synthetic {
namespace {

// Kappa for a quarter circle by one cubic (max radial error 0.027 %).
constexpr double kappa = 0.5522847498307936;

GroundTruthCurve line(const Vec3& a, const Vec3& b, Layer layer) {
  return {make_line(a, b), layer};
}

// Builds a closed or open cubic poly-Bézier piece by piece.
class PolyBezierBuilder {
 public:
  explicit PolyBezierBuilder(const Vec3& start) { curve_.control_points.push_back(start); }
  void cubic(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    // push_back, not insert({...}): GCC 12 reports a false -Warray-bounds on
    // an initializer_list of Eigen vectors.
    curve_.control_points.push_back(p1);
    curve_.control_points.push_back(p2);
    curve_.control_points.push_back(p3);
  }
  void line_to(const Vec3& p) {
    const Vec3 a = curve_.control_points.back();
    cubic(a + (p - a) / 3.0, a + 2.0 * (p - a) / 3.0, p);
  }
  // Quarter arc around `c` from c + r a to c + r b (a ⟂ b, unit).
  void quarter_arc(const Vec3& c, double r, const Vec3& a, const Vec3& b) {
    cubic(c + r * a + kappa * r * b, c + r * b + kappa * r * a, c + r * b);
  }
  Curve finish(bool close) {
    if (close) curve_.control_points.back() = curve_.control_points.front();
    curve_.closed = close;
    curve_.sharp.assign(static_cast<std::size_t>(curve_.segment_count()) + 1, false);
    return curve_;
  }

 private:
  Curve curve_;
};

std::array<Vec3, 4> circle_dirs(const Vec3& u, const Vec3& v) { return {u, v, -u, -v}; }

Vec3 circle_point(const Vec3& c, const Vec3& u, const Vec3& v, double r, int k) {
  return c + r * circle_dirs(u, v)[static_cast<std::size_t>(k % 4)];
}

// Rounded rectangle centred at c in the plane (u, v): half extents hu, hv,
// corner radius r; starts at the middle of the -v side.
Curve rounded_rectangle(const Vec3& c, const Vec3& u, const Vec3& v, double hu, double hv,
                        double r) {
  PolyBezierBuilder b(c - hv * v);
  b.line_to(c + (hu - r) * u - hv * v);
  b.quarter_arc(c + (hu - r) * u - (hv - r) * v, r, -v, u);
  b.line_to(c + hu * u + (hv - r) * v);
  b.quarter_arc(c + (hu - r) * u + (hv - r) * v, r, u, v);
  b.line_to(c - (hu - r) * u + hv * v);
  b.quarter_arc(c - (hu - r) * u + (hv - r) * v, r, v, -u);
  b.line_to(c - hu * u - (hv - r) * v);
  b.quarter_arc(c - (hu - r) * u - (hv - r) * v, r, -u, -v);
  b.line_to(c - hv * v);
  return b.finish(true);
}

// The 12 edges of the box c ± h (componentwise).
void add_box_edges(GroundTruthNetwork& net, const Vec3& c, const Vec3& h, Layer layer) {
  auto corner = [&](int i) {
    return Vec3(c.x() + ((i & 1) ? h.x() : -h.x()), c.y() + ((i & 2) ? h.y() : -h.y()),
                c.z() + ((i & 4) ? h.z() : -h.z()));
  };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) net.curves.push_back(line(corner(i), corner(i | bit), layer));
}

}  // namespace

Curve make_circle(const Vec3& c, const Vec3& u, const Vec3& v, double r) {
  const auto d = circle_dirs(u, v);
  PolyBezierBuilder b(c + r * d[0]);
  for (std::size_t k = 0; k < 4; ++k) b.quarter_arc(c, r, d[k], d[(k + 1) % 4]);
  return b.finish(true);
}

const std::vector<std::string>& model_names() {
  static const std::vector<std::string> names{"cube", "rounded_box", "mug", "chair", "lamp"};
  return names;
}

GroundTruthNetwork make_cube(const Vec3& center, double size) {
  GroundTruthNetwork net{"cube", {}};
  add_box_edges(net, center, Vec3::Constant(size / 2), Layer::scaffold);
  return net;
}

GroundTruthNetwork make_rounded_box(const Vec3& center, double size) {
  GroundTruthNetwork net{"rounded_box", {}};
  const Vec3 h = size * Vec3(0.5, 0.3, 0.4);
  add_box_edges(net, center, h, Layer::scaffold);
  const double margin = 0.06 * size;
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 n = Vec3::Unit(axis), u = Vec3::Unit((axis + 1) % 3), v = Vec3::Unit((axis + 2) % 3);
    const double hu = h[(axis + 1) % 3] - margin, hv = h[(axis + 2) % 3] - margin;
    const double r = 0.35 * std::min(hu, hv);
    for (double side : {-1.0, 1.0}) {
      net.curves.push_back(
          {rounded_rectangle(center + side * h[axis] * n, u, v, hu, hv, r), Layer::shape});
    }
  }
  return net;
}

GroundTruthNetwork make_mug(const Vec3& center, double size) {
  GroundTruthNetwork net{"mug", {}};
  const double height = 0.9 * size, radius = 0.3 * size;
  const Vec3 u = Vec3::UnitX(), v = -Vec3::UnitZ();
  const Vec3 base = center - 0.5 * height * Vec3::UnitY(), rim = center + 0.5 * height * Vec3::UnitY();
  net.curves.push_back({make_circle(rim, u, v, radius), Layer::shape});
  net.curves.push_back({make_circle(base, u, v, radius), Layer::shape});
  for (int k = 0; k < 4; ++k) {
    net.curves.push_back(line(circle_point(base, u, v, radius, k), circle_point(rim, u, v, radius, k),
                              Layer::shape));
  }
  // Handle on the +x side, ends on the side line at 75 % and 25 % of its height.
  const Curve& side = net.curves[2].curve;
  const Vec3 a = side.control_points.front() + 0.75 * (side.control_points.back() - side.control_points.front());
  const Vec3 b = side.control_points.front() + 0.25 * (side.control_points.back() - side.control_points.front());
  const double w = 0.45 * radius, drop = a.y() - b.y();
  const Vec3 m = 0.5 * (a + b) + w * u;
  PolyBezierBuilder handle(a);
  handle.cubic(a + 0.8 * w * u + 0.1 * drop * Vec3::UnitY(), m + 0.3 * drop * Vec3::UnitY(), m);
  handle.cubic(m - 0.3 * drop * Vec3::UnitY(), b + 0.8 * w * u - 0.1 * drop * Vec3::UnitY(), b);
  net.curves.push_back({handle.finish(false), Layer::shape});
  return net;
}

GroundTruthNetwork make_chair(const Vec3& center, double size) {
  GroundTruthNetwork net{"chair", {}};
  const double floor = center.y() - 0.5 * size, seat = floor + 0.45 * size, top = floor + size;
  const double hw = 0.225 * size, hd = 0.21 * size;
  auto at = [&](double x, double y, double z) { return Vec3(center.x() + x, y, center.z() + z); };
  const Vec3 fl = at(-hw, seat, hd), fr = at(hw, seat, hd), bl = at(-hw, seat, -hd), br = at(hw, seat, -hd);
  net.curves.push_back(line(fl, fr, Layer::shape));
  net.curves.push_back(line(fr, br, Layer::shape));
  net.curves.push_back(line(br, bl, Layer::shape));
  net.curves.push_back(line(bl, fl, Layer::shape));
  for (const Vec3& p : {fl, fr, bl, br})
    net.curves.push_back(line(p, Vec3(p.x(), floor, p.z()), Layer::shape));
  const Vec3 tl = at(-hw, top, -hd), tr = at(hw, top, -hd);
  net.curves.push_back(line(bl, tl, Layer::shape));
  net.curves.push_back(line(br, tr, Layer::shape));
  const double mid = seat + 0.5 * (top - seat);
  net.curves.push_back(line(at(-hw, mid, -hd), at(hw, mid, -hd), Layer::shape));
  PolyBezierBuilder rail(tl);
  const double arch = 0.06 * size;
  rail.cubic(at(-hw / 3, top + arch, -hd), at(hw / 3, top + arch, -hd), tr);
  net.curves.push_back({rail.finish(false), Layer::shape});
  return net;
}

GroundTruthNetwork make_lamp(const Vec3& center, double size) {
  GroundTruthNetwork net{"lamp", {}};
  const Vec3 u = Vec3::UnitX(), v = -Vec3::UnitZ(), up = Vec3::UnitY();
  const double floor = center.y() - 0.5 * size, rb = 0.2 * size;
  const Vec3 base(center.x(), floor, center.z());
  net.curves.push_back({make_circle(base, u, v, rb), Layer::shape});
  net.curves.push_back(line(circle_point(base, u, v, rb, 0), circle_point(base, u, v, rb, 2), Layer::shape));
  net.curves.push_back(line(circle_point(base, u, v, rb, 1), circle_point(base, u, v, rb, 3), Layer::shape));
  const Vec3 stem_top = base + 0.6 * size * up;
  net.curves.push_back(line(base, stem_top, Layer::shape));
  const Vec3 arm_end = stem_top + 0.3 * size * u + 0.25 * size * up;
  net.curves.push_back(line(stem_top, arm_end, Layer::shape));
  // Shade: its top circle passes through the arm end (at its joint t = 2).
  const double rt = 0.06 * size, rs = 0.16 * size;
  const Vec3 top_c = arm_end + rt * u, bottom_c = top_c - 0.2 * size * up;
  net.curves.push_back({make_circle(top_c, u, v, rt), Layer::shape});
  net.curves.push_back({make_circle(bottom_c, u, v, rs), Layer::shape});
  for (int k = 0; k < 4; ++k) {
    net.curves.push_back(line(circle_point(top_c, u, v, rt, k), circle_point(bottom_c, u, v, rs, k),
                              Layer::shape));
  }
  return net;
}

GroundTruthNetwork make_model(const std::string& name, const Vec3& center, double size) {
  if (name == "cube") return make_cube(center, size);
  if (name == "rounded_box") return make_rounded_box(center, size);
  if (name == "mug") return make_mug(center, size);
  if (name == "chair") return make_chair(center, size);
  if (name == "lamp") return make_lamp(center, size);
  std::string allowed;
  for (const auto& n : model_names()) allowed += (allowed.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown synthetic model '" + name + "' (allowed: " + allowed + ", mesh)");
}

}  // namespace sketchlab::synthetic
