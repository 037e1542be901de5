#include "compare/diff_text.hpp"

#include "io/exact_number.hpp"

namespace mrsim {
namespace {

std::string quoted(const std::string& text) {
  constexpr std::size_t kMax = 80;
  std::string shown = text.size() > kMax ? text.substr(0, kMax - 3) + "..." : text;
  return "\"" + shown + "\"";
}

std::string both_values(const ValueArray& a, const ValueArray& b, std::size_t i) {
  return "A " + element_text(a, i) + ", B " + element_text(b, i);
}

std::string count_text(const ArrayDiff& d, const char* noun) {
  return std::to_string(d.differing) + " of " + std::to_string(d.total) + " " + noun + " differ";
}

std::string single_value_text(const ArrayDiff& d, const ValueArray& a, const ValueArray& b) {
  std::string text = both_values(a, b, 0);
  if (a.kind == ValueKind::Real)
    text += " (abs " + number_text(d.max_abs) + ", rel " + number_text(d.max_rel) + ")";
  return text;
}

}  // namespace

std::string number_text(double value) { return exact_number(value); }

std::string shape_text(const Shape& shape, const std::string& separator) {
  if (shape.empty()) return "scalar";
  std::string text = "[";
  for (std::size_t k = 0; k < shape.size(); ++k)
    text += (k > 0 ? separator : "") + std::to_string(shape[k]);
  return text + "]";
}

std::string index_text(std::size_t flat, const Shape& shape, const AxisNames& axes) {
  const std::vector<std::size_t> index = multi_index(flat, shape);
  if (axes.empty() || axes.size() < index.size()) {
    std::string text = "[";
    for (std::size_t k = 0; k < index.size(); ++k)
      text += (k > 0 ? ", " : "") + std::to_string(index[k]);
    return text + "]";
  }
  std::string text;
  for (std::size_t k = 0; k < index.size(); ++k) {
    if (k > 0 && k + 1 == index.size() && shape[k] == 1) break;
    text += (k > 0 ? " " : "") + axes[k] + " " + std::to_string(index[k]);
  }
  return text;
}

std::string element_text(const ValueArray& v, std::size_t i) {
  switch (v.kind) {
    case ValueKind::Real:
      return number_text(v.reals[i]);
    case ValueKind::Integer:
      return std::to_string(v.integers[i]);
    case ValueKind::Text:
      return quoted(v.texts[i]);
    case ValueKind::Bytes:
      return std::to_string(v.texts[i].size()) + " bytes";
  }
  return "?";
}

std::optional<std::string> layout_difference(const ValueArray& a, const ValueArray& b,
                                             const std::string& separator) {
  if (a.kind != b.kind)
    return std::string("types differ: A ") + kind_name(a.kind) + ", B " + kind_name(b.kind);
  if (a.shape != b.shape) {
    return "shapes differ: A " + shape_text(a.shape, separator) + ", B " +
           shape_text(b.shape, separator);
  }
  return std::nullopt;
}

std::string diff_text(const ArrayDiff& d, const ValueArray& a, const ValueArray& b,
                      const AxisNames& axes) {
  if (d.total == 1) return single_value_text(d, a, b);
  const auto at = [&](std::size_t i) { return index_text(i, a.shape, axes); };
  switch (a.kind) {
    case ValueKind::Real: {
      std::string text = count_text(d, "values") + "; max abs " + number_text(d.max_abs) + " at " +
                         at(d.abs_at) + " (" + both_values(a, b, d.abs_at) + "); max rel " +
                         number_text(d.max_rel) + " at " + at(d.rel_at);
      if (d.rel_at != d.abs_at) text += " (" + both_values(a, b, d.rel_at) + ")";
      return text;
    }
    case ValueKind::Integer:
      return count_text(d, "integers") + " (exact comparison); max abs " + number_text(d.max_abs) +
             " at " + at(d.abs_at) + " (" + both_values(a, b, d.abs_at) + ")";
    case ValueKind::Text:
      return count_text(d, "strings") + "; first at " + at(d.first) + " (" +
             both_values(a, b, d.first) + ")";
    case ValueKind::Bytes:
      return count_text(d, "binary values") + "; first at " + at(d.first);
  }
  return count_text(d, "values");
}

}  // namespace mrsim
