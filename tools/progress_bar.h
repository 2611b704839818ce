// The CLI's progress bar on stderr: long runs (a 19 M-face mesh takes minutes) say how far they
// are. On a terminal: redrawn in place, silent for the first second so that short runs print
// nothing. Otherwise (logs, asked for with --progress): one line per 10 % from the start.
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
