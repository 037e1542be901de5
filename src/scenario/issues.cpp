#include "scenario/issues.hpp"

#include <algorithm>
#include <tuple>

#include "core/error.hpp"
#include "scenario/json_path.hpp"

namespace mrsim::scenario {

namespace {

// Long cascades help nobody: the first problems are what the user fixes first.
constexpr std::size_t kMaxReported = 20;

}  // namespace

std::string format_issue(const SourceMap& positions, const Issue& issue) {
  return format_location(positions.find(issue.pointer)) + ": " + key_path(issue.pointer) + ": " +
         issue.message;
}

void throw_if_any(const SourceMap& positions, std::vector<Issue> issues) {
  if (issues.empty()) return;
  auto order = [&](const Issue& issue) {
    const Location where = positions.find(issue.pointer);
    return std::tuple(where.rank, where.line, where.column, issue.pointer);
  };
  std::stable_sort(issues.begin(), issues.end(),
                   [&](const Issue& a, const Issue& b) { return order(a) < order(b); });
  std::vector<std::string> lines;
  for (const auto& issue : issues) {
    std::string line = format_issue(positions, issue);
    if (std::find(lines.begin(), lines.end(), line) != lines.end()) continue;  // found twice
    if (lines.size() == kMaxReported) {
      lines.emplace_back("(further problems not shown)");
      break;
    }
    lines.push_back(std::move(line));
  }
  std::string text;
  for (const auto& line : lines) text += (text.empty() ? "" : "\n") + line;
  throw InputError(text);
}

}  // namespace mrsim::scenario
