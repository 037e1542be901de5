#pragma once
// A read position in an in-memory file, for text tokens and binary values alike (gmsh binary
// files mix both). Every read is bounds-checked and every failure throws InputError naming the
// file and the place (line for text, byte offset once binary data has been read), so a
// truncated or garbage file can never make a reader crash, loop or read past the end.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>

namespace mrsim {

class InputCursor {
 public:
  /// `comment`: a character that starts a comment running to the end of the line ('\0': none).
  InputCursor(std::string_view bytes, std::filesystem::path path, char comment = '\0');

  // --- text ---------------------------------------------------------------------------------
  /// True when only whitespace and comments remain.
  bool at_end();
  /// The next whitespace-separated token; `what` names it in the error at end of file.
  std::string_view token(std::string_view what);
  /// The next token without consuming it ("" at end of file).
  std::string_view peek_token();
  std::int64_t integer(std::string_view what);
  /// An integer in [lo, hi]: counts, dimensions and flags have a meaningful range.
  std::int64_t integer_in(std::string_view what, std::int64_t lo, std::int64_t hi);
  double real(std::string_view what);
  /// The next token must be `keyword` (exact match).
  void expect(std::string_view keyword);
  /// Only blanks or a comment may remain on the current line; consumes the newline.
  void end_line(std::string_view what);
  /// Moves just past the next occurrence of `marker`; false (position unchanged) if absent.
  bool skip_past(std::string_view marker);

  // --- binary -------------------------------------------------------------------------------
  void set_swap_bytes(bool swap) { swap_ = swap; }
  template <class T>
  T binary(std::string_view what) {
    static_assert(std::is_arithmetic_v<T>);
    if (remaining() < sizeof(T)) fail_truncated(what);
    T value;
    char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + pos_, sizeof(T));
    if (swap_) std::reverse(raw, raw + sizeof(T));
    std::memcpy(&value, raw, sizeof(T));
    pos_ += sizeof(T);
    in_binary_ = true;
    return value;
  }

  // --- bounds and errors --------------------------------------------------------------------
  std::size_t remaining() const { return bytes_.size() - pos_; }
  std::size_t offset() const { return pos_; }
  /// Rejects a count that cannot fit in the rest of the file, before anything is allocated
  /// for it: a lying header must give an error, not a multi-gigabyte allocation.
  void require_room(std::uint64_t count, std::size_t min_bytes_each, std::string_view what);
  [[noreturn]] void fail(std::string_view message) const;
  [[noreturn]] void fail_truncated(std::string_view what) const;
  const std::filesystem::path& path() const { return path_; }

 private:
  void skip_blanks_and_comments();
  std::string where() const;

  std::string_view bytes_;
  std::filesystem::path path_;
  char comment_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  bool swap_ = false;
  bool in_binary_ = false;  // line numbers are meaningless once binary data has been crossed
};

}  // namespace mrsim
