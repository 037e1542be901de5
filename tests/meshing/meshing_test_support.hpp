#pragma once
// Helpers for the meshing tests: data locations, a scratch folder per test, small surfaces
// written as text, and an assertion on InputError messages.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "support/scratch_and_shared.hpp"

namespace mrsim::test {

namespace fs = std::filesystem;




/// A unit cube [0,1]^3 as OFF text, outward oriented; `extra` is appended to the faces.
inline std::string cube_off(const std::string& first_vertex = "0 0 0", int faces = 12,
                            const std::string& extra_faces = "") {
  return "OFF\n8 " + std::to_string(faces) + " 0\n" + first_vertex +
         "\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
         "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
         "3 2 3 7\n3 2 7 6\n3 1 2 6\n3 1 6 5\n3 0 4 7\n3 0 7 3\n" +
         extra_faces;
}

/// Expects `action` to throw InputError whose message contains every piece of `pieces`.
inline void expect_input_error(const std::function<void()>& action, std::initializer_list<std::string> pieces) {
  try {
    action();
    ADD_FAILURE() << "no InputError thrown";
  } catch (const InputError& e) {
    for (const std::string& piece : pieces) {
      EXPECT_NE(std::string(e.what()).find(piece), std::string::npos) << "message: " << e.what() << "\nlacks: " << piece;
    }
  }
}

}  // namespace mrsim::test
