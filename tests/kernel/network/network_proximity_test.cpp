// Proximity queries answered by the spatial index equal brute force (every
// curve through closest_point), before and after removals and replacements.
#include <catch2/catch.hpp>
#include <algorithm>
#include <random>

#include "kernel/network/random_network.hpp"
#include "sketchlab/geometry/closest_point.hpp"
#include "network/spatial_index.hpp"
#include "sketchlab/network.hpp"

using namespace sketchlab;
using namespace sketchlab::test;

namespace {

std::vector<CurveHit> brute_curves_near(const Network& net, const Vec3& p, double r) {
  std::vector<CurveHit> out;
  for (const auto& [id, c] : net.curves()) {
    const ClosestPoint cp = closest_point(c.curve, p);
    if (cp.distance <= r) out.push_back({id, cp.t, cp.point, cp.distance});
  }
  std::sort(out.begin(), out.end(), [](const CurveHit& a, const CurveHit& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.curve < b.curve;
  });
  return out;
}

std::vector<CurveHit> brute_curves_near_polyline(const Network& net, const std::vector<Vec3>& poly, double r) {
  std::vector<CurveHit> out;
  for (const auto& [id, c] : net.curves()) {
    const ClosestPoint cp = closest_point_to_polyline(c.curve, poly);
    if (cp.distance <= r) out.push_back({id, cp.t, cp.point, cp.distance});
  }
  std::sort(out.begin(), out.end(), [](const CurveHit& a, const CurveHit& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.curve < b.curve;
  });
  return out;
}

std::vector<KeypointHit> brute_keypoints_near(const Network& net, const Vec3& p, double r) {
  std::vector<KeypointHit> out;
  for (const auto& [id, c] : net.curves())
    for (std::size_t k = 0; k < c.keypoints.size(); ++k) {
      const double d = (c.keypoints[k].position - p).norm();
      if (d <= r) out.push_back({id, static_cast<int>(k), c.keypoints[k].position, d});
    }
  std::sort(out.begin(), out.end(), [](const KeypointHit& a, const KeypointHit& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    return a.curve != b.curve ? a.curve < b.curve : a.keypoint < b.keypoint;
  });
  return out;
}

std::vector<NodeHit> brute_nodes_near(const Network& net, const Vec3& p, double r) {
  std::vector<NodeHit> out;
  for (const auto& [id, n] : net.nodes()) {
    const double d = (n.position - p).norm();
    if (d <= r) out.push_back({id, d});
  }
  std::sort(out.begin(), out.end(), [](const NodeHit& a, const NodeHit& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.node < b.node;
  });
  return out;
}

void require_same(const std::vector<CurveHit>& a, const std::vector<CurveHit>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    REQUIRE(a[i].curve == b[i].curve);
    REQUIRE(a[i].t == b[i].t);
    REQUIRE(a[i].distance == b[i].distance);
    REQUIRE(a[i].point == b[i].point);
  }
}

// Queries near the data (on a curve, at a keypoint, at random) with radii from
// 0 to well above a cell; returns how many hits were compared.
std::size_t check_point_queries(const Network& net, std::mt19937_64& rng, int count) {
  std::vector<CurveId> ids;
  for (const auto& [id, c] : net.curves()) ids.push_back(id);
  std::size_t hits = 0;
  const double radii[] = {0.0, 0.01, 0.04, 0.15};
  for (int q = 0; q < count; ++q) {
    Vec3 p = random_point(rng, -0.1, 1.1);
    if (q % 3 == 1 && !ids.empty()) {
      const NetworkCurve& c = net.curves().at(pick(rng, ids));
      p = evaluate(c.curve, uniform(rng, 0.0, c.curve.t_max())) + random_point(rng, -0.01, 0.01);
    } else if (q % 3 == 2 && !ids.empty()) {
      const NetworkCurve& c = net.curves().at(pick(rng, ids));
      p = c.keypoints[0].position;  // exactly on an item: tests r = 0 and inclusivity
    }
    const double r = radii[q % 4];
    const auto a = net.curves_near(p, r);
    require_same(a, brute_curves_near(net, p, r));
    hits += a.size();
    const auto k = net.keypoints_near(p, r);
    const auto kb = brute_keypoints_near(net, p, r);
    REQUIRE(k.size() == kb.size());
    for (std::size_t i = 0; i < k.size(); ++i) {
      REQUIRE(k[i].curve == kb[i].curve);
      REQUIRE(k[i].keypoint == kb[i].keypoint);
      REQUIRE(k[i].distance == kb[i].distance);
    }
    const auto n = net.nodes_near(p, r);
    const auto nb = brute_nodes_near(net, p, r);
    REQUIRE(n.size() == nb.size());
    for (std::size_t i = 0; i < n.size(); ++i) {
      REQUIRE(n[i].node == nb[i].node);
      REQUIRE(n[i].distance == nb[i].distance);
    }
    hits += k.size() + n.size();
  }
  return hits;
}

