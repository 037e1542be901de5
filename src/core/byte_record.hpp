#pragma once
// A flat record of plain values and arrays, for results kept between runs in binary
// (simulation/result_cache.hpp): each array is its element count then its bytes, in this
// machine's representation (a cache never leaves the machine that wrote it, and its key holds
// the build). The reader checks every count against what is left and against a bound the
// caller gives, so a damaged record throws std::runtime_error instead of allocating or reading
// what is not there.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace mrsim {

class ByteRecordWriter {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <class T>
  void array(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    value(static_cast<std::uint64_t>(v.size()));
    if (!v.empty()) bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  std::string take() && { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class ByteRecordReader {
 public:
  explicit ByteRecordReader(std::string_view bytes) : rest_(bytes) {}

  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    std::memcpy(&v, take(sizeof v), sizeof v);
    return v;
  }
  /// An array of at most `most` elements.
  template <class T>
  std::vector<T> array(std::size_t most) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto n = value<std::uint64_t>();
    if (n > most || n > rest_.size() / sizeof(T))
      throw std::runtime_error("an array longer than it can be");
    std::vector<T> v(static_cast<std::size_t>(n));
    if (n > 0) std::memcpy(v.data(), take(v.size() * sizeof(T)), v.size() * sizeof(T));
    return v;
  }
  /// Throws unless every byte was read.
  void expect_end() const {
    if (!rest_.empty()) throw std::runtime_error("bytes after the record");
  }

 private:
  const char* take(std::size_t n) {
    if (n > rest_.size()) throw std::runtime_error("a truncated record");
    const char* p = rest_.data();
    rest_.remove_prefix(n);
    return p;
  }
  std::string_view rest_;
};

}  // namespace mrsim
