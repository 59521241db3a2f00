#pragma once
// Reads recordings (format: event_json.hpp). Every problem is an error naming
// the file and line, except the one an interrupted write leaves: a last line
// without its terminating newline.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "sketchlab/recording/recording.hpp"

namespace sketchlab {

struct RecordingReadOptions {
  // A last line without its newline is what a writer killed mid-line (or a
  // full disk) leaves. By default it is reported through warn() (io/warning.hpp)
  // with file:line and skipped, every earlier event read; when it is a
  // complete event that only lacks the newline it is kept. true: refuse the
  // file instead (RecordingError "truncated").
  bool refuse_truncated = false;
};

// Throws RecordingError ("file:line: reason") for: a missing or unreadable
// file, an empty file, bad JSON, a wrong or missing format/version (naming the
// supported versions), an unknown event type (listing the allowed ones), a
// missing, unknown or mistyped field (naming it), non-finite or absurd
// numbers, an invalid stroke (no samples, fewer than 2, zero length, sample
// times decreasing), events out of time order, an empty line, a header line
// without its newline, and (with refuse_truncated) a last line without it.
Recording read_recording(const std::filesystem::path& path, const RecordingReadOptions& options = {});

// The same from a stream; `name` is used as the file name in errors.
Recording parse_recording(std::istream& in, const std::string& name,
                          const RecordingReadOptions& options = {});

}  // namespace sketchlab