std::size_t check_polyline_queries(const Network& net, std::mt19937_64& rng, int count) {
  std::size_t hits = 0;
  for (int q = 0; q < count; ++q) {
    std::vector<Vec3> poly{random_point(rng)};
    const int n = uniform_int(rng, 1, 8);
    const Vec3 dir = random_direction(rng);
    for (int i = 0; i < n; ++i) poly.push_back(poly.back() + 0.03 * dir + random_point(rng, -0.01, 0.01));
    const double r = q % 2 ? 0.04 : 0.01;
    const auto a = net.curves_near_polyline(poly, r);
    require_same(a, brute_curves_near_polyline(net, poly, r));
    hits += a.size();
  }
  return hits;
}

}  // namespace

TEST_CASE("proximity queries equal brute force on 2,000 curves", "[network][proximity]") {
  std::mt19937_64 rng(4242);
  Network net = random_network(rng, 2000);
  REQUIRE(net.curves().size() == 2000);
  CHECK(check_point_queries(net, rng, 200) > 200);
  CHECK(check_polyline_queries(net, rng, 8) > 3);

  {
    // After removals, replacements and additions.
    Edit e;
    std::vector<CurveId> ids;
    for (const auto& [id, c] : net.curves()) ids.push_back(id);
    std::shuffle(ids.begin(), ids.end(), rng);
    std::map<CurveId, double> t_max;
    for (std::size_t i = 0; i < 300; ++i) e.curves_removed.push_back(ids[i]);
    for (std::size_t i = 300; i < 600; ++i) {
      // Same segment count, so the nodes on it stay valid.
      e.curves_replaced.push_back(random_network_curve(rng, ids[i], net.find_curve(ids[i])->curve.segment_count()));
    }
    for (int i = 0; i < 100; ++i) e.curves_added.push_back(random_network_curve(rng, net.next_curve_id() + i));
    for (const auto& [id, n] : net.nodes())
      if (uniform_int(rng, 0, 9) == 0) e.nodes_removed.push_back(id);
    const Network before = net;
    const Edit inverse = net.apply(e);
    REQUIRE(net.curves().size() == 1800);
    CHECK(check_point_queries(net, rng, 150) > 100);
    CHECK(check_polyline_queries(net, rng, 6) > 2);

    // The copy taken before is untouched (deep-copied index) and still exact.
    CHECK(check_point_queries(before, rng, 50) > 20);

    net.apply(inverse);
    REQUIRE(net == before);
    CHECK(check_point_queries(net, rng, 100) > 50);
  }

  {
    // After a change of scale that rebuilds the grid: every curve made ten
    // times larger, then back; the cell size must follow and answers stay
    // exact.
    for (const double scale : {10.0, 0.1}) {
      Edit e;
      for (const auto& [id, c] : net.curves()) {
        NetworkCurve big = c;
        const Vec3 o = big.curve.control_points.front();
        for (Vec3& p : big.curve.control_points) p = o + scale * (p - o);
        for (Keypoint& k : big.keypoints) k.position = o + scale * (k.position - o);
        e.curves_replaced.push_back(big);
      }
      net.apply(e);
      CHECK(check_point_queries(net, rng, 60) > 20);
    }
  }
}

