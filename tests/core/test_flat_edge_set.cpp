// The constrained edges' set (flat_edge_set.h) against std::set on random work.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <utility>

#include "base/flat_edge_set.h"

using namespace vrs;

TEST(FlatEdgeSet, AnEdgeIsItsTwoEndsInEitherOrder) {
  FlatEdgeSet s;
  EXPECT_FALSE(s.contains(1, 2));
  EXPECT_TRUE(s.insert(2, 1));
  EXPECT_FALSE(s.insert(1, 2));
  EXPECT_TRUE(s.contains(1, 2) && s.contains(2, 1));
  EXPECT_FALSE(s.contains(1, 3));
  EXPECT_TRUE(s.insert(0xfffffffeu, 0xffffffffu)); // the largest ids are edges too
  EXPECT_TRUE(s.contains(0xffffffffu, 0xfffffffeu));
  EXPECT_EQ(s.size(), 2u);
  EXPECT_TRUE(s.erase(1, 2));
  EXPECT_FALSE(s.erase(2, 1));
  EXPECT_FALSE(s.contains(1, 2));
  EXPECT_EQ(s.size(), 1u);
}

TEST(FlatEdgeSet, AgreesWithStdSetThroughInsertsAndErasesThatReuseItsSlots) {
  std::mt19937 rng(7);
  FlatEdgeSet flat;
  std::set<std::pair<uint32_t, uint32_t>> ref;
  // Few distinct vertices: the same edges come and go, leaving tombstones to sweep.
  std::uniform_int_distribution<uint32_t> id(0, 60);
  for (int step = 0; step < 200000; ++step) {
    uint32_t a = id(rng), b = id(rng);
    if (a == b) continue;
    const auto e = std::minmax(a, b);
    switch (rng() % 3) {
    case 0: ASSERT_EQ(flat.insert(a, b), ref.insert(e).second) << step; break;
    case 1: ASSERT_EQ(flat.erase(a, b), ref.erase(e) == 1) << step; break;
    default: ASSERT_EQ(flat.contains(a, b), ref.count(e) == 1) << step;
    }
    ASSERT_EQ(flat.size(), ref.size());
  }
  for (uint32_t a = 0; a <= 60; ++a)
    for (uint32_t b = 0; b <= 60; ++b)
      EXPECT_EQ(flat.contains(a, b), a != b && ref.count(std::minmax(a, b)) == 1) << a << " " << b;
}
