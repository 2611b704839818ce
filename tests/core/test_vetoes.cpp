// What forbids a patch: topology, slivers, the input's side, fold-overs.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "fill/candidates.h"
#include "remove/removal.h"
#include "remove/vetoes.h"
#include "ring_case.h"
#include "test_meshes.h"

using namespace vrs;

// The arrow-shaped ring: seen from ring vertices 2 and 4 the notch at 3 is behind an edge, so
// their fans hold a triangle turned over; from the notch itself every triangle is fine.
TEST(Vetoes, FoldOverRefusesAFanTurnedOverTheFaceItReplaces) {
  RingCase s;
  s.mesh = vrs_test::concave_fan();
  open_ring(s, 6);
  Evaluator eval(Mode::Surface3D, {0, 0, 1}, s.mesh.positions.data());
  RemovalLimits limits;
  // The last-resort pass: one corner agreeing with the face is enough for the input-normal
  // veto; make every corner's input normal ambiguous (both sides) so that only the fold-over
  // veto is left to see the turned-over triangle.
  limits.agreeing_corners = 1;
  for (size_t i = 0; i < s.normals.size(); i += 4)
    s.normals[i + 2] = (i / 4) % 2 ? 1.0f : -1.0f;
  Patch p = projected(s, 6, {0, 0, 1});
  for (int apex : {2, 4}) {
    ASSERT_TRUE(fill_candidate(s.ring, OpenRing::Border, 1 + apex, p));
    EXPECT_EQ(veto_shape(s.ring, p, p.face_n, s.normals.data(), limits, false), RejectFoldOver)
        << "apex " << apex;
  }
  ASSERT_TRUE(fill_candidate(s.ring, OpenRing::Border, 1 + 3, p));
  EXPECT_EQ(veto_shape(s.ring, p, p.face_n, s.normals.data(), limits, false), RejectCount);
  // In the eased passes the input judges fold-overs (InputSurface::folds), not the faces
  // replaced: the turned-over fans pass here and are refused (or not) by the input.
  limits.folds_judged_by_input = true;
  for (int apex : {2, 4}) {
    ASSERT_TRUE(fill_candidate(s.ring, OpenRing::Border, 1 + apex, p));
    EXPECT_EQ(veto_shape(s.ring, p, p.face_n, s.normals.data(), limits, false), RejectCount)
        << "apex " << apex;
  }
  limits.folds_judged_by_input = false;
  // With the input normals all up and their veto on, the same fan is refused by it first.
  for (size_t i = 0; i < s.normals.size(); i += 4)
    s.normals[i + 2] = 1.0f;
  limits.agreeing_corners = 3;
  ASSERT_TRUE(fill_candidate(s.ring, OpenRing::Border, 1 + 2, p));
  EXPECT_EQ(veto_shape(s.ring, p, p.face_n, s.normals.data(), limits, false), RejectFlip);
  // The corners' test still holds when the input judges fold-overs.
  limits.folds_judged_by_input = true;
  EXPECT_EQ(veto_shape(s.ring, p, p.face_n, s.normals.data(), limits, false), RejectFlip);
}

// The corners tell whether they can vouch for an accepted patch, and why not: flat and alike
// they can; one turned 60 degrees from the patch cannot, nor one whose faces spread wide (a
// crease, a thin wall): the planner then asks the input itself, and on a crease the price
// counts the surface moved.
TEST(Vetoes, CornersSayWhenTheyCannotVouchForAPatch) {
  RingCase s;
  s.mesh = vrs_test::hexagon_fan();
  open_ring(s, 6);
  Evaluator eval(Mode::Surface3D, {0, 0, 1}, s.mesh.positions.data());
  Patch p = projected(s, 6, {0, 0, 1});
  ASSERT_TRUE(fill_candidate(s.ring, OpenRing::Border, 1, p));
  auto unsure = [&] {
    uint8_t d = 0;
    EXPECT_EQ(veto_shape(s.ring, p, p.face_n, s.normals.data(), RemovalLimits{}, false, &d),
              RejectCount);
    return int(d);
  };
  EXPECT_EQ(unsure(), 0);
  const uint32_t corner = s.ring.v[2];
  float* n = s.normals.data() + 4 * size_t(corner);
  n[0] = 0.866f, n[1] = 0, n[2] = 0.5f; // 60 degrees off, still on the patch's side
  EXPECT_EQ(unsure(), kCornerTurned);
  n[0] = 0, n[2] = 1;
  n[3] = 0.6f; // its faces spread about 37 degrees
  EXPECT_EQ(unsure(), kCornerOnCrease);
  n[0] = 0.866f, n[2] = 0.5f;
  EXPECT_EQ(unsure(), kCornerTurned | kCornerOnCrease);
  n[0] = 0, n[2] = 1;
  n[3] = 0.1f;
  EXPECT_EQ(unsure(), 0);
}

