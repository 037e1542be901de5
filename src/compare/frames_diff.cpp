#include "compare/frames_diff.hpp"

#include <algorithm>
#include <map>

#include "compare/array_diff.hpp"
#include "compare/diff_text.hpp"
#include "compare/pvd_frames.hpp"
#include "compare/vtm_frames.hpp"
#include "core/vtk_module.hpp"

namespace mrsim {
namespace {

namespace fs = std::filesystem;

const char* const kShapeSeparator = "×";

// Matches items of A and B by name: A's order, then B's extras. Null where one side lacks it.
template <class T, class NameOf>
std::vector<std::pair<const T*, const T*>> pair_by_name(const std::vector<T>& a,
                                                        const std::vector<T>& b, NameOf name_of) {
  std::map<std::string, const T*> in_b;
  for (const T& item : b) in_b.emplace(name_of(item), &item);
  std::vector<std::pair<const T*, const T*>> pairs;
  for (const T& item : a) {
    const auto match = in_b.find(name_of(item));
    pairs.emplace_back(&item, match != in_b.end() ? match->second : nullptr);
    if (match != in_b.end()) in_b.erase(match);
  }
  for (const T& item : b) {
    if (in_b.count(name_of(item)) > 0) pairs.emplace_back(nullptr, &item);
  }
  return pairs;
}

ValueArray times_of(const std::vector<PvdFrame>& frames, std::size_t count) {
  ValueArray v{ValueKind::Real, {count}, {}, {}, {}};
  for (std::size_t i = 0; i < count; ++i) v.reals.push_back(frames[i].time);
  return v;
}

class FramesDiffer {
 public:
  FramesDiffer(const Tolerance& tolerance, CompareReport& report)
      : tolerance_(tolerance), report_(report) {}

  void run(const std::vector<PvdFrame>& a, const std::vector<PvdFrame>& b) {
    const std::size_t count = std::min(a.size(), b.size());
    compare_lists(a, b, count);
    for (std::size_t i = 0; i < count; ++i) {
      label_ = "frame " + std::to_string(frame_number(a[i].file, static_cast<long long>(i))) +
               " (t = " + number_text(a[i].time) + " s)";
      compare_frame(vtk_module().read_vtm_frame(a[i].file), vtk_module().read_vtm_frame(b[i].file));
    }
    report_.frames_compared(count);
  }

 private:
  void compare_lists(const std::vector<PvdFrame>& a, const std::vector<PvdFrame>& b,
                     std::size_t count) {
    report_.compared(Section::Frames, 2);
    if (a.size() != b.size()) {
      report_.add(Section::Frames,
                  {"frames.pvd", "A lists " + std::to_string(a.size()) + " frames, B " +
                                     std::to_string(b.size()) + "; the first " +
                                     std::to_string(count) + " are compared"});
    }
    const ValueArray times_a = times_of(a, count);
    const ValueArray times_b = times_of(b, count);
    const ArrayDiff d = diff_arrays(times_a, times_b, tolerance_);
    if (d.any())
      report_.add(Section::Frames,
                  {"frames.pvd timesteps", diff_text(d, times_a, times_b, {"entry"})});
  }

  void compare_frame(const std::vector<FrameBlock>& a, const std::vector<FrameBlock>& b) {
    for (const auto& [block_a, block_b] :
         pair_by_name(a, b, [](const FrameBlock& f) { return f.name; })) {
      if (block_a == nullptr || block_b == nullptr) {
        const std::string name = (block_a != nullptr ? block_a : block_b)->name;
        report_.compared(Section::Frames);
        add("block " + name, "", block_a != nullptr ? "only in A" : "only in B");
        continue;
      }
      compare_block(*block_a, *block_b);
    }
  }

  void compare_block(const FrameBlock& a, const FrameBlock& b) {
    const std::string block = "block " + a.name;
    // Arrays of blocks of different kinds or sizes cannot match: one line says why.
    if (a.type != b.type) {
      report_.compared(Section::Frames);
      return add(block, "", "types differ: A " + a.type + ", B " + b.type);
    }
    if (a.points != b.points || a.cells != b.cells) {
      report_.compared(Section::Frames);
      return add(block, "",
                 "sizes differ: A " + std::to_string(a.points) + " points, " +
                     std::to_string(a.cells) + " cells; B " + std::to_string(b.points) +
                     " points, " + std::to_string(b.cells) + " cells");
    }
    const auto label_of = [](const BlockArray& array) { return array.label; };
    for (const auto& [array_a, array_b] : pair_by_name(a.arrays, b.arrays, label_of)) {
      report_.compared(Section::Frames);
      if (array_a == nullptr || array_b == nullptr) {
        add(block + " " + (array_a != nullptr ? array_a : array_b)->label, "",
            array_a != nullptr ? "only in A" : "only in B");
        continue;
      }
      compare_array(block, *array_a, *array_b);
    }
  }

  void compare_array(const std::string& block, const BlockArray& a, const BlockArray& b) {
    const std::string series = block + " " + a.label;
    std::string shape = " ";  // appended: GCC 12 warns falsely on " " + string (bug 105651)
    shape += shape_text(a.values.shape, kShapeSeparator);
    if (const auto layout = layout_difference(a.values, b.values, kShapeSeparator))
      return add(series, shape, *layout);
    const ArrayDiff d = diff_arrays(a.values, b.values, tolerance_);
    if (d.any()) add(series, shape, diff_text(d, a.values, b.values, a.axes));
  }

  void add(const std::string& series, const std::string& shape, std::string detail) {
    report_.add_frame_difference(series, {label_ + " " + series + shape, std::move(detail)});
  }

  Tolerance tolerance_;
  CompareReport& report_;
  std::string label_;
};

}  // namespace

void diff_frames(const fs::path& run_a, const fs::path& run_b, const Tolerance& tolerance,
                 CompareReport& report) {
  const fs::path pvd_a = run_a / "frames.pvd";
  const fs::path pvd_b = run_b / "frames.pvd";
  std::error_code ec;
  const bool in_a = fs::exists(pvd_a, ec);
  const bool in_b = fs::exists(pvd_b, ec);
  if (!in_a && !in_b) return;
  if (in_a != in_b) {
    report.compared(Section::Frames);
    return report.add(Section::Frames, {"frames.pvd", in_a ? "only in A" : "only in B"});
  }
  FramesDiffer(tolerance, report).run(read_pvd_frames(pvd_a), read_pvd_frames(pvd_b));
}

}  // namespace mrsim
