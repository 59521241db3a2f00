// libFuzzer harness: the sketch JSON reader (io/sketch_json.hpp). Contract:
// any bytes either read or throw std::runtime_error naming the file, with no
// undefined behaviour (issue 17, D7: float-to-integer conversions out of
// range); what reads writes back to a sketch that reads the same.
#include "fuzz_support.hpp"
#include "sketchlab/io/sketch_json.hpp"

using namespace sketchlab;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Sketch sketch;
  try {
    sketch = parse_sketch_json(text, "fuzz.json");
  } catch (const std::runtime_error&) {
    return 0;
  }
  const std::string written = sketch_to_json(sketch);
  Sketch back;
  try {
    back = parse_sketch_json(written, "back.json");
  } catch (const std::exception& e) {
    fuzz::broken(std::string("a sketch the reader accepted does not read back: ") + e.what());
  }
  if (!(back.network == sketch.network)) fuzz::broken("read, write, read gives another network");
  return 0;
}
