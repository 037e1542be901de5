#include "io/summary_json.hpp"

#include "io/atomic_file.hpp"

namespace mrsim {

void write_json_file(const std::filesystem::path& file, const nlohmann::json& summary) {
  // nlohmann::json prints doubles in their shortest round-trip form, so no precision is lost;
  // non-finite numbers become null (JSON has no NaN), which readers must accept.
  write_file_atomically(file, summary.dump(2) + "\n");
}

}  // namespace mrsim
