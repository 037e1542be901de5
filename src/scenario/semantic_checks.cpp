#include "scenario/semantic_checks.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "scenario/issues.hpp"
#include "scenario/json_path.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

constexpr const char* kAxes[] = {"x", "y", "z"};

void check_box(const json& box, const std::string& pointer, std::vector<Issue>& issues) {
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const double lo = box["min"][axis].get<double>(), hi = box["max"][axis].get<double>();
    if (lo > hi)
      issues.push_back({pointer, std::string("min must be <= max on every axis (") + kAxes[axis] +
                                     ": " + box["min"][axis].dump() + " > " +
                                     box["max"][axis].dump() + ")"});
  }
}

void check_half_space(const json& half_space, const std::string& pointer,
                      std::vector<Issue>& issues) {
  const json& n = half_space["normal"];
  if (n[0].get<double>() == 0 && n[1].get<double>() == 0 && n[2].get<double>() == 0)
    issues.push_back({child_pointer(pointer, "normal"), "must not be zero (it orients the plane)"});
}

void check_fixed(const json& document, std::vector<Issue>& issues) {
  const std::size_t levels = document["object"]["levels"].size();
  const json& fixed = document["fixed"];
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    const std::string pointer = child_pointer("/fixed", i);
    const json& region = fixed[i];
    if (region.contains("box")) check_box(region["box"], child_pointer(pointer, "box"), issues);
    if (region.contains("half_space"))
      check_half_space(region["half_space"], child_pointer(pointer, "half_space"), issues);
    if (region.contains("level") && region["level"].get<std::size_t>() >= levels)
      issues.push_back({child_pointer(pointer, "level"),
                        "no level " + region["level"].dump() + " (object.levels has " +
                            std::to_string(levels) + (levels == 1 ? " level)" : " levels)")});
  }
}

void check_loads(const json& document, std::vector<Issue>& issues) {
  const json& loads = document["loads"];
  for (std::size_t i = 0; i < loads.size(); ++i) {
    const std::string pointer = child_pointer("/loads", i);
    check_box(loads[i]["box"], child_pointer(pointer, "box"), issues);
    const json& profile = loads[i]["profile"];
    for (std::size_t k = 1; k < profile.size(); ++k)
      if (profile[k][0].get<double>() <= profile[k - 1][0].get<double>())
        issues.push_back({child_pointer(child_pointer(pointer, "profile"), k),
                          "times must increase (" + profile[k][0].dump() + " after " +
                              profile[k - 1][0].dump() + ")"});
  }
}

// More frames than this would overflow the frame counters (duration 8.589934610e+7 s ran 9
// frames) and could not be logged anyway: 1e8 rows of /frames are tens of GB.
constexpr double kMaxFrames = 1.0e8;

void check_time(const json& time, std::vector<Issue>& issues) {
  const double duration = time["duration"].get<double>(), frame_dt = time["frame_dt"].get<double>();
  if (duration < frame_dt)
    issues.push_back({"/time/duration", "must be >= time.frame_dt (" + time["duration"].dump() +
                                            " < " + time["frame_dt"].dump() + ")"});
  const double frames = duration / frame_dt;
  if (!(frames <= kMaxFrames)) {
    std::ostringstream os;
    os << std::setprecision(3) << "gives " << frames << " frames of time.frame_dt "
       << time["frame_dt"].dump() << " s; at most 1.0e+8 frames are run";
    issues.push_back({"/time/duration", os.str()});
  }
}

void check_material(const json& material, std::vector<Issue>& issues) {
  for (const auto& [key, value] : material["derived"].items())
    if (!std::isfinite(value.get<double>()))
      issues.push_back({"/material", "the elastic constants give a non-finite " + key});
}

