#include "compare/scenario_diff.hpp"

#include "scenario/yaml_to_json.hpp"

namespace mrsim {
namespace {

nlohmann::json parse(const YamlText& yaml) {
  scenario::YamlOptions options;
  options.origin = yaml.origin;
  return scenario::yaml_to_json(yaml.text, options).value;
}

// Where a run writes and how often it checkpoints change no result.
bool is_output_place(const std::string& path, const std::string&) {
  return path == "output.dir" || path == "output.checkpoint_every" ||
         path == "output.compression";
}

}  // namespace

JsonDiff diff_scenarios(const YamlText& a, const YamlText& b, const Tolerance& tolerance) {
  return diff_json(parse(a), parse(b), tolerance, is_output_place);
}

}  // namespace mrsim
