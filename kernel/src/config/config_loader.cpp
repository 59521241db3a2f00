#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "config_internal.hpp"

namespace sketchlab {

namespace fs = std::filesystem;

namespace {

using Path = std::vector<std::string>;

const std::vector<std::string> stack_keys = {"name", "input", "corrector", "surfacer", "time_budget"};
const std::vector<std::string> plugin_keys = {"plugin", "params"};
const std::vector<std::string> experiment_keys = {"experiment", "recordings", "stacks", "outputs",
                                                  "sweep"};
const std::vector<std::string> output_keys = {"dir", "sketch_json", "stroke_csv", "ply", "obj",
                                              "mlp", "pictures", "report", "timestamp"};
const std::vector<std::string> range_keys = {"from", "to", "step"};

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

std::string dotted(const Path& path) {
  std::string text;
  for (const auto& part : path) text += (text.empty() ? "" : ".") + part;
  return text.empty() ? "the document" : "'" + text + "'";
}

Path child(Path path, const std::string& step) {
  path.push_back(step);
  return path;
}

std::string describe_node(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Scalar: return "'" + node.Scalar() + "'";
    case YAML::NodeType::Null: return "nothing";
    default: return "nothing";
  }
}

// Reads the YAML tree of one file, knowing which parts came from overrides.
class Reader {
 public:
  Reader(fs::path file, const std::vector<Override>& overrides)
      : file_(std::move(file)), base_(fs::absolute(file_).parent_path()), overridden_(overrides) {}

  const fs::path& file() const { return file_; }

  YAML::Node load(const std::vector<Override>& overrides) const {
    YAML::Node root = config_detail::load_yaml(file_);
    config_detail::apply_overrides(root, overrides);
    return root;
  }

  // Where the override that set `path` (or a prefix of it) was given (the
  // command line, a sweep entry), else the node's line in the file. The last
  // override of a path is the one that counts.
  SourceLocation where(const YAML::Node& node, const Path& path) const {
    for (auto o = overridden_.rbegin(); o != overridden_.rend(); ++o) {
      if (o->path.size() <= path.size() && std::equal(o->path.begin(), o->path.end(), path.begin()))
        return o->origin;
    }
    const int line = node.IsDefined() ? node.Mark().line : -1;
    if (line >= 0) return {file_.string(), line + 1};
    // No mark: a map an override created on its way, or an empty document.
    for (auto o = overridden_.rbegin(); o != overridden_.rend(); ++o) {
      if (path.size() < o->path.size() && std::equal(path.begin(), path.end(), o->path.begin()))
        return o->origin;
    }
    return {file_.string(), 0};
  }

  [[noreturn]] void fail(const YAML::Node& node, const Path& path, const std::string& message) const {
    throw_config_error(where(node, path), message);
  }

  // Base directory for relative recordings given at `path`.
  fs::path base_for(const YAML::Node& node, const Path& path) const {
    return where(node, path).line > 0 ? base_ : fs::current_path();
  }

  // Checks that `node` is a map whose keys are all in `allowed` (no key twice).
  void expect_map(const YAML::Node& node, const Path& path, const std::string& what,
                  const std::vector<std::string>& allowed) const {
    if (!node.IsMap()) {
      fail(node, path, dotted(path) + " must be " + what + " (a map), not " + describe_node(node) +
                           " (allowed keys: " + join(allowed) + ")");
    }
    std::map<std::string, int> seen;
    for (const auto& entry : node) {
      const YAML::Node& key = entry.first;
      if (!key.IsScalar()) fail(key, path, "keys of " + what + " must be plain names");
      const std::string name = key.Scalar();
      if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
        fail(key, child(path, name),
             "unknown key '" + name + "' in " + what + " (allowed: " + join(allowed) + ")");
      }
      if (!seen.emplace(name, key.Mark().line + 1).second) {
        fail(key, child(path, name), "key '" + name + "' appears twice in " + what);
      }
    }
  }