TEST(Vetoes, TopologyRefusesATriangleThatAlreadyExists) {
  RingCase s;
  s.mesh = vrs_test::tetrahedron();
  open_ring(s, 0);
  Patch p = projected(s, 0, {1, 1, 1});
  ASSERT_TRUE(fill_candidate(s.ring, OpenRing::Border, 1, p));
  EXPECT_EQ(veto_topology(s.ring, p, OpenRing::Border, s.topo, s.mesh.triangles.data()),
            RejectTriangle);
}

TEST(Vetoes, SliverIsDegenerate) {
  RingCase s;
  s.mesh = vrs_test::hexagon_fan();
  // Ring vertices 0, 1 and 2 on one line: the fan from 0 makes the flat triangle (0, 1, 2).
  s.mesh.positions[3 * 1 + 0] = 0.5f * (s.mesh.positions[0] + s.mesh.positions[6]);
  s.mesh.positions[3 * 1 + 1] = 0.5f * (s.mesh.positions[1] + s.mesh.positions[7]);
  open_ring(s, 6);
  Evaluator eval(Mode::Surface3D, {0, 0, 1}, s.mesh.positions.data());
  Patch p = projected(s, 6, {0, 0, 1});
  ASSERT_TRUE(fill_candidate(s.ring, OpenRing::Border, 1, p));
  EXPECT_EQ(veto_shape(s.ring, p, p.face_n, s.normals.data(), RemovalLimits{}, false),
            RejectDegenerate);
}

namespace {

// The arrow-shaped ring with v raised above it (every filling drops it), planned with `price`.
struct RaisedArrow {
  RingCase s;
  std::unique_ptr<Evaluator> eval;
  RemovalLimits limits;
  RaisedArrow() {
    s.mesh = vrs_test::concave_fan();
    s.mesh.positions[3 * 6 + 2] = 0.3f;
    open_ring(s, 6);
    eval = std::make_unique<Evaluator>(Mode::Surface3D, Vec3{0, 0, 1}, s.mesh.positions.data());
  }
  Reject plan(const Pricer& price, Patch& out, double& cost, int hint = -1) const {
    Planner planner(*eval, s.topo, s.mesh.triangles.data(), s.normals.data(), limits, price, true);
    return planner.plan(6, s.ring, {0, 0, 1}, out, cost, true, OpenRing::Border, true, hint);
  }
};
// The fan from the notch (ring vertex 3, candidate 4).
bool notch_fan(const Patch& p) {
  return p.count == 4 && p.tri[0][0] == 3 && p.tri[1][0] == 3;
}
double seven(const void*, uint32_t, const Ring&, const Patch&) {
  return 7.0;
}
int estimates = 0; // estimates asked of the pricers below

} // namespace

// The planner keeps a candidate no veto refuses, and the one its estimate ranks first.
TEST(Vetoes, PlannerTakesTheBestRankedValidCandidate) {
  const RaisedArrow a;
  // Rank the fan from the notch first, the projection last.
  Pricer price{[](const void*, uint32_t, const Ring&, const Patch& p, double, bool& complete) {
                 complete = true;
                 return notch_fan(p) ? 0.0 : 1.0;
               },
               seven, nullptr};
  Patch out;
  double cost = 0;
  ASSERT_EQ(a.plan(price, out, cost), RejectCount);
  EXPECT_EQ(cost, 7.0);
  EXPECT_EQ(out.candidate, 1 + 3);
  for (int t = 0; t < out.count; ++t)
    EXPECT_EQ(out.tri[t][0], 3) << "triangle " << t;
}

// An estimate that stopped early is a lower bound: the planner finishes it before it ranks
// the candidate by it. Here the notch's fan says 0 when capped (stopped), 5 when finished;
// every other candidate 1: the planner must not take the notch's fan.
TEST(Vetoes, PlannerFinishesAnEstimateThatStoppedBeforeRankingByIt) {
  const RaisedArrow a;
  Pricer price{[](const void*, uint32_t, const Ring&, const Patch& p, double cap, bool& complete) {
                 complete = !notch_fan(p) || std::isinf(cap);
                 return notch_fan(p) ? (complete ? 5.0 : 0.0) : 1.0;
               },
               seven, nullptr};
  Patch out;
  double cost = 0;
  ASSERT_EQ(a.plan(price, out, cost), RejectCount);
  EXPECT_FALSE(notch_fan(out));
  EXPECT_NE(out.candidate, 1 + 3);
}

