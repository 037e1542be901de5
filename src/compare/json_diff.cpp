#include "compare/json_diff.hpp"

#include <set>

#include "io/exact_number.hpp"
#include "scenario/json_path.hpp"

namespace mrsim {
namespace {

using nlohmann::json;

constexpr std::size_t kMaxValueText = 80;
const char* const kMissing = "(missing)";

class JsonDiffer {
 public:
  JsonDiffer(const Tolerance& tolerance, const IgnoreKey& ignore)
      : tolerance_(tolerance), ignore_(ignore) {}

  void compare(const json& a, const json& b, const std::string& pointer) {
    if (a.is_object() && b.is_object()) return compare_objects(a, b, pointer);
    if (a.is_array() && b.is_array() && a.size() == b.size()) {
      for (std::size_t i = 0; i < a.size(); ++i)
        compare(a[i], b[i], scenario::child_pointer(pointer, i));
      return;
    }
    ++result_.compared;
    if (!leaves_equal(a, b)) add(pointer, json_value_text(a), json_value_text(b));
  }

  JsonDiff take() { return std::move(result_); }

 private:
  void compare_objects(const json& a, const json& b, const std::string& pointer) {
    std::set<std::string> keys;  // sorted: a stable report whatever the key order
    for (const auto& item : a.items()) keys.insert(item.key());
    for (const auto& item : b.items()) keys.insert(item.key());
    for (const std::string& key : keys) {
      const std::string child = scenario::child_pointer(pointer, key);
      if (ignore_ && ignore_(scenario::key_path(child), key)) {
        result_.ignored.push_back(scenario::key_path(child));
        continue;
      }
      const bool in_a = a.contains(key);
      const bool in_b = b.contains(key);
      if (in_a && in_b) {
        compare(a.at(key), b.at(key), child);
        continue;
      }
      ++result_.compared;
      add(child, in_a ? json_value_text(a.at(key)) : kMissing,
          in_b ? json_value_text(b.at(key)) : kMissing);
    }
  }

  bool leaves_equal(const json& a, const json& b) const {
    if (a.is_number_integer() && b.is_number_integer()) return a == b;  // counters: exactly
    if (a.is_number() && b.is_number()) return within(a.get<double>(), b.get<double>(), tolerance_);
    return a == b;
  }

  void add(const std::string& pointer, std::string a, std::string b) {
    result_.differences.push_back({scenario::key_path(pointer), std::move(a), std::move(b)});
  }

  Tolerance tolerance_;
  const IgnoreKey& ignore_;
  JsonDiff result_;
};

}  // namespace

JsonDiff diff_json(const json& a, const json& b, const Tolerance& tolerance,
                   const IgnoreKey& ignore) {
  JsonDiffer differ(tolerance, ignore);
  differ.compare(a, b, "");
  return differ.take();
}

std::string json_value_text(const json& value) {
  if (value.is_number_float()) return exact_number(value.get<double>());
  std::string text = value.dump();
  if (text.size() > kMaxValueText) text = text.substr(0, kMaxValueText - 3) + "...";
  return text;
}

}  // namespace mrsim
