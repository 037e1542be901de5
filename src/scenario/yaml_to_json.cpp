#include "scenario/yaml_to_json.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include <optional>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/error.hpp"
#include "scenario/json_path.hpp"
#include "scenario/yaml_scalar.hpp"

namespace mrsim::scenario {

namespace {

using nlohmann::json;

// A scenario is a handful of nested mappings; anything deeper is a mistake or an attack.
constexpr std::size_t kMaxDepth = 64;
// Caps alias expansion ("billion laughs"): each alias copies its anchored value.
constexpr std::size_t kMaxNodes = 1'000'000;

const std::string kCoreTag = "tag:yaml.org,2002:";

class JsonBuilder final : public YAML::EventHandler {
 public:
  JsonBuilder(const YamlOptions& options, std::string_view source)
      : options_(options), source_(source) {}

  bool has_value() const { return has_root_ && !document_.value.is_null(); }
  YamlDocument take() { return std::move(document_); }

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ == 1) first_document_ = mark;
    // yaml-cpp 0.7 can start endless empty documents at one place (e.g. on a stray ',' in
    // column 1) without consuming input: that is a syntax error, not a second document.
    else if (mark.pos == first_document_.pos)
      fail(mark, "YAML syntax error: unexpected character");
    else
      fail(mark, "a scenario holds a single YAML document, but a second one starts here");
  }
  void OnDocumentEnd() override {}
  void OnAnchor(const YAML::Mark& /*mark*/, const std::string& name) override {
    pending_anchor_name_ = name;
  }
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override;
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override;
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override;
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value style) override;
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value style) override;
  void OnMapEnd() override { close(); }

 private:
  struct Frame {
    json value;
    std::string pointer;
    YAML::anchor_t anchor = YAML::NullAnchor;
    std::size_t nodes_at_start = 0;
    std::optional<std::string> pending_key;  // mappings: the key waiting for its value
  };

  Location location(const YAML::Mark& mark) const;
  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& message) const;
  [[noreturn]] void fail_here(const YAML::Mark& mark, const std::string& message) const;
  std::string pending_pointer() const;
  bool expecting_key() const;
  void accept_key(const json& key, const YAML::Mark& mark);
  std::string next_pointer(const YAML::Mark& mark);
  void attach(json value);
  void add_leaf(json value, const YAML::Mark& mark, YAML::anchor_t anchor);
  void open(json container, const YAML::Mark& mark, YAML::anchor_t anchor);
  void close();
  void count_nodes(std::size_t count, const YAML::Mark& mark);
  void remember_anchor_name(YAML::anchor_t anchor);
  json typed_scalar(const YAML::Mark& mark, const std::string& tag, const std::string& text) const;
  void check_container_tag(const YAML::Mark& mark, const std::string& tag,
                           const std::string& kind) const;

  void check_closed_quote(const YAML::Mark& mark) const;

  const YamlOptions& options_;
  std::string_view source_;  // the text parsed, to check quoted scalars
  YamlDocument document_;
  bool has_root_ = false;
  int documents_ = 0;
  YAML::Mark first_document_;
  std::size_t nodes_ = 0;
  std::vector<Frame> stack_;
  std::unordered_map<YAML::anchor_t, json> anchored_;
  std::unordered_map<YAML::anchor_t, std::size_t> anchored_nodes_;
  std::unordered_map<YAML::anchor_t, std::string> anchor_names_;
  std::unordered_set<YAML::anchor_t> open_anchors_;  // anchors whose value is being built
  std::string pending_anchor_name_;
};

Location JsonBuilder::location(const YAML::Mark& mark) const {
  if (!options_.positions || mark.is_null()) return {options_.origin, 0, 0, options_.rank};
  return {options_.origin, mark.line + 1, mark.column + 1, options_.rank};
}

void JsonBuilder::fail(const YAML::Mark& mark, const std::string& message) const {
  throw InputError(format_location(location(mark)) + ": " + message);
}

// Errors about a value name the key path it would have had (an override's text already
// names its path).
void JsonBuilder::fail_here(const YAML::Mark& mark, const std::string& message) const {
  if (!options_.positions) fail(mark, message);
  fail(mark, key_path(pending_pointer()) + ": " + message);
}

std::string JsonBuilder::pending_pointer() const {
  if (stack_.empty()) return "";
  const Frame& parent = stack_.back();
  if (parent.value.is_object())
    return parent.pending_key ? child_pointer(parent.pointer, *parent.pending_key) : parent.pointer;
  return child_pointer(parent.pointer, parent.value.size());
}

