// Agreement with CASSIE's own automatic patches on every bundled session,
// both ways soapfilm_compare measures it: the cycles on CASSIE's final curve
// networks (sketch_graph) and the incremental replay of CASSIE's curves
// (patches created at the same event, and alive at the end). The figures
// asserted are the totals this implementation reaches with its default
// parameters (README.md, "Fidelity to CASSIE"), less a small margin; a
// regression lowers them.
#include <catch2/catch.hpp>

#include <filesystem>

#include "cassie_graph.hpp"
#include "cassie_replay.hpp"
#include "test_paths.hpp"

using namespace sketchlab;

TEST_CASE("fidelity to CASSIE's automatic patches on every bundled session", "[soapfilm][slow]") {
  const std::filesystem::path dir = test::source_path("data/cassie");
  const soapfilm::SoapfilmParams params;
  soapfilm::FidelityReport final;
  soapfilm::ReplayFigures replay;
  // The replay's final graph nodes against CASSIE's exported ones, without
  // reusing the nodes deleted curves left (the default) and with.
  soapfilm::NodeAgreement nodes, nodes_left_over;
  soapfilm::ReplayOptions left_over;
  left_over.graph.reuse_left_over = true;
  int sessions = 0, patch_sessions = 0, remade = 0, missed_break_alive = 0;
  for (const auto& f : std::filesystem::directory_iterator(dir / "sketch_history")) {
    if (f.path().extension() != ".json") continue;  // the folder's README
    const std::string name = f.path().stem().string();
    INFO(name);
    const soapfilm::CassieSession session = soapfilm::load_cassie_session(dir, name);
    ++sessions;
    const auto graph = dir / "sketch_graph" / (name + ".json");
    soapfilm::ReplayResult r;
    REQUIRE_NOTHROW(r = soapfilm::replay_cassie_session(session, params));
    // Every curve CASSIE drew or deleted goes through (a user's patch edit
    // may name a patch we do not have: that is a disagreement, not an error).
    for (const soapfilm::ReplayEvent& e : r.events)
      if (e.kind == "stroke" || e.kind == "delete") CHECK(e.error == "");
    if (session.system != 2) {  // freehand and Armature sessions: CASSIE made no patches
      CHECK(r.figures.cassie_created == 0);
      continue;
    }
    ++patch_sessions;
    REQUIRE(std::filesystem::exists(graph));
    soapfilm::FidelityReport fr;
    REQUIRE_NOTHROW(fr = soapfilm::compare_with_cassie(graph, session, params.search));
    CHECK(fr.found + fr.missed == fr.cassie_automatic);
    final += fr;
    const Network exported = soapfilm::load_cassie_network(graph).network;
    nodes += soapfilm::compare_graph_nodes(exported, r.network);
    nodes_left_over +=
        soapfilm::compare_graph_nodes(exported, soapfilm::replay_cassie_session(session, params, left_over).network);
    // Every disagreement of the replay has exactly one cause.
    const soapfilm::ReplayFigures& rf = r.figures;
    CHECK(rf.causes.missed_created() == rf.cassie_created - rf.matched_created);
    CHECK(rf.causes.extra_created() == rf.ours_created - rf.matched_created);
    CHECK(rf.causes.missed_end() == rf.cassie_final - rf.matched_final);
    CHECK(rf.causes.extra_end() == rf.ours_final - rf.matched_final);
    // ... and each one no walk closes over, exactly one place where the
    // walks leave it (replay_causes.hpp, Departure), listed once.
    const soapfilm::ReplayCauses& c = rf.causes;
    CHECK(c.astray_near_tie + c.astray_at_two + c.astray_at_undefined + c.astray_at_sharp + c.astray_at_crossing +
              c.astray_at_smooth + c.astray_no_start + c.astray_no_cycle ==
          c.miss_not_found);
    CHECK(static_cast<int>(r.astray.size()) == c.miss_not_found);
    for (const soapfilm::AstrayMiss& m : r.astray) {
      const bool at_node = m.at.where != soapfilm::Departure::no_start && m.at.where != soapfilm::Departure::no_cycle;
      CHECK(at_node == (m.at.node != 0));
      if (at_node) CHECK(m.at.followed <= m.at.length);
    }
    // Each extra of ours CASSIE never made ("other") listed once, as made.
    CHECK(static_cast<int>(r.extras.size()) == c.extra_other);
    for (const soapfilm::ExtraPatch& x : r.extras) {
      CHECK(x.pieces >= 1);
      CHECK(x.sharp_nodes <= x.pieces);  // a cycle has no more nodes than segments
      CHECK(x.max_degree >= 2);
      if (x.removed_at) CHECK(*x.removed_at >= x.group);
    }
    // Each cycle made at another event than CASSIE's listed once from each
    // side (cassie_replay.hpp, TimingPair).
    int timing_cassie = 0, timing_ours = 0;
    for (const soapfilm::TimingPair& p : r.timing) {
      CHECK((p.cassie || p.ours));
      timing_cassie += p.cassie.has_value();
      timing_ours += p.ours.has_value();
    }
    CHECK(timing_cassie == c.miss_elsewhere);
    CHECK(timing_ours == c.extra_elsewhere);
    // Each of CASSIE's breaks we did not make at its event listed once
    // (cassie_replay.hpp, MissedBreak; tenth round).
    CHECK(static_cast<int>(r.missed_breaks.size()) == rf.cassie_broken - rf.matched_broken);
    for (const soapfilm::MissedBreak& m : r.missed_breaks) {
      CHECK(m.group.has_value());
      if (m.ours_alive) CHECK(m.ours_ever);
      missed_break_alive += m.ours_alive;
    }
    // A stroke event that removes a patch and makes one over the same
    // strokes again (CASSIE logs no such remake; ninth round).
    for (const soapfilm::ReplayEvent& e : r.events)
      if (e.kind == "stroke")
        for (const soapfilm::StrokeSet& s : e.added)
          remade += std::count(e.removed.begin(), e.removed.end(), s) > 0;
    replay += r.figures;
  }
  CHECK(sessions == 18);
  CHECK(patch_sessions == 10);
  INFO("final " << final.found << "/" << final.cassie_automatic << " of " << final.ours << " cycles");
  INFO("replay created " << replay.matched_created << "/" << replay.cassie_created << " of " << replay.ours_created
                         << "; end " << replay.matched_final << "/" << replay.cassie_final << " of "
                         << replay.ours_final);
  // CASSIE's set at the end leaves out the patches its log shows broken by
  // a later stroke (cassie_breaks.hpp): 362 of its automatic patches.
  CHECK(final.cassie_automatic == 479);
  CHECK(replay.cassie_created == 1727);
  CHECK(replay.cassie_broken == 362);
  // Measured: final 356/479 (74.3 %), precision 356/505 (70.5 %); replay
  // created 1418/1727 (82.1 %), precision 1418/1757 (80.7 %; 1412/1752
  // before two-curve loops through planeless nodes were walked; twelfth round:
  // a meeting reuses the new curve's node before the old curve's, 1755
  // made before); at the end
  // 407/480 (84.8 %), precision 407/473 (86.0 %) (ninth round: a crossed
  // patch found again over split pieces keeps its identity; before, 1764
  // made, 80.0 %, and 407/471, 86.4 %; now 410/480, 85.4 %, and 410/476,
  // 86.1 %); 321 of CASSIE's 362 breaks made by
  // us at the same event. The whole-network search on the replay's own
  // final network: 385/480.
  CHECK(final.found >= 352);
  CHECK(double(final.found) / final.ours >= 0.70);
  CHECK(replay.recall_created() >= 0.820);
  CHECK(replay.precision_created() >= 0.805);
  CHECK(replay.recall_final() >= 0.852);
  CHECK(replay.precision_final() >= 0.855);
  CHECK(replay.matched_broken >= 318);
  // Of the 41 breaks we do not make, measured 20 where our patch over the
  // same strokes was alive and we did not remove it (tenth round, README).
  CHECK(missed_break_alive <= 22);
  CHECK(replay.rebuilt_found >= 380);
  // Measured 1072/1076 and 1060/1065 (default), 957/1076 and 945/1068
  // (reusing what deleted curves left): CASSIE's exported graph has a node
  // where the curves meet, not at those (README.md, "Fidelity").
  CHECK(nodes.cassie == 1076);
  CHECK(nodes.cassie_matched >= 1068);
  CHECK(nodes.ours_matched * 100 >= nodes.ours * 99);
  CHECK(nodes_left_over.cassie_matched >= 950);
  CHECK(nodes_left_over.ours_matched * 100 >= nodes_left_over.ours * 87);
  // The replay's main causes of disagreement (README.md, "Causes"):
  // measured 86 CASSIE patches whose curves hold no closed path in our graph
  // and 76 that one does but no walk follows (9 leaving it at a sharp node,
  // 30 at a smooth node whose normals cross, 31 at another smooth node; 81
  // before two-curve loops through planeless nodes were walked), 20
  // broken by a later crossing CASSIE did not break; fewer is better, more
  // is a regression.
  CHECK(replay.causes.miss_not_closed <= 88);
  CHECK(replay.causes.miss_not_found <= 78);
  CHECK(replay.causes.end_removed_by_crossing <= 25);
  // Our patches CASSIE never made, at any event or by hand: measured 183
  // (eighth round 180; the ninth round's kept identities change which
  // patch the users' deletions hit in 01-2-1, +6 there; twelfth round's
  // node order, -3 in vintage_car and teapot).
  CHECK(replay.causes.extra_other <= 185);
  // Timing (ninth round): CASSIE's patches made by us at another event,
  // measured 67, and ours CASSIE made at another event, 99 (117 when a
  // crossed patch found again over split pieces was made anew). Stroke
  // events that remove a patch and make one over the same strokes: 26
  // then (all 18 sessions), 5 now (the new cycle runs over other pieces
  // of those strokes).
  CHECK(replay.causes.miss_elsewhere <= 70);
  CHECK(replay.causes.extra_elsewhere <= 104);
  CHECK(remade <= 5);
  // Most extra cycles on the final networks are patches CASSIE's users had
  // to add by hand (the original missed them).
  CHECK(final.extra_matching_manual * 10 >= final.extra * 7);
}