TEST_CASE("proximity queries reject bad arguments and handle the empty network", "[network][proximity]") {
  Network net;
  CHECK(net.curves_near(Vec3::Zero(), 1.0).empty());
  CHECK(net.keypoints_near(Vec3::Zero(), 1.0).empty());
  CHECK(net.nodes_near(Vec3::Zero(), 1.0).empty());
  CHECK(net.curves_near_polyline({Vec3::Zero()}, 1.0).empty());
  CHECK_THROWS_AS(net.curves_near(Vec3::Zero(), -1.0), std::invalid_argument);
  CHECK_THROWS_AS(net.curves_near(Vec3::Zero(), std::nan("")), std::invalid_argument);
  CHECK_THROWS_AS(net.curves_near(Vec3(std::nan(""), 0, 0), 1.0), std::invalid_argument);
  CHECK_THROWS_AS(net.curves_near_polyline({}, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(net.keypoints_near(Vec3::Zero(), -0.5), std::invalid_argument);

  // A single long diagonal line (one cubic, chunked) is found along its length.
  Edit e;
  NetworkCurve line;
  line.id = 1;
  line.curve = make_line(Vec3(-3, -3, -3), Vec3(3, 3, 3));
  line.keypoints = default_keypoints(line.curve);
  e.curves_added.push_back(line);
  net.apply(e);
  for (double s = -3.0; s <= 3.0; s += 0.37) {
    const auto hits = net.curves_near(Vec3(s, s, s + 0.01), 0.0101);
    REQUIRE(hits.size() == 1);
    CHECK(hits[0].distance == Approx(0.01 * std::sqrt(2.0 / 3.0)).epsilon(1e-6));
  }
  CHECK(net.curves_near(Vec3(1, -1, 0), 0.5).empty());
  CHECK(net.keypoints_near(Vec3(0, 0, 0), 1e-9).size() == 1);  // the arclength midpoint
}

TEST_CASE("a glitch segment kilometres away stays a few index entries and queries stay exact",
          "[network][proximity][reliability]") {
  // Issue 17, D3 (reproducer H1): a 30 cm sketch of centimetre segments plus
  // one tracking-glitch sample 10 km away used to cut the glitch segment into
  // chunks of ~10 m, each filling a cube of 1000^3 one-centimetre cells.
  std::mt19937_64 rng(17);
  Network net = random_network(rng, 300);
  Edit e;
  const double far_away[] = {1e3, 1e4, 1e6};
  for (const double far : far_away) {
    NetworkCurve glitch;
    glitch.id = net.next_curve_id() + e.curves_added.size();
    glitch.curve = make_line(Vec3(0.14, 0.14, 0.1), Vec3(far, far, far));
    glitch.keypoints = default_keypoints(glitch.curve);
    e.curves_added.push_back(glitch);
  }
  net.apply(e);
  CHECK(check_point_queries(net, rng, 100) > 50);
  CHECK(check_polyline_queries(net, rng, 12) > 2);
  // Far along the glitch lines only they answer.
  const auto hits = net.curves_near(Vec3(5e3, 5e3, 5e3), 1.0);
  REQUIRE(hits.size() == 2);

  SpatialIndex index;
  for (const auto& [id, c] : net.curves()) index.insert_curve(c);
  // Each glitch segment is cut into at most 1024 chunks, all too wide for the
  // grid; the 300 ordinary curves fill a few thousand cells.
  CHECK(index.oversized_chunks() <= 3 * 1024);
  CHECK(index.occupied_cells() < 100000);
  for (const auto& [id, c] : net.curves()) index.erase_curve(id);
  CHECK(index.oversized_chunks() == 0);
  CHECK(index.occupied_cells() == 0);
}
