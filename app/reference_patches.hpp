#pragma once
// CASSIE's own patches for the teacher-forced rebuild (`sketchlab fidelity` /
// `teacher-forced` with --cassie-logs): the patch log of a session's
// raw_data, meshed by the soapfilm surfacer (lab/teacher_forced.hpp,
// TeacherForcedOptions::patches).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

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

}  // namespace sketchlab::cli
