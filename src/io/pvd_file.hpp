#pragma once
// frames.pvd: the ParaView "Collection" file that lists one data file per time step.
#include <filesystem>
#include <span>
#include <string>

namespace mrsim {

struct PvdEntry {
  double time = 0;   // s, written so that it parses back exactly
  std::string file;  // relative to the .pvd, with '/' separators
};

/// The XML text of a collection listing `entries` in order.
std::string pvd_text(std::span<const PvdEntry> entries);

}  // namespace mrsim
