#pragma once
// A validation check leaves a record of what it measured, so docs/validation.md is generated
// from the tests (scripts/validation_report.py), never typed by hand.
//
// Each record is `<dir>/<id>.json`; a dynamic check adds `<dir>/<id>.csv` (header line of
// column names, then rows; the first column is the abscissa). `<dir>` is $MRSIM_VALIDATION_OUT
// or, by default, `<build>/validation`. The test still asserts on its own: the record is a
// report, written whether the check passes or fails.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrsim::validation {

struct Check {
  std::string id;        // file name, e.g. "beam_static_20x4x4"
  std::string group;     // section of the report, e.g. "Beam statics"
  std::string title;     // one line: what is checked, on which mesh
  std::string quantity;  // e.g. "tip deflection"
  std::string unit;      // e.g. "m", "Hz", "" for ratios
  double measured = 0;
  double reference = 0;
  std::string reference_source;  // e.g. "validation.md §2.3, CalculiX C3D4 same mesh"
  double lower = 0, upper = 0;   // the band the test asserts: lower <= measured <= upper
  std::string tolerance;         // the band in words, e.g. "±1 %"
  std::string note;              // optional remark (why this band)
};

/// The abscissa, then the curves, for the plot of a dynamic check.
struct Series {
  std::string x_label;               // e.g. "t (s)"
  std::string y_label;               // e.g. "tip deflection (m)"
  std::vector<std::string> columns;  // names: x first, then one per curve
  std::vector<std::vector<double>> rows;
  std::string kind = "line";  // "line" or "loglog"
};

inline std::filesystem::path record_dir() {
  const char* env = std::getenv("MRSIM_VALIDATION_OUT");
  std::filesystem::path dir = env && *env ? env : MRSIM_BINARY_DIR "/validation";
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_series(const std::string& id, const Series& s) {
  std::ofstream csv(record_dir() / (id + ".csv"));
  for (size_t c = 0; c < s.columns.size(); ++c) csv << (c ? "," : "") << s.columns[c];
  csv << '\n';
  csv.precision(10);
  for (const auto& row : s.rows) {
    for (size_t c = 0; c < row.size(); ++c) csv << (c ? "," : "") << row[c];
    csv << '\n';
  }
  if (!csv) throw std::runtime_error("cannot write validation series " + id);
}

/// Writes the record (and its series, if any); returns whether measured is within the band.
inline bool record(const Check& c, const Series* series = nullptr) {
  nlohmann::json j = {{"id", c.id},
                      {"group", c.group},
                      {"title", c.title},
                      {"quantity", c.quantity},
                      {"unit", c.unit},
                      {"measured", c.measured},
                      {"reference", c.reference},
                      {"reference_source", c.reference_source},
                      {"lower", c.lower},
                      {"upper", c.upper},
                      {"tolerance", c.tolerance},
                      {"note", c.note}};
  const bool pass = c.measured >= c.lower && c.measured <= c.upper;
  j["pass"] = pass;
  if (series) {
    write_series(c.id, *series);
    j["series"] = {{"file", c.id + ".csv"},
                   {"x_label", series->x_label},
                   {"y_label", series->y_label},
                   {"kind", series->kind}};
  }
  std::ofstream(record_dir() / (c.id + ".json")) << j.dump(2) << '\n';
  return pass;
}

}  // namespace mrsim::validation