  void require(const YAML::Node& map, const Path& path, const std::string& key,
               const std::string& what, const std::vector<std::string>& allowed) const {
    if (!map[key]) {
      fail(map, path, what + " has no '" + key + "' (allowed: " + join(allowed) + ")");
    }
  }

  std::string read_string(const YAML::Node& node, const Path& path) const {
    if (!node.IsScalar() || node.Scalar().empty()) {
      fail(node, path, dotted(path) + " must be a non-empty string, not " + describe_node(node));
    }
    return node.Scalar();
  }

  bool read_bool(const YAML::Node& node, const Path& path) const {
    if (node.IsScalar() && node.Tag() != "!") {
      const std::string& s = node.Scalar();
      if (s == "true" || s == "True" || s == "TRUE") return true;
      if (s == "false" || s == "False" || s == "FALSE") return false;
    }
    fail(node, path, dotted(path) + " must be a boolean, not " + describe_node(node) +
                         " (allowed: true, false)");
  }

  ParamValue read_param(const YAML::Node& node, const Path& path) const {
    if (!node.IsScalar()) {
      fail(node, path, "parameter " + dotted(path) + " must be a single value, not " +
                           describe_node(node) + " (allowed: true, false, a number or a string)");
    }
    const std::string& s = node.Scalar();
    if (node.Tag() == "!") return s;  // quoted: always a string
    if (s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "false" || s == "False" || s == "FALSE") return false;
    if (auto i = parse_integer(s)) return *i;
    if (auto d = parse_real(s)) return *d;
    if (s.find_first_not_of("+-0123456789") == std::string::npos && !s.empty() &&
        s.find_first_of("0123456789") != std::string::npos) {
      fail(node, path, "parameter " + dotted(path) + ": integer " + s + " does not fit in 64 bits");
    }
    return s;
  }

  PluginChoice read_plugin(const YAML::Node& node, const Path& path, const std::string& role) const {
    PluginChoice choice;
    choice.location = where(node, path);
    if (node.IsScalar()) {  // shorthand `corrector: freehand`
      choice.plugin = read_string(node, path);
      return choice;
    }
    expect_map(node, path, "a " + role + " choice", plugin_keys);
    require(node, path, "plugin", "the " + role + " choice", plugin_keys);
    choice.plugin = read_string(node["plugin"], child(path, "plugin"));
    choice.location = where(node["plugin"], child(path, "plugin"));
    if (const YAML::Node params = node["params"]; params && !params.IsNull()) {
      const Path params_path = child(path, "params");
      if (!params.IsMap()) {
        fail(params, params_path, dotted(params_path) + " must be a map of parameter values, not " +
                                      describe_node(params));
      }
      for (const auto& entry : params) {
        if (!entry.first.IsScalar()) fail(entry.first, params_path, "parameter names must be plain names");
        const std::string name = entry.first.Scalar();
        const Path param_path = child(params_path, name);
        if (choice.params.count(name)) fail(entry.first, param_path, "parameter '" + name + "' appears twice");
        choice.params[name] = read_param(entry.second, param_path);
        choice.param_locations[name] = where(entry.second, param_path);
      }
    }
    return choice;
  }

  StackConfig read_stack(const YAML::Node& node, const Path& path) const {
    expect_map(node, path, "a stack", stack_keys);
    StackConfig stack;
    stack.location = where(node, path);
    require(node, path, "corrector", "the stack", stack_keys);
    if (node["name"]) stack.name = read_string(node["name"], child(path, "name"));
    if (node["input"]) stack.input = read_plugin(node["input"], child(path, "input"), "input");
    stack.corrector = read_plugin(node["corrector"], child(path, "corrector"), "corrector");
    if (node["surfacer"]) {
      stack.surfacer = read_plugin(node["surfacer"], child(path, "surfacer"), "surfacer");
    }
    if (node["time_budget"]) {
      const YAML::Node& v = node["time_budget"];
      const Path p = child(path, "time_budget");
      const std::optional<double> seconds = v.IsScalar() ? parse_real(v.Scalar()) : std::nullopt;
      if (!seconds || !(*seconds > 0.0 && *seconds <= 86400.0))
        fail(v, p, dotted(p) + " must be a number of seconds in (0, 86400], not " + describe_node(v));
      stack.time_budget = *seconds;
    }
    return stack;
  }

