// libFuzzer harness: CASSIE's final-network export (sketch_graph JSON) as the
// soap-film comparison reads it (plugins/surfacers/soapfilm/cassie_graph.hpp),
// then what the comparison and the surfacer do with a loaded network: the
// whole-network cycle search and the patch mesh of its first cycles.
// Contract (issue 16: "neither may crash: a malformed or unexpected graph gets
// a clear error naming the file and element"): only CassieFormatError escapes
// the loader; a loaded network is searched and meshed with no crash, no
// undefined behaviour, no hang, and every mesh vertex is finite.
#include "cassie_graph.hpp"
#include "fuzz_support.hpp"
#include "patch_upkeep.hpp"
#include "soapfilm_params.hpp"
#include "soapfilm_surfacer.hpp"

using namespace sketchlab;
using namespace sketchlab::soapfilm;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::silence_warnings();
  const auto file = fuzz::write_file("sketch_graph.json", {reinterpret_cast<const char*>(data), size});
  CassieNetwork net;
  try {
    net = load_cassie_network(file);
  } catch (const CassieFormatError& e) {
    if (std::string(e.what()).find(file.string()) == std::string::npos)
      fuzz::broken(std::string("the error does not name the file: ") + e.what());
    return 0;
  }
  const SoapfilmParams params;
  const auto cycles = detect_all_cycles(net.network, params.search);
  // Mesh a few (each is a CGAL fill, remesh and smooth: the surfacer's path).
  for (std::size_t i = 0; i < cycles.size() && i < 3; ++i) {
    const auto patch = make_patch(net.network, static_cast<PatchId>(i + 1), cycles[i], true, params, nullptr);
    if (!patch) continue;
    for (const Vec3& v : patch->mesh.vertices)
      if (!v.allFinite()) fuzz::broken("a patch mesh has a non-finite vertex");
  }
  return 0;
}
