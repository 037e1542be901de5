// Where a difference is and how the report says it: worst absolute and relative places,
// multi-indices for 2-D/3-D arrays, named axes for VTK arrays, exact numbers.
#include <gtest/gtest.h>

#include <limits>

#include "compare/array_diff.hpp"
#include "compare/diff_text.hpp"

namespace mrsim {
namespace {

ValueArray reals(Shape shape, std::vector<double> values) {
  return {ValueKind::Real, std::move(shape), std::move(values), {}, {}};
}

TEST(ArrayDiff, FindsCountFirstWorstAbsoluteAndRelative) {
  const ValueArray a = reals({5}, {1.0, 100.0, 3.0, 0.001, 5.0});
  const ValueArray b = reals({5}, {1.0, 100.5, 3.0, 0.002, 5.0});
  const ArrayDiff d = diff_arrays(a, b, {});
  EXPECT_EQ(d.total, 5u);
  EXPECT_EQ(d.differing, 2u);
  EXPECT_EQ(d.first, 1u);
  EXPECT_EQ(d.abs_at, 1u);
  EXPECT_DOUBLE_EQ(d.max_abs, 0.5);
  EXPECT_EQ(d.rel_at, 3u);
  EXPECT_DOUBLE_EQ(d.max_rel, 0.5);
}

TEST(ArrayDiff, NaNAgainstANumberIsInfinitelyFar) {
  const ValueArray a = reals({2}, {1.0, 2.0});
  const ValueArray b = reals({2}, {1.5, std::numeric_limits<double>::quiet_NaN()});
  const ArrayDiff d = diff_arrays(a, b, {});
  EXPECT_EQ(d.differing, 2u);
  EXPECT_EQ(d.abs_at, 1u);
  EXPECT_TRUE(std::isinf(d.max_abs));
}

TEST(ArrayDiff, RejectsDifferentKindsOrSizes) {
  const ValueArray ints{ValueKind::Integer, {2}, {}, {1, 2}, {}};
  EXPECT_THROW(diff_arrays(reals({2}, {1, 2}), ints, {}), std::invalid_argument);
  EXPECT_THROW(diff_arrays(reals({2}, {1, 2}), reals({3}, {1, 2, 3}), {}), std::invalid_argument);
}

TEST(ArrayDiff, MultiIndexIsRowMajor) {
  EXPECT_EQ(multi_index(53, {51, 3}), (std::vector<std::size_t>{17, 2}));
  EXPECT_EQ(multi_index(23, {2, 3, 4}), (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_EQ(multi_index(7, {51}), (std::vector<std::size_t>{7}));
  EXPECT_TRUE(multi_index(0, {}).empty());
}

TEST(DiffText, IndicesAsMultiIndicesOrNamedAxes) {
  EXPECT_EQ(index_text(53, {51, 3}), "[17, 2]");
  EXPECT_EQ(index_text(17, {51}), "[17]");
  EXPECT_EQ(index_text(1037, {3386, 3}, {"point", "component"}), "point 345 component 2");
  EXPECT_EQ(index_text(345, {3386}, {"point", "component"}), "point 345");
  EXPECT_EQ(shape_text({51, 3}), "[51, 3]");
  EXPECT_EQ(shape_text({3386, 3}, "×"), "[3386×3]");
  EXPECT_EQ(shape_text({}), "scalar");
}

TEST(DiffText, ReportsCountWorstPlaceAndBothValuesExactly) {
  std::vector<double> va(33, 0.5), vb(33, 0.5);
  vb[3 * 10 + 2] = 0.5 + 1e-5;  // [10, 2]
  vb[3 * 4 + 1] = 0.5 - 1e-6;   // [4, 1]
  const ValueArray a = reals({11, 3}, va), b = reals({11, 3}, vb);
  const ArrayDiff d = diff_arrays(a, b, {});
  const std::string text = diff_text(d, a, b);
  EXPECT_NE(text.find("2 of 33 values differ"), std::string::npos) << text;
  EXPECT_NE(text.find("max abs 9.99999999995449e-06 at [10, 2] (A 0.5, B 0.50001)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("max rel"), std::string::npos) << text;
}

TEST(DiffText, IntegersSayExactAndShowTheValues) {
  const ValueArray a{ValueKind::Integer, {2, 2}, {}, {1, 2, 3, 4}, {}};
  const ValueArray b{ValueKind::Integer, {2, 2}, {}, {1, 2, 3, 5}, {}};
  const std::string text = diff_text(diff_arrays(a, b, {1, 1}), a, b);
  EXPECT_NE(text.find("1 of 4 integers differ (exact comparison)"), std::string::npos) << text;
  EXPECT_NE(text.find("at [1, 1] (A 4, B 5)"), std::string::npos) << text;
}

TEST(DiffText, SingleValuesAndLayouts) {
  const ValueArray a = reals({}, {0.25}), b = reals({}, {0.5});
  EXPECT_EQ(diff_text(diff_arrays(a, b, {}), a, b), "A 0.25, B 0.5 (abs 0.25, rel 0.5)");
  EXPECT_EQ(*layout_difference(reals({51}, std::vector<double>(51)),
                               reals({26}, std::vector<double>(26))),
            "shapes differ: A [51], B [26]");
  const ValueArray ints{ValueKind::Integer, {}, {}, {1}, {}};
  EXPECT_EQ(*layout_difference(a, ints), "types differ: A float, B integer");
  EXPECT_FALSE(layout_difference(a, b).has_value());
}

TEST(DiffText, Strings) {
  const ValueArray a{ValueKind::Text, {3}, {}, {}, {"split", "merge", "gc"}};
  const ValueArray b{ValueKind::Text, {3}, {}, {}, {"split", "split", "gc"}};
  EXPECT_EQ(diff_text(diff_arrays(a, b, {}), a, b),
            "1 of 3 strings differ; first at [1] (A \"merge\", B \"split\")");
}

}  // namespace
}  // namespace mrsim
