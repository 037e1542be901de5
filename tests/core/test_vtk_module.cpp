// The VTK library's entry table (core/vtk_module.hpp): a table from this build is taken; one of
// another layout or another revision is refused with a RunError that names the library and says
// how to rebuild, before any of its functions is called. In a program that links VTK's part in
// (this test), vtk_module() is that part's own table.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "core/vtk_module.hpp"
#include "mrsim/version.hpp"

using namespace mrsim;

namespace {

std::string refusal(const VtkEntryPoints& e) {
  try {
    check_vtk_entry_points(e, "/opt/x/libmrsim_vtk.so");
  } catch (const RunError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(VtkModule, ThisBuildsTableIsTaken) {
  const VtkEntryPoints& e = vtk_module();
  EXPECT_EQ(e.size, sizeof(VtkEntryPoints));
  EXPECT_STREQ(e.git_revision, kGitRevision);
  EXPECT_NE(e.read_vtu, nullptr);
  EXPECT_NE(e.series_writer, nullptr);
  EXPECT_EQ(refusal(e), "");
}

TEST(VtkModule, AnotherRevisionOrLayoutIsRefused) {
  VtkEntryPoints other = vtk_module();
  other.git_revision = "0123abc";
  const std::string said = refusal(other);
  EXPECT_NE(said.find("/opt/x/libmrsim_vtk.so was built from revision 0123abc"), std::string::npos)
      << said;
  EXPECT_NE(said.find(std::string("this mrsim from ") + kGitRevision), std::string::npos) << said;
  EXPECT_NE(said.find("scripts/build.sh"), std::string::npos) << said;
  other = vtk_module();
  other.size += 8;
  EXPECT_NE(refusal(other).find("is from another build of mrsim"), std::string::npos);
  other = vtk_module();
  other.git_revision = nullptr;
  EXPECT_NE(refusal(other).find("built from revision ?"), std::string::npos);
}
