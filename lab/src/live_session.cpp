#include "sketchlab/lab/live_session.hpp"

#include <stdexcept>

namespace sketchlab {
namespace {

std::vector<StackInstance> require_stacks(std::vector<StackInstance> stacks) {
  if (stacks.empty()) throw std::invalid_argument("LiveSession: at least one stack is required");
  for (const auto& s : stacks)
    if (!s.corrector)
      throw std::invalid_argument("LiveSession: stack '" + s.name + "' has no corrector");
  return stacks;
}

}  // namespace

LiveSession::LiveSession(const RecordingHeader& header, std::vector<StackInstance> stacks,
                         const std::filesystem::path& recording, bool overwrite)
    : header_(header),
      stacks_(require_stacks(std::move(stacks))),
      writer_(recording, header, overwrite) {
  sessions_.reserve(stacks_.size());
  for (const auto& s : stacks_) sessions_.emplace_back(header_.workspace, s.corrector, s.surfacer, PreprocessParams{},
                           s.time_budget_s);
}

std::vector<StepReport> LiveSession::handle(const Event& event) {
  writer_.append(event);
  std::vector<StepReport> reports;
  reports.reserve(sessions_.size());
  for (auto& session : sessions_) reports.push_back(session.handle(event));
  return reports;
}

}  // namespace sketchlab
