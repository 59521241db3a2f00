#pragma once
// The edit between two states of one network, for correctors that build
// their result on a copy (JustDrawIt folds back blended strokes and redoes
// them) and hand the kernel an ordinary edit.
#include "sketchlab/edit.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab {

// The edit turning `from` into `to`, comparing items by id (both networks
// must share one id space, e.g. `to` folded from a copy of `from`):
//  - curves and nodes only in `to` are added, those in both that differ are
//    replaced, those only in `from` are removed; a node of both whose every
//    incidence in `from` is on a removed curve is added (apply drops such a
//    node when it removes the curves, before it replaces nodes);
//  - patches that differ or exist in one network only are removed (from
//    `from`) and added (from `to`): a patch has no replacement;
//  - counters are left unset (Network::apply advances them past the ids
//    added).
// Each list is in ascending id order. from.apply(edit_between(from, to))
// leaves from.curves(), nodes() and patches() equal to `to`'s; the edit is
// empty() when they are equal already. Never throws.
Edit edit_between(const Network& from, const Network& to);

}  // namespace sketchlab
