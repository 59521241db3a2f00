// `sketchlab plugins [NAME]`: what plugins are installed, with parameters.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <set>

#include "commands.hpp"
#include "sketchlab/plugin/plugin_host.hpp"

namespace sketchlab::cli {
namespace {

std::string number(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string degrees(double radians) { return number(radians * 180.0 / std::numbers::pi, 4) + "°"; }

// A parameter's default and allowed values as a reader wants them: numbers
// to 6 significant digits with their unit, angles (declared in radians,
// written in radians in configs) also in degrees.
std::pair<std::string, std::string> describe(const ParamSpec& spec) {
  const bool numeric = spec.type == ParamType::real || spec.type == ParamType::integer;
  if (!numeric) return {format_value(spec.default_value), describe_allowed(spec)};
  const double v = std::holds_alternative<double>(spec.default_value)
                       ? std::get<double>(spec.default_value)
                       : static_cast<double>(std::get<std::int64_t>(spec.default_value));
  const bool rad = spec.unit == "rad";
  const std::string unit = spec.unit.empty() ? "" : " " + spec.unit;
  std::string shown = spec.type == ParamType::integer ? format_value(spec.default_value) : number(v, 6);
  shown += unit;
  if (rad) shown += " = " + degrees(v);
  std::string allowed(to_string(spec.type));
  const auto bound = [&](double b) { return spec.type == ParamType::integer ? number(b, 15) : number(b, 6); };
  if (spec.min && spec.max) {
    allowed += " in [" + bound(*spec.min) + ", " + bound(*spec.max) + "]" + unit;
    if (rad) allowed += " = [" + degrees(*spec.min) + ", " + degrees(*spec.max) + "]";
  } else if (spec.min) {
    allowed += " >= " + bound(*spec.min) + unit + (rad ? " = " + degrees(*spec.min) : "");
  } else if (spec.max) {
    allowed += " <= " + bound(*spec.max) + unit + (rad ? " = " + degrees(*spec.max) : "");
  } else if (!unit.empty()) {
    allowed += " (" + spec.unit + ")";
  }
  return {shown, allowed};
}

// Display width in terminal columns (UTF-8: count code points, e.g. '°').
std::size_t columns(const std::string& s) {
  return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

std::string pad(const std::string& s, std::size_t width) {
  return s + std::string(width > columns(s) ? width - columns(s) : 0, ' ');
}

void print_plugin(const LoadedPlugin& p, bool details) {
  const auto& d = *p.descriptor;
  std::cout << to_string(d.kind) << " " << d.name << " " << d.version << ": " << d.summary << "\n";
  if (details) std::cout << "  file: " << p.path.string() << "\n";
  std::vector<std::pair<std::string, std::string>> rows;
  std::size_t name_w = 0, default_w = 0;
  for (const auto& spec : d.params) {
    rows.push_back(describe(spec));
    name_w = std::max(name_w, columns(spec.name));
    default_w = std::max(default_w, columns(rows.back().first));
  }
  for (std::size_t i = 0; i < d.params.size(); ++i) {
    const auto& spec = d.params[i];
    std::cout << "  " << pad(spec.name, name_w) << " = " << pad(rows[i].first, default_w) << "  "
              << rows[i].second;
    if (details && !spec.doc.empty()) std::cout << "\n      " << spec.doc;
    std::cout << "\n";
  }
}

}  // namespace

void add_plugins_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "plugins", "List the plugins found (SKETCHLAB_PLUGIN_PATH, then the install or build tree) with their "
                 "parameters");
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
      std::cerr << (name->empty() ? std::string("no plugins found") : "no plugin named '" + *name + "'");
      std::set<std::string> names;
      for (const auto& p : host.plugins()) names.insert(p.descriptor->name);
      if (!names.empty()) {
        std::cerr << "; plugins:";
        for (const auto& n : names) std::cerr << " " << n;
      }
      std::cerr << "; searched:";
      for (const auto& d : dirs) std::cerr << " " << d.string();
      std::cerr << (dirs.empty() ? " (no directory exists)" : "") << "\n";
      exit_code = 1;
    }
  });
}

}  // namespace sketchlab::cli
