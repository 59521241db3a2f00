#pragma once
// Reads recordings (format: event_json.hpp). Every problem is an error naming
// the file and line; nothing is skipped.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "sketchlab/recording/recording.hpp"

namespace sketchlab {

// Throws RecordingError ("file:line: reason") for: a missing or unreadable
// file, an empty file, bad JSON, a wrong or missing format/version (naming the
// supported versions), an unknown event type (listing the allowed ones), a
// missing, unknown or mistyped field (naming it), non-finite or absurd
// numbers, an invalid stroke (no samples, fewer than 2, zero length), events
// out of time order, an empty line, and a last line without its newline
// ("truncated", as left by an interrupted write).
Recording read_recording(const std::filesystem::path& path);

// The same from a stream; `name` is used as the file name in errors.
Recording parse_recording(std::istream& in, const std::string& name);

}  // namespace sketchlab
