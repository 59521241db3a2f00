// Session::revert_last() must equal folding one event fewer, for every kind
// of event; the replay viewer steps back through it.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "session_fixtures.hpp"
#include "sketchlab/session.hpp"

namespace {

using namespace sketchlab;
using test::FitCorrector;
using test::sampled_stroke;

Stroke wobbly_stroke(StrokeId id, const Vec3& origin, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 0.001);
  return sampled_stroke(id, 30, id, 0.01, [&](int i) -> Vec3 {
    const double u = i / 29.0;
    return origin + Vec3(0.3 * u, 0.04 * std::sin(4 * u), 0.0) + Vec3(noise(rng), noise(rng), noise(rng));
  });
}

// A mix of every event kind a session folds, including refused ones
// (nothing to redo, duplicate stroke id) and a redo stack cleared by a stroke.
std::vector<Event> mixed_events() {
  std::mt19937_64 rng(21);
  std::vector<Event> events;
  double t = 0.0;
  auto add = [&](EventPayload p) { events.push_back(Event{t += 1.0, std::move(p)}); };
  add(ModeEvent{Layer::scaffold});
  add(StrokeEvent{wobbly_stroke(1, Vec3::Zero(), rng)});
  add(StrokeEvent{wobbly_stroke(2, Vec3(0, 0.2, 0), rng)});
  add(ReferenceEvent{2, "truth", make_line(Vec3::Zero(), Vec3(1, 0, 0))});
  add(ReferenceEvent{2, "truth", make_line(Vec3::Zero(), Vec3(0, 1, 0))});
  add(UndoEvent{});
  add(RedoEvent{});
  add(RedoEvent{});  // nothing to redo
  add(UndoEvent{});
  add(StrokeEvent{wobbly_stroke(3, Vec3(0, 0.4, 0), rng)});  // clears the redo stack
  add(StrokeEvent{wobbly_stroke(3, Vec3(0, 0.6, 0), rng)});  // duplicate id: refused
  add(CorrectionEvent{false});
  add(StrokeEvent{wobbly_stroke(4, Vec3(0, 0.8, 0), rng)});
  Workspace scaled;
  scaled.scale = 2.0;
  add(WorkspaceEvent{scaled});
  add(DeleteNearEvent{Vec3(0, 0.4, 0), 0.05});
  add(DeleteStrokeEvent{4});
  add(UndoEvent{});
  add(RelationEvent{"truth", ConstraintKind::parallel, {1, 2}, {}});
  add(AddPatchEvent{Vec3::Zero()});  // no surfacer: refused
  return events;
}

Session fold(const std::vector<Event>& events, std::size_t count,
             const std::shared_ptr<Corrector>& corrector) {
  Session s({}, corrector, nullptr);
  for (std::size_t i = 0; i < count; ++i) s.handle(events[i]);
  return s;
}

bool same_state(const Session& a, const Session& b) {
  return a.sketch() == b.sketch() && a.references() == b.references() &&
         a.relations() == b.relations() && a.events_handled() == b.events_handled();
}

}  // namespace

TEST_CASE("reverting each event equals folding one event fewer", "[session]") {
  const auto events = mixed_events();
  auto fit = std::make_shared<FitCorrector>();
  Session s = fold(events, events.size(), fit);
  for (std::size_t k = events.size(); k-- > 0;) {
    REQUIRE(s.revert_last());
    INFO("after reverting event " << k << " (" << event_type_name(events[k].payload) << ")");
    REQUIRE(same_state(s, fold(events, k, fit)));
  }
  CHECK_FALSE(s.revert_last());
}

TEST_CASE("stepping back and forth returns the same sketch at every step", "[session]") {
  const auto events = mixed_events();
  auto fit = std::make_shared<FitCorrector>();
  Session s({}, fit, nullptr);
  std::mt19937_64 rng(5);
  std::size_t position = 0;
  for (int move = 0; move < 200; ++move) {
    const bool back = position == events.size() || (position > 0 && rng() % 3 == 0);
    if (back) {
      REQUIRE(s.revert_last());
      --position;
    } else {
      s.handle(events[position++]);
    }
    REQUIRE(same_state(s, fold(events, position, fit)));
  }
}
