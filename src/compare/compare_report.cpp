#include "compare/compare_report.hpp"

#include <algorithm>

#include "compare/diff_text.hpp"

namespace mrsim {
namespace {

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// "log.h5 /a", "log.h5 /b", "summary.json c" -> "log.h5 /a, /b; summary.json c": each file named
// once (items are "FILE WHAT", grouped in order of first appearance).
std::string grouped(const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, std::string>> groups;
  for (const std::string& item : items) {
    const std::size_t space = item.find(' ');
    const std::string file = item.substr(0, space);
    const std::string what = space == std::string::npos ? "" : item.substr(space + 1);
    auto group =
        std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == file; });
    if (group == groups.end()) {
      groups.emplace_back(file, what);
    } else {
      group->second += ", ";
      group->second += what;
    }
  }
  std::string text;
  for (const auto& [file, what] : groups) {
    if (!text.empty()) text += "; ";
    text += file;
    text += ' ';
    text += what;
  }
  return text;
}

}  // namespace

void CompareReport::compared(Section section, std::size_t count) {
  counts(section).compared += count;
}

void CompareReport::add_lines(Section section, std::vector<Difference> lines) {
  ++counts(section).differing;
  for (Difference& line : lines) lines_.push_back(std::move(line));
}

void CompareReport::add_frame_difference(const std::string& series, Difference line) {
  ++counts(Section::Frames).differing;
  auto [it, added] = series_.try_emplace(series);
  if (added) series_order_.push_back(series);
  if (it->second.shown == kFramesPerSeries) {
    ++it->second.more;
    return;
  }
  ++it->second.shown;
  lines_.push_back(std::move(line));
}

void CompareReport::ignore(const std::string& what) {
  if (std::find(ignored_.begin(), ignored_.end(), what) == ignored_.end()) ignored_.push_back(what);
}

bool CompareReport::identical() const {
  return std::all_of(std::begin(counts_), std::end(counts_),
                     [](const Counts& c) { return c.differing == 0; });
}

std::string CompareReport::summary_line(const Tolerance& tolerance) const {
  const std::string within =
      "rtol=" + number_text(tolerance.rtol) + ", atol=" + number_text(tolerance.atol);
  const Counts& log = counts(Section::Log);
  const Counts& scenario = counts(Section::Scenario);
  const Counts& frames = counts(Section::Frames);
  const Counts& summary = counts(Section::Summary);
  const std::string vtu_frames = " in " + plural(frames_, "frame", "frames");
  if (identical()) {
    return "mrsim compare: identical within " + within + " (" +
           plural(log.compared, "log.h5 dataset or attribute", "log.h5 datasets and attributes") +
           ", " + plural(scenario.compared, "scenario key", "scenario keys") + ", " +
           plural(frames.compared, "VTU array", "VTU arrays") + vtu_frames + ", " +
           plural(summary.compared, "summary.json key", "summary.json keys") + ")";
  }
  const auto of = [](const Counts& c, const std::string& what) {
    return std::to_string(c.differing) + " of " + std::to_string(c.compared) + " " + what;
  };
  return "mrsim compare: " + of(log, "log.h5 datasets/attributes") + ", " +
         of(scenario, "scenario keys") + ", " + of(frames, "VTU arrays" + vtu_frames) + ", " +
         of(summary, "summary.json keys") + " differ (" + within + ")";
}

void CompareReport::print(std::ostream& out, const Tolerance& tolerance) const {
  out << "A: " << run_a_ << "\nB: " << run_b_ << '\n';
  for (const Difference& line : lines_) out << line.subject << ": " << line.detail << '\n';
  for (const std::string& name : series_order_) {
    const Series& s = series_.at(name);
    if (s.more > 0)
      out << name << ": and " << plural(s.more, "more frame", "more frames") << " differ\n";
  }
  if (!ignored_.empty()) out << "ignored: " << grouped(ignored_) << '\n';
  out << summary_line(tolerance) << '\n';
}

}  // namespace mrsim
