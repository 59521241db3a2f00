#pragma once
// A reference system's own constraint decisions, to restrict the search to
// them (issue #15: how much of the gap to CASSIE is which constraints are
// chosen, and how much is the geometry of the curve given the same choice).
// With the `oracle` parameter, a stroke listed in the file skips item 15's
// greedy search: for each target the reference applied, the constraint we
// detect nearest to it, if within `oracle_radius`·δ(s), is enforced; the
// others are rejected. Strokes the file does not list are searched as usual.
#include <filesystem>
#include <map>
#include <vector>

#include "constraint_types.hpp"
#include "sketchlab/network.hpp"
#include "sketchlab/types.hpp"

namespace sketchlab::cassie {

// Per stroke id, the targets (m, world) of the position constraints the
// reference applied; an empty list means it applied none.
using ConstraintOracle = std::map<StrokeId, std::vector<Vec3>>;

// Reads an oracle file: UTF-8 text, one stroke per line, `#` starts a
// comment, blank lines are skipped; a line is the stroke id (integer >= 0)
// followed by 3·k finite numbers, the k applied targets' x y z in metres
// (k >= 0). `sketchlab fidelity --cassie-subset` writes one from CASSIE's
// raw_data logs. Throws std::runtime_error naming the file and the line for
// a missing file, a bad stroke id, a stroke listed twice, a coordinate that
// is not a finite number or a count of numbers not a multiple of 3.
ConstraintOracle read_constraint_oracle(const std::filesystem::path& file);

// Per constraint: whether it is the one nearest to one of the `applied`
// targets (ties: the first) and within `radius` (m) of it. Nearest, not every
// one within the radius: targets the reference rejected lie near ones it
// applied (73 of our 950 study targets are within δ/2 of both).
std::vector<bool> oracle_matches(const std::vector<Candidate>& constraints, const std::vector<Vec3>& applied,
                                 double radius);

// With `oracle_positions`: each matched constraint (oracle_matches) takes
// the position of the applied target it matched, and a curve target its
// parameter there on the curve of `network` it lies on (closest point), so
// that what still differs is the curve, not where items 7-8 put the target.
void take_oracle_positions(std::vector<Candidate>& constraints, const std::vector<Vec3>& applied, double radius,
                           const Network& network);

}  // namespace sketchlab::cassie
