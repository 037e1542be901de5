#include "scenario/yaml_scalar.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <regex>

namespace mrsim::scenario {

namespace {

bool is_null(const std::string& s) {
  return s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL";
}

std::optional<bool> as_bool(const std::string& s) {
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  return std::nullopt;
}

bool is_non_finite(const std::string& s) {
  static const std::regex pattern(R"([-+]?\.(inf|Inf|INF)|\.(nan|NaN|NAN))");
  return std::regex_match(s, pattern);
}

std::optional<std::int64_t> parse_integer(const std::string& s, int base, std::size_t skip) {
  std::int64_t value = 0;
  const char* first = s.data() + skip;
  const char* last = s.data() + s.size();
  const auto [end, error] = std::from_chars(first, last, value, base);
  if (error == std::errc::result_out_of_range)
    throw ScalarError("integer '" + s + "' is out of range");
  if (error != std::errc{} || end != last) return std::nullopt;
  return value;
}

std::optional<std::int64_t> as_integer(const std::string& s) {
  static const std::regex decimal(R"([-+]?[0-9]+)");
  static const std::regex octal(R"(0o[0-7]+)");
  static const std::regex hex(R"(0x[0-9a-fA-F]+)");
  if (std::regex_match(s, decimal)) return parse_integer(s, 10, s[0] == '+' ? 1 : 0);
  if (std::regex_match(s, octal)) return parse_integer(s, 8, 2);
  if (std::regex_match(s, hex)) return parse_integer(s, 16, 2);
  return std::nullopt;
}

std::optional<double> as_float(const std::string& s) {
  static const std::regex pattern(R"([-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?)");
  if (!std::regex_match(s, pattern)) return std::nullopt;
  // from_chars rejects a leading '+', which YAML allows.
  const std::size_t skip = s[0] == '+' ? 1 : 0;
  double value = 0;
  const auto [end, error] =
      std::from_chars(s.data() + skip, s.data() + s.size(), value, std::chars_format::general);
  if (error == std::errc::result_out_of_range || !std::isfinite(value))
    throw ScalarError("number '" + s + "' is out of range (not a finite double)");
  if (error != std::errc{} || end != s.data() + s.size()) return std::nullopt;
  return value;
}

}  // namespace

nlohmann::json resolve_plain_scalar(const std::string& text) {
  if (is_null(text)) return nullptr;
  if (auto b = as_bool(text)) return *b;
  if (is_non_finite(text))
    throw ScalarError("'" + text + "' is not a finite number; only finite values are accepted");
  if (auto i = as_integer(text)) return *i;
  if (auto d = as_float(text)) return *d;
  return text;
}

}  // namespace mrsim::scenario
