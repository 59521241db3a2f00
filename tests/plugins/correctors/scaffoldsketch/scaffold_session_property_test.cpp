// Properties of long random scaffold sessions (hundreds of noisy VR strokes
// through the kernel Session), issue #18: no NaN; no line shorter than half
// its drawn length unless two distinct point constraints demand it; no line
// moved farther from its stroke than the constraints chain it, i.e. in every
// direction the enforced constraints leave free the line stays where it was
// drawn (the corrected ends are, to first order, the configuration closest
// to the drawn ends among those satisfying the enforced constraints).
#include <catch2/catch.hpp>

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include "random_scaffold_session.hpp"
#include "scaffold_candidates.hpp"
#include "scaffold_line.hpp"
#include "scaffoldsketch_corrector.hpp"
#include "sketchlab/session.hpp"

using namespace sketchlab;
using namespace sketchlab::scaffoldsketch;
using namespace sketchlab::scaffoldsketch::test;

namespace {

struct SessionFigures {
  int lines = 0;
  double min_length_ratio = 1e300;  // corrected / drawn, over undemanded lines
  double max_end_move = 0;          // m, over all lines
  double max_free_move = 0;         // m: largest move within the enforced terms' null space
};

// Whether the enforced constraints may demand a short line: two point
// constraints on different points of the line naming different keypoints or
// lines (one keypoint held by two points of the line is defect 1a), or two
// direction constraints along different directions (they fix the direction,
// and the line along it nearest the drawn one may be short).
bool length_demanded(const std::vector<Constraint>& constraints) {
  auto is_point = [](const Constraint& c) {
    return c.kind == ConstraintKind::coincident_point || c.kind == ConstraintKind::point_on_curve;
  };
  auto is_direction = [](const Constraint& c) {
    return c.kind == ConstraintKind::parallel || c.kind == ConstraintKind::perpendicular;
  };
  for (const Constraint& s : constraints)
    for (const Constraint& t : constraints) {
      if (!s.enforced || !t.enforced) continue;
      if (is_point(s) && is_point(t) && s.references[0].parameter != t.references[0].parameter &&
          (s.kind != t.kind ||
           (s.kind == ConstraintKind::coincident_point ? (s.target - t.target).norm() > 1e-9
                                                       : s.references[1].id != t.references[1].id)))
        return true;
      if (is_direction(s) && is_direction(t) && s.target.cross(t.target).norm() > 1e-6) return true;
    }
  return false;
}

// The component of (a, b) - (a0, b0) in the null space of the enforced
// terms' Jacobian at (a, b): zero when the free directions kept the drawn
// position (m). With only direction terms enforced the drawn length is
// kept too (direction_only_length drawn), so the length is held as well.
double free_move(const std::vector<ScaffoldTerm>& terms, const std::vector<Constraint>& records,
                 const Vec3& a, const Vec3& b, const Vec3& a0, const Vec3& b0) {
  Eigen::MatrixXd j(3 * terms.size() + 1, 6);
  j.setZero();
  Eigen::Index rows = 0;
  bool directions_only = true;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    if (!records[i].enforced) continue;
    directions_only &= terms[i].kind == TermKind::parallel || terms[i].kind == TermKind::perpendicular;
    Vec3 r;
    Eigen::Matrix<double, 3, 6> ji;
    const int n = term_residual(terms[i], a, b, r, ji);
    j.middleRows(rows, n) = ji.topRows(n);
    rows += n;
  }
  if (rows > 0 && directions_only) {
    const Vec3 u = (b - a).normalized();
    j.row(rows++) << -u.transpose(), u.transpose();
  }
  Eigen::Matrix<double, 6, 1> x;
  x << a - a0, b - b0;
  if (rows == 0) return x.norm();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j.topRows(rows), Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  Eigen::Matrix<double, 6, 1> free = x;
  for (Eigen::Index k = 0; k < sv.size(); ++k)
    if (sv(k) > 1e-6 * sv(0)) free -= svd.matrixV().col(k) * svd.matrixV().col(k).dot(x);
  return free.norm();
}

