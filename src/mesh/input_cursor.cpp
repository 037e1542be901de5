#include "mesh/input_cursor.hpp"

#include <charconv>

#include "mesh/mesh_input.hpp"

namespace mrsim {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

// from_chars rejects a leading '+', which C and Fortran writers may emit.
std::string_view without_plus(std::string_view token) {
  return (token.size() > 1 && token[0] == '+') ? token.substr(1) : token;
}

}  // namespace

InputCursor::InputCursor(std::string_view bytes, std::filesystem::path path, char comment)
    : bytes_(bytes), path_(std::move(path)), comment_(comment) {}

void InputCursor::skip_blanks_and_comments() {
  while (pos_ < bytes_.size()) {
    const char c = bytes_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (is_blank(c)) {
      ++pos_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

bool InputCursor::at_end() {
  skip_blanks_and_comments();
  return pos_ >= bytes_.size();
}

std::string_view InputCursor::token(std::string_view what) {
  skip_blanks_and_comments();
  if (pos_ >= bytes_.size()) fail_truncated(what);
  const std::string_view tok = peek_token();
  pos_ += tok.size();
  return tok;
}

std::string_view InputCursor::peek_token() {
  skip_blanks_and_comments();
  const std::size_t start = pos_;
  std::size_t end = pos_;
  while (end < bytes_.size() && !is_blank(bytes_[end]) && !(comment_ != '\0' && bytes_[end] == comment_)) ++end;
  return bytes_.substr(start, end - start);
}

std::int64_t InputCursor::integer(std::string_view what) {
  const std::string_view tok = without_plus(token(what));
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), value);
  if (ec != std::errc() || end != tok.data() + tok.size())
    fail(cat("expected ", what, " (an integer), found ", quoted_token(tok)));
  return value;
}

std::int64_t InputCursor::integer_in(std::string_view what, std::int64_t lo, std::int64_t hi) {
  const std::int64_t value = integer(what);
  if (value < lo || value > hi) fail(cat(what, " is ", value, ", expected a value in [", lo, ", ", hi, "]"));
  return value;
}

double InputCursor::real(std::string_view what) {
  const std::string_view tok = without_plus(token(what));
  double value = 0;
  // from_chars is locale-independent and correctly rounded: the same text gives the same bits
  // in every format, which the cross-format tests check.
  const auto [end, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), value);
  if (ec != std::errc() || end != tok.data() + tok.size())
    fail(cat("expected ", what, " (a number), found ", quoted_token(tok)));
  return value;
}

void InputCursor::expect(std::string_view keyword) {
  const std::string_view tok = token(keyword);
  if (tok != keyword) fail(cat("expected ", keyword, ", found ", quoted_token(tok)));
}

void InputCursor::end_line(std::string_view what) {
  while (pos_ < bytes_.size() && bytes_[pos_] != '\n') {
    const char c = bytes_[pos_];
    if (comment_ != '\0' && c == comment_) {
      while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      break;
    }
    if (!is_blank(c)) {
      std::size_t end = pos_;
      while (end < bytes_.size() && !is_blank(bytes_[end])) ++end;
      fail(cat("unexpected extra value ", quoted_token(bytes_.substr(pos_, end - pos_)), " after ", what));
    }
    ++pos_;
  }
  if (pos_ < bytes_.size()) {
    ++pos_;
    ++line_;
  }
}

bool InputCursor::skip_past(std::string_view marker) {
  const std::size_t found = bytes_.find(marker, pos_);
  if (found == std::string_view::npos) return false;
  if (!in_binary_) line_ += static_cast<std::size_t>(std::count(bytes_.begin() + pos_, bytes_.begin() + found, '\n'));
  pos_ = found + marker.size();
  return true;
}

void InputCursor::require_room(std::uint64_t count, std::size_t min_bytes_each, std::string_view what) {
  if (min_bytes_each == 0) min_bytes_each = 1;
  if (count > remaining() / min_bytes_each)
    fail(cat("the file announces ", count, " ", what, ", but only ", remaining(),
             " bytes remain: the count is wrong or the file is truncated"));
}

std::string InputCursor::where() const {
  return in_binary_ ? cat("byte ", pos_) : cat("line ", line_);
}

void InputCursor::fail(std::string_view message) const {
  throw mesh_error(path_, cat(where(), ": ", message));
}

void InputCursor::fail_truncated(std::string_view what) const {
  throw mesh_error(path_, cat(where(), ": unexpected end of file while reading ", what,
                              " (the file is truncated)"));
}

}  // namespace mrsim
