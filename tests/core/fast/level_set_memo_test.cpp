// LevelSetMemo (engine/fast/level_set_check.hpp): walks of one A that share a memo answer as
// walks without it, whatever B they check; the memo is consulted (its entries decide pieces)
// and only for the A, level and sagitta it was made for.
#include <gtest/gtest.h>

#include <cstdint>

#include "engine/fast/level_set_check.hpp"
#include "engine/fast/segment_index.hpp"

namespace penshape {
namespace {

using fast::IRing;

IRing square(std::int64_t x0, std::int64_t y0, std::int64_t side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

// [0, 1000] x [0, 500] with a saw of 20 teeth (40 units wide, 30 high) along its top: at level
// 100 the offsets of the teeth's inner edges are deep inside the level set of their neighbours.
IRing saw() {
  IRing ring{{0, 0}, {1000, 0}, {1000, 500}};
  for (std::int64_t x = 1000; x > 0; x -= 50) {
    ring.push_back({x - 20, 530});
    ring.push_back({x - 40, 500});
  }
  ring.back() = {0, 500};
  return ring;
}

// B's that the level set {d(., saw) = 100} avoids or meets: squares beyond its right side
// (x = 1100) by 10 or -3 units, one above the teeth (y = 630) by 10 or -3 units, and a square
// holding all of it.
std::vector<IRing> test_regions() {
  return {square(1110, 100, 300), square(1097, 100, 300), square(200, 640, 300),
          square(200, 627, 300), square(-5000, -5000, 10000)};
}

TEST(LevelSetMemo, SharedMemoAnswersAsNoMemo) {
  const fast::SegmentIndex a({saw()}, 100);
  ASSERT_TRUE(fast::is_certifiable_region(a));
  fast::LevelSetMemo memo(a, 100.0, 2.0);
  int rejected = 0;
  for (int round = 0; round < 2; ++round) { // the second round reads what the first recorded
    for (const IRing& b_ring : test_regions()) {
      const fast::SegmentIndex b({b_ring}, 100);
      const bool plain = fast::level_set_avoids({&a, 100.0, &b, 1.0, 2.0}, {});
      const bool shared = fast::level_set_avoids({&a, 100.0, &b, 1.0, 2.0, nullptr, &memo}, {});
      EXPECT_EQ(shared, plain) << "B at " << b_ring[0].x << ", " << b_ring[0].y;
      rejected += plain ? 0 : 1;
    }
  }
  EXPECT_EQ(rejected, 6); // -3 units beyond the side and the teeth, and the big square: twice
  std::size_t known = 0, deep = 0;
  for (std::size_t v = 0; v < a.segments().size(); ++v) {
    known += memo.known(v, 0) ? 1U : 0U;
    deep += memo.deep(v, 0) ? 1U : 0U;
  }
  // An accepted walk records every deep test it made: each edge's offset is asked, except the
  // pieces that continue a run proven clear of B (asked the clear test first, and passed by it).
  EXPECT_GT(known, a.segments().size() / 4);
  EXPECT_GT(deep, 0U);
  EXPECT_LT(deep, known);
}

// A memo saying "deep" everywhere makes the walk accept a B that meets the level set: entries
// decide. A memo for another level or sagitta is not consulted.
TEST(LevelSetMemo, EntriesDecideOnlyForTheirWalk) {
  const fast::SegmentIndex a({saw()}, 100);
  const fast::SegmentIndex b({square(1097, 100, 300)}, 100);
  const auto all_deep = [](const fast::SegmentIndex& of, double level, double sagitta) {
    fast::LevelSetMemo memo(of, level, sagitta);
    for (std::size_t v = 0; v < of.segments().size(); ++v) {
      for (unsigned bit = 0; bit < fast::LevelSetMemo::kEntries; ++bit) memo.record(v, bit, true);
    }
    return memo;
  };
  fast::LevelSetMemo lying = all_deep(a, 100.0, 2.0);
  EXPECT_TRUE(fast::level_set_avoids({&a, 100.0, &b, 1.0, 2.0, nullptr, &lying}, {}));
  fast::LevelSetMemo other_level = all_deep(a, 99.0, 2.0);
  EXPECT_FALSE(fast::level_set_avoids({&a, 100.0, &b, 1.0, 2.0, nullptr, &other_level}, {}));
  fast::LevelSetMemo other_sagitta = all_deep(a, 100.0, 1.0);
  EXPECT_FALSE(fast::level_set_avoids({&a, 100.0, &b, 1.0, 2.0, nullptr, &other_sagitta}, {}));
  const fast::SegmentIndex other_a({saw()}, 100);
  fast::LevelSetMemo memo_of_other = all_deep(other_a, 100.0, 2.0);
  EXPECT_FALSE(fast::level_set_avoids({&a, 100.0, &b, 1.0, 2.0, nullptr, &memo_of_other}, {}));
}

} // namespace
} // namespace penshape
