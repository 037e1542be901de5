#pragma once
// Text form of a double that parses back to the very same double (shortest round-trip form,
// e.g. 0.04 and 0.08000000000000002). Used wherever a time is written as text, so that the
// times in frames.pvd equal /frames/time in log.h5 bit for bit.
#include <string>

namespace mrsim {

std::string exact_number(double value);

}  // namespace mrsim