 private:
  static std::optional<std::int64_t> parse_integer(const std::string& s) {
    std::int64_t value = 0;
    const char* begin = s.data() + (s.size() > 1 && s[0] == '+' ? 1 : 0);
    auto [end, ec] = std::from_chars(begin, s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return value;
  }

  static std::optional<double> parse_real(const std::string& s) {
    if (s == ".inf" || s == "+.inf" || s == ".Inf" || s == ".INF") {
      return std::numeric_limits<double>::infinity();
    }
    if (s == "-.inf" || s == "-.Inf" || s == "-.INF") return -std::numeric_limits<double>::infinity();
    if (s == ".nan" || s == ".NaN" || s == ".NAN") return std::numeric_limits<double>::quiet_NaN();
    // Plain decimal or exponent notation only: from_chars alone would also
    // take "inf" and "nan", which YAML reads as strings.
    if (s.empty() || s.find_first_not_of("+-.0123456789eE") != std::string::npos ||
        s.find_first_of("0123456789") == std::string::npos) {
      return std::nullopt;
    }
    double value = 0.0;
    const char* begin = s.data() + (s.size() > 1 && s[0] == '+' ? 1 : 0);
    auto [end, ec] = std::from_chars(begin, s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return value;
  }

  fs::path file_;
  fs::path base_;
  std::vector<Override> overridden_;
};

// Stack names: explicit ones must be unique; the others take the corrector
// plugin name, with -2, -3, ... when that is taken.
void name_stacks(std::vector<StackConfig>& stacks) {
  std::map<std::string, SourceLocation> taken;
  for (const auto& s : stacks) {
    if (s.name.empty()) continue;
    auto [it, inserted] = taken.emplace(s.name, s.location);
    if (!inserted) {
      throw_config_error(s.location, "stack name '" + s.name + "' is already used by the stack at " +
                                         it->second.to_string() + " (stack names must be unique)");
    }
  }
  for (auto& s : stacks) {
    if (!s.name.empty()) continue;
    std::string name = s.corrector.plugin;
    for (int k = 2; taken.count(name); ++k) name = s.corrector.plugin + "-" + std::to_string(k);
    s.name = name;
    taken.emplace(name, s.location);
  }
}

// Values of one sweep axis: a list, or a range {from, to, step} (inclusive,
// to within 1e-9 of a step).
std::vector<std::string> sweep_values(const Reader& reader, const YAML::Node& node, const Path& path) {
  std::vector<std::string> values;
  if (node.IsSequence() && node.size() > 0) {
    for (const auto& v : node) {
      if (!v.IsScalar()) reader.fail(v, path, "sweep values must be plain values (numbers, true/false, names)");
      // Values are applied as override text (parsed as YAML again): keep
      // quoted scalars quoted so "true" stays a string.
      if (v.Tag() != "!") {
        values.push_back(v.Scalar());
        continue;
      }
      std::string quoted = "\"";
      for (char c : v.Scalar()) quoted += (c == '"' || c == '\\') ? std::string{'\\', c} : std::string{c};
      values.push_back(quoted + "\"");
    }
    return values;
  }
  if (!node.IsMap())
    reader.fail(node, path, "a sweep axis takes a non-empty list of values or a range {from, to, step}");
  reader.expect_map(node, path, "a sweep range", range_keys);
  for (const char* k : {"from", "to", "step"}) reader.require(node, path, k, "the sweep range", range_keys);
  const auto number = [&](const char* key) {
    const YAML::Node& v = node[key];
    try {
      const double x = v.as<double>();
      if (!std::isfinite(x)) throw YAML::Exception(v.Mark(), "not finite");
      return x;
    } catch (const YAML::Exception&) {
      reader.fail(v, child(path, key), "'" + std::string(key) + "' must be a finite number");
    }
  };
  const double from = number("from"), to = number("to"), step = number("step");
  if (!(step > 0.0) || to < from)
    reader.fail(node, path, "a sweep range needs step > 0 and to >= from");
  const double count = std::floor((to - from) / step + 1e-9) + 1.0;
  if (count > 10000) reader.fail(node, path, "a sweep range may hold at most 10000 values");
  for (int k = 0; k < static_cast<int>(count); ++k) {
    char buf[64];
    const double x = from + k * step;
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    values.emplace_back(buf, end);
  }
  return values;
}

std::vector<SweepAxis> read_sweep(const Reader& reader, const YAML::Node& sweep, std::size_t stacks) {
  const Path path = {"sweep"};
  if (!sweep.IsMap())
    reader.fail(sweep, path, "'sweep' must map parameter paths (stacks.<index or *>.corrector.params.NAME) to values");
  std::vector<SweepAxis> axes;
  for (const auto& entry : sweep) {
    const std::string key = entry.first.Scalar();
    SweepAxis axis;
    axis.location = reader.where(entry.first, child(path, key));
    try {
      axis.path = config_detail::split_key_path(key);
    } catch (const std::invalid_argument& e) {
      reader.fail(entry.first, child(path, key),
                  "sweep key '" + key + "' has " + e.what() + " (expected stacks.<index or *>.<path>, "
                  "e.g. stacks.0.corrector.params.delta)");
    }
    const auto& p = axis.path;
    bool index_ok = p.size() >= 3 && p[0] == "stacks";
    if (index_ok && p[1] != "*") {
      std::size_t i = 0;
      auto [end, ec] = std::from_chars(p[1].data(), p[1].data() + p[1].size(), i);
      index_ok = ec == std::errc() && end == p[1].data() + p[1].size() && i < stacks;
    }
    if (!index_ok)
      reader.fail(entry.first, child(path, key),
                  "sweep key '" + key + "' must be stacks.<index below " + std::to_string(stacks) +
                      " or *>.<path>, e.g. stacks.0.corrector.params.delta");
    axis.values = sweep_values(reader, entry.second, child(path, key));
    axes.push_back(std::move(axis));
  }
  return axes;
}

}  // namespace

namespace config_detail {

YAML::Node load_yaml(const fs::path& file) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    throw ConfigError(file.string() + ": cannot read the file");
  } catch (const YAML::Exception& e) {
    throw ConfigError(file.string() + ":" + std::to_string(e.mark.line + 1) + ": invalid YAML: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  return root;
}

StackConfig read_experiment_stack(const YAML::Node& root, const fs::path& file,
                                  const std::vector<Override>& overrides, std::size_t index) {
  const Reader reader(file, overrides);
  YAML::Node tree = YAML::Clone(root);
  apply_overrides(tree, overrides);
  const YAML::Node stacks = tree["stacks"];
  if (!stacks.IsSequence() || index >= stacks.size())
    reader.fail(stacks, {"stacks"}, "'stacks' has no entry " + std::to_string(index));
  return reader.read_stack(stacks[index], {"stacks", std::to_string(index)});
}

}  // namespace config_detail

StackConfig load_stack(const fs::path& file, const std::vector<Override>& overrides) {
  const Reader reader(file, overrides);
  const YAML::Node root = reader.load(overrides);
  StackConfig stack = reader.read_stack(root, {});
  if (stack.name.empty()) stack.name = file.stem().string();
  return stack;
}

ExperimentConfig load_experiment(const fs::path& file, const std::vector<Override>& overrides) {
  const Reader reader(file, overrides);
  const YAML::Node root = reader.load(overrides);
  reader.expect_map(root, {}, "an experiment", experiment_keys);

  ExperimentConfig config;
  config.file = file;
  config.name = root["experiment"] ? reader.read_string(root["experiment"], {"experiment"})
                                   : file.stem().string();

  reader.require(root, {}, "stacks", "the experiment", experiment_keys);
  const YAML::Node stacks = root["stacks"];
  if (!stacks.IsSequence() || stacks.size() == 0) {
    reader.fail(stacks, {"stacks"},
                "'stacks' must be a non-empty list of stacks, not " +
                    (stacks.IsSequence() ? std::string("an empty list") : describe_node(stacks)) +
                    " (each with keys: " + join(stack_keys) + ")");
  }
  for (std::size_t i = 0; i < stacks.size(); ++i) {
    config.stacks.push_back(reader.read_stack(stacks[i], {"stacks", std::to_string(i)}));
  }
  name_stacks(config.stacks);

  if (const YAML::Node outputs = root["outputs"]; outputs && !outputs.IsNull()) {
    const Path path = {"outputs"};
    reader.expect_map(outputs, path, "the outputs", output_keys);
    if (outputs["dir"]) config.outputs.dir = reader.read_string(outputs["dir"], child(path, "dir"));
    const std::pair<const char*, bool OutputsConfig::*> flags[] = {
        {"sketch_json", &OutputsConfig::sketch_json},
        {"stroke_csv", &OutputsConfig::stroke_csv},
        {"ply", &OutputsConfig::ply},
        {"obj", &OutputsConfig::obj},
        {"mlp", &OutputsConfig::mlp},
        {"pictures", &OutputsConfig::pictures},
        {"report", &OutputsConfig::report},
        {"timestamp", &OutputsConfig::timestamp}};
    for (const auto& [key, field] : flags) {
      if (outputs[key]) config.outputs.*field = reader.read_bool(outputs[key], child(path, key));
    }
  }

  // Files are looked up last, once the whole structure is known to be valid.
  reader.require(root, {}, "recordings", "the experiment", experiment_keys);
  const YAML::Node recordings = root["recordings"];
  const Path recordings_path = {"recordings"};
  std::vector<std::pair<YAML::Node, Path>> patterns;
  if (recordings.IsScalar()) {
    patterns.emplace_back(recordings, recordings_path);
  } else if (recordings.IsSequence() && recordings.size() > 0) {
    for (std::size_t i = 0; i < recordings.size(); ++i) {
      patterns.emplace_back(recordings[i], child(recordings_path, std::to_string(i)));
    }
  } else {
    reader.fail(recordings, recordings_path,
                "'recordings' must be a non-empty list of files or globs, not " +
                    (recordings.IsSequence() ? std::string("an empty list") : describe_node(recordings)) +
                    " (allowed: paths relative to the config file, with glob(3) wildcards *, ? and [...])");
  }
  for (const auto& [node, path] : patterns) {
    const std::string pattern = reader.read_string(node, path);
    try {
      for (auto& f : config_detail::expand_pattern(pattern, reader.base_for(node, path))) {
        config.recordings.push_back(std::move(f));
      }
    } catch (const std::runtime_error& e) {
      reader.fail(node, path, e.what());
    }
  }
  std::sort(config.recordings.begin(), config.recordings.end());
  config.recordings.erase(std::unique(config.recordings.begin(), config.recordings.end()),
                          config.recordings.end());

  if (const YAML::Node sweep = root["sweep"]; sweep && !sweep.IsNull())
    config.sweep = read_sweep(reader, sweep, config.stacks.size());
  config.overrides = overrides;

  YAML::Node resolved = YAML::Clone(root);
  resolved["recordings"] = YAML::Node(YAML::NodeType::Sequence);
  for (const auto& r : config.recordings) resolved["recordings"].push_back(r.string());
  YAML::Emitter out;
  out << resolved;
  config.resolved_yaml = std::string(out.c_str()) + "\n";
  return config;
}

}  // namespace sketchlab
