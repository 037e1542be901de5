// load_scenario: the pipeline from a YAML file to the typed Scenario.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.hpp"
#include "scenario/defaults.hpp"
#include "scenario/json_path.hpp"
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

// `substeps: 512.0` is an integer for JSON Schema (draft 7: a number with no fraction), but
// valijson types it by its JSON representation: where the schema asks for an integer, an
// integral float becomes one before validation (issue 18 defect 10).
void integral_floats_to_integers(json& value, const json& document, const std::string& pointer) {
  if (value.is_object()) {
    for (auto& [key, item] : value.items())
      integral_floats_to_integers(item, document, scenario::child_pointer(pointer, key));
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      integral_floats_to_integers(value[i], document, scenario::child_pointer(pointer, i));
  } else if (value.is_number_float()) {
    const double x = value.get<double>();
    if (std::trunc(x) != x || std::abs(x) > 9.0e15) return;  // exact in a double and int64
    const json* node = scenario::schema_at(pointer, document);
    if (node && node->value("type", "") == "integer") value = static_cast<std::int64_t>(x);
  }
}

}  // namespace

Scenario load_scenario_text(std::string_view yaml, const fs::path& source,
                            const std::vector<std::string>& overrides) {
  auto [document, positions] = scenario::yaml_to_json(yaml, {source.string(), true, 0});
  scenario::apply_overrides(document, positions, overrides);
  integral_floats_to_integers(document, document, "");
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