bool JsonBuilder::expecting_key() const {
  return !stack_.empty() && stack_.back().value.is_object() && !stack_.back().pending_key;
}

void JsonBuilder::accept_key(const json& key, const YAML::Mark& mark) {
  if (!key.is_string())
    fail_here(mark, "mapping keys must be strings (got " +
                        (key.is_null() ? "an empty key" : key.dump()) + ")");
  Frame& map = stack_.back();
  const auto name = key.get<std::string>();
  const auto pointer = child_pointer(map.pointer, name);
  if (map.value.contains(name)) {
    const auto first = document_.positions.at(pointer);
    fail(mark, key_path(pointer) + ": duplicate key (first defined at " +
                   (first.line > 0
                        ? "line " + std::to_string(first.line) + ":" + std::to_string(first.column)
                        : "an earlier place") +
                   ")");
  }
  document_.positions.set(pointer, location(mark));
  map.pending_key = name;
}

// The pointer of the value about to be added; records its position unless the key did.
std::string JsonBuilder::next_pointer(const YAML::Mark& mark) {
  if (stack_.empty()) {
    document_.positions.set("", location(mark));
    return "";
  }
  const Frame& parent = stack_.back();
  if (parent.pending_key) return child_pointer(parent.pointer, *parent.pending_key);
  auto pointer = child_pointer(parent.pointer, parent.value.size());
  document_.positions.set(pointer, location(mark));
  return pointer;
}

void JsonBuilder::attach(json value) {
  if (stack_.empty()) {
    document_.value = std::move(value);
    has_root_ = true;
    return;
  }
  Frame& parent = stack_.back();
  if (parent.pending_key) {
    parent.value[*parent.pending_key] = std::move(value);
    parent.pending_key.reset();
  } else {
    parent.value.push_back(std::move(value));
  }
}

void JsonBuilder::count_nodes(std::size_t count, const YAML::Mark& mark) {
  nodes_ += count;
  if (nodes_ > kMaxNodes)
    fail_here(mark, "the document is too large (more than " + std::to_string(kMaxNodes) +
                        " values after expanding aliases)");
}

void JsonBuilder::remember_anchor_name(YAML::anchor_t anchor) {
  if (anchor == YAML::NullAnchor) return;
  anchor_names_[anchor] = pending_anchor_name_;
}

void JsonBuilder::add_leaf(json value, const YAML::Mark& mark, YAML::anchor_t anchor) {
  remember_anchor_name(anchor);
  next_pointer(mark);
  count_nodes(1, mark);
  if (anchor != YAML::NullAnchor) {
    anchored_[anchor] = value;
    anchored_nodes_[anchor] = 1;
  }
  attach(std::move(value));
}

void JsonBuilder::open(json container, const YAML::Mark& mark, YAML::anchor_t anchor) {
  remember_anchor_name(anchor);
  if (stack_.size() >= kMaxDepth)
    fail_here(mark, "nesting deeper than " + std::to_string(kMaxDepth) + " levels");
  auto pointer = next_pointer(mark);
  count_nodes(1, mark);
  if (anchor != YAML::NullAnchor) open_anchors_.insert(anchor);
  stack_.push_back(Frame{std::move(container), std::move(pointer), anchor, nodes_ - 1, {}});
}

void JsonBuilder::close() {
  Frame frame = std::move(stack_.back());
  stack_.pop_back();
  if (frame.anchor != YAML::NullAnchor) {
    anchored_[frame.anchor] = frame.value;
    anchored_nodes_[frame.anchor] = nodes_ - frame.nodes_at_start;
    open_anchors_.erase(frame.anchor);
  }
  attach(std::move(frame.value));
}

void JsonBuilder::OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) {
  if (expecting_key()) fail_here(mark, "mapping keys must be strings (got an empty key)");
  add_leaf(nullptr, mark, anchor);
}

void JsonBuilder::OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) {
  const std::string name = "*" + anchor_names_[anchor];
  if (open_anchors_.contains(anchor))
    fail_here(mark, "recursive alias " + name + ": it refers to a value that contains it");
  count_nodes(anchored_nodes_.at(anchor), mark);
  // A copy, so that later changes (defaults, overrides) to one place leave the other intact.
  json value = anchored_.at(anchor);
  if (expecting_key()) {
    accept_key(value, mark);
    return;
  }
  next_pointer(mark);
  attach(std::move(value));
}

void JsonBuilder::OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                           const std::string& text) {
  json value = typed_scalar(mark, tag, text);
  if (expecting_key()) {
    remember_anchor_name(anchor);
    if (anchor != YAML::NullAnchor) {
      anchored_[anchor] = value;
      anchored_nodes_[anchor] = 1;
    }
    accept_key(value, mark);
    return;
  }
  add_leaf(std::move(value), mark, anchor);
}

