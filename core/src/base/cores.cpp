#include "base/cores.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "vrs/simplify.h"

#if defined(__linux__)
#include <sched.h>
#endif

namespace vrs {

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return in ? s.str() : std::string();
}

// The process's cgroup of `controller` ("" for cgroup v2's single hierarchy) as
// /proc/self/cgroup names it, "" when none is named.
std::string cgroup_path(const std::string& controller) {
  std::istringstream lines(read_text("/proc/self/cgroup"));
  for (std::string line; std::getline(lines, line);) {
    const size_t a = line.find(':'), b = line.find(':', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    const std::string list = line.substr(a + 1, b - a - 1);
    bool named = controller.empty() ? list.empty() : false;
    for (size_t at = 0; !controller.empty() && at <= list.size();) {
      const size_t end = std::min(list.find(',', at), list.size());
      named = named || list.compare(at, end - at, controller) == 0;
      at = end + 1;
    }
    if (named) return line.substr(b + 1);
  }
  return "";
}

// The CPU quota's cores, 0 for none found: the process's own cgroup first, then the root a
// container sees as its own.
int quota_cores() {
#if defined(__linux__)
  for (const std::string& dir : {"/sys/fs/cgroup" + cgroup_path(""), std::string("/sys/fs/cgroup")})
    if (const int n = cores_in_quota(read_text(dir + "/cpu.max"))) return n;
  for (const std::string& dir :
       {"/sys/fs/cgroup/cpu" + cgroup_path("cpu"), std::string("/sys/fs/cgroup/cpu")}) {
    const std::string quota = read_text(dir + "/cpu.cfs_quota_us"),
                      period = read_text(dir + "/cpu.cfs_period_us");
    if (quota.empty() || period.empty()) continue;
    if (const int n = cores_in_quota(std::atoll(quota.c_str()), std::atoll(period.c_str())))
      return n;
  }
#endif
  return 0;
}

} // namespace

int cores_in_quota(long long quota_us, long long period_us) {
  if (quota_us <= 0 || period_us <= 0) return 0;
  return int(std::min<long long>(1 << 20, (quota_us + period_us - 1) / period_us));
}

int cores_in_quota(const std::string& cpu_max) {
  std::istringstream in(cpu_max);
  std::string quota;
  long long period = 0;
  if (!(in >> quota >> period) || quota == "max") return 0;
  char* end = nullptr;
  const long long q = std::strtoll(quota.c_str(), &end, 10);
  return end && *end == '\0' ? cores_in_quota(q, period) : 0;
}

int usable_cores() {
  int n = int(std::thread::hardware_concurrency());
#if defined(__linux__)
  cpu_set_t allowed;
  if (sched_getaffinity(0, sizeof allowed, &allowed) == 0 && CPU_COUNT(&allowed) > 0)
    n = CPU_COUNT(&allowed);
#endif
  if (const int q = quota_cores()) n = n > 0 ? std::min(n, q) : q;
  return std::max(1, n);
}

} // namespace vrs
