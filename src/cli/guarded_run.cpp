#include "cli/guarded_run.hpp"

#include <iostream>
#include <new>

#include "core/error.hpp"

namespace mrsim {

int guarded_run(const std::function<int()>& command) {
  try {
    return command();
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const RunError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitRunFailure;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
    return kExitRunFailure;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitRunFailure;
  }
}

}  // namespace mrsim
