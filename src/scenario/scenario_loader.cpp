// load_scenario: the pipeline from a YAML file to the typed Scenario.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.hpp"
#include "scenario/defaults.hpp"
#include "scenario/material.hpp"
#include "scenario/overrides.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_builder.hpp"
#include "scenario/schema.hpp"
#include "scenario/schema_validator.hpp"
#include "scenario/semantic_checks.hpp"
#include "scenario/yaml_emitter.hpp"
#include "scenario/yaml_to_json.hpp"

namespace mrsim {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Scenarios are a few kilobytes; a huge file is a wrong path (a mesh, a log), not a scenario.
constexpr std::uintmax_t kMaxScenarioBytes = 16u << 20;

std::string read_text_file(const fs::path& file) {
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (!fs::exists(status)) throw InputError(file.string() + ": no such file");
  if (fs::is_directory(status))
    throw InputError(file.string() + ": is a directory, expected a YAML scenario file");
  if (fs::file_size(file, ec) > kMaxScenarioBytes && !ec)
    throw InputError(file.string() + ": too large for a scenario file (over 16 MiB)");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot be opened for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(file.string() + ": read error");
  return text.str();
}

// Values the schema cannot default because they depend on other values.
void fill_computed_defaults(json& document) {
  if (!document["output"].contains("dir"))
    document["output"]["dir"] = "out/" + document["name"].get<std::string>();
  scenario::add_derived_elastic_constants(document["material"]);
}

}  // namespace

Scenario load_scenario_text(std::string_view yaml, const fs::path& source,
                            const std::vector<std::string>& overrides) {
  auto [document, positions] = scenario::yaml_to_json(yaml, {source.string(), true, 0});
  scenario::apply_overrides(document, positions, overrides);
  scenario::validate_against_schema(document, positions);
  scenario::inject_defaults(document);
  fill_computed_defaults(document);
  scenario::check_semantics(document, positions);
  return scenario::build_scenario(document, source);
}

Scenario load_scenario(const fs::path& file, const std::vector<std::string>& overrides) {
  return load_scenario_text(read_text_file(file), file, overrides);
}

std::string resolved_yaml(const Scenario& s) {
  return "# mrsim resolved scenario: every default explicit; material.derived holds both\n"
         "# elastic pairs. Schema: schemas/scenario.schema.json\n" +
         scenario::to_block_yaml(s.resolved, scenario::property_order());
}

fs::path schema_path() { return fs::path(MRSIM_SCHEMA_DIR) / "scenario.schema.json"; }

}  // namespace mrsim
