#pragma once
// The sketch file (DESIGN.md "Formats"): JSON with the workspace, curves (as
// control points, with layer, source stroke and keypoints), nodes, segments,
// patches (boundary and mesh; the mesh's vertex normals when it has them,
// e.g. a surfacer's shading, so a sketch read back draws as the one written),
// the raw strokes' ids, and the constraints each stroke's correction
// considered. Keys are written in a fixed order and numbers in shortest
// round-trip form, so equal sketches give equal bytes.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "sketchlab/session.hpp"
#include "sketchlab/sketch.hpp"

namespace sketchlab {

// `steps` (optional) adds each stroke's considered constraints.
std::string sketch_to_json(const Sketch& sketch, const std::vector<StepReport>* steps = nullptr);

// Reads a sketch file back (workspace and network; strokes and history are
// not stored). Throws std::runtime_error "file: field: reason" on bad input,
// including ids, versions and face indices that are not integers in range
// (1.5, -1, 1e300), faces naming vertices the mesh does not have and a
// normals list not one per vertex. A mesh without "normals" (files written
// before they were kept) reads with none.
Sketch read_sketch_json(const std::filesystem::path& file);
// The same from the file's text; `name` is used as the file name in errors.
Sketch parse_sketch_json(std::string_view text, const std::string& name);

}  // namespace sketchlab
