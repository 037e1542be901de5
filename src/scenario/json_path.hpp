#pragma once
// JSON pointers (RFC 6901) are the internal address of a value; key paths
// ("object.levels.0.mesh") are what users read in messages and write in `--set`.
#include <string>
#include <vector>

namespace mrsim::scenario {

/// "/a/b" + "c" -> "/a/b/c", escaping '~' and '/' in the key.
std::string child_pointer(const std::string& parent, const std::string& key);
std::string child_pointer(const std::string& parent, std::size_t index);
/// "/a/b/c" -> "/a/b"; "" stays "".
std::string parent_pointer(const std::string& pointer);
/// Unescaped reference tokens of a pointer: "/a/b~1c" -> {"a", "b/c"}.
std::vector<std::string> pointer_tokens(const std::string& pointer);
/// True when `pointer` is `ancestor` or lies below it.
bool is_same_or_below(const std::string& pointer, const std::string& ancestor);
/// "/object/levels/0/mesh" -> "object.levels.0.mesh"; the root is "(document)".
std::string key_path(const std::string& pointer);

}  // namespace mrsim::scenario
