// libFuzzer harness: a CASSIE session as the soap-film replay reads it
// (plugins/surfacers/soapfilm/cassie_session.hpp): the sketch_history JSON,
// then a line "#raw#", then the raw_data JSON (both halves are mutated),
// loaded with CASSIE's constraint logs and, when small, replayed through the
// surfacer (cassie_replay.hpp: graph edits, cycle walks, patch meshes, the
// comparison with CASSIE's patch log). Contract (issue 16): only
// CassieFormatError escapes the loader; a loaded session replays with no
// exception, crash, undefined behaviour or hang.
#include "cassie_json.hpp"
#include "cassie_replay.hpp"
#include "cassie_session.hpp"
#include "fuzz_support.hpp"

using namespace sketchlab;
using namespace sketchlab::soapfilm;

namespace {

// Replaying is a surfacer update per event: bounded so that one input stays
// well within libFuzzer's -timeout under ASan.
constexpr std::size_t kMaxReplayedStrokes = 40;
constexpr std::size_t kMaxReplayedPatches = 40;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::silence_warnings();
  const auto [history, raw] = fuzz::cassie_halves({reinterpret_cast<const char*>(data), size});
  fuzz::write_file("session/sketch_history/fuzz.json", history);
  fuzz::write_file("session/raw_data/fuzz.json", raw);
  const auto dir = fuzz::scratch_dir() / "session";
  CassieSession session;
  try {
    session = load_cassie_session(dir, "fuzz", true);
  } catch (const CassieFormatError&) {
    return 0;
  }
  if (session.strokes.size() > kMaxReplayedStrokes || session.patches.size() > kMaxReplayedPatches) return 0;
  try {
    (void)replay_cassie_session(session, SoapfilmParams{});
  } catch (const std::exception& e) {
    fuzz::broken(std::string("the replay of a loaded session threw: ") + e.what());
  }
  return 0;
}
