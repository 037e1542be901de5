#include "compare/log_diff.hpp"

#include <algorithm>
#include <map>

#include "compare/array_diff.hpp"
#include "compare/diff_text.hpp"
#include "compare/hdf5_tree.hpp"
#include "compare/scenario_diff.hpp"

namespace mrsim {
namespace {

constexpr std::string_view kScenarioAttribute = "/@scenario";

struct ItemPair {
  std::string name;
  const Hdf5Item* a = nullptr;
  const Hdf5Item* b = nullptr;
};

// A's items in A's order, then those only B has.
std::vector<ItemPair> pair_items(const Hdf5Tree& a, const Hdf5Tree& b) {
  std::map<std::string, const Hdf5Item*> in_b;
  for (const Hdf5Item& item : b.items()) in_b[item.name] = &item;
  std::vector<ItemPair> pairs;
  for (const Hdf5Item& item : a.items()) {
    const auto match = in_b.find(item.name);
    pairs.push_back({item.name, &item, match != in_b.end() ? match->second : nullptr});
    if (match != in_b.end()) in_b.erase(match);
  }
  for (const Hdf5Item& item : b.items()) {
    if (in_b.count(item.name) > 0) pairs.push_back({item.name, nullptr, &item});
  }
  return pairs;
}

bool is_ignored(const std::string& name) {
  return std::find(kIgnoredLogItems.begin(), kIgnoredLogItems.end(), name) !=
         kIgnoredLogItems.end();
}

bool is_single_text(const ValueArray& v) {
  return v.kind == ValueKind::Text && v.texts.size() == 1;
}

std::string subject(const std::string& name, const ValueArray& v) {
  std::string text = "log.h5 " + name;
  if (!v.shape.empty()) {
    text += ' ';  // not " " + ...: GCC 12 warns falsely on it (bug 105651)
    text += shape_text(v.shape);
  }
  return text;
}

class LogDiffer {
 public:
  LogDiffer(const std::filesystem::path& a, const std::filesystem::path& b,
            const Tolerance& tolerance, CompareReport& report)
      : a_(a),
        b_(b),
        file_a_(a.string()),
        file_b_(b.string()),
        tolerance_(tolerance),
        report_(report) {}

  void run() {
    for (const ItemPair& pair : pair_items(a_, b_)) {
      if (is_ignored(pair.name)) {
        report_.ignore("log.h5 " + pair.name);
        continue;
      }
      report_.compared(Section::Log);
      if (pair.a == nullptr || pair.b == nullptr) {
        report_.add(Section::Log,
                    {"log.h5 " + pair.name, pair.a != nullptr ? "only in A" : "only in B"});
        continue;
      }
      compare(pair.name, a_.read(*pair.a), b_.read(*pair.b));
    }
  }

 private:
  void compare(const std::string& name, const ValueArray& a, const ValueArray& b) {
    if (name == kScenarioAttribute && is_single_text(a) && is_single_text(b))
      return compare_scenarios(a, b);
    if (const auto layout = layout_difference(a, b))
      return report_.add(Section::Log, {subject(name, a), *layout});
    const ArrayDiff d = diff_arrays(a, b, tolerance_);
    if (d.any()) report_.add(Section::Log, {subject(name, a), diff_text(d, a, b)});
  }

  void compare_scenarios(const ValueArray& a, const ValueArray& b) {
    const JsonDiff d = diff_scenarios({a.texts[0], file_a_ + " attribute scenario"},
                                      {b.texts[0], file_b_ + " attribute scenario"}, tolerance_);
    for (const std::string& path : d.ignored) report_.ignore("log.h5 /@scenario " + path);
    if (d.differences.empty()) return;
    std::vector<Difference> lines;
    for (const JsonDifference& key : d.differences) {
      lines.push_back({"log.h5 /@scenario " + key.path, "A " + key.a + ", B " + key.b});
    }
    report_.add_lines(Section::Log, std::move(lines));
  }

  Hdf5Tree a_;
  Hdf5Tree b_;
  std::string file_a_;
  std::string file_b_;
  Tolerance tolerance_;
  CompareReport& report_;
};

}  // namespace

void diff_logs(const std::filesystem::path& a, const std::filesystem::path& b,
               const Tolerance& tolerance, CompareReport& report) {
  LogDiffer(a, b, tolerance, report).run();
}

}  // namespace mrsim
