// The W-cycle schedule of method.md §5.4 (time/w_cycle.hpp): which levels each tick kicks.
#include <gtest/gtest.h>

#include <vector>

#include "time/w_cycle.hpp"

namespace mrsim {
namespace {

TEST(WCycle, RulerSequenceOfFourLevels) {
  const WCycle wc(3);
  std::vector<int> coarse;
  for (int t = 0; t < 8; ++t) coarse.push_back(wc.coarse_level(t));
  EXPECT_EQ(coarse, (std::vector<int>{-1, 2, 1, 2, 0, 2, 1, 2}));
}

// Level k is kicked 2^k times per frame, every 2^(K-k) ticks; the steps its kicks open (finest
// level) or sit in the middle of (coarser levels) tile the frame without gap or overlap; no
// tick kicks more than two levels.
TEST(WCycle, EveryLevelTilesTheFrameAtEqualSpacing) {
  for (int K = 0; K <= 8; ++K) {
    const WCycle wc(K);
    std::vector<std::vector<int>> kicks(K + 1);
    for (int t = 0; t < wc.ticks_per_frame(); ++t) {
      int n = 0;
      for (int k = 0; k <= K; ++k)
        if (wc.kicks(k, t)) {
          kicks[k].push_back(t);
          ++n;
        }
      EXPECT_LE(n, 2) << "tick " << t;
      EXPECT_GE(n, 1);
    }
    for (int k = 0; k <= K; ++k) {
      ASSERT_EQ(static_cast<int>(kicks[k].size()), 1 << k) << "K " << K << " level " << k;
      const int P = wc.period(k), offset = k == K ? 0 : P / 2;
      for (size_t j = 0; j < kicks[k].size(); ++j)
        EXPECT_EQ(kicks[k][j], static_cast<int>(j) * P + offset) << "K " << K << " level " << k;
    }
  }
}

// Refined at once after a kick: the first kick on the finer level is one of its kick times,
// its step begins where the last coarse step ended, and no finer kick falls in between.
TEST(WCycle, RefinementJoinsTheFinerLevelWhereTheCoarseStepEnds) {
  const WCycle wc(5);
  for (int k = 0; k < 5; ++k)
    for (int t = 0; t < wc.ticks_per_frame(); ++t) {
      if (!wc.kicks(k, t)) continue;
      const int first = wc.first_kick_after_refining(k, t);
      const int coarse_end = t + wc.period(k) / 2;
      const int fine_start = k + 1 == 5 ? first : first - wc.period(k + 1) / 2;
      EXPECT_EQ(fine_start, coarse_end) << "level " << k << " tick " << t;
      if (first < wc.ticks_per_frame()) {
        EXPECT_TRUE(wc.kicks(k + 1, first));
      }
    }
}

TEST(WCycle, RejectsImpossibleCaps) {
  EXPECT_THROW(WCycle(-1), std::invalid_argument);
  EXPECT_THROW(WCycle(31), std::invalid_argument);
}

}  // namespace
}  // namespace mrsim
