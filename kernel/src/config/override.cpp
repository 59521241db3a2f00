#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "config_internal.hpp"

namespace sketchlab {

namespace {

std::string trim(const std::string& s) {
  auto begin = std::find_if_not(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); });
  auto end = std::find_if_not(s.rbegin(), s.rend(), [](unsigned char c) { return std::isspace(c); });
  return begin < end.base() ? std::string(begin, end.base()) : std::string();
}

std::string describe_override(const Override& o) {
  std::string key;
  for (const auto& part : o.path) key += (key.empty() ? "" : ".") + part;
  return "override '" + key + "=" + o.value + "'";
}

}  // namespace

Override parse_override(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) {
    throw ConfigError("command line: override '" + text + "' has no '=' (expected key.path=value)");
  }
  Override o;
  o.value = text.substr(eq + 1);
  try {
    o.path = config_detail::split_key_path(text.substr(0, eq));
  } catch (const std::invalid_argument& e) {
    throw ConfigError("command line: override '" + text + "' has " + e.what() +
                      " (expected key.path=value)");
  }
  return o;
}

namespace config_detail {

std::vector<std::string> split_key_path(const std::string& text) {
  const std::string key = trim(text);
  if (key.empty()) throw std::invalid_argument("an empty key");
  std::vector<std::string> path;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    const std::string part = trim(key.substr(start, dot == std::string::npos ? dot : dot - start));
    if (part.empty()) throw std::invalid_argument("an empty key segment in '" + key + "'");
    path.push_back(part);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return path;
}

void apply_overrides(YAML::Node& root, const std::vector<Override>& overrides) {
  for (const auto& o : overrides) {
    auto fail = [&](const std::string& why) -> void {
      throw ConfigError(o.origin.to_string() + ": " + describe_override(o) + ": " + why);
    };
    if (o.path.empty()) fail("empty key");

    YAML::Node value;
    try {
      value = YAML::Load(o.value);
    } catch (const YAML::Exception& e) {
      fail("value is not valid YAML: " + e.msg);
    }

    // Node handles share their target, so assigning through `node` edits
    // the tree in place (reset() rebinds a handle without touching data).
    YAML::Node node;
    node.reset(root);
    std::string walked;
    for (std::size_t i = 0; i < o.path.size(); ++i) {
      const std::string& step = o.path[i];
      const bool last = i + 1 == o.path.size();
      YAML::Node next;
      if (node.IsSequence()) {
        const bool digits = !step.empty() && std::all_of(step.begin(), step.end(), [](unsigned char c) {
          return std::isdigit(c);
        });
        const std::size_t size = node.size();
        if (!digits || step.size() > 9 || std::stoul(step) >= size) {
          fail("'" + step + "' is not an index of " + (walked.empty() ? "the list" : "'" + walked + "'") +
               " (allowed: 0 to " + std::to_string(size == 0 ? 0 : size - 1) +
               (size == 0 ? ", but the list is empty)" : ")"));
        }
        next.reset(node[std::stoul(step)]);
      } else if (node.IsMap() || node.IsNull() || !node.IsDefined()) {
        // A missing key (or a null value) becomes a map holding it.
        if (!node.IsMap()) node = YAML::Node(YAML::NodeType::Map);
        next.reset(node[step]);
      } else {
        fail("'" + walked + "' is a scalar, so it has no key '" + step + "'");
      }
      if (last) {
        next = value;
      } else {
        node.reset(next);
      }
      walked += (walked.empty() ? "" : ".") + step;
    }
  }
}

}  // namespace config_detail
}  // namespace sketchlab
