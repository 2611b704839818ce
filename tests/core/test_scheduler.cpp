// Batches (scheduler.h): what is read off the queue, and when a plan made before a batch's
// commits still holds.
#include <gtest/gtest.h>

#include "driver/scheduler.h"
#include "queue/bucket_queue.h"

using namespace vrs;

namespace {

Ring ring_of(std::initializer_list<uint32_t> vs) {
  Ring r;
  for (uint32_t v : vs)
    r.v[r.verts++] = v;
  r.faces = r.verts;
  return r;
}

} // namespace

TEST(Scheduler, ABatchIsTheFrontOfTheLowestIntervalInQueueOrderUpToItsSize) {
  BucketQueue q;
  IntervalMap map;
  map.n = 10;
  map.f_max = 1.0;
  q.init(20, map);
  for (uint32_t v : {7u, 3u, 11u}) // interval 0, in this order
    q.push(v, 0.01);
  q.push(5, 0.5); // a higher interval: not in the batch
  std::vector<uint32_t> ids(2);
  int from = -1;
  ASSERT_EQ(take_front(q, ids, from), 2u);
  EXPECT_EQ(ids[0], 7u);
  EXPECT_EQ(ids[1], 3u);
  EXPECT_EQ(from, 0);
  ids.resize(kBatch);
  ASSERT_EQ(take_front(q, ids, from), 3u);
  EXPECT_EQ(ids[2], 11u);
  // Nothing is taken off the queue: the driver erases what it commits or refuses.
  EXPECT_TRUE(q.contains(7) && q.contains(3) && q.contains(11));
}

TEST(Scheduler, APlanHoldsUntilACommitTouchesItsVertexOrRing) {
  std::vector<uint8_t> flags(20, 0);
  TakenMarks marks;
  const Ring a = ring_of({1, 2, 3, 4}), b = ring_of({6, 7, 8}), c = ring_of({9, 10, 4});
  EXPECT_TRUE(marks.holds(flags, 0, a));
  marks.mark(flags, 0, a); // vertex 0 removed: it and its ring 1-4 are taken
  EXPECT_TRUE(marks.holds(flags, 5, b)) << "disjoint";
  EXPECT_FALSE(marks.holds(flags, 2, ring_of({11, 12, 13}))) << "its own vertex is taken";
  EXPECT_FALSE(marks.holds(flags, 12, c)) << "a ring vertex is taken";
  flags[15] = kFlagStale;
  marks.clear(flags); // the next batch: nothing taken, other bits left alone
  EXPECT_TRUE(marks.holds(flags, 12, c));
  for (uint32_t v = 0; v < 20; ++v)
    EXPECT_EQ(flags[v], v == 15 ? kFlagStale : 0) << v;
}
