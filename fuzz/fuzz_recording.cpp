// libFuzzer harness: the recording reader (recording_reader.hpp). Contract:
// any bytes either read, or throw RecordingError; nothing else escapes, and
// no undefined behaviour (ASan + UBSan). What reads writes back and reads to
// the same recording (the format's byte-for-byte round trip).
#include <sstream>

#include "fuzz_support.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/recording/recording_writer.hpp"

using namespace sketchlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::silence_warnings();
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (const bool refuse : {false, true}) {
    RecordingReadOptions options;
    options.refuse_truncated = refuse;
    std::istringstream in(text);
    Recording rec;
    try {
      rec = parse_recording(in, "fuzz.jsonl", options);
    } catch (const RecordingError&) {
      continue;
    }
    std::ostringstream out;
    try {
      write_recording(out, rec);
    } catch (const std::exception& e) {
      fuzz::broken(std::string("a recording the reader accepted cannot be written: ") + e.what());
    }
    std::istringstream back(out.str());
    if (!(parse_recording(back, "back.jsonl") == rec)) fuzz::broken("read, write, read gives another recording");
  }
  return 0;
}
