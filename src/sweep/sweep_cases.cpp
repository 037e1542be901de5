#include "sweep/sweep_cases.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "scenario/yaml_emitter.hpp"

namespace mrsim::sweep {

namespace {

using nlohmann::json;

std::size_t product_count(const SweepSpec& spec) {
  std::size_t n = 1;
  for (const auto& p : spec.product) n *= p.values.size();
  return n;
}

// Mixed-radix digits of `combination`, last parameter fastest.
std::vector<std::pair<std::string, json>> product_row(const SweepSpec& spec,
                                                      std::size_t combination) {
  std::vector<std::pair<std::string, json>> row(spec.product.size());
  for (std::size_t k = spec.product.size(); k-- > 0;) {
    const auto& p = spec.product[k];
    row[k] = {p.key, p.values[combination % p.values.size()]};
    combination /= p.values.size();
  }
  return row;
}

std::string flow_yaml(const json& value) {
  std::string text;
  const bool list = value.is_array();
  for (const auto& item : value.items()) {
    if (!text.empty()) text += ", ";
    if (!list) text += scenario::yaml_string(item.key()) + ": ";
    text += yaml_value(item.value());
  }
  return list ? "[" + text + "]" : "{" + text + "}";
}

}  // namespace

std::vector<SweepCase> expand_cases(const SweepSpec& spec) {
  const std::size_t rows = spec.zip.empty() ? 1 : spec.zip.front().values.size();
  std::vector<SweepCase> cases;
  for (std::size_t c = 0; c < product_count(spec); ++c) {
    for (std::size_t r = 0; r < rows; ++r) {
      SweepCase one{static_cast<int>(cases.size()), product_row(spec, c)};
      for (const auto& z : spec.zip) one.params.emplace_back(z.key, z.values[r]);
      cases.push_back(std::move(one));
    }
  }
  return cases;
}

std::vector<std::string> parameter_keys(const SweepSpec& spec) {
  std::vector<std::string> keys;
  for (const auto& p : spec.product) keys.push_back(p.key);
  for (const auto& p : spec.zip) keys.push_back(p.key);
  return keys;
}

std::string yaml_value(const json& value) {
  if (value.is_number_float()) return scenario::yaml_float(value.get<double>());
  if (value.is_string()) return scenario::yaml_string(value.get<std::string>());
  if (value.is_array() || value.is_object()) return flow_yaml(value);
  return value.dump();  // integers, booleans, null
}

std::string plain_value(const json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) {
    const double v = value.get<double>();
    // Whole numbers as integers ("50000", not "5e+04"): what a table reader expects.
    if (v == std::trunc(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
  }
  return value.dump();
}

std::string case_name(int index) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "case_%04d", index);
  return buffer;
}

std::vector<std::string> case_overrides(const SweepSpec& spec, const SweepCase& c) {
  std::vector<std::string> overrides = spec.set;
  for (const auto& [key, value] : c.params) overrides.push_back(key + "=" + yaml_value(value));
  return overrides;
}

}  // namespace mrsim::sweep
