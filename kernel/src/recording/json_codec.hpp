#pragma once
// Kernel-private JSON conversions for the recording format (see
// sketchlab/recording/event_json.hpp). Writers produce ordered_json so keys
// come out in the documented order; readers take any json value and throw
// std::invalid_argument naming the field.
#include <nlohmann/json.hpp>
#include <string>

#include "sketchlab/curve.hpp"
#include "sketchlab/event.hpp"
#include "sketchlab/recording/event_json.hpp"
#include "sketchlab/view.hpp"
#include "sketchlab/workspace.hpp"

namespace sketchlab::json_codec {

using ojson = nlohmann::ordered_json;
using json = nlohmann::json;

inline constexpr double max_coordinate = recording_max_coordinate;  // metres or pixels
inline constexpr double max_time = recording_max_time;              // seconds

ojson to_json(const Vec3& v);
ojson to_json(const Workspace& ws);
ojson to_json(const Curve& curve);
ojson to_json(const View& view);
ojson to_json(const Stroke& stroke);  // fields only: id, layer, ..., samples
ojson to_json(const Event& event);
ojson to_json(const RecordingHeader& header);

// `what` names the value in error messages (e.g. "workspace").
Workspace workspace_from_json(const json& j, const std::string& what);
Curve curve_from_json(const json& j, const std::string& what);
View view_from_json(const json& j, const std::string& what);
Event event_from_json(const json& j);
RecordingHeader header_from_json(const json& j);

// Parses one line; bad JSON becomes std::invalid_argument("bad JSON: ...").
json parse_line(std::string_view line);

}  // namespace sketchlab::json_codec
