#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "base/workers.h"
#include "queue/bucket_queue.h"
#include "queue/heap_queue.h"

using namespace vrs;

namespace {

IntervalMap linear(int n, double f_max) {
  IntervalMap m;
  m.n = n;
  m.f_max = f_max;
  return m;
}

template <class Q> std::vector<uint32_t> drain(Q& q) {
  std::vector<uint32_t> out;
  while (!q.empty()) {
    uint32_t v = q.front();
    q.erase(v);
    out.push_back(v);
  }
  return out;
}

} // namespace

TEST(IntervalMap, LinearSplitsTheRangeEvenlyAndClampsToTheLast) {
  IntervalMap m = linear(10, 1.0);
  EXPECT_EQ(m.interval_of(0.0), 0);
  EXPECT_EQ(m.interval_of(0.05), 0);
  EXPECT_EQ(m.interval_of(0.15), 1);
  EXPECT_EQ(m.interval_of(0.95), 9);
  EXPECT_EQ(m.interval_of(7.0), 9);
}

TEST(IntervalMap, LogarithmicResolvesSmallFactors) {
  IntervalMap m = linear(12, 1.0);
  m.kind = IntervalMapping::Logarithmic;
  // Six decades over twelve intervals: two per decade.
  EXPECT_EQ(m.interval_of(1e-7), 0);
  EXPECT_EQ(m.interval_of(2e-6), 0);
  EXPECT_EQ(m.interval_of(2e-5), 2);
  EXPECT_EQ(m.interval_of(2e-3), 6);
  EXPECT_EQ(m.interval_of(1.0), 11);
  EXPECT_LT(m.interval_of(1e-4), m.interval_of(1e-3));
}

TEST(BucketQueue, PopsTheLowestIntervalFirstAndFifoInside) {
  BucketQueue q;
  q.init(6, linear(4, 1.0));
  q.push(0, 0.9);
  q.push(1, 0.1);
  q.push(2, 0.6);
  q.push(3, 0.15); // same interval as 1, after it
  q.push(4, 0.05); // same interval as 1, after 3
  EXPECT_EQ(drain(q), (std::vector<uint32_t>{1, 3, 4, 2, 0}));
}

TEST(BucketQueue, ReEvaluatedVertexGoesToTheBackOfItsInterval) {
  BucketQueue q;
  q.init(4, linear(4, 1.0));
  q.push(0, 0.1);
  q.push(1, 0.1);
  q.push(2, 0.1);
  q.push(0, 0.12); // re-evaluated, same interval
  EXPECT_EQ(drain(q), (std::vector<uint32_t>{1, 2, 0}));
}

TEST(BucketQueue, EraseAndOnlyLastLeft) {
  BucketQueue q;
  q.init(3, linear(4, 1.0));
  q.push(0, 0.1);
  q.push(1, 1.0);
  EXPECT_FALSE(q.only_last_left());
  q.erase(0);
  EXPECT_FALSE(q.contains(0));
  EXPECT_TRUE(q.only_last_left());
  q.erase(0); // erasing twice is harmless
  EXPECT_EQ(q.size(), 1u);
}

TEST(BucketQueue, RespreadRestoresOrderInsideTheLastInterval) {
  BucketQueue q;
  q.init(3, linear(4, 1.0));
  std::vector<float> f = {5.0f, 2.0f, 1.0f};
  for (uint32_t v = 0; v < 3; ++v)
    q.push(v, f[v]); // all beyond f_max: last interval
  EXPECT_TRUE(q.only_last_left());
  q.respread(f.data());
  EXPECT_FALSE(q.only_last_left());
  EXPECT_EQ(drain(q), (std::vector<uint32_t>{2, 1, 0}));
}

TEST(BucketQueue, ManyIntervalsAcrossBitmapWords) {
  BucketQueue q;
  q.init(3, linear(300, 300.0));
  q.push(0, 250.5);
  q.push(1, 130.5);
  q.push(2, 64.5);
  EXPECT_EQ(drain(q), (std::vector<uint32_t>{2, 1, 0}));
}

