// libFuzzer harness: the CASSIE dataset importer (sketchlab/lab/cassie_import.hpp).
// The input is the sketch_history JSON, then a line "#raw#", then the
// raw_data JSON (both halves are mutated). Contract: std::runtime_error
// naming the file, or a recording; nothing else escapes, no undefined
// behaviour. (Whether every imported recording is writable is issue 17's D9,
// the importer's own: a refusal by the writer is accepted here.)
#include <sstream>

#include "fuzz_support.hpp"
#include "sketchlab/lab/cassie_import.hpp"
#include "sketchlab/recording/recording_writer.hpp"

using namespace sketchlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto [history, raw] = fuzz::cassie_halves({reinterpret_cast<const char*>(data), size});
  const auto history_file = fuzz::write_file("history.json", history);
  const auto raw_file = fuzz::write_file("raw.json", raw);
  Recording rec;
  try {
    rec = import_cassie(history_file, raw_file, "fuzz");
  } catch (const std::runtime_error&) {
    return 0;
  }
  std::ostringstream out;
  try {
    write_recording(out, rec);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
