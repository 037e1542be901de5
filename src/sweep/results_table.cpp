#include "sweep/results_table.hpp"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "sweep/case_folder.hpp"

namespace mrsim::sweep {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// CRLF, as RFC 4180 and Python's csv module (which wrote the plotting fixture) do.
constexpr const char* kEnd = "\r\n";

struct Row {
  std::string name;
  std::string status = "pending";
  std::optional<CaseStatus> ended;
  json summary;  // null when the case wrote none
};

json read_summary(const fs::path& folder) {
  std::ifstream in(folder / "summary.json", std::ios::binary);
  if (!in) return nullptr;
  json j = json::parse(in, nullptr, false);
  return j.is_object() ? j : json(nullptr);
}

Row read_row(const fs::path& sweep_dir, const SweepCase& c) {
  const fs::path folder = case_folder(sweep_dir, c.index);
  Row row;
  row.name = case_name(c.index);
  row.ended = read_status(folder);
  if (!row.ended) return row;  // pending or interrupted: figures would be partial
  const int code = row.ended->exit_code;
  row.status = code == 0 ? "done" : code == 130 || code == 143 ? "interrupted" : "failed";
  row.summary = read_summary(folder);
  return row;
}

// Numbers in nlohmann's shortest round-trip form; null (e.g. no tool) is an empty cell.
std::string number_cell(const json& summary, const std::string& key) {
  if (!summary.is_object() || !summary.contains(key)) return "";
  const json& v = summary[key];
  return v.is_number() ? v.dump() : "";
}

std::string active_cell(const json& summary, std::size_t level) {
  if (!summary.is_object() || !summary.contains("final_active")) return "";
  const json& list = summary["final_active"];
  return list.is_array() && level < list.size() ? list[level].dump() : "";
}

std::string evaluations_cell(const json& summary) {
  if (!summary.is_object() || !summary.contains("force_evaluations")) return "";
  const json& v = summary["force_evaluations"];
  if (v.is_number()) return v.dump();
  if (!v.is_array()) return "";
  long long total = 0;
  for (const auto& n : v) total += n.is_number() ? n.get<long long>() : 0;
  return std::to_string(total);
}

std::size_t level_count(const std::vector<Row>& rows) {
  std::size_t n = 0;
  for (const auto& row : rows)
    if (row.summary.is_object() && row.summary.contains("final_active"))
      n = std::max(n, row.summary["final_active"].size());
  return n;
}

std::string header(const std::vector<std::string>& keys, std::size_t levels) {
  std::string h = "case,status,exit_code,message";
  for (const auto& key : keys) h += "," + csv_field("param:" + key);
  h += ",peak_tool_force,max_displacement";
  for (std::size_t l = 0; l < levels; ++l) h += ",final_active_L" + std::to_string(l);
  return h + ",wall_time,real_time_factor,force_evaluations,steps,splits,merges" + kEnd;
}

std::string line(const Row& row, const SweepCase& c, std::size_t levels) {
  std::string l = row.name + "," + row.status + ",";
  if (row.ended) l += std::to_string(row.ended->exit_code);
  l += "," + csv_field(row.ended ? row.ended->message : "");
  for (const auto& param : c.params) l += "," + csv_field(plain_value(param.second));
  const json& s = row.summary;
  l += "," + number_cell(s, "peak_tool_force") + "," + number_cell(s, "max_displacement");
  for (std::size_t k = 0; k < levels; ++k) l += "," + active_cell(s, k);
  l += "," + number_cell(s, "wall_time") + "," + number_cell(s, "real_time_factor") + "," +
       evaluations_cell(s);
  for (const char* key : {"steps", "splits", "merges"}) l += "," + number_cell(s, key);
  return l + kEnd;
}

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

std::string results_csv(const fs::path& sweep_dir, const std::vector<std::string>& keys,
                        const std::vector<SweepCase>& cases) {
  std::vector<Row> rows;
  for (const auto& c : cases) rows.push_back(read_row(sweep_dir, c));
  const std::size_t levels = level_count(rows);
  std::string text = header(keys, levels);
  for (std::size_t i = 0; i < cases.size(); ++i) text += line(rows[i], cases[i], levels);
  return text;
}

std::string cases_csv(const std::vector<std::string>& keys, const std::vector<SweepCase>& cases) {
  std::string text = "case";
  for (const auto& key : keys) text += "," + csv_field(key);
  text += kEnd;
  for (const auto& c : cases) {
    text += case_name(c.index);
    for (const auto& param : c.params) text += "," + csv_field(plain_value(param.second));
    text += kEnd;
  }
  return text;
}

}  // namespace mrsim::sweep