// The enforced constraints, for failure messages.
std::string enforced_list(const std::vector<Constraint>& constraints) {
  std::ostringstream o;
  for (const Constraint& c : constraints)
    if (c.enforced)
      o << to_string(c.kind) << "@" << c.references[0].parameter << " -> "
        << c.references[1].id << " (" << c.target.transpose() << ")\n";
  return o.str();
}

SessionFigures run_session(unsigned seed, int strokes, const ScaffoldParams& params) {
  Session session(Workspace{}, std::make_shared<ScaffoldSketchCorrector>(params, ShapeParams{}),
                  nullptr);
  RandomScaffoldSession user(seed);
  SessionFigures f;
  for (int k = 0; k < strokes; ++k) {
    const StrokeId id = 1000 + static_cast<StrokeId>(k);
    const Stroke s = user.next(id, session.sketch().network);
    const Vec3 a0 = s.samples.front().position, b0 = s.samples.back().position;
    // The candidates the corrector sees (same order as its constraints).
    const std::vector<ScaffoldTerm> terms = scaffold_candidates(
        a0, b0, session.sketch().network, session.sketch().workspace, params, 1.0);
    const StepReport r = session.handle(Event{0.1 * k, StrokeEvent{s}});
    INFO("seed " << seed << " stroke " << k);
    REQUIRE(r.error.empty());
    const bool finite = std::all_of(r.constraints.begin(), r.constraints.end(), [](const Constraint& c) {
      return std::isfinite(c.residual) && std::isfinite(c.weight) && c.target.allFinite();
    });
    REQUIRE(finite);
    if (r.stats.outcomes.at("mode") != mode_scaffold_line) continue;
    const auto ids = curves_of_stroke(session.sketch(), id);
    REQUIRE(ids.size() == 1);
    const Curve& line = session.sketch().network.find_curve(ids[0])->curve;
    const Vec3 a = line.control_points.front(), b = line.control_points.back();
    REQUIRE(a.allFinite());
    REQUIRE(b.allFinite());
    REQUIRE(r.constraints.size() == terms.size());
    user.corrected(a, b);
    ++f.lines;
    const double drawn = (b0 - a0).norm(), length = (b - a).norm();
    f.max_end_move = std::max(f.max_end_move, std::max((a - a0).norm(), (b - b0).norm()));
    const double free = free_move(terms, r.constraints, a, b, a0, b0);
    f.max_free_move = std::max(f.max_free_move, free);
    const bool demanded = length_demanded(r.constraints);
    if (!demanded) f.min_length_ratio = std::min(f.min_length_ratio, length / drawn);
    if (free > 1e-5 || (!demanded && length < 0.5 * drawn)) {  // described on failure only
      INFO("drawn " << a0.transpose() << " -> " << b0.transpose() << ", corrected "
                    << a.transpose() << " -> " << b.transpose() << "\n"
                    << enforced_list(r.constraints));
      CHECK(free <= 1e-5);
      CHECK((demanded || length >= 0.5 * drawn));
    }
  }
  return f;
}

}  // namespace

TEST_CASE("long random scaffold sessions: no collapsed or drifting lines and no NaN",
          "[scaffoldsketch]") {
  for (const bool midpoint : {true, false}) {
    ScaffoldParams params;
    params.midpoint_snapping = midpoint;
    const SessionFigures f = run_session(midpoint ? 11u : 12u, 250, params);
    INFO("midpoint snapping " << midpoint << ": " << f.lines << " lines, min length ratio "
                              << f.min_length_ratio << ", max end move " << f.max_end_move
                              << ", max move in free directions " << f.max_free_move);
    CHECK(f.lines > 150);
  }
}

TEST_CASE("long random scaffold sessions over many seeds", "[scaffoldsketch][slow]") {
  for (unsigned seed = 100; seed < 112; ++seed) {
    ScaffoldParams params;
    params.midpoint_snapping = seed % 2 == 0;
    const SessionFigures f = run_session(seed, 500, params);
    CHECK(f.lines > 300);
  }
}