void JsonBuilder::OnSequenceStart(const YAML::Mark& mark, const std::string& tag,
                                  YAML::anchor_t anchor, YAML::EmitterStyle::value /*style*/) {
  if (expecting_key()) fail_here(mark, "mapping keys must be strings (got a list)");
  check_container_tag(mark, tag, "seq");
  open(json::array(), mark, anchor);
}

void JsonBuilder::OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                             YAML::EmitterStyle::value /*style*/) {
  if (expecting_key()) fail_here(mark, "mapping keys must be strings (got a mapping)");
  check_container_tag(mark, tag, "map");
  open(json::object(), mark, anchor);
}

void JsonBuilder::check_container_tag(const YAML::Mark& mark, const std::string& tag,
                                      const std::string& kind) const {
  if (tag == "?" || tag == "!" || tag == kCoreTag + kind) return;
  fail_here(mark, "unsupported YAML tag '" + tag + "'");
}

// Plain scalars are typed by the YAML 1.2 core schema; quoted ones ("!") are strings; the
// core tags (!!str, !!int, ...) force or check a type.
json JsonBuilder::typed_scalar(const YAML::Mark& mark, const std::string& tag,
                               const std::string& text) const {
  if (tag == "!") check_closed_quote(mark);
  if (tag == "!" || tag == kCoreTag + "str") return text;
  if (tag != "?" && tag.rfind(kCoreTag, 0) != 0)
    fail_here(mark, "unsupported YAML tag '" + tag + "'");
  json value;
  try {
    value = resolve_plain_scalar(text);
  } catch (const ScalarError& e) {
    fail_here(mark, e.what());
  }
  if (tag == "?") return value;
  const std::string kind = tag.substr(kCoreTag.size());
  if (kind == "float" && value.is_number()) return value.get<double>();
  if ((kind == "int" && value.is_number_integer()) || (kind == "bool" && value.is_boolean()) ||
      (kind == "null" && value.is_null()))
    return value;
  fail_here(mark, "'" + text + "' is not a valid !!" + kind);
}

// yaml-cpp 0.7 reads a quoted scalar that is never closed up to the end of the text: `dir:
// "out/beam` as the last key gave output.dir = `"out/beam every: 1 "` and exit 0. The closing
// quote must exist: '"' ends a double-quoted scalar unless escaped by '\\', '\'' ends a
// single-quoted one unless doubled.
void JsonBuilder::check_closed_quote(const YAML::Mark& mark) const {
  if (mark.pos < 0 || static_cast<std::size_t>(mark.pos) >= source_.size()) return;
  const char quote = source_[mark.pos];
  if (quote != '"' && quote != '\'') return;
  for (std::size_t i = mark.pos + 1; i < source_.size(); ++i) {
    if (quote == '"' && source_[i] == '\\') {
      ++i;
    } else if (source_[i] == quote) {
      if (quote == '\'' && i + 1 < source_.size() && source_[i + 1] == '\'') {
        ++i;
        continue;
      }
      return;
    }
  }
  fail_here(mark, std::string("unterminated quoted string: no closing ") + quote);
}

// Ignores every event: a first pass that only lets yaml-cpp find syntax errors.
class SyntaxOnly final : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

// Reads at most two documents: one is all a scenario may hold, a second is an error, and
// yaml-cpp may otherwise loop forever on some malformed input (see OnDocumentStart).
void parse_documents(const std::string& text, YAML::EventHandler& handler,
                     const YamlOptions& options) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  try {
    for (int document = 0; document < 2 && parser.HandleNextDocument(handler); ++document) {
    }
  } catch (const YAML::Exception& e) {
    Location where{options.origin, 0, 0, options.rank};
    if (options.positions && !e.mark.is_null()) {
      where.line = e.mark.line + 1;
      where.column = e.mark.column + 1;
    }
    throw InputError(format_location(where) + ": YAML syntax error: " + e.msg);
  }
}

}  // namespace

YamlDocument yaml_to_json(std::string_view text, const YamlOptions& options) {
  const std::string copy(text);
  // yaml-cpp reports a syntax error only after the events before it, which our checks
  // could misread ("[0, 0" looks like a list holding a mapping): find syntax errors first.
  SyntaxOnly syntax;
  parse_documents(copy, syntax, options);
  JsonBuilder builder(options, copy);
  parse_documents(copy, builder, options);
  if (!builder.has_value()) throw InputError(options.origin + ": empty YAML document");
  return builder.take();
}

}  // namespace mrsim::scenario
