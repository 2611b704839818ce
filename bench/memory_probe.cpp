#include <fstream>
#include <string>

#include "peers.h"

namespace vrs_bench {

namespace {

double status_mb(const char* key) { // VmRSS / VmHWM of this process, in MiB
  std::ifstream in("/proc/self/status");
  std::string k;
  double kb = 0;
  while (in >> k) {
    if (k == key) {
      in >> kb;
      return kb / 1024.0;
    }
    std::getline(in, k);
  }
  return 0;
}

} // namespace

MemoryProbe::MemoryProbe() {
  std::ofstream("/proc/self/clear_refs") << "5"; // reset VmHWM to the current VmRSS
  before_mb_ = status_mb("VmRSS:");
}

void MemoryProbe::finish(PeerResult& r) const {
  r.peak_mb = status_mb("VmHWM:");
  r.extra_mb = r.peak_mb - before_mb_;
}

} // namespace vrs_bench