// A pop whose ring is unchanged tries the candidate its last plan chose first, without ranking;
// a hint some veto refuses is no shortcut: the whole plan is made, and chooses as it would.
TEST(Vetoes, PlannerTriesItsHintFirstAndPlansInFullWhenItIsRefused) {
  const RaisedArrow a;
  Pricer price{[](const void*, uint32_t, const Ring&, const Patch& p, double, bool& complete) {
                 ++estimates;
                 complete = true;
                 return notch_fan(p) ? 0.0 : 1.0;
               },
               seven, nullptr};
  Patch full, hinted;
  double cost = 0;
  estimates = 0;
  ASSERT_EQ(a.plan(price, full, cost), RejectCount);
  ASSERT_GT(estimates, 1);
  ASSERT_EQ(full.candidate, 1 + 3);
  estimates = 0;
  ASSERT_EQ(a.plan(price, hinted, cost, full.candidate), RejectCount);
  EXPECT_EQ(estimates, 0);
  EXPECT_EQ(cost, 7.0);
  ASSERT_EQ(hinted.count, full.count);
  for (int t = 0; t < full.count; ++t) {
    EXPECT_EQ(hinted.tri[t], full.tri[t]) << "triangle " << t;
    EXPECT_EQ(hinted.from[t], full.from[t]) << "triangle " << t;
  }
  // The fan from ring vertex 2 turns a triangle over (FoldOverRefuses... above): refused as a
  // hint, the plan is made in full and takes the notch's fan again.
  estimates = 0;
  ASSERT_EQ(a.plan(price, hinted, cost, 1 + 2), RejectCount);
  EXPECT_GT(estimates, 1);
  EXPECT_EQ(hinted.candidate, 1 + 3);
  EXPECT_TRUE(notch_fan(hinted));
}

namespace {

// The raised arrow with the notch's fan ranked first (priced 7) and its diagonal (3, 5) an edge
// elsewhere in the mesh: the mesh's topology veto refuses it.
struct NotchDiagonalElsewhere {
  RingCase s;
  std::unique_ptr<Evaluator> eval;
  RemovalLimits limits;
  std::unique_ptr<Planner> planner;
  NotchDiagonalElsewhere() {
    s.mesh = vrs_test::concave_fan();
    s.mesh.positions[3 * 6 + 2] = 0.3f;
    s.mesh.positions.insert(s.mesh.positions.end(), {0.0f, 1.0f, -5.0f});
    s.mesh.triangles.insert(s.mesh.triangles.end(), {3u, 5u, 7u});
    open_ring(s, 6);
    eval = std::make_unique<Evaluator>(Mode::Surface3D, Vec3{0, 0, 1}, s.mesh.positions.data());
    Pricer price{[](const void*, uint32_t, const Ring&, const Patch& p, double, bool& complete) {
                   complete = true;
                   return notch_fan(p) ? 0.0 : 1.0;
                 },
                 seven, nullptr};
    planner = std::make_unique<Planner>(*eval, s.topo, s.mesh.triangles.data(), s.normals.data(),
                                        limits, price, true);
  }
};

} // namespace

// A candidate taken after one the mesh's other faces refused (an edge found elsewhere, which can
// go while the ring stays) is no hint for the next plan; one after the ring's own refusals is.
TEST(Vetoes, APlanAfterARefusalByTheMeshLeavesNoHint) {
  const NotchDiagonalElsewhere n;
  const RingCase& s = n.s;
  ASSERT_EQ(s.ring.verts, 6);
  const Planner& planner = *n.planner;
  Patch out;
  double cost = 0;
  // Priced without the mesh's look-ups, the notch's fan is taken and is a hint.
  ASSERT_EQ(planner.plan(6, s.ring, {0, 0, 1}, out, cost, false), RejectCount);
  EXPECT_TRUE(notch_fan(out));
  EXPECT_EQ(out.candidate, 1 + 3);
  // With them, its diagonal (3, 5) exists: another is taken, and is no hint.
  ASSERT_EQ(planner.plan(6, s.ring, {0, 0, 1}, out, cost), RejectCount);
  EXPECT_FALSE(notch_fan(out));
  EXPECT_EQ(out.candidate, kNoCandidate);
}

// A stale price planned above the queue's next (`lead`) is pushed back, not committed: its
// first ranked candidate is priced after the shape veto alone and returned without the mesh's
// vetoes; under the lead the whole plan is made.
TEST(Vetoes, APlanPricedOverItsLeadIsNotAskedTheMesh) {
  const NotchDiagonalElsewhere n;
  const RingCase& s = n.s;
  const Planner& planner = *n.planner;
  Patch out;
  double cost = 0;
  ASSERT_EQ(planner.plan(6, s.ring, {0, 0, 1}, out, cost, true, OpenRing::Border, true, -1, 5.0),
            RejectCount);
  EXPECT_TRUE(notch_fan(out));
  EXPECT_EQ(out.candidate, 1 + 3); // the hint its next plan tries, with the mesh's vetoes
  EXPECT_GT(cost, 5.0);
  // At or under the lead it would be committed: asked the mesh, refused, another taken.
  ASSERT_EQ(planner.plan(6, s.ring, {0, 0, 1}, out, cost, true, OpenRing::Border, true, -1, 7.0),
            RejectCount);
  EXPECT_FALSE(notch_fan(out));
  EXPECT_EQ(out.candidate, kNoCandidate);
}
