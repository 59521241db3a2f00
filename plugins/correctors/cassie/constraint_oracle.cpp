#include "constraint_oracle.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "sketchlab/geometry/closest_point.hpp"
#include "sketchlab/io/text_file.hpp"

namespace sketchlab::cassie {

ConstraintOracle read_constraint_oracle(const std::filesystem::path& file) {
  std::istringstream in(read_text_file(file));
  ConstraintOracle out;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const auto fail = [&](const std::string& what) {
      throw std::runtime_error(file.string() + ":" + std::to_string(line_no) + ": " + what +
                               " (expected: stroke id >= 0, then x y z in metres per applied target)");
    };
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    std::string id_text;
    if (!(fields >> id_text)) continue;
    std::size_t used = 0;
    long long id = -1;
    try {
      id = std::stoll(id_text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != id_text.size() || id < 0) fail("stroke id '" + id_text + "' is not an integer >= 0");
    std::vector<double> numbers;
    for (std::string x; fields >> x;) {
      double v = 0.0;
      try {
        v = std::stod(x, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != x.size() || !std::isfinite(v)) fail("coordinate '" + x + "' is not a finite number");
      numbers.push_back(v);
    }
    if (numbers.size() % 3 != 0) fail(std::to_string(numbers.size()) + " coordinates, not a multiple of 3");
    std::vector<Vec3> targets;
    for (std::size_t i = 0; i < numbers.size(); i += 3)
      targets.emplace_back(numbers[i], numbers[i + 1], numbers[i + 2]);
    if (!out.emplace(static_cast<StrokeId>(id), std::move(targets)).second)
      fail("stroke " + id_text + " is listed twice");
  }
  return out;
}

std::vector<bool> oracle_matches(const std::vector<Candidate>& constraints, const std::vector<Vec3>& applied,
                                 double radius) {
  std::vector<bool> out(constraints.size(), false);
  for (const Vec3& a : applied) {
    std::size_t nearest = constraints.size();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < constraints.size(); ++i)
      if (const double d = (constraints[i].target - a).norm(); d <= radius && d < best) best = d, nearest = i;
    if (nearest < constraints.size()) out[nearest] = true;
  }
  return out;
}

void take_oracle_positions(std::vector<Candidate>& constraints, const std::vector<Vec3>& applied, double radius,
                           const Network& network) {
  std::vector<const Vec3*> taken(constraints.size(), nullptr);
  for (const Vec3& a : applied) {
    const std::vector<bool> one = oracle_matches(constraints, {a}, radius);
    for (std::size_t i = 0; i < one.size(); ++i)
      if (one[i]) taken[i] = &a;
  }
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    if (!taken[i]) continue;
    Candidate& c = constraints[i];
    c.target = *taken[i];
    if (c.kind == TargetKind::curve) c.t_curve = closest_point(network.curves().at(c.curve).curve, c.target).t;
  }
}

}  // namespace sketchlab::cassie
