// soapfilm_compare DATA_DIR [SESSION...]: runs the soapfilm cycle detection
// on CASSIE's own final curve networks (DATA_DIR/sketch_graph) and compares
// the cycles with CASSIE's automatic patches (DATA_DIR/raw_data) by their
// bounding strokes. Prints "name value unit" lines.
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "cassie_graph.hpp"

int main(int argc, char** argv) {
  using namespace sketchlab::soapfilm;
  if (argc < 2) {
    std::cerr << "usage: soapfilm_compare DATA_DIR [SESSION...] [--max-segments N] [--trim-angle RAD] [--sharp-error E] [--keep-outer]\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::vector<std::string> sessions;
  CycleSearchParams params;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--max-segments" && i + 1 < argc)
      params.max_segments = std::atoi(argv[++i]);
    else if (a == "--trim-angle" && i + 1 < argc)
      params.trim_angle = std::atof(argv[++i]);
    else if (a == "--keep-outer")
      params.reject_outer = false;
    else if (a == "--sharp-error" && i + 1 < argc)
      params.frame.sharp_error = std::atof(argv[++i]);
    else
      sessions.push_back(a);
  }
  if (sessions.empty()) sessions = {"hat", "chair", "01-2-1", "02-1-2"};
  try {
    for (const std::string& s : sessions) {
      const FidelityReport r = compare_with_cassie(dir / "sketch_graph" / (s + ".json"),
                                                   dir / "raw_data" / (s + ".json"), params);
      std::cout << s << ".cassie_automatic " << r.cassie_automatic << " patches\n"
                << s << ".cassie_manual " << r.cassie_manual << " patches\n"
                << s << ".ours " << r.ours << " cycles\n"
                << s << ".found " << r.found << " patches\n"
                << s << ".missed " << r.missed << " patches\n"
                << s << ".extra " << r.extra << " cycles\n"
                << s << ".extra_matching_manual " << r.extra_matching_manual << " cycles\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "soapfilm_compare: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
