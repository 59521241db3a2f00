#pragma once
// CASSIE's own patches for the teacher-forced rebuild (`sketchlab fidelity` /
// `teacher-forced` with --cassie-logs): the patch log of a session's
// raw_data, meshed by the soapfilm surfacer (lab/teacher_forced.hpp,
// TeacherForcedOptions::patches).
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sketchlab/lab/cassie_import.hpp"
#include "sketchlab/lab/teacher_forced.hpp"
#include "sketchlab/plugin/plugin_host.hpp"

namespace sketchlab::cli {

// The surfacer that meshes the reference patches: `name` with its default
// parameters, or null (with a warning on stderr naming what is missing) when
// the plugin is not loaded, so the comparison goes on without patches.
std::shared_ptr<Surfacer> reference_patch_surfacer(const PluginHost& host, const std::string& name);

// The reference patches (lab reference_patches) of
// `raw_data_dir`/<session>.json (the recording's header source "session",
// else `fallback_session`). Throws std::runtime_error naming the file for
// malformed data.
std::vector<ReferencePatch> cassie_reference_patches(const Recording& recording,
                                                     const std::filesystem::path& raw_data_dir,
                                                     const std::string& fallback_session);

// The raw_data file of a recording's session (as above).
std::filesystem::path cassie_raw_data_file(const Recording& recording, const std::filesystem::path& raw_data_dir,
                                           const std::string& fallback_session);

// CASSIE's per-stroke constraint logs of the recording's raw_data file (as
// above; lab read_cassie_constraint_logs). Every raw_data export logs its
// strokes, so a file without any is most likely another export's
// (sketch_graph, sketch_history, given by mistake): warns on stderr naming
// the file and saying what the comparison goes on without (`left_out`), and
// returns an empty map. Throws as cassie_reference_patches.
std::map<StrokeId, CassieConstraintLog> cassie_constraint_logs(const Recording& recording,
                                                               const std::filesystem::path& raw_data_dir,
                                                               const std::string& fallback_session,
                                                               const std::string& left_out);

}  // namespace sketchlab::cli
