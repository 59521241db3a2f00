#pragma once
// CASSIE's curve graph, rebuilt while its own curves are replayed (CASSIE
// app, item 22): every stroke end is a node; where the new curve meets an
// alive curve it reuses a node of the new curve within 0.5δ, else a node of
// the old curve within δ, else a new node splits the old curve; a closed
// stroke is one node. CASSIE splits a Bézier stroke at each intersection it
// enforced (item 12), so the intersections of a replayed Bézier curve are its
// joints lying on an alive curve; a line is not split (item 17) and meets a
// curve at an end lying on it, or where it passes within 0.2δ of it (item
// 17: a node is made only when the constraint ends that close to the final
// line). Where CASSIE logged the stroke, its applied intersection
// constraints may decide the joints instead (logged_meets below).
#include <vector>

#include "sketchlab/edit.hpp"
#include "sketchlab/lab/cassie_import.hpp"
#include "sketchlab/network.hpp"

namespace sketchlab::soapfilm {

struct CassieGraphParams {
  double delta = 0.02;       // δ at zoom 1 (m); δ/s at zoom s
  // m: a joint this close to an alive curve lies on it. CASSIE solves in
  // single precision; the joints of its enforced intersections lie within
  // ~1e-4 m of the other curve, others farther (measured on the bundled
  // sessions, README.md).
  double on_curve = 1e-4;
  double line_meets = 0.2;   // ×δ: a line meets a curve passing this close (item 17)
  double reuse_old = 1.0;    // ×δ: reuse a node of the old curve this close (item 22)
  double reuse_new = 0.5;    // ×δ: reuse a node of the new curve this close (item 22)
  // Item 22 ("reuses a node within 0.5δ on the new stroke, within δ on the
  // old one"): where both exist, the new stroke's node is reused (as its
  // ends are: an end with a node of the new curve within 0.5δ gets no other);
  // unset, the old curve's (before the twelfth round; README.md).
  bool reuse_new_first = true;
  // A closed curve's seam stays a graph node when other curves split it
  // (CurveGraph's closed_seam_nodes; set from the surfacer's parameter).
  bool closed_seam_nodes = false;
  // Reuse also a node only a deleted curve made, left on an old curve as one
  // incidence inside it (not a graph node: curve_graph.hpp). Off, as CASSIE's
  // graph: its exported final graphs have a node where the curves meet, not
  // at such nodes (1,072 of their 1,076 nodes matched off, 957 on), and its
  // log never snaps an end onto one (README.md, "Fidelity"). On, over a graph
  // CASSIE did not have, creates as many (1,412) and keeps more to the end
  // (408 against 402 of 480).
  bool reuse_left_over = false;
  // ×δ, 0 = off. CASSIE's graph intersections are the intersection
  // constraints its solve applied (CASSIE app, items 21–22), but the solve
  // may leave the new end up to ~1 mm off the old curve (vintage_car,
  // README.md "Fidelity"). On a logged stroke (CassieCurve::log), a joint
  // (a line: an end) within this of a logged applied intersection meets the
  // alive curves that pass within logged_on_curve of its position and within
  // this of the joint, at their closest point to the joint.
  double logged_meets = 0.0;
  // m: a logged applied position lies on a curve passing this close (its
  // target; an older export's bare position, with no isIntersection flag,
  // counts as an intersection with such a curve).
  double logged_on_curve = 1e-4;
  // With logged_meets: a logged stroke's joint (a line's end or closest
  // point) near no logged applied intersection meets nothing, instead of
  // the on_curve (line_meets) test.
  bool logged_only = false;
};

// One curve of a replayed stroke.
struct CassieCurve {
  StrokeId stroke = 0;   // source_stroke of the network curve
  Curve curve;
  double scale = 1.0;    // zoom s > 0 when it was drawn
  // CASSIE's log of the stroke (a mirrored twin's: its twin's, reflected),
  // or null; not owned, read during cassie_graph_edit only.
  const CassieConstraintLog* log = nullptr;
};

// The edit adding `curves` to `network` in order (a stroke and its mirrored
// twin: each later one meets the earlier ones too), with CASSIE's nodes: one
// network curve each (ids from network.next_curve_id(), layer shape), new
// nodes and the existing nodes they reuse (as nodes_replaced). Throws
// std::invalid_argument for an invalid curve or scale.
Edit cassie_graph_edit(const Network& network, const std::vector<CassieCurve>& curves,
                       const CassieGraphParams& params = {});

}  // namespace sketchlab::soapfilm
