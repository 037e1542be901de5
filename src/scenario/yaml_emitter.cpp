#include "scenario/yaml_emitter.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "scenario/yaml_scalar.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

// "1e+05" -> "1.0e+5", "1000" -> "1000.0", "2.5e-07" -> "2.5e-7".
std::string normalise_float(const std::string& shortest) {
  const auto e = shortest.find('e');
  std::string mantissa = shortest.substr(0, e);
  if (mantissa.find('.') == std::string::npos) mantissa += ".0";
  if (e == std::string::npos) return mantissa;
  std::string exponent = shortest.substr(e + 1);
  const char sign = exponent[0] == '-' ? '-' : '+';
  if (exponent[0] == '-' || exponent[0] == '+') exponent.erase(0, 1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return mantissa + "e" + sign + exponent;
}

// Words PyYAML (YAML 1.1) reads as booleans or null although YAML 1.2 says string.
bool is_yaml11_word(const std::string& text) {
  static constexpr std::array<std::string_view, 25> words = {
      "y",   "Y",   "yes",  "Yes",  "YES",   "n",     "N",     "no",    "No",
      "NO",  "on",  "On",   "ON",   "off",   "Off",   "OFF",   "true",  "True",
      "TRUE", "false", "False", "FALSE", "null", "Null", "NULL"};
  return text == "~" || std::find(words.begin(), words.end(), text) != words.end();
}

bool is_ascii_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

bool is_word_char(char c) {
  return is_ascii_letter(c) || (c >= '0' && c <= '9') || c == '_' || c == '.' || c == '/' ||
         c == '-';
}

// (\.\.?/)?[A-Za-z_/][A-Za-z0-9_./-]*( [A-Za-z0-9_./-]+)*, scanned by hand: std::regex
// recurses once per character and a 30 000-character output.dir overflowed the stack.
bool has_plain_shape(const std::string& text) {
  std::size_t i = text.rfind("../", 0) == 0 ? 3 : text.rfind("./", 0) == 0 ? 2 : 0;
  if (i >= text.size() || !(is_ascii_letter(text[i]) || text[i] == '_' || text[i] == '/'))
    return false;
  for (++i; i < text.size(); ++i) {
    if (text[i] == ' ' && i + 1 < text.size() && is_word_char(text[i + 1])) continue;
    if (!is_word_char(text[i])) return false;
  }
  return true;
}

bool is_safe_plain(const std::string& text) {
  // Starts with a letter, '_', '/', "./" or "../" (not a digit, sign or lone '.': those may
  // read as numbers in one YAML version or the other); no characters YAML gives a meaning to.
  return has_plain_shape(text) && !is_yaml11_word(text) &&
         resolve_plain_scalar(text).is_string();
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (u < 0x20 || u == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += std::string("\\x") + hex[u >> 4] + hex[u & 15];
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string scalar_text(const json& value) {
  if (value.is_string()) return yaml_string(value.get<std::string>());
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_float()) return yaml_float(value.get<double>());
  if (value.is_number()) return value.dump();
  return "null";
}

bool is_scalar_list(const json& value) {
  return value.is_array() &&
         std::none_of(value.begin(), value.end(), [](const json& v) { return v.is_structured(); });
}

std::string flow_list(const json& list) {
  std::string out = "[";
  for (std::size_t i = 0; i < list.size(); ++i) out += (i ? ", " : "") + scalar_text(list[i]);
  return out + "]";
}

class Writer {
 public:
  explicit Writer(const std::vector<std::string>& order) : order_(order) {}

  void mapping(const json& map, std::size_t indent, std::string& out) const {
    for (const auto& key : ordered_keys(map)) {
      out += std::string(indent, ' ') + yaml_string(key) + ":";
      value(map[key], indent, out);
    }
  }

 private:
  // The value after "key:" (or "-"): inline when it is a scalar or short, below otherwise.
  void value(const json& v, std::size_t indent, std::string& out) const {
    if (v.is_object() && !v.empty()) {
      out += "\n";
      mapping(v, indent + 2, out);
    } else if (v.is_array() && !is_scalar_list(v)) {
      out += "\n";
      list(v, indent + 2, out);
    } else if (v.is_array()) {
      out += " " + flow_list(v) + "\n";
    } else {
      out += " " + (v.is_object() ? std::string("{}") : scalar_text(v)) + "\n";
    }
  }

  // "- " takes the place of the first two spaces of the item's first line.
  void list(const json& items, std::size_t indent, std::string& out) const {
    for (const auto& item : items) {
      if (item.is_object() && !item.empty()) {
        std::string block;
        mapping(item, indent + 2, block);
        out += std::string(indent, ' ') + "- " + block.substr(indent + 2);
      } else if (item.is_array() && !is_scalar_list(item)) {
        std::string block;
        list(item, indent + 2, block);
        out += std::string(indent, ' ') + "- " + block.substr(indent + 2);
      } else {
        out += std::string(indent, ' ') + "-";
        value(item, indent, out);
      }
    }
  }

  std::vector<std::string> ordered_keys(const json& map) const {
    std::vector<std::string> keys;
    for (const auto& [key, v] : map.items()) keys.push_back(key);
    auto rank = [&](const std::string& key) {
      return std::find(order_.begin(), order_.end(), key) - order_.begin();
    };
    std::stable_sort(keys.begin(), keys.end(),
                     [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
    return keys;
  }

  const std::vector<std::string>& order_;
};

}  // namespace

std::string yaml_float(double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("non-finite number in YAML output");
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return normalise_float(std::string(buffer, result.ptr));
}

std::string yaml_string(const std::string& text) {
  return is_safe_plain(text) ? text : quoted(text);
}

std::string to_block_yaml(const json& document, const std::vector<std::string>& key_order) {
  const Writer writer(key_order);
  if (document.is_object() && !document.empty()) {
    std::string out;
    writer.mapping(document, 0, out);
    return out;
  }
  return (document.is_structured() ? document.dump() : scalar_text(document)) + "\n";
}

}  // namespace mrsim::scenario
