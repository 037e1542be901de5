#include "compare/compare_runs.hpp"

#include <string>

#include "compare/frames_diff.hpp"
#include "compare/log_diff.hpp"
#include "compare/scenario_diff.hpp"
#include "compare/summary_diff.hpp"
#include "core/error.hpp"
#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

void check_run_folder(const fs::path& run) {
  std::error_code ec;
  if (!fs::exists(run, ec)) throw InputError(run.string() + ": no such folder");
  if (!fs::is_directory(run, ec)) throw InputError(run.string() + ": not a folder");
}

void report_json(const JsonDiff& d, Section section, const std::string& file,
                 CompareReport& report) {
  report.compared(section, d.compared);
  for (const std::string& path : d.ignored) report.ignore(file + " " + path);
  for (const JsonDifference& key : d.differences) {
    report.add(section, {file + " " + key.path, "A " + key.a + ", B " + key.b});
  }
}

void diff_scenario_files(const fs::path& a, const fs::path& b, const Tolerance& tolerance,
                         CompareReport& report) {
  const std::string text_a = read_whole_file(a / "scenario.yaml");
  const std::string text_b = read_whole_file(b / "scenario.yaml");
  const JsonDiff d = diff_scenarios({text_a, (a / "scenario.yaml").string()},
                                    {text_b, (b / "scenario.yaml").string()}, tolerance);
  report_json(d, Section::Scenario, "scenario.yaml", report);
}

nlohmann::json read_json(const fs::path& file) {
  try {
    return nlohmann::json::parse(read_whole_file(file));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not valid JSON: " + e.what());
  }
}

// A run killed before its end may lack summary.json: one missing is a difference, not an error.
void diff_summary_files(const fs::path& a, const fs::path& b, const Tolerance& tolerance,
                        CompareReport& report) {
  std::error_code ec;
  const bool in_a = fs::exists(a / "summary.json", ec);
  const bool in_b = fs::exists(b / "summary.json", ec);
  if (!in_a && !in_b) return;
  if (in_a != in_b) {
    report.compared(Section::Summary);
    return report.add(Section::Summary, {"summary.json", in_a ? "only in A" : "only in B"});
  }
  const JsonDiff d =
      diff_summaries(read_json(a / "summary.json"), read_json(b / "summary.json"), tolerance);
  report_json(d, Section::Summary, "summary.json", report);
}

}  // namespace

CompareReport compare_runs(const fs::path& run_a, const fs::path& run_b,
                           const Tolerance& tolerance) {
  check_run_folder(run_a);
  check_run_folder(run_b);
  CompareReport report(run_a.string(), run_b.string());
  diff_scenario_files(run_a, run_b, tolerance, report);
  diff_logs(run_a / "log.h5", run_b / "log.h5", tolerance, report);
  diff_frames(run_a, run_b, tolerance, report);
  diff_summary_files(run_a, run_b, tolerance, report);
  return report;
}

}  // namespace mrsim
