// A flat record of values and arrays (core/byte_record.hpp): what is written reads back bit for
// bit; a lying count, a short record or trailing bytes throw instead of allocating or reading
// past the end.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "core/byte_record.hpp"

using namespace mrsim;

TEST(ByteRecord, ValuesAndArraysReadBackBitForBit) {
  ByteRecordWriter w;
  w.value(std::uint64_t{3});
  w.array(std::vector<int>{-1, 0, 7});
  w.array(std::vector<std::array<double, 2>>{{0.1, -0.0}, {1e-300, 2.5}});
  w.array(std::vector<int>{});
  const std::string bytes = std::move(w).take();
  ByteRecordReader r(bytes);
  EXPECT_EQ(r.value<std::uint64_t>(), 3u);
  EXPECT_EQ(r.array<int>(3), (std::vector<int>{-1, 0, 7}));
  const auto pairs = r.array<std::array<double, 2>>(2);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_TRUE(std::signbit(pairs[0][1]));
  EXPECT_EQ(pairs[1][0], 1e-300);
  EXPECT_TRUE(r.array<int>(0).empty());
  EXPECT_NO_THROW(r.expect_end());
}

TEST(ByteRecord, DamageThrowsInsteadOfReadingOrAllocating) {
  ByteRecordWriter w;
  w.array(std::vector<double>{1, 2, 3});
  const std::string bytes = std::move(w).take();
  {
    ByteRecordReader r(bytes);
    EXPECT_THROW(r.array<double>(2), std::runtime_error) << "more than the caller's bound";
  }
  {
    ByteRecordReader r(std::string_view(bytes).substr(0, bytes.size() - 1));
    EXPECT_THROW(r.array<double>(10), std::runtime_error) << "truncated";
  }
  {
    std::string lying = bytes;
    const std::uint64_t huge = std::numeric_limits<std::uint64_t>::max() / 8;
    std::memcpy(lying.data(), &huge, sizeof huge);
    ByteRecordReader r(lying);
    EXPECT_THROW(r.array<double>(std::numeric_limits<std::size_t>::max()), std::runtime_error)
        << "a count beyond the bytes left";
  }
  {
    const std::string longer = bytes + "x";
    ByteRecordReader r(longer);
    r.array<double>(3);
    EXPECT_THROW(r.expect_end(), std::runtime_error);
  }
  {
    ByteRecordReader r(std::string_view(bytes).substr(0, 4));
    EXPECT_THROW(r.value<std::uint64_t>(), std::runtime_error);
  }
}