void check_adaptivity(const json& document, std::vector<Issue>& issues) {
  const json& space = document["adaptivity"]["space"];
  const json& time = document["time"];
  if (document["adaptivity"]["time"]["enabled"].get<bool>() && time.contains("substeps")) {
    const auto n = time["substeps"].get<std::int64_t>();
    if ((n & (n - 1)) != 0)
      issues.push_back({"/time/substeps",
                        "must be a power of two with adaptivity.time.enabled (time levels halve "
                        "the step: frame_dt / 2^k), got " + std::to_string(n)});
  }
  if (document["adaptivity"]["time"]["enabled"].get<bool>() &&
      time["integrator"].get<std::string>() == "newton_cotes")
    issues.push_back({"/time/integrator",
                      "newton_cotes is a two-step scheme: every particle needs the same step, so "
                      "it does not run with adaptivity.time.enabled (use modified_euler)"});
  const auto checks = space["split_checks"].get<std::int64_t>();
  if ((checks & (checks - 1)) != 0)
    issues.push_back({"/adaptivity/space/split_checks",
                      "must be a power of two (the frame's steps are split into equal parts), "
                      "got " + std::to_string(checks)});
  else if (checks > 1 && document["adaptivity"]["time"]["enabled"].get<bool>())
    issues.push_back({"/adaptivity/space/split_checks",
                      "needs one global step: time levels run a whole frame's W-cycle at once "
                      "(set it to 1, or adaptivity.time.enabled to false)"});
  else if (checks > 1 && time.contains("substeps") &&
           time["substeps"].get<std::int64_t>() % checks != 0)
    issues.push_back({"/adaptivity/space/split_checks",
                      "must divide time.substeps (" + time["substeps"].dump() +
                          ") into equal parts, got " + std::to_string(checks)});
  const std::size_t levels = document["object"]["levels"].size();
  if (space.contains("max_level") && space["max_level"].get<std::size_t>() >= levels)
    issues.push_back({"/adaptivity/space/max_level",
                      "no level " + space["max_level"].dump() + " (object.levels has " +
                          std::to_string(levels) + (levels == 1 ? " level)" : " levels)")});
  if (space["coarsen_below"].get<double>() >= space["refine_above"].get<double>())
    issues.push_back({"/adaptivity/space/coarsen_below",
                      "must be below refine_above (" + space["coarsen_below"].dump() +
                          " >= " + space["refine_above"].dump() +
                          "): a point would split and merge back every frame"});
}

void check_tool(const json& tool, const std::string& pointer, std::vector<Issue>& issues) {
  const json& trajectory = tool["trajectory"];
  if (!trajectory.is_array()) return;
  const std::string keys = child_pointer(pointer, "trajectory");
  for (std::size_t k = 0; k < trajectory.size(); ++k) {
    if (k > 0 && trajectory[k]["t"].get<double>() <= trajectory[k - 1]["t"].get<double>())
      issues.push_back({child_pointer(child_pointer(keys, k), "t"),
                        "keyframe times must increase (" + trajectory[k]["t"].dump() + " after " +
                            trajectory[k - 1]["t"].dump() + ")"});
    if (trajectory[k].contains("orientation")) {
      double norm = 0;
      for (const json& c : trajectory[k]["orientation"]) norm += c.get<double>() * c.get<double>();
      if (!(norm > 1e-24))
        issues.push_back({child_pointer(child_pointer(keys, k), "orientation"),
                          "must not be zero (a unit quaternion [w, x, y, z])"});
    }
  }
}

// `tool` is the short form of a list of one; tool names name groups in log.h5.
void check_tools(const json& document, std::vector<Issue>& issues) {
  if (document.contains("tool") && !document["tools"].empty())
    issues.push_back({"/tools", "give either tool (one) or tools (a list), not both"});
  if (document.contains("tool")) check_tool(document["tool"], "/tool", issues);
  const json& tools = document["tools"];
  for (std::size_t i = 0; i < tools.size(); ++i) {
    check_tool(tools[i], child_pointer("/tools", i), issues);
    for (std::size_t j = 0; j < i; ++j)
      if (tools[i].contains("name") && tools[j].contains("name") && tools[i]["name"] == tools[j]["name"])
        issues.push_back({child_pointer(child_pointer("/tools", i), "name"),
                          "tool names must differ (" + tools[i]["name"].dump() + " is tools[" +
                              std::to_string(j) + "]'s)"});
  }
}

// The name becomes the folder out/<name>: "." and ".." would point elsewhere.
void check_name(const json& name, std::vector<Issue>& issues) {
  if (name == "." || name == "..")
    issues.push_back({"/name", "must not be '.' or '..' (it names the output folder out/<name>)"});
}

}  // namespace

void check_semantics(const json& document, const SourceMap& positions) {
  std::vector<Issue> issues;
  check_name(document["name"], issues);
  check_fixed(document, issues);
  check_loads(document, issues);
  check_tools(document, issues);
  check_time(document["time"], issues);
  check_material(document["material"], issues);
  check_adaptivity(document, issues);
  throw_if_any(positions, issues);
}

}  // namespace mrsim::scenario
