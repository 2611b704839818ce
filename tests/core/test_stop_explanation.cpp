// The words of Report::stop_detail, from the counts of the remaining vertices.
#include <gtest/gtest.h>

#include "driver/stop_explanation.h"

using namespace vrs;

TEST(StopExplanation, NothingLeftToSayIsNone) {
  EXPECT_EQ(explain_remaining(Remaining{}, false, false), "remaining vertices: none");
}

TEST(StopExplanation, EachCauseIsCountedOnceInItsOrderAndVetoesByName) {
  Remaining r;
  r.boundary = 12;
  r.locked = 2;
  r.refused[RejectFold] = 3;
  r.refused[RejectFlip] = 1;
  r.untried = 4;
  const std::string s = explain_remaining(r, false, false);
  EXPECT_EQ(s, "remaining vertices: 12 on the boundary, kept (boundary simplification is off); "
               "2 locked; 4 refused by the vetoes (" +
                   std::string(reject_name(RejectFold)) + " 3, " + reject_name(RejectFlip) +
                   " 1); 4 without a usable plane (degenerate or non-finite neighbourhood)");
}

TEST(StopExplanation, BoundaryWordsFollowTheBoundarySetting) {
  Remaining r;
  r.boundary = 5;
  r.corners = 2;
  const std::string s = explain_remaining(r, true, false);
  EXPECT_NE(s.find("5 on the boundary in a single triangle"), std::string::npos) << s;
  EXPECT_NE(s.find("2 at corners of the outline"), std::string::npos) << s;
  EXPECT_EQ(s.find("boundary simplification is off"), std::string::npos) << s;
}

TEST(StopExplanation, TheLastResortSaysFoldOversStoppedItOnlyWhenItRan) {
  Remaining r;
  r.refused[RejectFoldOver] = 7;
  const std::string said = explain_remaining(r, false, true);
  EXPECT_NE(said.find("the last resort stopped: every filling left for 7 of them would fold"),
            std::string::npos)
      << said;
  EXPECT_EQ(explain_remaining(r, false, false).find("last resort"), std::string::npos);
}

TEST(StopExplanation, SaysHowToWeldOnlyWhereSplitVerticesMakeMostSeams) {
  Remaining r;
  r.constrained = 10;
  r.split_seam_edges = 60;
  r.constrained_edges = 100;
  const std::string most = explain_remaining(r, false, false);
  EXPECT_NE(most.find("most seams are where split vertices meet (60 of 100 edges)"),
            std::string::npos)
      << most;
  r.split_seam_edges = 50; // half: texture seams as many as the copies'
  EXPECT_EQ(explain_remaining(r, false, false).find("split_vertices"), std::string::npos);
  r.split_seam_edges = 60;
  r.constrained = 0; // nothing kept by a seam: nothing to say about them
  EXPECT_EQ(explain_remaining(r, false, false).find("split_vertices"), std::string::npos);
}

// Report::stop_cause: the group that keeps most of the remaining vertices; the vetoes count
// together, outline corners with the boundary; of equal groups the first the words list.
TEST(StopExplanation, TheCauseIsTheLargestGroup) {
  EXPECT_EQ(main_cause(Remaining{}), StopCause::None);
  Remaining r;
  r.boundary = 3;
  r.refused[RejectFold] = 2;
  r.refused[RejectFoldOver] = 2;
  EXPECT_EQ(main_cause(r), StopCause::Vetoes);
  r.corners = 1;
  EXPECT_EQ(main_cause(r), StopCause::Boundary); // 4 against 4: the boundary is listed first
  r.split_seam = 5;
  EXPECT_EQ(main_cause(r), StopCause::SplitSeam);
  r.untried = 6;
  EXPECT_EQ(main_cause(r), StopCause::NoPlane);
  EXPECT_STREQ(stop_cause_name(StopCause::NoPlane), "no_plane");
  EXPECT_STREQ(stop_cause_name(StopCause::PriceJump), "price_jump");
}
