#pragma once
// Line-by-line reading of the text surface formats (OFF, OBJ, ascii PLY and STL): each line is
// split into whitespace-separated tokens, comments are stripped, and every parse error names
// the file and the 1-based line, e.g. "bunny.off:12: expected a number, got 'x'".
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace mrsim {

class TextLines {
 public:
  /// `comment`: a character that starts a comment to the end of the line ('\0': none).
  TextLines(std::string_view text, std::filesystem::path path, char comment);

  /// Advances to the next line holding at least one token; false at end of text.
  bool next();
  const std::vector<std::string_view>& tokens() const { return tokens_; }
  int line_number() const { return line_; }
  /// Byte offset just past the current line (where binary PLY data starts).
  std::size_t end_offset() const { return pos_; }

  double real(std::size_t index) const;
  std::int64_t integer(std::size_t index) const;
  /// Throws InputError "path:line: message".
  [[noreturn]] void fail(const std::string& message) const;
  /// Throws InputError "path: message" (errors not tied to a line, e.g. end of file).
  [[noreturn]] void fail_file(const std::string& message) const;

 private:
  std::string_view token(std::size_t index) const;
  std::string_view text_;
  std::filesystem::path path_;
  char comment_;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::vector<std::string_view> tokens_;
};

}  // namespace mrsim
