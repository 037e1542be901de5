#pragma once
// The number of online processors, counted once per process.
//
// glibc's get_nprocs() reads /sys/devices/system/cpu/online at every call (open, read, close:
// about 4 us on a virtual machine), and VTK 9.1 asks for it through
// std::thread::hardware_concurrency() each time it computes an array's range for an XML header,
// sequential backend or not: 8 236 times in liver_probe's 71 frames, 32 ms of a 1.1 s run.
// processor_count.cpp also defines get_nprocs(), which takes the place of glibc's for the
// libraries of a program that links this file (libstdc++ calls it through the dynamic linker),
// so the count is read once. Only thread-pool sizes depend on it.

namespace mrsim {

/// The online processors (sysconf), counted at the first call.
int online_processors();

}  // namespace mrsim
