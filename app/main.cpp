// sketchlab: replay, compare and export 3D sketch beautification results.
#include <iostream>

#include "commands.hpp"
#include "sketchlab/heap_policy.hpp"
#include "sketchlab/version.hpp"

int main(int argc, char** argv) {
  sketchlab::keep_freed_heap();  // per-stroke latency without allocator system calls
  CLI::App app{"sketchlab " SKETCHLAB_KERNEL_VERSION
               ": 3D sketch beautification with interchangeable correctors and surfacers"};
  app.require_subcommand(1);
  app.set_version_flag("--version", SKETCHLAB_KERNEL_VERSION);
  int exit_code = 0;
  sketchlab::cli::add_plugins_command(app, exit_code);
  sketchlab::cli::add_run_command(app, exit_code);
  sketchlab::cli::add_convert_command(app, exit_code);
#ifdef SKETCHLAB_HAVE_VIEWER
  sketchlab::cli::add_render_command(app, exit_code);
#endif
#ifdef SKETCHLAB_HAVE_DESKTOP_VIEWER
  sketchlab::cli::add_view_command(app, exit_code);
#endif
#ifdef SKETCHLAB_HAVE_VR_VIEWER
  sketchlab::cli::add_vr_command(app, exit_code);
#endif
  sketchlab::cli::add_teacher_forced_command(app, exit_code);
  sketchlab::cli::add_fidelity_command(app, exit_code);
  sketchlab::cli::add_record_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "sketchlab: " << e.what() << "\n";
    return 1;
  }
  return exit_code;
}
