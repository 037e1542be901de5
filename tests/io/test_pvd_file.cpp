// Exact text form of times and the .pvd collection text.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "io/exact_number.hpp"
#include "io/pvd_file.hpp"

namespace mrsim {
namespace {

TEST(ExactNumber, ParsesBackToTheSameDouble) {
  const std::vector<double> values = {0.0,
                                      0.04,
                                      0.08000000000000002,
                                      0.1 + 0.2,
                                      1.0 / 3.0,
                                      2.0,
                                      1e-300,
                                      4.9406564584124654e-324,
                                      std::numeric_limits<double>::max(),
                                      -0.04 * 7,
                                      std::nextafter(1.0, 2.0)};
  for (const double v : values) {
    const std::string text = exact_number(v);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
  }
}

TEST(ExactNumber, UsesTheShortestForm) {
  EXPECT_EQ(exact_number(0.0), "0");
  EXPECT_EQ(exact_number(0.04), "0.04");
  EXPECT_EQ(exact_number(2.0), "2");
  EXPECT_EQ(exact_number(0.08000000000000002), "0.08000000000000002");
}

TEST(PvdFile, ListsEntriesInOrderAsACollection) {
  const std::vector<PvdEntry> entries = {{0.0, "frames/frame_000000.vtm"},
                                         {0.04, "frames/frame_000001.vtm"}};
  EXPECT_EQ(pvd_text(entries),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"frames/frame_000000.vtm\"/>\n"
            "    <DataSet timestep=\"0.04\" group=\"\" part=\"0\" file=\"frames/frame_000001.vtm\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
}

TEST(PvdFile, EscapesFileNames) {
  const std::vector<PvdEntry> entries = {{1.0, "a&b\"<c>.vtm"}};
  EXPECT_NE(pvd_text(entries).find("file=\"a&amp;b&quot;&lt;c&gt;.vtm\""), std::string::npos);
}

}  // namespace
}  // namespace mrsim
