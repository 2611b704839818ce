// The CLI's progress bar on stderr: long runs (a 19 M-face mesh takes minutes) say how far they
// are. Silent for the first second, so short runs print nothing; redrawn in place on a
// terminal, one line per 10 % otherwise (logs).
#pragma once

#include <chrono>

namespace vrs_tool {

class ProgressBar {
 public:
  // `terminal`: stderr is a terminal (redraw in place).
  ProgressBar(bool enabled, bool terminal);
  // The core's progress callback: never asks to stop.
  bool update(float fraction);
  // Ends the bar's line, if one was drawn.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_, terminal_, drawn_ = false;
  Clock::time_point start_, last_;
  int last_tenth_ = -1;
};

} // namespace vrs_tool
