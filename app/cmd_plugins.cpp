// `sketchlab plugins [NAME]`: what plugins are installed, with parameters.
#include <iomanip>
#include <iostream>

#include "commands.hpp"
#include "sketchlab/plugin/plugin_host.hpp"

namespace sketchlab::cli {
namespace {

void print_plugin(const LoadedPlugin& p, bool details) {
  const auto& d = *p.descriptor;
  std::cout << to_string(d.kind) << " " << d.name << " " << d.version << ": " << d.summary << "\n";
  if (details) std::cout << "  file: " << p.path.string() << "\n";
  for (const auto& spec : d.params) {
    std::cout << "  " << std::left << std::setw(18) << spec.name << " = " << std::setw(10)
              << format_value(spec.default_value) << " " << describe_allowed(spec);
    if (details && !spec.doc.empty()) std::cout << "\n      " << spec.doc;
    std::cout << "\n";
  }
}

}  // namespace

void add_plugins_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "plugins", "List the plugins found (build tree, install tree, SKETCHLAB_PLUGIN_PATH) with their parameters");
  auto name = std::make_shared<std::string>();
  cmd->add_option("name", *name, "Show only this plugin, with parameter documentation");
  cmd->callback([name, &exit_code] {
    PluginHost host;
    const auto dirs = PluginHost::default_search_paths();
    host.load_directories(dirs);
    bool found = false;
    for (const auto& p : host.plugins()) {
      if (!name->empty() && p.descriptor->name != *name) continue;
      print_plugin(p, !name->empty());
      found = true;
    }
    for (const auto& e : host.errors())
      std::cerr << "warning: plugin " << e.path.string() << " not loaded: " << e.reason << "\n";
    if (!found) {
      std::cerr << (name->empty() ? std::string("no plugins found") : "no plugin named '" + *name + "'")
                << "; searched:";
      for (const auto& d : dirs) std::cerr << " " << d.string();
      std::cerr << (dirs.empty() ? " (no directory exists)" : "") << "\n";
      exit_code = 1;
    }
  });
}

}  // namespace sketchlab::cli
