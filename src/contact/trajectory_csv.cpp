// Device recordings of a tool trajectory: `t, x, y, z[, qw, qx, qy, qz]` per line.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "contact/tool_trajectory.hpp"
#include "core/error.hpp"

namespace mrsim {

namespace {

constexpr std::string_view kSpace = " \t\r\v\f";

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(kSpace);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(kSpace) - first + 1);
}

// Comma separated when the line has a comma (spaces around commas allowed; an empty field is
// kept so it is reported), whitespace separated otherwise.
std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  const bool commas = line.find(',') != std::string_view::npos;
  const std::string_view seps = commas ? std::string_view(",") : kSpace;
  std::size_t start = 0;
  while (start <= line.size()) {
    const std::size_t end = std::min(line.find_first_of(seps, start), line.size());
    const std::string_view field = trim(line.substr(start, end - start));
    if (commas || !field.empty()) fields.push_back(field);
    start = end + 1;
  }
  return fields;
}

// Locale-independent (from_chars); accepts a leading '+', which from_chars does not.
bool parse_number(std::string_view s, double& value) {
  if (s.size() > 1 && s.front() == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  if (s.empty()) return false;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size();
}

class CsvReader {
 public:
  explicit CsvReader(std::filesystem::path file) : file_(std::move(file)) {}

  std::vector<Keyframe> read() {
    if (std::filesystem::is_directory(file_)) fail_file("is a directory, not a trajectory file");
    std::ifstream in(file_);
    if (!in) fail_file("cannot open the trajectory file");
    std::string line;
    while (std::getline(in, line)) {
      ++line_number_;
      read_line(line);
    }
    if (in.bad()) fail_file("cannot read the trajectory file");
    if (keys_.empty()) fail_file("no sample (only a header, comments or blank lines)");
    return std::move(keys_);
  }

 private:
  [[noreturn]] void fail_file(const std::string& reason) const {
    std::ostringstream msg;
    msg << file_.string() << ": " << reason;
    throw InputError(msg.str());
  }

  [[noreturn]] void fail_line(const std::string& reason) const {
    std::ostringstream msg;
    msg << file_.string() << ':' << line_number_ << ": " << reason;
    throw InputError(msg.str());
  }

  void read_line(std::string_view line) {
    line = trim(line.substr(0, line.find('#')));
    if (line.empty()) return;
    const std::vector<std::string_view> fields = split_fields(line);
    double first = 0;
    if (!seen_content_ && !parse_number(fields.front(), first)) {
      seen_content_ = true;  // the header: names only, nothing to check
      return;
    }
    seen_content_ = true;
    check_columns(fields.size());
    double values[8] = {0, 0, 0, 0, 1, 0, 0, 0};  // identity quaternion when absent
    for (std::size_t i = 0; i < fields.size(); ++i) values[i] = number(fields[i], i);
    add_sample(values);
  }

  void check_columns(std::size_t count) {
    if (count != 4 && count != 8) {
      std::ostringstream s;
      s << "expected 4 (t, x, y, z) or 8 (t, x, y, z, qw, qx, qy, qz) columns, found " << count;
      fail_line(s.str());
    }
    if (columns_ != 0 && count != columns_) {
      std::ostringstream s;
      s << count << " columns where the samples before have " << columns_;
      fail_line(s.str());
    }
    columns_ = count;
  }

  double number(std::string_view field, std::size_t column) const {
    double value = 0;
    std::ostringstream s;
    s << "column " << column + 1 << " '" << field << "' ";
    if (!parse_number(field, value)) fail_line(s.str() + "is not a number");
    if (!std::isfinite(value)) fail_line(s.str() + "is not finite");
    return value;
  }

  void add_sample(const double* v) {
    Keyframe key;
    key.t = v[0];
    key.position = Vec3(v[1], v[2], v[3]);
    key.orientation = Quat(v[4], v[5], v[6], v[7]);
    const double norm = key.orientation.norm();
    if (norm < 1e-12) fail_line("the quaternion is zero");
    key.orientation.coeffs() /= norm;
    if (!keys_.empty() && !(key.t > keys_.back().t)) {
      std::ostringstream s;
      s << std::setprecision(12) << "time " << key.t << " s is not after " << keys_.back().t
        << " s";
      fail_line(s.str());
    }
    keys_.push_back(key);
  }

  std::filesystem::path file_;
  int line_number_ = 0;
  bool seen_content_ = false;  // a header is only allowed before any other content
  std::size_t columns_ = 0;
  std::vector<Keyframe> keys_;
};

}  // namespace

std::vector<Keyframe> read_trajectory_csv(const std::filesystem::path& file) {
  return CsvReader(file).read();
}

}  // namespace mrsim
