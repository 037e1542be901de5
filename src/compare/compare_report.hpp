#pragma once
// What `mrsim compare` found: the differences in the order met, how many items of each kind
// were compared, what was deliberately left out, and the printed report. Per-frame VTU
// differences are capped per series (one block's one array across frames), so that a drift
// that grows over 1000 frames reads as 20 lines and a count rather than 1000 lines.
#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "compare/tolerance.hpp"

namespace mrsim {

enum class Section { Log, Scenario, Frames, Summary };

struct Difference {
  std::string subject;  // what: "log.h5 /frames/kinetic_energy [51]"
  std::string detail;   // how:  "3 of 51 values differ; ..."
};

class CompareReport {
 public:
  static constexpr std::size_t kFramesPerSeries = 20;

  CompareReport(std::string run_a, std::string run_b)
      : run_a_(std::move(run_a)), run_b_(std::move(run_b)) {}

  /// `count` more items of `section` were compared (a dataset, a key, a VTU array of a frame).
  void compared(Section section, std::size_t count = 1);
  /// One compared item differs; `line` says how.
  void add(Section section, Difference line) { add_lines(section, {std::move(line)}); }
  /// One compared item differs in several ways (the scenario attribute: one line per key).
  void add_lines(Section section, std::vector<Difference> lines);
  /// A VTU item of one frame differs; `series` names it across frames ("block level_2 point
  /// array displacement"). Past kFramesPerSeries frames of a series, it is only counted.
  void add_frame_difference(const std::string& series, Difference line);
  /// Something left out on purpose ("log.h5 /frames/wall_time"); listed once.
  void ignore(const std::string& what);
  void frames_compared(std::size_t frames) { frames_ = frames; }

  bool identical() const;
  std::size_t differing(Section section) const { return counts(section).differing; }
  std::size_t compared_count(Section section) const { return counts(section).compared; }
  const std::vector<Difference>& lines() const { return lines_; }

  /// The report: "A: ...", "B: ...", one line per difference, the capped series, the ignored
  /// items, and one summary line.
  void print(std::ostream& out, const Tolerance& tolerance) const;

 private:
  struct Counts {
    std::size_t compared = 0;
    std::size_t differing = 0;
  };
  struct Series {
    std::size_t shown = 0;
    std::size_t more = 0;
  };
  Counts& counts(Section section) { return counts_[static_cast<std::size_t>(section)]; }
  const Counts& counts(Section section) const { return counts_[static_cast<std::size_t>(section)]; }
  std::string summary_line(const Tolerance& tolerance) const;

  std::string run_a_;
  std::string run_b_;
  Counts counts_[4];
  std::vector<Difference> lines_;
  std::vector<std::string> series_order_;
  std::map<std::string, Series> series_;
  std::vector<std::string> ignored_;
  std::size_t frames_ = 0;
};

}  // namespace mrsim
