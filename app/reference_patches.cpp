#include "reference_patches.hpp"

#include <iostream>

#include "sketchlab/io/warning.hpp"

namespace sketchlab::cli {

std::shared_ptr<Surfacer> reference_patch_surfacer(const PluginHost& host, const std::string& name) {
  if (!host.find(PluginKind::surfacer, name)) {
    std::cerr << "warning: surfacer plugin '" << name
              << "' is not loaded (soapfilm needs CGAL: scripts/setup.sh); CASSIE's patches are left out\n";
    return nullptr;
  }
  return host.make_surfacer(name, {});
}

std::filesystem::path cassie_raw_data_file(const Recording& recording, const std::filesystem::path& raw_data_dir,
                                           const std::string& fallback_session) {
  const auto it = recording.header.source.find("session");
  return raw_data_dir / ((it == recording.header.source.end() ? fallback_session : it->second) + ".json");
}

std::vector<ReferencePatch> cassie_reference_patches(const Recording& recording,
                                                     const std::filesystem::path& raw_data_dir,
                                                     const std::string& fallback_session) {
  return reference_patches(read_cassie_patches(cassie_raw_data_file(recording, raw_data_dir, fallback_session)));
}

std::map<StrokeId, CassieConstraintLog> cassie_constraint_logs(const Recording& recording,
                                                               const std::filesystem::path& raw_data_dir,
                                                               const std::string& fallback_session,
                                                               const std::string& left_out) {
  const std::filesystem::path file = cassie_raw_data_file(recording, raw_data_dir, fallback_session);
  auto logs = read_cassie_constraint_logs(file);
  if (logs.empty())
    warn(file.string() + ": no stroke log (allSketchedStrokes), so the session is compared without " + left_out +
         "; does --cassie-logs name CASSIE's raw_data folder?");
  return logs;
}

}  // namespace sketchlab::cli
