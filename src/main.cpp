#include <cstdlib>

#include "cli/app.hpp"
#include "core/huge_page_heap.hpp"
#include "core/processor_count.hpp"

int main(int argc, char** argv) {
  // VTK's own threads (Debian builds its SMP tools on TBB) computed array ranges for the frames'
  // XML headers on a pool beside the simulation's threads: 5 % of liver_probe's CPU at
  // --threads 1, spinning and rescheduling for arrays of a few thousand values. Sequential
  // writes the same frames. Set before VTK's first use; a user's own choice is kept.
  setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 0);
  // The meshes, the levels' operators and the log's buffers: tens of MiB written once at
  // set-up, in 2 MiB pages rather than thousands of 4 KiB faults (core/huge_page_heap.hpp).
  mrsim::reserve_huge_page_heap(std::size_t{64} << 20);
  // Counted once, for every library that asks (core/processor_count.hpp). This call is also
  // what links processor_count.cpp, whose get_nprocs() the libraries then bind to: an archive
  // member that nothing in the program names is left out.
  mrsim::online_processors();
  return mrsim::run_cli(argc, argv);
}
