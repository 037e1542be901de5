#include <cstdlib>

#include "cli/app.hpp"

int main(int argc, char** argv) {
  // VTK's own threads (Debian builds its SMP tools on TBB) computed array ranges for the frames'
  // XML headers on a pool beside the simulation's threads: 5 % of liver_probe's CPU at
  // --threads 1, spinning and rescheduling for arrays of a few thousand values. Sequential
  // writes the same frames. Set before VTK's first use; a user's own choice is kept.
  setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 0);
  return mrsim::run_cli(argc, argv);
}
