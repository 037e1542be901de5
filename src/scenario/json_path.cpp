#include "scenario/json_path.hpp"

namespace mrsim::scenario {

namespace {

std::string escape_token(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string unescape_token(const std::string& token) {
  std::string out;
  for (std::size_t i = 0; i < token.size(); ++i) {
    if (token[i] == '~' && i + 1 < token.size()) {
      out += token[i + 1] == '1' ? '/' : '~';
      ++i;
    } else {
      out += token[i];
    }
  }
  return out;
}

}  // namespace

std::string child_pointer(const std::string& parent, const std::string& key) {
  return parent + "/" + escape_token(key);
}

std::string child_pointer(const std::string& parent, std::size_t index) {
  return parent + "/" + std::to_string(index);
}

std::string parent_pointer(const std::string& pointer) {
  const auto slash = pointer.rfind('/');
  return slash == std::string::npos ? std::string{} : pointer.substr(0, slash);
}

std::vector<std::string> pointer_tokens(const std::string& pointer) {
  std::vector<std::string> tokens;
  std::size_t start = 1;
  while (start <= pointer.size() && !pointer.empty()) {
    const auto slash = pointer.find('/', start);
    const auto end = slash == std::string::npos ? pointer.size() : slash;
    tokens.push_back(unescape_token(pointer.substr(start, end - start)));
    start = end + 1;
  }
  return tokens;
}

bool is_same_or_below(const std::string& pointer, const std::string& ancestor) {
  if (pointer.compare(0, ancestor.size(), ancestor) != 0) return false;
  return pointer.size() == ancestor.size() || pointer[ancestor.size()] == '/';
}

std::string key_path(const std::string& pointer) {
  if (pointer.empty()) return "(document)";
  std::string out;
  for (const auto& token : pointer_tokens(pointer)) {
    if (!out.empty()) out += '.';
    out += token;
  }
  return out;
}

}  // namespace mrsim::scenario