TEST(BucketQueue, MatchesFifoListsThroughChurnThatBlanksAndCompactsItsArrays) {
  // A reference: one FIFO per interval. Few vertices and intervals, many pushes, moves and
  // erases, so that blanks pile up at the heads and inside the lists and get swept.
  std::mt19937 rng(11);
  const int n = 40, intervals = 4;
  BucketQueue q;
  q.init(n, linear(intervals, 1.0));
  std::vector<std::vector<uint32_t>> ref(intervals);
  auto where = [&](uint32_t v) {
    for (int i = 0; i < intervals; ++i)
      if (std::find(ref[i].begin(), ref[i].end(), v) != ref[i].end()) return i;
    return -1;
  };
  auto remove = [&](uint32_t v) {
    const int i = where(v);
    if (i >= 0) ref[i].erase(std::find(ref[i].begin(), ref[i].end(), v));
  };
  std::uniform_real_distribution<double> factor(0.0, 0.99);
  for (int step = 0; step < 100000; ++step) {
    const uint32_t v = rng() % n;
    switch (rng() % 4) {
    case 0: // push (to the back, also when queued)
    case 1: {
      const double f = factor(rng);
      q.push(v, f);
      remove(v);
      ref[q.map().interval_of(f)].push_back(v);
      break;
    }
    case 2:
      q.erase(v);
      remove(v);
      break;
    default: { // update: moves only when the interval changes
      if (!q.contains(v)) break;
      const double f = factor(rng);
      q.update(v, f);
      const int i = q.map().interval_of(f);
      if (i != where(v)) remove(v), ref[i].push_back(v);
    }
    }
    size_t total = 0;
    for (const auto& l : ref)
      total += l.size();
    ASSERT_EQ(q.size(), total) << step;
    ASSERT_EQ(q.contains(v), where(v) >= 0) << step;
    if (where(v) >= 0) {
      ASSERT_EQ(q.interval(v), where(v)) << step;
    }
    // The front batch is the lowest non-empty list, in order.
    std::vector<uint32_t> front(n);
    front.resize(q.read_front(front.data(), front.size()));
    std::vector<uint32_t> expected;
    for (const auto& l : ref)
      if (!l.empty()) {
        expected = l;
        break;
      }
    ASSERT_EQ(front, expected) << step;
    if (!expected.empty()) {
      ASSERT_EQ(q.front(), expected[0]) << step;
    }
  }
}

TEST(BucketQueue, FillIsPushesInBlockOrderOnAnyThreads) {
  // Blocks of uneven sizes (some empty), vertices in no order, factors over 130 intervals (three
  // bitmap words), some at 0 and past the range: the table filled on the workers must be the
  // one the pushes make, slots included (the erases of a churn read them), on any threads.
  std::mt19937 rng(5);
  const uint32_t n = 20000;
  std::vector<uint32_t> vertices(n);
  for (uint32_t v = 0; v < n; ++v)
    vertices[v] = v;
  std::shuffle(vertices.begin(), vertices.end(), rng);
  std::vector<std::vector<uint32_t>> blocks(23);
  for (uint32_t v : vertices)
    if (rng() % 5) blocks[rng() % 3 == 0 ? 0 : rng() % blocks.size()].push_back(v);
  blocks[7].clear();
  std::vector<float> factor(n);
  for (auto& f : factor)
    f = rng() % 50 == 0 ? 0.0f : float(std::uniform_real_distribution<double>(0, 1.1)(rng));
  for (int threads : {1, 2, 3, 8}) {
    BucketQueue pushed, filled;
    pushed.init(n, linear(130, 1.0));
    for (const auto& block : blocks)
      for (uint32_t v : block)
        pushed.push(v, factor[v]);
    Workers workers(threads);
    filled.init(n, linear(130, 1.0), &workers);
    filled.fill(blocks, factor.data(), &workers);
    ASSERT_EQ(filled.size(), pushed.size()) << threads;
    for (uint32_t v = 0; v < n; ++v) {
      ASSERT_EQ(filled.contains(v), pushed.contains(v)) << threads;
      if (pushed.contains(v)) {
        ASSERT_EQ(filled.interval(v), pushed.interval(v)) << threads;
      }
    }
    std::mt19937 churn(threads);
    for (int step = 0; step < 30000; ++step) {
      const uint32_t v = churn() % n;
      if (churn() % 2) {
        pushed.erase(v), filled.erase(v);
      } else {
        const double f = std::uniform_real_distribution<double>(0, 1)(churn);
        pushed.update(v, f), filled.update(v, f);
      }
    }
    ASSERT_EQ(drain(filled), drain(pushed)) << threads;
  }
}

TEST(HeapQueue, IsExactAndBreaksTiesByInsertionOrder) {
  HeapQueue q;
  q.init(1000, linear(4, 1.0));
  std::mt19937 rng(7);
  std::vector<std::pair<double, uint32_t>> ref;
  for (uint32_t v = 0; v < 1000; ++v) {
    double f = double(rng() % 50) / 50.0;
    q.push(v, f);
    ref.push_back({f, v});
  }
  for (uint32_t v = 0; v < 1000; v += 7) { // re-push: goes behind its equals
    double f = double(rng() % 50) / 50.0;
    q.push(v, f);
    auto it = std::find_if(ref.begin(), ref.end(), [&](auto& e) { return e.second == v; });
    ref.erase(it);
    ref.push_back({f, v});
  }
  for (uint32_t v = 3; v < 1000; v += 11) {
    q.erase(v);
    ref.erase(std::find_if(ref.begin(), ref.end(), [&](auto& e) { return e.second == v; }));
  }
  std::stable_sort(ref.begin(), ref.end(), [](auto& a, auto& b) { return a.first < b.first; });
  std::vector<uint32_t> expect;
  for (auto& e : ref)
    expect.push_back(e.second);
  EXPECT_EQ(drain(q), expect);
}
