#include "progress_bar.h"

#include <algorithm>
#include <cstdio>

namespace vrs_tool {

ProgressBar::ProgressBar(bool enabled, bool terminal)
    : enabled_(enabled), terminal_(terminal), start_(Clock::now()), last_(start_) {}

bool ProgressBar::update(float fraction) {
  if (!enabled_) return true;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0 && terminal_) return true;
  const float f = std::min(1.0f, std::max(0.0f, fraction));
  if (terminal_) {
    if (drawn_ && now - last_ < std::chrono::milliseconds(250) && f < 1.0f) return true;
    constexpr int kWidth = 30;
    const int full = int(f * kWidth + 0.5f);
    char bar[kWidth + 1];
    for (int i = 0; i < kWidth; ++i)
      bar[i] = i < full ? '#' : '.';
    bar[kWidth] = '\0';
    std::fprintf(stderr, "\rsimplifying [%s] %3d %%  %.0f s", bar, int(f * 100 + 0.5f), elapsed);
  } else {
    const int tenth = int(f * 10);
    if (tenth == last_tenth_) return true;
    last_tenth_ = tenth;
    std::fprintf(stderr, "simplifying: %3d %%  %.0f s\n", tenth * 10, elapsed);
  }
  std::fflush(stderr);
  drawn_ = true;
  last_ = now;
  return true;
}

void ProgressBar::finish() {
  if (drawn_ && terminal_) std::fprintf(stderr, "\n");
}

} // namespace vrs_tool
