#include "scenario/schema_validator.hpp"

#include <algorithm>
#include <charconv>
#include <memory>
#include <optional>
#include <string>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include "scenario/json_path.hpp"
#include "scenario/schema.hpp"
#include "scenario/violation_message.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

const valijson::Schema& compiled_schema() {
  // valijson schemas are built in place and not copyable; build once, keep for the process.
  static const std::unique_ptr<valijson::Schema> schema = [] {
    auto built = std::make_unique<valijson::Schema>();
    valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
    valijson::adapters::NlohmannJsonAdapter adapter(scenario_schema());
    parser.populateSchema(adapter, *built);
    return built;
  }();
  return *schema;
}

std::optional<std::size_t> parse_index(const std::string& token, std::size_t size) {
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), index);
  if (error != std::errc{} || end != token.data() + token.size() || index >= size)
    return std::nullopt;
  return index;
}

// valijson's own texts, without the "Failed to validate ... child/property/item" echoes of
// a nested failure: the last resort when no rebuilt message applies.
std::vector<Issue> raw_issues(const valijson::ValidationResults& results, const json& document) {
  std::vector<Issue> issues;
  for (const auto& error : results)
    if (error.description.rfind("Failed to validate", 0) != 0)
      issues.push_back({valijson_context_pointer(error.context, document), error.description});
  if (issues.empty()) issues.push_back({"", "does not match the scenario schema"});
  return issues;
}

// valijson matches "pattern" with std::regex, which recurses once per character: a name of
// 30 000 characters overflowed the stack (exit 139). No value of a scenario needs more than a
// path's length, so longer strings are refused before the schema is applied, where they are.
constexpr std::size_t kMaxText = 4096;         // PATH_MAX on Linux
constexpr std::size_t kMaxDescription = 65536;  // free text, never matched by a pattern

// The offset of the first byte that is not part of well-formed UTF-8 (no overlong forms, no
// surrogates, at most U+10FFFF), or npos.
std::size_t invalid_utf8_at(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    int more = 0;
    unsigned lo = 0x80, hi = 0xBF;  // the range of the second byte
    if (c < 0x80) {
      ++i;
      continue;
    } else if (c >= 0xC2 && c <= 0xDF) {
      more = 1;
    } else if (c >= 0xE0 && c <= 0xEF) {
      more = 2;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      more = 3;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    for (int k = 1; k <= more; ++k) {
      if (i + k >= s.size()) return i;
      const auto b = static_cast<unsigned char>(s[i + k]);
      if (k == 1 ? (b < lo || b > hi) : (b < 0x80 || b > 0xBF)) return i;
    }
    i += more + 1;
  }
  return std::string::npos;
}

// Text that would be copied into every output: no NUL or other control character (tabs and
// line breaks are fine), valid UTF-8 (issue 18 defect 9).
void check_text(const std::string& s, const std::string& pointer, std::vector<Issue>& out) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F) {
      out.push_back({pointer, "contains the control character " + std::to_string(c) +
                                  " at byte " + std::to_string(i) + "; write text only"});
      return;
    }
  }
  if (const std::size_t at = invalid_utf8_at(s); at != std::string::npos)
    out.push_back({pointer, "is not valid UTF-8 (byte " + std::to_string(at) + ")"});
}

void text_issues(const json& value, const std::string& pointer, bool free_text,
                  std::vector<Issue>& out) {
  if (value.is_string()) {
    const std::string& text = value.get_ref<const std::string&>();
    const std::size_t n = text.size();
    const std::size_t limit = free_text ? kMaxDescription : kMaxText;
    if (n > limit)
      out.push_back({pointer, "is " + std::to_string(n) + " bytes long; at most " +
                                  std::to_string(limit) + " are accepted"});
    else
      check_text(text, pointer, out);
  } else if (value.is_object()) {
    for (const auto& [key, item] : value.items())
      text_issues(item, child_pointer(pointer, key), key == "description", out);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      text_issues(value[i], child_pointer(pointer, i), false, out);
  }
}

}  // namespace

std::string valijson_context_pointer(const std::vector<std::string>& context,
                                     const json& document) {
  std::string pointer;
  const json* value = &document;
  for (const auto& part : context) {
    if (part.size() < 2 || part.front() != '[' || part.back() != ']') continue;
    const std::string token = part.substr(1, part.size() - 2);
    if (value->is_array()) {
      const auto index = parse_index(token, value->size());
      if (!index) break;
      pointer = child_pointer(pointer, *index);
      value = &(*value)[*index];
    } else if (value->is_object() && value->contains(token)) {
      pointer = child_pointer(pointer, token);
      value = &(*value)[token];
    } else {
      break;
    }
  }
  return pointer;
}

std::vector<Issue> schema_issues(const json& document) {
  std::vector<Issue> bad_text;
  text_issues(document, "", false, bad_text);
  if (!bad_text.empty()) return bad_text;
  valijson::Validator validator;
  valijson::ValidationResults results;
  valijson::adapters::NlohmannJsonAdapter adapter(document);
  if (validator.validate(compiled_schema(), adapter, &results)) return {};
  std::vector<std::string> flagged;
  for (const auto& error : results) {
    auto pointer = valijson_context_pointer(error.context, document);
    if (std::find(flagged.begin(), flagged.end(), pointer) == flagged.end())
      flagged.push_back(std::move(pointer));
  }
  std::vector<Issue> issues;
  for (const auto& pointer : flagged) {
    const json* node = schema_at(pointer, document);
    if (!node) continue;
    auto found = describe_violations(document.at(json::json_pointer(pointer)), *node, pointer);
    issues.insert(issues.end(), found.begin(), found.end());
  }
  return issues.empty() ? raw_issues(results, document) : issues;
}

void validate_against_schema(const json& document, const SourceMap& positions) {
  throw_if_any(positions, schema_issues(document));
}

}  // namespace mrsim::scenario
