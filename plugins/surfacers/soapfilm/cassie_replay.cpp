#include "cassie_replay.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "cassie_breaks.hpp"
#include "patch_upkeep.hpp"
#include "sketchlab/geometry/bezier.hpp"
#include "sketchlab/session.hpp"
#include "timed_soapfilm.hpp"

namespace sketchlab::soapfilm {
namespace {

// What the replay knows of each curve it added.
struct Curves {
  std::map<CurveId, std::int64_t> cassie_of;  // network curve -> CASSIE stroke
  std::map<std::int64_t, CurveId> curve_of;   // and back
};

// Adds the CASSIE curves of one action (a stroke and its mirrored twin) with
// CASSIE's graph; the session sees one stroke, whose id they all carry.
class CassieCurves : public Corrector {
 public:
  CassieCurves(const CassieSession& session, const CassieGraphParams& params, Curves& curves)
      : session_(&session), params_(params), curves_(&curves) {}
  // The strokes (indices into session.strokes) the next StrokeEvent adds.
  void next(std::vector<std::size_t> strokes) { next_ = std::move(strokes); }
  Correction correct(const Stroke& stroke, const Sketch& sketch) override {
    Correction c;
    std::vector<CassieCurve> in;
    for (std::size_t i : next_) {
      const CassieStroke& s = session_->strokes[i];
      const auto log = session_->logs.find(static_cast<StrokeId>(s.id));
      in.push_back({stroke.id, s.curve, s.canvas_scale, log == session_->logs.end() ? nullptr : &log->second});
    }
    try {
      c.edit = cassie_graph_edit(sketch.network, in, params_);
      for (std::size_t k = 0; k < next_.size(); ++k) {
        const std::int64_t id = session_->strokes[next_[k]].id;
        curves_->cassie_of[c.edit.curves_added[k].id] = id;
        curves_->curve_of[id] = c.edit.curves_added[k].id;
      }
    } catch (const std::exception& e) {
      c.error = e.what();
    }
    return c;
  }

