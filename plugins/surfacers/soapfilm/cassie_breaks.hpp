#pragma once
// CASSIE's automatic patch deletions, inferred from its patch log. The app
// deletes a patch a new stroke crosses (CASSIE app, items 25 and 27) and
// searches the broken cycle again first, but raw_data logs only creations
// and the user's own deletions. A split leaves a signature in the log: at
// the crossing stroke's event CASSIE creates the halves, each over that
// event's new stroke(s) and some of the broken patch's strokes, and together
// they use all of them. Without this, CASSIE's "alive at the end" set keeps
// every broken patch (its strokes are all still there).
#include <cstdint>
#include <map>

#include "cassie_session.hpp"

namespace sketchlab::soapfilm {

// Automatic patch id -> time of the stroke event that broke it: the first
// event after the patch's creation at which CASSIE created at least two
// automatic patches that each hold a stroke created at that event and whose
// other strokes (non-empty) are the patch's, and together are all of them.
// Events are grouped as in the replay: a patch logged at time t belongs to
// the last stroke creation or deletion at or before t (+0.1 ms). Patches
// CASSIE split without making two halves (it found one, or none) are not
// inferred: the set is a lower bound.
std::map<std::int64_t, double> inferred_breaks(const CassieSession& session);

}  // namespace sketchlab::soapfilm
