#pragma once
// Reading the CASSIE dataset's JSON files (Yu et al., CHI 2021; MIT): the
// pieces shared by the final-network loader (sketch_graph) and the session
// replay (sketch_history + raw_data). Every error names the file and the
// element ("<file>: stroke 12: piece 3 has 5 control points; need 4 or 2").
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "sketchlab/curve.hpp"

namespace sketchlab::soapfilm {

// A problem in one input file; what() names the file and the element.
struct CassieFormatError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses a whole file. Throws CassieFormatError "<file>: cannot open" or
// "<file>: <parser message>".
nlohmann::json read_cassie_json(const std::filesystem::path& path);

// item[key]; throws std::invalid_argument "<what>: missing field '<key>'".
const nlohmann::json& cassie_field(const nlohmann::json& item, const char* key, const std::string& what);

// [x, y, z] (array form) or {x, y, z} (object form, raw_data) as a point;
// throws std::invalid_argument naming `what` for another shape, a
// non-finite coordinate or one beyond recording_max_coordinate (1e6 m).
Vec3 cassie_point(const nlohmann::json& value, const std::string& what);

// Appends CASSIE pieces (cubic: 4 points; line: 2 points, stored as a cubic
// with inner points at thirds like the kernel's lines) to `curve`, which may
// already hold pieces: the first point of the pieces then replaces nothing
// and must be the curve's last point. Throws std::invalid_argument naming
// `what` and the piece index for a piece of another size.
void append_cassie_pieces(Curve& curve, const nlohmann::json& pieces, const std::string& what);

// Sets the sharp flags (none) and closes the curve when its ends coincide
// within `tolerance` m (the end point is then made equal to the start).
void finish_cassie_curve(Curve& curve, double tolerance = 1e-6);

}  // namespace sketchlab::soapfilm
