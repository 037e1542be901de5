// Issue 18 "your own fuzzers", the scenario half in its short, seeded form: mutations of the
// bundled scenarios (bit flips, truncation, deleted and duplicated lines, swapped scalars,
// extreme numbers, aliases, stray quotes and bytes) must either load or be refused with an
// InputError; nothing else may escape, and a scenario that loads holds no NaN or infinity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "scenario/scenario.hpp"
#include "test_support.hpp"

namespace mrsim {
namespace {

std::vector<std::string> bundled_texts() {
  std::vector<std::string> texts;
  for (const auto& e : std::filesystem::directory_iterator(test::source_dir() / "scenarios"))
    if (e.path().extension() == ".yaml") {
      std::ifstream in(e.path());
      std::stringstream ss;
      ss << in.rdbuf();
      texts.push_back(ss.str());
    }
  return texts;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);) lines.push_back(line);
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

// One mutation of `text`, chosen by `rng`.
std::string mutate(std::string text, std::mt19937& rng) {
  static const char* kScalars[] = {"1.0e+308",
                                   "-1.0e+308",
                                   "1.0e-320",
                                   ".nan",
                                   ".inf",
                                   "-0",
                                   "0",
                                   "null",
                                   "~",
                                   "''",
                                   "[]",
                                   "{}",
                                   "\"\\u0000\"",
                                   "*a",
                                   "&a 1",
                                   "0x7fffffff",
                                   "9223372036854775808",
                                   "true",
                                   "\"",
                                   "- -"};
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  if (text.empty()) return text;
  std::vector<std::string> lines = lines_of(text);
  switch (pick(7)) {
    case 0:  // bit flip
      text[pick(text.size())] ^= static_cast<char>(1u << pick(8));
      return text;
    case 1:  // truncation
      return text.substr(0, pick(text.size()));
    case 2:  // a line deleted
      lines.erase(lines.begin() + static_cast<long>(pick(lines.size())));
      return joined(lines);
    case 3:  // a line duplicated
      lines.insert(lines.begin() + static_cast<long>(pick(lines.size())),
                   lines[pick(lines.size())]);
      return joined(lines);
    case 4: {  // the value after a ':' replaced by a hostile scalar
      std::string& line = lines[pick(lines.size())];
      const auto colon = line.find(": ");
      if (colon != std::string::npos)
        line = line.substr(0, colon + 2) + kScalars[pick(std::size(kScalars))];
      return joined(lines);
    }
    case 5: {  // a stray byte inserted
      text.insert(pick(text.size()), 1, "\t\"'{[&*!|>%@`\x01\xff"[pick(15)]);
      return text;
    }
    default: {  // two lines swapped
      std::swap(lines[pick(lines.size())], lines[pick(lines.size())]);
      return joined(lines);
    }
  }
}

int env_or(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atoi(v) : fallback;
}

bool all_finite(const nlohmann::json& j) {
  if (j.is_number_float()) return std::isfinite(j.get<double>());
  if (j.is_structured())
    for (const auto& item : j)
      if (!all_finite(item)) return false;
  return true;
}

TEST(ScenarioFuzz, MutatedBundledScenariosLoadOrAreInputErrors) {
  const std::vector<std::string> texts = bundled_texts();
  ASSERT_GE(texts.size(), 5u);
  // Seeded: a few hundred inputs in ctest; scripts/fuzz_scenarios.sh sets more, and other seeds.
  const int inputs = env_or("MRSIM_FUZZ_INPUTS", 400);
  std::mt19937 rng(static_cast<unsigned>(env_or("MRSIM_FUZZ_SEED", 20261126)));
  const auto source = test::source_dir() / "scenarios" / "fuzzed.yaml";
  int loaded = 0, refused = 0;
  for (int k = 0; k < inputs; ++k) {
    std::string text = texts[static_cast<std::size_t>(k) % texts.size()];
    const int rounds = 1 + k % 3;
    for (int r = 0; r < rounds; ++r) text = mutate(text, rng);
    try {
      const Scenario sc = load_scenario_text(text, source);
      ++loaded;
      EXPECT_TRUE(all_finite(sc.resolved)) << "input " << k << " loaded with a NaN:\n" << text;
    } catch (const InputError&) {
      ++refused;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "input " << k << " escaped as " << e.what() << ":\n" << text;
    }
  }
  std::printf("scenario fuzz: %d inputs, %d loaded, %d refused with an input error\n", inputs,
              loaded, refused);
  EXPECT_GT(refused, inputs / 4);  // the mutations do break scenarios
  EXPECT_GT(loaded, inputs / 40);  // and some are harmless (the loader does not refuse all)
}

}  // namespace
}  // namespace mrsim
