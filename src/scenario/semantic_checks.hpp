#pragma once
// Rules the schema cannot express (relations between values), checked on the document once
// it is schema-valid and its defaults are in.
#include <nlohmann/json.hpp>

#include "scenario/source_map.hpp"

namespace mrsim::scenario {

/// Name not "." or "..", box min <= max on every axis, half-space normal non-zero, fixed.level names an existing
/// level, time.duration >= time.frame_dt, derived elastic constants finite.
/// Throws InputError listing every violation with its place.
void check_semantics(const nlohmann::json& document, const SourceMap& positions);

}  // namespace mrsim::scenario