 private:
  const CassieSession* session_;
  CassieGraphParams params_;
  Curves* curves_;
  std::vector<std::size_t> next_;
};

struct Step {
  double time = 0.0;
  int order = 0;  // at one time: stroke creations, deletions, then patch edits
  std::string kind;
  std::vector<std::size_t> index;  // into session.strokes (all created or deleted at `time`) or patches (one)
};

StrokeSet strokes_of(const Curves& curves, const Patch& p) {
  StrokeSet out;
  for (const OrientedSegment& piece : p.boundary) out.insert(curves.cassie_of.at(piece.curve));
  return out;
}

// A point on the patch (its first triangle's centroid), for a
// DeletePatchEvent that must pick exactly this patch.
std::optional<Vec3> point_on(const Patch& p) {
  if (p.mesh.faces.empty()) return std::nullopt;
  const auto& f = p.mesh.faces.front();
  return (p.mesh.vertices[f[0]] + p.mesh.vertices[f[1]] + p.mesh.vertices[f[2]]) / 3.0;
}

// `base` completed with what the cycle is on our graph (ExtraPatch);
// `graph` and `searcher` are over the network the patch was made on.
ExtraPatch describe(CurveGraph& graph, CycleSearcher& searcher, const Patch& p, ExtraPatch base) {
  std::map<NodeId, int> ends;  // segment ends of the cycle at each node
  for (int s : boundary_key(graph, p.boundary)) {
    ++base.pieces;
    ++ends[graph.segment(s).node0];
    ++ends[graph.segment(s).node1];
  }
  for (const auto& [node, k] : ends) {
    base.sharp_nodes += searcher.frame(node).sharp ? 1 : 0;
    base.revisited += k > 2 ? 1 : 0;
    base.max_degree = std::max(base.max_degree, static_cast<int>(graph.outgoing(node).size()));
  }
  return base;
}

// TimingPair: for each stroke set created unmatched on both sides, the
// creations paired in time order.
std::vector<TimingPair> timing_pairs(const CassieSession& session, const std::vector<ReplayEvent>& events,
                                     const std::map<PatchId, ExtraPatch>& made,
                                     const std::map<std::pair<std::size_t, StrokeSet>, int>& cassie_at,
                                     const std::map<std::pair<std::size_t, StrokeSet>, int>& ours_at) {
  std::map<StrokeSet, std::vector<std::size_t>> cassie_left, ours_left;
  auto unmatched = [](const auto& from, const auto& other, auto& into) {
    for (const auto& [key, n] : from) {
      const auto o = other.find(key);
      for (int k = o == other.end() ? 0 : o->second; k < n; ++k) into[key.second].push_back(key.first);
    }
  };
  unmatched(cassie_at, ours_at, cassie_left);
  unmatched(ours_at, cassie_at, ours_left);
  std::map<std::size_t, const ReplayEvent*> opening;  // group -> its stroke or delete event
  for (const ReplayEvent& e : events)
    if ((e.kind == "stroke" || e.kind == "delete") && !opening.count(e.group)) opening[e.group] = &e;
  std::map<std::int64_t, const CassieStroke*> stroke;
  for (const CassieStroke& s : session.strokes) stroke[s.id] = &s;
  std::map<double, std::size_t> stroke_group;  // a stroke event's time -> its group
  for (const ReplayEvent& e : events)
    if (e.kind == "stroke") stroke_group.emplace(e.time, e.group);
  std::set<StrokeSet> cassie_ever, ours_ever, keys;
  for (const auto& [key, n] : cassie_at) cassie_ever.insert(key.second);
  for (const auto& [key, n] : ours_at) ours_ever.insert(key.second);
  for (const auto& [strokes, g] : cassie_left)
    if (ours_ever.count(strokes)) keys.insert(strokes);
  for (const auto& [strokes, g] : ours_left)
    if (cassie_ever.count(strokes)) keys.insert(strokes);
  std::vector<TimingPair> out;
  for (const StrokeSet& strokes : keys) {
    const std::vector<std::size_t> theirs = cassie_left[strokes], mine = ours_left[strokes];
    TimingPair base;
    base.strokes = strokes;
    for (std::int64_t s : strokes)
      if (stroke.count(s) && (!stroke.count(base.youngest) || stroke[s]->created > stroke[base.youngest]->created))
        base.youngest = s;
    if (stroke.count(base.youngest) && stroke_group.count(stroke[base.youngest]->created))
      base.youngest_group = stroke_group[stroke[base.youngest]->created];
    for (std::size_t k = 0; k < std::max(theirs.size(), mine.size()); ++k) {
      TimingPair p = base;
      if (k < theirs.size()) p.cassie = theirs[k];
      if (k < mine.size()) p.ours = mine[k];
      if (p.cassie) {
        const std::size_t g = *p.cassie;
        if (const auto e = opening.find(g); e != opening.end()) {
          const ReplayEvent& ev = *e->second;
          StrokeSet own;
          for (const CassieStroke& s : session.strokes)
            if (s.created == ev.time) own.insert(s.id);
          const bool in_cycle = std::any_of(own.begin(), own.end(), [&](std::int64_t s) { return strokes.count(s); });
          p.met_at_cassie = !in_cycle && std::any_of(ev.met.begin(), ev.met.end(), [&](std::int64_t s) {
            return strokes.count(s) && !own.count(s);
          });
        }
        for (const auto& [id, x] : made)
          if (x.strokes == strokes && x.group < g && (!x.removed_at || *x.removed_at >= g)) p.ours_alive_at_cassie = true;
        for (const auto& [id, x] : made)
          if (x.strokes == strokes && x.removed_at == g) p.ours_removed_at_cassie = true;
        for (const auto& [key, n] : cassie_at)
          if (key.second == strokes && key.first < g) p.cassie_made_before = true;
        p.ours_same_event = ours_at.count({g, strokes}) > 0;
      }
      if (p.ours)
        for (const auto& [id, x] : made)
          if (x.strokes == strokes && x.group < *p.ours && x.removed_at && *x.removed_at <= *p.ours &&
              opening.count(*x.removed_at) &&
              opening[*x.removed_at]->kind == "stroke")
            p.ours_broken_before = true;
      out.push_back(std::move(p));
    }
  }
  return out;
}

}  // namespace

Stroke placeholder_stroke(StrokeId id) {
  Stroke s;
  s.id = id;
  Sample a, b;
  b.position = Vec3(0.01, 0.0, 0.0);
  b.time = 0.1;
  s.samples = {a, b};
  return s;
}

ReplayFigures& ReplayFigures::operator+=(const ReplayFigures& o) {
  cassie_created += o.cassie_created;
  ours_created += o.ours_created;
  matched_created += o.matched_created;
  matched_elsewhere += o.matched_elsewhere;
  ours_removed += o.ours_removed;
  cassie_broken += o.cassie_broken;
  matched_broken += o.matched_broken;
  cassie_final += o.cassie_final;
  rebuilt_ours += o.rebuilt_ours;
  rebuilt_found += o.rebuilt_found;
  ours_final += o.ours_final;
  matched_final += o.matched_final;
  causes += o.causes;
  return *this;
}

ReplayResult replay_cassie_session(const CassieSession& session, const SoapfilmParams& params,
                                   const ReplayOptions& options) {
  ReplayResult result;
  result.warnings = session.warnings;

  // Strokes created (deleted) at one time are one action: a stroke and its
  // mirrored twin, as CASSIE adds (removes) them.
  std::vector<Step> steps;
  std::map<double, std::vector<std::size_t>> created, deleted;
  for (std::size_t i = 0; i < session.strokes.size(); ++i) {
    const CassieStroke& s = session.strokes[i];
    created[s.created].push_back(i);
    if (s.deleted) deleted[*s.deleted].push_back(i);
  }
  for (const auto& [t, list] : created) steps.push_back({t, 0, "stroke", list});
  for (const auto& [t, list] : deleted) steps.push_back({t, 1, "delete", list});
  if (options.user_patch_edits)
    for (std::size_t i = 0; i < session.patches.size(); ++i) {
      const CassiePatch& p = session.patches[i];
      if (!p.automatic && p.created && p.hand) steps.push_back({*p.created, 2, "add_patch", {i}});
      if (p.deleted_by_hand) steps.push_back({*p.deleted_by_hand, 3, "delete_patch", {i}});
    }
  std::stable_sort(steps.begin(), steps.end(), [](const Step& a, const Step& b) {
    return a.time != b.time ? a.time < b.time : a.order < b.order;
  });

  // A group: a stroke event and the patch edits up to the next one. A CASSIE
  // automatic patch belongs to the last group at or before its time.
  std::vector<double> group_times;
  for (const Step& st : steps)
    if (st.kind == "stroke" || st.kind == "delete") group_times.push_back(st.time);
  auto group_of = [&](double t) -> std::optional<std::size_t> {
    auto it = std::upper_bound(group_times.begin(), group_times.end(), t + 1e-4);
    if (it == group_times.begin()) return std::nullopt;
    return static_cast<std::size_t>(it - group_times.begin() - 1);
  };
  std::map<std::pair<std::size_t, StrokeSet>, int> cassie_at, ours_at;
  for (const CassiePatch& p : session.patches)
    if (p.automatic && p.created)
      if (const auto g = group_of(*p.created)) ++cassie_at[{*g, p.strokes}];
  // CASSIE's patches missed at their group, classified on our network as it
  // is when the group ends; and how each of ours was last removed.
  struct Missing {
    StrokeSet strokes;
    MissingCycle why;
    AstrayDetail astray;
    std::size_t group;
  };
  std::vector<Missing> missing;
  std::map<StrokeSet, std::string> removed_by;

  auto surfacer = std::make_shared<TimedSoapfilm>(params);
  Curves curves;
  CassieGraphParams graph_params = options.graph;
  graph_params.closed_seam_nodes = params.search.closed_seam_nodes;
  auto corrector = std::make_shared<CassieCurves>(session, graph_params, curves);
  Session live(Workspace{}, corrector, surfacer);
  std::map<PatchId, StrokeSet> ours;          // our alive patches -> strokes
  std::map<PatchId, bool> automatic;
  std::map<std::int64_t, PatchId> of_cassie;  // CASSIE manual patch -> ours made for it
  std::map<std::int64_t, StrokeId> action_of;  // CASSIE stroke -> the session stroke that added it
  std::map<PatchId, ExtraPatch> made;          // each automatic patch of ours as made (for extras)
  StrokeId next_stroke = 1;
  std::size_t groups_seen = 0;

  for (std::size_t step = 0; step < steps.size(); ++step) {
    const Step& st = steps[step];
    ReplayEvent ev;
    ev.kind = st.kind;
    ev.time = st.time;
    const bool stroke_event = st.kind == "stroke" || st.kind == "delete";
    if (stroke_event) {
      ev.element = session.strokes[st.index.front()].id;
      ++groups_seen;
    } else {
      ev.element = session.patches[st.index.front()].id;
    }
    ev.group = groups_seen == 0 ? 0 : groups_seen - 1;

    StepReport report;
    if (st.kind == "stroke") {
      const StrokeId id = next_stroke++;
      for (std::size_t i : st.index) action_of[session.strokes[i].id] = id;
      corrector->next(st.index);
      report = live.handle(Event{st.time, StrokeEvent{placeholder_stroke(id)}});
    } else if (st.kind == "delete") {
      // Whole actions by their session stroke; a twin deleted alone by a
      // point on it.
      std::map<StrokeId, int> left;
      for (const auto& [cassie, id] : action_of)
        if (curves.curve_of.count(cassie) && live.sketch().network.find_curve(curves.curve_of.at(cassie))) ++left[id];
      std::map<StrokeId, std::vector<std::int64_t>> asked;
      for (std::size_t i : st.index) asked[action_of[session.strokes[i].id]].push_back(session.strokes[i].id);
      for (const auto& [id, list] : asked) {
        if (static_cast<int>(list.size()) == left[id]) {
          report = live.handle(Event{st.time, DeleteStrokeEvent{id}});
        } else {
          for (std::int64_t cassie : list) {
            const CurveId c = curves.curve_of.at(cassie);
            const NetworkCurve* nc = live.sketch().network.find_curve(c);
            if (!nc) continue;
            report = live.handle(Event{st.time, DeleteNearEvent{evaluate(nc->curve, 0.5 * nc->curve.t_max()), 1e-9}});
            if (live.sketch().network.find_curve(c))
              result.warnings.push_back(session.name + ": stroke " + std::to_string(cassie) +
                                        " lies on another curve and could not be deleted alone");
          }
        }
        if (!report.error.empty()) ev.error = report.error;
      }
    } else if (st.kind == "add_patch") {
      report = live.handle(Event{st.time, AddPatchEvent{*session.patches[st.index.front()].hand}});
    } else {
      // The user deleted a CASSIE patch: delete ours over the same strokes
      // (the one made for it if it was a manual one).
      const CassiePatch& cp = session.patches[st.index.front()];
      std::optional<PatchId> target;
      if (auto it = of_cassie.find(cp.id); it != of_cassie.end() && ours.count(it->second)) target = it->second;
      for (const auto& [id, strokes] : ours)
        if (!target && strokes == cp.strokes) target = id;
      if (!target) {
        ev.error = "no patch of ours over the strokes of CASSIE patch " + std::to_string(cp.id);
      } else {
        const Patch& p = live.sketch().network.patches().at(*target);
        if (const auto at = point_on(p); at)
          report = live.handle(Event{st.time, DeletePatchEvent{*at}});
        else
          ev.error = "patch " + std::to_string(*target) + " has no mesh to point at";
      }
    }
    if (ev.error.empty()) ev.error = report.error;
    SurfacerCost cost = surfacer->take();
    ev.surfacer_wall_ms = cost.wall_ms;
    ev.surfacer_cpu_ms = cost.cpu_ms;
    ev.patches_meshed = static_cast<int>(cost.meshed.size());
    ev.meshed = std::move(cost.meshed);

    // What changed: patch ids are never reused, so a diff of the id sets.
    const Network& net = live.sketch().network;
    if (st.kind == "stroke" && report.error.empty() && !live.sketch().history.done.empty())
      for (const HistoryStep& h : live.sketch().history.done.back().steps)
        for (const auto* list : {&h.forward.nodes_added, &h.forward.nodes_replaced})
          for (const Node& n : *list)
            for (const NodeIncidence& inc : n.incidences)
              if (const auto it = curves.cassie_of.find(inc.curve); it != curves.cassie_of.end())
                ev.met.insert(it->second);
    for (auto it = ours.begin(); it != ours.end();) {
      if (net.patches().count(it->first)) {
        ++it;
        continue;
      }
      if (automatic[it->first]) {
        ev.removed.push_back(it->second);
        removed_by[it->second] = st.kind;
        ++result.figures.ours_removed;
        made[it->first].removed_at = ev.group;
      }
      it = ours.erase(it);
    }
    const PatchId first_new = ours.empty() ? 0 : ours.rbegin()->first + 1;
    std::optional<CurveGraph> graph;  // built once, if this step made an automatic patch
    std::optional<CycleSearcher> searcher;
    for (auto it = net.patches().lower_bound(first_new); it != net.patches().end(); ++it) {
      if (ours.count(it->first)) continue;
      const StrokeSet strokes = strokes_of(curves, it->second);
      ours[it->first] = strokes;
      automatic[it->first] = it->second.automatic;
      if (it->second.automatic) {
        ev.added.push_back(strokes);
        ++ours_at[{ev.group, strokes}];
        if (!graph) searcher.emplace(graph.emplace(net), params.search);
        ExtraPatch& x = made[it->first] =
            describe(*graph, *searcher, it->second, {ev.group, st.time, st.kind, ev.element, strokes});
        x.broken_here = static_cast<int>(ev.removed.size());
      } else if (st.kind == "add_patch") {
        of_cassie[ev.element] = it->first;
      }
    }
    const bool group_ends = step + 1 == steps.size() || steps[step + 1].kind == "stroke" ||
                            steps[step + 1].kind == "delete";
    if (groups_seen > 0 && group_ends)
      for (auto it = cassie_at.lower_bound({ev.group, StrokeSet{}}); it != cassie_at.end() && it->first.first == ev.group;
           ++it) {
        const auto o = ours_at.find(it->first);
        const int unmatched = it->second - std::min(it->second, o == ours_at.end() ? 0 : o->second);
        if (unmatched == 0) continue;
        AstrayDetail astray;
        const MissingCycle why = classify_missing(net, curves.curve_of, it->first.second, params.search, &astray);
        for (int k = 0; k < unmatched; ++k) missing.push_back({it->first.second, why, astray, ev.group});
      }
    result.events.push_back(std::move(ev));
  }

  // Along the way.
  std::set<StrokeSet> ours_ever;
  for (const ReplayEvent& e : result.events)
    for (const StrokeSet& s : e.added) {
      ours_ever.insert(s);
      ++result.figures.ours_created;
    }
  std::set<std::int64_t> alive;
  for (const CassieStroke& s : session.strokes)
    if (!s.deleted) alive.insert(s.id);
  std::set<StrokeSet> cassie_final, cassie_ever, by_hand;
  const std::map<std::int64_t, double> broken = inferred_breaks(session);
  std::set<std::pair<std::size_t, StrokeSet>> ours_removed_at;
  for (const ReplayEvent& e : result.events)
    for (const StrokeSet& s : e.removed) ours_removed_at.insert({e.group, s});
  for (const CassiePatch& p : session.patches) {
    if (!p.automatic) {
      by_hand.insert(p.strokes);
      continue;
    }
    if (!p.created) continue;
    ++result.figures.cassie_created;
    cassie_ever.insert(p.strokes);
    const bool all_alive = std::all_of(p.strokes.begin(), p.strokes.end(), [&](std::int64_t s) { return alive.count(s); });
    if (const auto b = broken.find(p.id); b != broken.end()) {
      ++result.figures.cassie_broken;
      const auto g = group_of(b->second);
      if (g && ours_removed_at.count({*g, p.strokes})) {
        ++result.figures.matched_broken;
      } else {
        MissedBreak miss{p.strokes, g, false, ours_ever.count(p.strokes) > 0};
        int alive_ours = 0;  // ours over these strokes alive when the group began
        for (const ReplayEvent& e : result.events) {
          if (!g || e.group >= *g) break;
          alive_ours += static_cast<int>(std::count(e.added.begin(), e.added.end(), p.strokes)) -
                        static_cast<int>(std::count(e.removed.begin(), e.removed.end(), p.strokes));
        }
        miss.ours_alive = alive_ours > 0;
        result.missed_breaks.push_back(std::move(miss));
      }
      continue;
    }
    if (!p.deleted_by_hand && all_alive && !p.strokes.empty()) cassie_final.insert(p.strokes);
  }
  ReplayCauses& why = result.figures.causes;
  for (const auto& [key, n] : cassie_at) {
    const int m = std::min(n, ours_at.count(key) ? ours_at.at(key) : 0);
    result.figures.matched_created += m;
    if (n > m && ours_ever.count(key.second)) result.figures.matched_elsewhere += n - m;
  }
  for (const auto& [strokes, cause, astray, group] : missing) {
    if (ours_ever.count(strokes)) {
      ++why.miss_elsewhere;
      continue;
    }
    switch (cause) {
      case MissingCycle::curve_absent: ++why.miss_curve_absent; break;
      case MissingCycle::not_closed: ++why.miss_not_closed; break;
      case MissingCycle::not_found: {
        ++why.miss_not_found;
        auto stroke = [&](const std::optional<CurveId>& c) {
          const auto it = c ? curves.cassie_of.find(*c) : curves.cassie_of.end();
          return it == curves.cassie_of.end() ? std::int64_t{-1} : it->second;
        };
        result.astray.push_back({group, group_times[group], strokes, astray, stroke(astray.taken), stroke(astray.wanted)});
        switch (astray.where) {
          case Departure::near_tie: ++why.astray_near_tie; break;
          case Departure::at_two: ++why.astray_at_two; break;
          case Departure::at_undefined: ++why.astray_at_undefined; break;
          case Departure::at_sharp: ++why.astray_at_sharp; break;
          case Departure::at_crossing: ++why.astray_at_crossing; break;
          case Departure::at_smooth: ++why.astray_at_smooth; break;
          case Departure::no_start: ++why.astray_no_start; break;
          case Departure::none:
          case Departure::no_cycle: ++why.astray_no_cycle; break;
        }
        break;
      }
      case MissingCycle::refused_two: ++why.miss_refused_two; break;
      case MissingCycle::not_searched: ++why.miss_not_searched; break;
    }
  }
  for (const auto& [key, m] : ours_at) {
    const auto c = cassie_at.find(key);
    int extra = m - std::min(m, c == cassie_at.end() ? 0 : c->second);
    if (extra == 0) continue;
    int& bucket = cassie_ever.count(key.second) ? why.extra_elsewhere
                  : by_hand.count(key.second)   ? why.extra_by_hand
                                                : why.extra_other;
    bucket += extra;
    if (&bucket != &why.extra_other) continue;
    for (auto it = made.begin(); it != made.end() && extra > 0; ++it)
      if (it->second.group == key.first && it->second.strokes == key.second) {
        ExtraPatch x = it->second;
        for (auto h = cassie_at.lower_bound({key.first, StrokeSet{}}); h != cassie_at.end() && h->first.first == key.first;
             ++h)
          x.cassie_here.push_back(h->first.second);
        result.extras.push_back(std::move(x));
        --extra;
      }
  }
  result.timing = timing_pairs(session, result.events, made, cassie_at, ours_at);
  // At the end.
  std::set<StrokeSet> ours_final;
  for (const auto& [id, strokes] : ours)
    if (automatic[id]) ours_final.insert(strokes);
  result.figures.cassie_final = static_cast<int>(cassie_final.size());
  result.figures.ours_final = static_cast<int>(ours_final.size());
  for (const StrokeSet& s : cassie_final) {
    if (ours_final.count(s))
      ++result.figures.matched_final;
    else if (!ours_ever.count(s))
      ++why.end_never_created;
    else if (removed_by.count(s) && removed_by.at(s) == "stroke")
      ++why.end_removed_by_crossing;
    else
      ++why.end_removed_other;
  }
  result.network = live.sketch().network;
  std::set<StrokeSet> rebuilt;
  for (const auto& cycle : detect_all_cycles(live.sketch().network, params.search)) {
    StrokeSet s;
    for (const OrientedSegment& piece : cycle) s.insert(curves.cassie_of.at(piece.curve));
    rebuilt.insert(s);
  }
  result.figures.rebuilt_ours = static_cast<int>(rebuilt.size());
  for (const StrokeSet& s : cassie_final) result.figures.rebuilt_found += rebuilt.count(s) ? 1 : 0;
  for (const StrokeSet& s : ours_final) {
    if (cassie_final.count(s)) continue;
    if (by_hand.count(s))
      ++why.end_extra_by_hand;
    else if (cassie_ever.count(s))
      ++why.end_extra_cassie_gone;
    else
      ++why.end_extra_other;
  }
  return result;
}

}  // namespace sketchlab::soapfilm
