#pragma once
// Suggestions for misspelled keys and enum values ("did you mean 'every'?").
#include <optional>
#include <string>
#include <vector>

namespace mrsim::scenario {

/// Levenshtein distance (insertions, deletions, substitutions), case-insensitive.
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The candidate closest to `word` if it is close enough to be a plausible typo
/// (or one is a prefix of the other, e.g. "poisson" -> "poisson_ratio").
std::optional<std::string> closest_match(const std::string& word,
                                         const std::vector<std::string>& candidates);

}  // namespace mrsim::scenario
