#pragma once
// The verbs of the `sketchlab` command line. Each adds its subcommand to the
// app; the callback runs it and sets the process exit code.
#include <CLI/CLI.hpp>

namespace sketchlab::cli {

void add_plugins_command(CLI::App& app, int& exit_code);
void add_run_command(CLI::App& app, int& exit_code);
void add_convert_command(CLI::App& app, int& exit_code);
void add_render_command(CLI::App& app, int& exit_code);  // built with the viewers only
void add_view_command(CLI::App& app, int& exit_code);    // built with viewers/desktop only
void add_vr_command(CLI::App& app, int& exit_code);      // built with viewers/openxr only
void add_teacher_forced_command(CLI::App& app, int& exit_code);
void add_fidelity_command(CLI::App& app, int& exit_code);
void add_record_command(CLI::App& app, int& exit_code);

}  // namespace sketchlab::cli
