// The run's result back in the input's order (output.h), on a hand-made internal state.
#include <gtest/gtest.h>

#include "mesh/topology.h"
#include "write/output.h"

using namespace vrs;

namespace {

// Input: 5 vertices (0..4), 3 faces. Internal order reverses the vertices (v -> 4 - v) and
// swaps face slots 0 and 2; internal vertex 2 (input 2) was removed, slot 1 is dead.
struct Case {
  Mesh mesh;
  SpatialOrder order;
  std::vector<uint8_t> removed{0, 0, 1, 0, 0};
  UninitVector<uint32_t> kept_faces; // none dropped: each slot its own input face
  std::vector<uint32_t> corner_source{6, 7, 8, 0, 0, 0, 0, 1, 2};
  std::vector<float> face_bound{0.5f, 0.f, 0.25f};
  Case() {
    for (int v = 0; v < 5; ++v) // internal v holds input 4 - v's position
      mesh.positions.insert(mesh.positions.end(), {float(4 - v), 0.f, float(v)});
    mesh.triangles = {0, 1, 3, kNone, kNone, kNone, 4, 3, 1};
    order.vertex_new = {4, 3, 2, 1, 0};
    order.face_old = {2, 1, 0};
  }
};

} // namespace

TEST(Output, VerticesAndFacesReturnToTheInputOrderWithTheirSources) {
  Case c;
  Report rep;
  const std::vector<uint32_t> unwelded;
  const std::vector<uint8_t> none_turned;
  write_output(c.mesh, c.order, c.removed,
               {c.kept_faces, c.corner_source, c.face_bound, unwelded, unwelded, none_turned}, rep);
  ASSERT_EQ(rep.vertices, 4u);
  ASSERT_EQ(rep.faces, 2u);
  // Inputs 0, 1, 3, 4 survive, in that order, with their own positions.
  EXPECT_EQ(rep.remap, (std::vector<uint32_t>{0, 1, kRemoved, 2, 3}));
  EXPECT_EQ(c.mesh.positions, (std::vector<float>{0, 0, 4, 1, 0, 3, 3, 0, 1, 4, 0, 0}));
  // Input slot 0 is internal slot 2 (internal corners 4, 3, 1 = inputs 0, 1, 3), then input
  // slot 2 (internal 0, 1, 3 = inputs 4, 3, 1); the dead slot is gone.
  EXPECT_EQ(c.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 3, 2, 1}));
  EXPECT_EQ(rep.face_source, (std::vector<uint32_t>{0, 2}));
  EXPECT_EQ(rep.corner_source, (std::vector<uint32_t>{0, 1, 2, 6, 7, 8}));
  EXPECT_FLOAT_EQ(float(rep.error_bound), 0.5f);
}

// The case written back with no corner sources, bounds, welding nor turned faces.
Report write_plain(Case& c) {
  Report rep;
  const std::vector<uint32_t> none;
  const std::vector<float> no_bound;
  const std::vector<uint8_t> none_turned;
  write_output(c.mesh, c.order, c.removed, {c.kept_faces, none, no_bound, none, none, none_turned},
               rep);
  return rep;
}

TEST(Output, WithoutCornerSourcesOrBoundsNoneIsReported) {
  Case c;
  const Report rep = write_plain(c);
  EXPECT_TRUE(rep.corner_source.empty());
  EXPECT_EQ(rep.error_bound, 0.0);
  EXPECT_EQ(rep.face_source.size(), 2u);
}

TEST(Output, ARewrittenSlotHasNoSourceAndTheOthersTheFaceTheDropKept) {
  Case c;
  c.order.face_old[0] |= kRewrittenSlot; // internal slot 0 (input slot 2) made by the run
  c.kept_faces = {1, 2, 3}; // input face 0 dropped before the run: slot j is input face j + 1
  const Report rep = write_plain(c);
  // Still in the input slots' order: slot 0 (internal 2), then slot 2 (internal 0).
  EXPECT_EQ(c.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 3, 2, 1}));
  EXPECT_EQ(rep.face_source, (std::vector<uint32_t>{1, kRemoved}));
}

TEST(Output, InputWarningsNameEachProblemWorkedAround) {
  Report r;
  EXPECT_EQ(input_warnings(r), "");
  r.dropped_degenerate_faces = 3;
  r.unreferenced_vertices = 1;
  EXPECT_EQ(input_warnings(r), "3 faces with a repeated vertex dropped; 1 unreferenced vertices "
                               "left untouched");
}
