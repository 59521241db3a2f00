#pragma once
// What the session harnesses share (fuzz_stroke_session, fuzz_tablet_session):
// this build's plugins, loaded from SKETCHLAB_FUZZ_PLUGIN_DIR as the app
// loads them, and a Session whose contract is checked after every event:
// Session::handle never throws, and nothing non-finite reaches the sketch or
// the reports (sketch_to_json writes NaN and infinity as null).
#include <memory>
#include <string>
#include <vector>

#include "fuzz_support.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/plugin/plugin_host.hpp"
#include "sketchlab/session.hpp"

namespace sketchlab::fuzz {

inline const PluginHost& build_plugins() {
  static const PluginHost h = [] {
    PluginHost loaded;
    loaded.load_directories({SKETCHLAB_FUZZ_PLUGIN_DIR});
    return loaded;
  }();
  return h;
}

// An ordinary number in [-1, 1] (two bytes).
inline double unit(Bytes& b) {
  const int v = b.byte() | (b.byte() << 8);
  return v / 32767.5 - 1.0;
}

inline Vec3 unit_vector(Bytes& b) { return {unit(b), unit(b), unit(b)}; }

// Events one second apart through a Session, the contract checked after each.
class CheckedSession {
 public:
  CheckedSession(const Workspace& ws, std::shared_ptr<Corrector> corrector, std::shared_ptr<Surfacer> surfacer)
      : session_(ws, std::move(corrector), std::move(surfacer), {}, 5.0) {}

  // The last event's time (0 before the first); the next one's is a second
  // later, so a stroke's samples may start here.
  double last_time() const { return time_; }

  void handle(Event e) {
    e.time = time_ += 1.0;
    try {
      steps_.push_back(session_.handle(e));
    } catch (const std::exception& x) {
      broken(std::string("Session::handle threw: ") + x.what());
    } catch (...) {
      broken("Session::handle threw");
    }
    // Checked per event: a transient NaN later deleted would escape a check
    // at the end.
    if (sketch_to_json(session_.sketch(), &steps_).find("null") != std::string::npos)
      broken("a non-finite number reached the sketch or a report");
  }

 private:
  Session session_;
  std::vector<StepReport> steps_;
  double time_ = 0.0;
};

}  // namespace sketchlab::fuzz
