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

// The cgroup above `path` ("/a/b" -> "/a" -> "/"), "" above the root.
std::string parent_of(const std::string& path) {
  if (path.empty() || path == "/") return "";
  const size_t slash = path.find_last_of('/');
  return slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
}

// The least CPU quota of the process's cgroup and those above it (a container's limit may
// sit on a parent), in cores; 0 for none. Where the container's own cgroup is the root it
// sees, /proc/self/cgroup names "/".
int quota_cores() {
  int least = 0;
  auto take = [&](int n) {
    if (n > 0 && (least == 0 || n < least)) least = n;
  };
#if defined(__linux__)
  for (std::string p = cgroup_path(""); !p.empty(); p = parent_of(p))
    take(cores_in_quota(read_text("/sys/fs/cgroup" + p + "/cpu.max")));
  for (std::string p = cgroup_path("cpu"); !p.empty(); p = parent_of(p)) {
    const std::string dir = "/sys/fs/cgroup/cpu" + p;
    const std::string quota = read_text(dir + "/cpu.cfs_quota_us"),
                      period = read_text(dir + "/cpu.cfs_period_us");
    if (!quota.empty() && !period.empty())
      take(cores_in_quota(std::atoll(quota.c_str()), std::atoll(period.c_str())));
  }
#endif
  return least;
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
