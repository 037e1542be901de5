#include "sweep/sweep_spec.hpp"

#include <algorithm>
#include <fstream>
#include <memory>
#include <sstream>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include "core/error.hpp"
#include "scenario/issues.hpp"
#include "scenario/json_path.hpp"
#include "scenario/schema_validator.hpp"
#include "scenario/yaml_to_json.hpp"

namespace mrsim::sweep {

namespace {

using nlohmann::json;
using scenario::Issue;
using scenario::SourceMap;

const valijson::Schema& compiled_schema() {
  // valijson schemas are built in place and not copyable; build once, keep for the process.
  static const json document = json::parse(embedded_sweep_schema_text());
  static const std::unique_ptr<valijson::Schema> schema = [] {
    auto built = std::make_unique<valijson::Schema>();
    valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
    valijson::adapters::NlohmannJsonAdapter adapter(document);
    parser.populateSchema(adapter, *built);
    return built;
  }();
  return *schema;
}

// valijson reports an unknown top-level key at the root; naming the key at its own line is
// what the user needs.
std::vector<Issue> unknown_key_issues(const json& document) {
  static const json schema = json::parse(embedded_sweep_schema_text());
  std::vector<Issue> issues;
  if (!document.is_object()) return issues;
  for (const auto& item : document.items())
    if (!schema["properties"].contains(item.key()))
      issues.push_back({scenario::child_pointer("", item.key()),
                        "unknown key (known: base, output, set, product, zip)"});
  return issues;
}

// valijson repeats a nested failure once per enclosing level ("Failed to validate ...");
// only the innermost texts say what is wrong.
std::vector<Issue> schema_issues(const json& document) {
  valijson::Validator validator;
  valijson::ValidationResults results;
  valijson::adapters::NlohmannJsonAdapter adapter(document);
  if (validator.validate(compiled_schema(), adapter, &results)) return {};
  std::vector<Issue> issues = unknown_key_issues(document);
  for (const auto& error : results) {
    if (error.description.rfind("Failed to validate", 0) == 0) continue;
    std::string pointer = scenario::valijson_context_pointer(error.context, document);
    const bool echo = error.description.find("additionalProperties") != std::string::npos;
    if (pointer.empty() && echo) continue;  // an unknown key, already named at its own line
    issues.push_back({std::move(pointer), error.description});
  }
  if (issues.empty()) issues.push_back({"", "does not match the sweep schema"});
  return issues;
}

// nlohmann::json sorts keys; the file's order (by line, then column) is the case order.
std::vector<std::string> keys_in_file_order(const json& mapping, const std::string& pointer,
                                            const SourceMap& positions) {
  std::vector<std::string> keys;
  for (const auto& item : mapping.items()) keys.push_back(item.key());
  auto place = [&](const std::string& key) {
    const auto at = positions.find(scenario::child_pointer(pointer, key));
    return std::pair(at.line, at.column);
  };
  std::stable_sort(keys.begin(), keys.end(),
                   [&](const auto& a, const auto& b) { return place(a) < place(b); });
  return keys;
}

std::vector<Parameter> parameters(const json& document, const std::string& name,
                                  const SourceMap& positions) {
  std::vector<Parameter> result;
  if (!document.contains(name)) return result;
  const json& mapping = document.at(name);
  for (const auto& key : keys_in_file_order(mapping, "/" + name, positions)) {
    const json& list = mapping.at(key);
    result.push_back({key, std::vector<json>(list.begin(), list.end())});
  }
  return result;
}

// Rules JSON Schema cannot say: zip lists of one length, a key varied in one place only.
std::vector<Issue> consistency_issues(const SweepSpec& spec) {
  std::vector<Issue> issues;
  for (const auto& p : spec.zip) {
    if (p.values.size() == spec.zip.front().values.size()) continue;
    issues.push_back({scenario::child_pointer("/zip", p.key),
                      "zip lists must have the same length: " + std::to_string(p.values.size()) +
                          " values, but '" + spec.zip.front().key + "' has " +
                          std::to_string(spec.zip.front().values.size())});
  }
  for (const auto& p : spec.zip) {
    const bool twice = std::any_of(spec.product.begin(), spec.product.end(),
                                   [&](const Parameter& q) { return q.key == p.key; });
    if (twice)
      issues.push_back({scenario::child_pointer("/zip", p.key),
                        "'" + p.key + "' is varied in both product and zip"});
  }
  return issues;
}

}  // namespace

SweepSpec parse_sweep_text(std::string_view text, const std::filesystem::path& file) {
  const auto parsed = scenario::yaml_to_json(text, {file.string(), true, 0});
  scenario::throw_if_any(parsed.positions, schema_issues(parsed.value));
  const json& doc = parsed.value;
  SweepSpec spec;
  spec.file = file;
  spec.text = std::string(text);
  spec.base = file.parent_path() / doc.at("base").get<std::string>();
  spec.output = doc.value("output", std::string());
  if (doc.contains("set")) spec.set = doc.at("set").get<std::vector<std::string>>();
  spec.product = parameters(doc, "product", parsed.positions);
  spec.zip = parameters(doc, "zip", parsed.positions);
  scenario::throw_if_any(parsed.positions, consistency_issues(spec));
  return spec;
}

SweepSpec load_sweep(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError("cannot read sweep file " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return parse_sweep_text(text.str(), file);
}

}  // namespace mrsim::sweep
