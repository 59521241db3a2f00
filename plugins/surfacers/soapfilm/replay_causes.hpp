#pragma once
// Why the replay of a CASSIE session (cassie_replay.hpp) disagrees with
// CASSIE's patch log: each CASSIE automatic patch we did not create at its
// event, each one alive in CASSIE's log at the end but not ours, and each of
// our patches CASSIE did not make, is given one cause. The counts are what
// the README's breakdown table prints (soapfilm_compare).
#include <map>
#include <optional>

#include "cassie_session.hpp"
#include "cycle_search.hpp"

namespace sketchlab::soapfilm {

// A CASSIE automatic patch missing at the end of the event group where
// CASSIE made it, seen on our network at that moment (checked in this order).
enum class MissingCycle {
  curve_absent,  // one of its strokes has no curve in our network
  not_closed,    // its curves' graph segments hold no closed path through every one of its strokes (a node is missing)
  not_found,     // they do, but no walk from any graph segment of its curves closes over exactly its strokes (item 24's walk)
  refused_two,   // a walk closes over it, but one of its segments already bounds two patches (item 24)
  not_searched,  // a walk closes over it and nothing refuses it: the upkeep never walked from there, or its mesh failed
};

// Where the walks over a cycle they do not close (not_found) go astray. The
// cycles CASSIE may have walked are the node-simple cycles of the patch's
// curves through every one of its strokes (if there is none, the closed
// walks through them using each segment once); of our walks (two from each
// of their segments, item 25), the one following such a cycle longest from
// its start leaves it at a node of this kind (checked in this order).
enum class Departure {
  none,
  near_tie,         // the segment taken and the cycle's leave within tie_cos of each other (item 23's tie)
  at_two,           // a two-segment node
  at_undefined,     // a node with no fitted plane
  at_sharp,         // a sharp node (item 23)
  at_crossing,      // a smooth node whose fitted normal is more than 60° (as lines) from the normal carried
                    // there: item 24's |cos| < 0.5 case, where the app turns in the carried normal's plane
  at_smooth,        // another smooth node
  no_start,         // no walk starts along any of them (their segments' start nodes have no fitted plane)
  no_cycle,         // no closed walk over its curves' segments passes through every one of its strokes
};

// The node where the walk leaves the cycle (Departure), for tracing a case.
struct AstrayDetail {
  Departure where = Departure::none;
  NodeId node = 0;
  Vec3 position = Vec3::Zero();
  int segments = 0;            // graph segments at the node
  double max_offset = 0.0;     // item 23's max |n·t| there
  double agreement = 0.0;      // carried normal · fitted normal (unit; 0 where either is missing)
  std::optional<CurveId> taken, wanted;  // the curves of the segment taken (none: the walk stopped) and of the cycle's next one
  double apart = 0.0;  // rad between the tangents leaving the node along those two (0 when the walk stopped)
  int followed = 0, length = 0;   // segments of the cycle the walk followed, and its length
};

// Classifies a missing CASSIE patch over `strokes` on `network`, whose curve
// of each CASSIE stroke id is `curve_of` (stroke ids absent there, or curves
// no longer in the network, are absent). Walks two ways from every graph
// segment of the patch's curves with `params` (CycleSearcher::search_segment).
// For not_found, `astray` (when given) receives where the walks leave.
MissingCycle classify_missing(const Network& network, const std::map<std::int64_t, CurveId>& curve_of,
                              const StrokeSet& strokes, const CycleSearchParams& params,
                              AstrayDetail* astray = nullptr);

struct ReplayCauses {
  // CASSIE patches not created at their event (sum = cassie_created - matched_created).
  int miss_elsewhere = 0;  // we created the same strokes at another event
  int miss_curve_absent = 0, miss_not_closed = 0, miss_not_found = 0, miss_refused_two = 0, miss_not_searched = 0;
  // Our patches CASSIE did not create at that event (sum = ours_created - matched_created).
  int extra_elsewhere = 0;  // CASSIE made the same strokes automatically at another event
  int extra_by_hand = 0;    // CASSIE's user added a patch over the same strokes by hand (foundByAlgo false)
  int extra_other = 0;
  // CASSIE patches alive in its log at the end but not ours (sum = cassie_final - matched_final).
  int end_removed_by_crossing = 0;  // we created it; a later stroke broke it (item 25), CASSIE not (cassie_breaks.hpp)
  int end_removed_other = 0;        // we created it; a curve deletion or the user's patch deletion removed it
  int end_never_created = 0;
  // Ours alive at the end that are not in CASSIE's final set (sum = ours_final - matched_final).
  int end_extra_by_hand = 0;  // CASSIE's user added it by hand
  int end_extra_cassie_gone = 0;  // CASSIE made it automatically, but the user deleted it or a stroke of it is gone
  int end_extra_other = 0;
  // miss_not_found by where the walks go astray (Departure).
  int astray_near_tie = 0, astray_at_two = 0, astray_at_undefined = 0, astray_at_sharp = 0, astray_at_crossing = 0,
      astray_at_smooth = 0, astray_no_start = 0, astray_no_cycle = 0;
  int missed_created() const {
    return miss_elsewhere + miss_curve_absent + miss_not_closed + miss_not_found + miss_refused_two + miss_not_searched;
  }
  int extra_created() const { return extra_elsewhere + extra_by_hand + extra_other; }
  int missed_end() const { return end_removed_by_crossing + end_removed_other + end_never_created; }
  int extra_end() const { return end_extra_by_hand + end_extra_cassie_gone + end_extra_other; }
  ReplayCauses& operator+=(const ReplayCauses& o);
};

}  // namespace sketchlab::soapfilm
