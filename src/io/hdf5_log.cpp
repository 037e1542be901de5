#include "io/hdf5_log.hpp"

#include <algorithm>
#include <cstddef>
#include <exception>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/error.hpp"
#include "core/log.hpp"
#include "io/frame_data_check.hpp"
#include "io/hdf5_attributes.hpp"
#include "io/hdf5_error.hpp"
#include "io/hdf5_event_table.hpp"
#include "io/hdf5_frame_table.hpp"
#include "io/hdf5_group.hpp"
#include "io/hdf5_level_group.hpp"
#include "io/hdf5_read.hpp"
#include "io/hdf5_tool_group.hpp"

namespace mrsim {

namespace {

// Bumped whenever the layout documented in docs/output.md changes incompatibly.
constexpr std::int64_t kLogFormatVersion = 1;

// Paged file space (HDF5 >= 1.10): metadata and small raw data are allocated in pages of this
// size, kept in a page buffer of kLogPageBuffer bytes, and each flush writes whole dirty pages.
// A frame's flush rewrites the tail chunks of ~25 tables and their metadata: 45 pwrite calls
// a frame before, 13 after (liver_probe, 16 KiB pages), and system calls are dear on a VM
// (2026-12-04: 232-236 -> 222 ms CPU for the whole run). The buffer bounds the memory.
constexpr hsize_t kLogPageSize = 16 * 1024;
constexpr std::size_t kLogPageBuffer = 1024 * 1024;

h5::Handle create_file(const std::string& file) {
  h5::silence_automatic_error_printing();
  const h5::Where where{file, ""};
  h5::Handle creation = h5::checked(H5Pcreate(H5P_FILE_CREATE), H5Pclose, where,
                                    "create file creation properties");
  h5::check(H5Pset_file_space_strategy(creation.get(), H5F_FSPACE_STRATEGY_PAGE, false, 1), where,
            "set paged file space");
  h5::check(H5Pset_file_space_page_size(creation.get(), kLogPageSize), where, "set page size");
  // Otherwise default access properties on purpose: the superblock stays at version 2, whose
  // "open for writing" mark HDF5 ignores, so the file of a killed run opens as is (version 3,
  // libver latest, would refuse it until h5clear).
  h5::Handle access = h5::checked(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, where,
                                  "create file access properties");
  h5::check(H5Pset_page_buffer_size(access.get(), kLogPageBuffer, 0, 0), where,
            "set page buffer");
  return h5::checked(H5Fcreate(file.c_str(), H5F_ACC_TRUNC, creation.get(), access.get()),
                     H5Fclose, where, "create file");
}

// Without a page buffer: in HDF5 1.10.8 a speculative read through one can run past the page's
// end (HDF5 pull request 4279, 2024), and a resumed run reads headers it did not write.
h5::Handle open_file(const std::string& file) {
  h5::silence_automatic_error_printing();
  return h5::checked(H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose, {file, ""},
                     "open file to resume the run");
}

// The log of the same run: same format, and the levels, time levels and tools of the header.
void check_resumable(hid_t file_id, const Hdf5LogHeader& header, const std::string& file) {
  const h5::Where root{file, "/"};
  const std::int64_t version = h5::read_int64_attribute(file_id, "format_version", root);
  if (version != kLogFormatVersion)
    throw RunError(file + ": log format version " + std::to_string(version) + ", not " +
                   std::to_string(kLogFormatVersion));
  if (h5::read_string_attribute(file_id, "scenario", root) != header.scenario_yaml)
    throw RunError(file + ": written for another scenario than the one resumed");
}

void write_header_attributes(hid_t file_id, const Hdf5LogHeader& header, const std::string& file) {
  const h5::Where root{file, "/"};
  h5::set_string_attribute(file_id, "mrsim_version", header.version, root);
  h5::set_string_attribute(file_id, "git_revision", header.git_revision, root);
  h5::set_string_attribute(file_id, "scenario", header.scenario_yaml, root);
  h5::set_string_attribute(file_id, "start_time", header.start_time, root);
  h5::set_int64_attribute(file_id, "format_version", kLogFormatVersion, root);
}

}  // namespace

struct Hdf5Log::Impl {
  std::string file;
  h5::Handle file_id;
  h5::Handle levels_group;
  std::vector<h5::LevelGroup> levels;
  std::vector<std::size_t> points_per_level;
  std::optional<h5::FrameTable> frames;
  std::optional<h5::EventTable> events;
  std::vector<h5::ToolGroup> tools;

  // keep == nullptr: a new log; else the existing one, cut to `keep`.
  Impl(const std::filesystem::path& path, const Hdf5LogHeader& header, const Hdf5LogRows* keep)
      : file(path.string()), file_id(keep ? open_file(file) : create_file(file)) {
    bool created = true;
    if (keep) {
      check_resumable(file_id.get(), header, file);
    } else {
      write_header_attributes(file_id.get(), header, file);
    }
    levels_group = h5::open_or_create_group(file_id.get(), "levels", {file, "/levels"}, created);
    if (created)
      h5::set_int64_attribute(levels_group.get(), "count",
                              static_cast<std::int64_t>(header.levels.size()), {file, "/levels"});
    for (std::size_t k = 0; k < header.levels.size(); ++k) {
      if (header.levels[k] == nullptr) throw std::invalid_argument("Hdf5Log: level without mesh");
      levels.emplace_back(levels_group.get(), static_cast<int>(k), *header.levels[k], file);
      if (!keep && k < header.level_attributes.size())
        for (const NamedValues& a : header.level_attributes[k])
          levels.back().set_attribute(a.name, a.values);
      points_per_level.push_back(levels.back().points());
    }
    if (header.time_level_steps.empty())
      throw std::invalid_argument("Hdf5Log: no time level step");
    frames.emplace(file_id.get(), header.levels.size(), header.time_level_steps,
                   header.tools.size(), file);
    events.emplace(file_id.get(), file);
    tools.reserve(header.tools.size());
    for (std::size_t k = 0; k < header.tools.size(); ++k) {
      tools.emplace_back(file_id.get(), static_cast<int>(k), header.tools[k].name,
                         header.tools[k].shape, file);
    }
    if (keep) truncate(*keep);
    flush();  // the header alone is already a valid, readable file
  }

