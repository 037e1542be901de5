#pragma once
// A sweep file (issue 8): the base scenario, the overrides common to every case and the
// parameters varied by `product` and `zip`, parsed and checked against
// schemas/sweep.schema.json with file:line:col messages like the scenario's.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace mrsim::sweep {

/// One varied scenario key and the values it takes, in the order of the file.
struct Parameter {
  std::string key;                    // dotted key path, e.g. "material.damping.psi"
  std::vector<nlohmann::json> values;  // as read from YAML (numbers, strings, lists...)
};

struct SweepSpec {
  std::filesystem::path file;          // the sweep file as given
  std::string text;                    // its contents (copied to DIR/sweep.yaml)
  std::filesystem::path base;          // base scenario, resolved against the file's folder
  std::string output;                  // default output folder ("" when the file has none)
  std::vector<std::string> set;        // overrides for every case
  std::vector<Parameter> product;      // in file order
  std::vector<Parameter> zip;          // in file order, all of the same length
};

/// The schema text embedded at build time (src/sweep/embedded_sweep_schema.cpp.in).
std::string_view embedded_sweep_schema_text();

/// Parses and validates sweep YAML already in memory; `file` names it in messages and
/// anchors `base`. Throws InputError (exit 2) listing every problem with its line:column.
SweepSpec parse_sweep_text(std::string_view text, const std::filesystem::path& file);

/// Reads `file` and parses it; a missing or unreadable file is an InputError.
SweepSpec load_sweep(const std::filesystem::path& file);

}  // namespace mrsim::sweep
