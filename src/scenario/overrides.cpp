#include "scenario/overrides.hpp"

#include <charconv>

#include "core/error.hpp"
#include "scenario/json_path.hpp"
#include "scenario/yaml_to_json.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

struct Override {
  std::string text;  // as given, for messages
  std::vector<std::string> path;
  std::string value;
  int rank = 0;
};

// "--set name=aaaa… (30005 characters)": messages stay readable whatever was given.
std::string label(const std::string& text) {
  constexpr std::size_t kShown = 60;
  if (text.size() <= kShown + 20) return "--set " + text;
  return "--set " + text.substr(0, kShown) + "… (" + std::to_string(text.size()) +
         " characters)";
}

[[noreturn]] void fail(const std::string& text, const std::string& message) {
  throw InputError(label(text) + ": " + message);
}

std::vector<std::string> split_path(const std::string& text, const std::string& path) {
  std::vector<std::string> keys;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    keys.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (keys.back().empty()) fail(text, "empty key in path '" + path + "'");
    if (dot == std::string::npos) return keys;
    start = dot + 1;
  }
}

Override parse_override(const std::string& text, int rank) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) fail(text, "expected key.path=value");
  if (eq == 0) fail(text, "empty key path before '='");
  Override o{text, split_path(text, text.substr(0, eq)), text.substr(eq + 1), rank};
  if (o.value.find_first_not_of(" \t") == std::string::npos)
    fail(text, "missing value after '=' (write \"\" for an empty string)");
  return o;
}

bool is_index(const std::string& key) {
  return key.find_first_not_of("0123456789") == std::string::npos;
}

std::size_t list_index(const Override& o, const std::string& key, const json& list,
                       const std::string& pointer) {
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), index);
  if (!is_index(key) || error != std::errc{} || end != key.data() + key.size())
    fail(o.text, key_path(pointer) + " is a list: expected an index, got '" + key + "'");
  if (index > list.size())
    fail(o.text, "index " + key + " is out of range (" + key_path(pointer) + " has " +
                     std::to_string(list.size()) + (list.size() == 1 ? " item)" : " items)"));
  return index;
}

// The slot `key` of `container`, created (as null) when absent; `pointer` is advanced.
json& step_into(const Override& o, json& container, const std::string& key, std::string& pointer) {
  if (container.is_object()) {
    pointer = child_pointer(pointer, key);
    return container[key];
  }
  if (!container.is_array())
    fail(o.text, "cannot set '" + key + "' inside " + key_path(pointer) +
                     ", which is not a mapping or a list");
  const std::size_t index = list_index(o, key, container, pointer);
  if (index == container.size()) container.push_back(nullptr);
  pointer = child_pointer(pointer, index);
  return container[index];
}

// `key=null` removes the key, so that its default (or mrsim's computed value, e.g.
// time.substeps) applies again; a key that is not there is left alone.
void remove_one(const Override& o, json& document, SourceMap& positions) {
  json* parent = &document;
  std::string pointer;
  for (std::size_t i = 0; i < o.path.size(); ++i) {
    const std::string& key = o.path[i];
    const bool last = i + 1 == o.path.size();
    if (parent->is_object()) {
      if (!parent->contains(key)) return;
      pointer = child_pointer(pointer, key);
      if (last) {
        parent->erase(key);
        break;
      }
      parent = &(*parent)[key];
    } else if (parent->is_array()) {
      const std::size_t index = list_index(o, key, *parent, pointer);
      if (index >= parent->size()) return;
      pointer = child_pointer(pointer, index);
      if (last) {
        parent->erase(index);
        break;
      }
      parent = &(*parent)[index];
    } else {
      return;
    }
  }
  positions.erase_subtree(pointer);
}

void apply_one(const Override& o, json& document, SourceMap& positions) {
  const Location origin{label(o.text), 0, 0, o.rank};
  const std::string& v = o.value;
  if (v == "null" || v == "Null" || v == "NULL" || v == "~")
    return remove_one(o, document, positions);
  const json value =
      yaml_to_json(o.value, YamlOptions{label(o.text), /*positions=*/false, o.rank}).value;
  json* slot = &document;
  std::string pointer;
  for (std::size_t i = 0; i < o.path.size(); ++i) {
    slot = &step_into(o, *slot, o.path[i], pointer);
    const bool last = i + 1 == o.path.size();
    // A place created on the way: a list if the next key is an index, else a mapping.
    if (!last && slot->is_null()) {
      *slot = is_index(o.path[i + 1]) ? json::array() : json::object();
      positions.set(pointer, origin);
    }
  }
  *slot = value;
  positions.erase_subtree(pointer);
  positions.set(pointer, origin);
}

}  // namespace

void apply_overrides(json& document, SourceMap& positions,
                     const std::vector<std::string>& overrides) {
  for (std::size_t i = 0; i < overrides.size(); ++i)
    apply_one(parse_override(overrides[i], static_cast<int>(i) + 1), document, positions);
}

}  // namespace mrsim::scenario