  void truncate(const Hdf5LogRows& keep) {
    if (keep.tool_samples.size() != tools.size())
      throw RunError(file + ": " + std::to_string(keep.tool_samples.size()) +
                     " tool sample counts for " + std::to_string(tools.size()) + " tools");
    const auto rows = [](std::int64_t n) { return static_cast<hsize_t>(std::max<std::int64_t>(n, 0)); };
    // Every table checked before any is cut: a refused log stays as it was.
    bool enough = frames->rows() >= rows(keep.frames) && events->rows() >= rows(keep.events);
    for (const h5::LevelGroup& level : levels) enough = enough && level.rows() >= rows(keep.frames);
    for (std::size_t k = 0; k < tools.size(); ++k)
      enough = enough && tools[k].rows() >= rows(keep.tool_samples[k]);
    if (!enough)
      throw RunError(file + " holds fewer frames, events or tool samples than the checkpoint "
                     "counts: it is not the log the checkpoint was written with");
    for (h5::LevelGroup& level : levels) level.truncate(rows(keep.frames));
    frames->truncate(rows(keep.frames));
    events->truncate(rows(keep.events));
    for (std::size_t k = 0; k < tools.size(); ++k) tools[k].truncate(rows(keep.tool_samples[k]));
  }

  void flush() {
    h5::check(H5Fflush(file_id.get(), H5F_SCOPE_GLOBAL), {file, ""}, "flush file");
  }

  // Children first: HDF5 keeps a file open while any object in it is open.
  void close() {
    for (h5::ToolGroup& tool : tools) tool.close();
    events->close();
    frames->close();
    for (h5::LevelGroup& level : levels) level.close();
    h5::check(levels_group.close(), {file, "/levels"}, "close group");
    h5::check(file_id.close(), {file, ""}, "close file");
  }
};

Hdf5Log::Hdf5Log(const std::filesystem::path& file, const Hdf5LogHeader& header)
    : impl_(std::make_unique<Impl>(file, header, nullptr)) {}

Hdf5Log::Hdf5Log(const std::filesystem::path& file, const Hdf5LogHeader& header,
                 const Hdf5LogRows& keep)
    : impl_(std::make_unique<Impl>(file, header, &keep)) {}

Hdf5Log::~Hdf5Log() {
  try {
    close();
  } catch (const std::exception& e) {
    // A destructor must not throw; callers who care about the final close call close().
    warn(e.what());
  }
}

void Hdf5Log::append_frame(const FrameRecord& record) {
  if (!impl_) throw std::logic_error("Hdf5Log::append_frame after close");
  check_frame_record(record, impl_->points_per_level, impl_->frames->time_levels(),
                     impl_->frames->tools());
  for (std::size_t k = 0; k < impl_->levels.size(); ++k) {
    impl_->levels[k].append_status(record.status[k]);
  }
  impl_->events->write_pending();
  impl_->frames->append(record);  // last: /frames/frame counts complete frames
  impl_->flush();
}

void Hdf5Log::append_event(int frame, const std::string& kind, int level, long long point) {
  if (!impl_) throw std::logic_error("Hdf5Log::append_event after close");
  impl_->events->add(frame, kind, level, point);
}

void Hdf5Log::append_tool_samples(int tool, const ToolSamples& samples) {
  if (!impl_) throw std::logic_error("Hdf5Log::append_tool_samples after close");
  if (tool < 0 || static_cast<std::size_t>(tool) >= impl_->tools.size()) {
    throw std::invalid_argument("Hdf5Log::append_tool_samples: no tool " + std::to_string(tool) +
                                " (the header lists " + std::to_string(impl_->tools.size()) +
                                ")");
  }
  check_tool_samples(samples, tool);
  // No flush here: a frame's samples become durable with the frame's row, so a killed run
  // holds the samples of every complete frame at the cost of one flush per frame only.
  impl_->tools[static_cast<std::size_t>(tool)].append(samples);
}

Hdf5LogRows Hdf5Log::rows() const {
  if (!impl_) throw std::logic_error("Hdf5Log::rows after close");
  Hdf5LogRows r;
  r.frames = static_cast<std::int64_t>(impl_->frames->rows());
  r.events = static_cast<std::int64_t>(impl_->events->rows());
  for (const h5::ToolGroup& tool : impl_->tools)
    r.tool_samples.push_back(static_cast<std::int64_t>(tool.rows()));
  return r;
}

void Hdf5Log::close() {
  if (!impl_) return;
  // Released before closing: a failed close must not be retried by the destructor on ids
  // that are already half closed; the Handles still release whatever remains.
  const std::unique_ptr<Impl> impl = std::move(impl_);
  impl->close();
}

}  // namespace mrsim
