#include "meshing/text_lines.hpp"

#include <charconv>

#include "core/error.hpp"

namespace mrsim {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

TextLines::TextLines(std::string_view text, std::filesystem::path path, char comment)
    : text_(text), path_(std::move(path)), comment_(comment) {}

bool TextLines::next() {
  while (pos_ < text_.size()) {
    const std::size_t eol = text_.find('\n', pos_);
    const std::size_t end = eol == std::string_view::npos ? text_.size() : eol;
    std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = eol == std::string_view::npos ? text_.size() : eol + 1;
    ++line_;
    if (comment_ != '\0') line = line.substr(0, line.find(comment_));
    tokens_.clear();
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_blank(line[i])) ++i;
      const std::size_t start = i;
      while (i < line.size() && !is_blank(line[i])) ++i;
      if (i > start) tokens_.push_back(line.substr(start, i - start));
    }
    if (!tokens_.empty()) return true;
  }
  tokens_.clear();
  return false;
}

std::string_view TextLines::token(std::size_t index) const {
  if (index >= tokens_.size()) {
    fail("expected at least " + std::to_string(index + 1) + " values on the line, found " +
         std::to_string(tokens_.size()));
  }
  return tokens_[index];
}

double TextLines::real(std::size_t index) const {
  const std::string_view t = token(index);
  double value = 0.0;
  // from_chars accepts "nan" and "inf": non-finite coordinates are parsed and then rejected by
  // the surface checks with their own message.
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size()) {
    fail("expected a number, got '" + std::string(t) + "'");
  }
  return value;
}

std::int64_t TextLines::integer(std::size_t index) const {
  const std::string_view t = token(index);
  std::int64_t value = 0;
  const char* first = t.data();
  if (!t.empty() && t.front() == '+') ++first;
  const auto [end, ec] = std::from_chars(first, t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size()) {
    fail("expected an integer, got '" + std::string(t) + "'");
  }
  return value;
}

void TextLines::fail(const std::string& message) const {
  throw InputError(path_.string() + ":" + std::to_string(line_) + ": " + message);
}

void TextLines::fail_file(const std::string& message) const {
  throw InputError(path_.string() + ": " + message);
}

}  // namespace mrsim
