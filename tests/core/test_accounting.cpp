// What a removal does to its neighbours' fan areas (accounting.h), the lazy price's scale.
#include <gtest/gtest.h>

#include <cmath>

#include "driver/accounting.h"
#include "fill/candidates.h"

using namespace vrs;

namespace {

// A closed ring of k vertices on the unit circle in the plane z = 0.
void regular_ring(int k, Ring& ring, Patch& patch) {
  ring.verts = ring.faces = k;
  for (int i = 0; i < k; ++i) {
    ring.v[i] = uint32_t(i + 1);
    ring.f[i] = uint32_t(i);
    const double a = 2 * 3.14159265358979323846 * i / k;
    patch.q[i] = {std::cos(a), std::sin(a), 0};
  }
}

} // namespace

TEST(Accounting, FanAreaChangesAddUpToTheFacesGainedAndLostAtEachCorner) {
  for (double height : {0.0, 0.5}) {
    Ring ring;
    Patch patch;
    regular_ring(6, ring, patch);
    ASSERT_TRUE(fill_candidate(ring, OpenRing::Border, 1, patch)); // the fan from ring vertex 0
    const Vec3 c{0, 0, height};
    set_replaced_faces(c, ring, patch);
    std::array<double, kMaxRing + 1> change;
    fan_area_changes(ring, patch, change);
    // Each old face counts at its two ring corners, each new one at its three.
    double old_area = 0, new_area = 0, sum = 0;
    for (int i = 0; i < 6; ++i)
      old_area += triangle_area(c, patch.q[i], patch.q[(i + 1) % 6]);
    for (int t = 0; t < patch.count; ++t)
      new_area += triangle_area(patch.q[patch.tri[t][0]], patch.q[patch.tri[t][1]],
                                patch.q[patch.tri[t][2]]);
    for (int i = 0; i < 6; ++i)
      sum += change[i];
    EXPECT_NEAR(sum, 3 * new_area - 2 * old_area, 1e-12) << height;
    // The apex gains every new triangle; its two old faces go.
    EXPECT_NEAR(change[0],
                new_area - triangle_area(c, patch.q[5], patch.q[0]) -
                    triangle_area(c, patch.q[0], patch.q[1]),
                1e-12);
  }
}

TEST(Accounting, TheEndsOfAnOpenRingLoseOnlyTheirOneOldFace) {
  Ring ring;
  Patch patch;
  ring.verts = 3;
  ring.faces = 2;
  ring.v = {};
  patch.q[0] = {1, 0, 0};
  patch.q[1] = {0, 1, 0};
  patch.q[2] = {-1, 0, 0};
  ASSERT_TRUE(fill_candidate(ring, OpenRing::Border, 1, patch));
  ASSERT_EQ(patch.count, 1);
  std::array<double, kMaxRing + 1> change;
  const Vec3 c{0, 0, 0};
  set_replaced_faces(c, ring, patch);
  fan_area_changes(ring, patch, change);
  const double whole = triangle_area(patch.q[0], patch.q[1], patch.q[2]);
  EXPECT_NEAR(change[0], whole - triangle_area(c, patch.q[0], patch.q[1]), 1e-12);
  EXPECT_NEAR(change[2], whole - triangle_area(c, patch.q[1], patch.q[2]), 1e-12);
  EXPECT_NEAR(change[1], whole - 2 * 0.5, 1e-12);
}
