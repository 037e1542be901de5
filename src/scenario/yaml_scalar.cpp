#include "scenario/yaml_scalar.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>

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

// Hand-written scanners, not std::regex: its matcher recurses once per character and a long
// scalar (30 000 digits) overflowed the stack.
bool is_digit(char c, int base) {
  if (base == 16) return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
  return c >= '0' && c < static_cast<char>('0' + base);
}

// s[from, to) is one or more digits of `base`.
bool all_digits(const std::string& s, std::size_t from, std::size_t to, int base) {
  if (from >= to) return false;
  for (std::size_t i = from; i < to; ++i)
    if (!is_digit(s[i], base)) return false;
  return true;
}

std::size_t sign_length(const std::string& s) {
  return !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
}

bool is_non_finite(const std::string& s) {
  const std::string rest = s.substr(sign_length(s));
  if (rest == ".inf" || rest == ".Inf" || rest == ".INF") return true;
  return s == ".nan" || s == ".NaN" || s == ".NAN";
}

// [-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?
bool is_float_text(const std::string& s) {
  std::size_t i = sign_length(s);
  const std::size_t n = s.size();
  std::size_t e = s.find_first_of("eE", i);
  if (e == std::string::npos) e = n;
  const std::size_t dot = s.find('.', i);
  if (dot < e) {
    const bool before = dot > i && all_digits(s, i, dot, 10);
    const bool after = dot + 1 < e && all_digits(s, dot + 1, e, 10);
    if (!(dot == i ? after : before && (after || dot + 1 == e))) return false;
  } else if (!all_digits(s, i, e, 10)) {
    return false;
  }
  if (e == n) return true;
  i = e + 1;
  if (i < n && (s[i] == '-' || s[i] == '+')) ++i;
  return all_digits(s, i, n, 10);
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
  if (all_digits(s, sign_length(s), s.size(), 10))
    return parse_integer(s, 10, s[0] == '+' ? 1 : 0);
  if (s.rfind("0o", 0) == 0 && all_digits(s, 2, s.size(), 8)) return parse_integer(s, 8, 2);
  if (s.rfind("0x", 0) == 0 && all_digits(s, 2, s.size(), 16)) return parse_integer(s, 16, 2);
  return std::nullopt;
}

std::optional<double> as_float(const std::string& s) {
  if (!is_float_text(s)) return std::nullopt;
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
