#pragma once
// The recording format: JSON Lines, one JSON object per line, '\n' after every
// line (including the last). Units: metres (or pixels for 2D strokes) and
// seconds. Keys are written in the order shown; doubles are written in the
// shortest form that reads back to the same double, so read-then-write
// reproduces a file byte for byte.
//
// Line 1, the header:
//   {"format":"sketchlab-recording","version":1,"units":"m"|"px",
//    "workspace":WORKSPACE,"source":{"key":"value",...}}
// Every other line is one event, "t" (seconds since the session started, >= 0,
// non-decreasing along the file) and "type" first, then the payload:
//   stroke        "id":uint,"layer":"scaffold"|"shape"|"free"|"guide"|"auto",
//                 "workspace_scale":s>0,["pixels":true,]["view":VIEW,]
//                 "samples":[[x,y,z,t,pressure],...]
//                 A sample has 5 numbers, or 9 when its orientation is not the
//                 identity: [x,y,z,t,pressure,qw,qx,qy,qz] (unit quaternion).
//                 "pixels" (samples are pixels of "view") is written only when
//                 true, "view" only when present. At least 2 samples, not all
//                 at one position, finite, pressure in [0,1].
//   undo, redo    (no payload)
//   delete_near   "point":[x,y,z],"radius":r>0
//   delete_stroke "stroke":uint
//   mode          "mode":layer name
//   workspace     "workspace":WORKSPACE
//   correction    "enabled":bool
//   add_patch     "point":[x,y,z]
//   delete_patch  "point":[x,y,z]
//   reference     "stroke":uint,"track":string,"curve":CURVE
//   relation      "track":string,"kind":constraint kind name (constraint.hpp),
//                 "strokes":[uint,...] (at least 1),"parameters":[t,...]
//                 (curve parameters on the strokes' reference curves; may be
//                 empty)
// WORKSPACE = {"up":[x,y,z],"grid_enabled":bool,"grid_spacing":s>0,
//              "grid_origin":[x,y,z],"mirror_enabled":bool,
//              "mirror_normal":[x,y,z],"mirror_offset":d,"scale":s>0}
// CURVE     = {"kind":"bezier"|"line","points":[[x,y,z],...] (3K+1),
//              "sharp":[bool,...] (K+1),"closed":bool}
// VIEW      = {"view":[[4 numbers] x 4 rows],"projection":[[4] x 4 rows],
//              "viewport":[x,y,width,height],"dpi":d>0}
//
// Readers reject (never skip) anything else: unknown or missing fields,
// mistyped or non-finite numbers (JSON has no NaN; null or strings in numeric
// fields are errors), absurd magnitudes (coordinates beyond 1e6, times beyond
// 1e9 s), unknown event types.
#include <string>
#include <string_view>

#include "sketchlab/event.hpp"

namespace sketchlab {

// The format's bounds on magnitudes: coordinates (metres or pixels) and
// times (seconds). Sessions refuse strokes beyond them too, whoever made them.
inline constexpr double recording_max_coordinate = 1e6;
inline constexpr double recording_max_time = 1e9;

// One line (without the trailing '\n'). Throws std::invalid_argument with the
// reason when the event could not be read back (non-finite or absurd values,
// an invalid stroke or curve), so nothing unreadable is ever written.
std::string to_json_line(const Event& event);
std::string to_json_line(const RecordingHeader& header);

// Parse one line. Throw std::invalid_argument with the reason (no location;
// the recording reader adds "file:line:").
Event event_from_json_line(std::string_view line);
RecordingHeader header_from_json_line(std::string_view line);

}  // namespace sketchlab
