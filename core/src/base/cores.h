// How many cores a run may use: the machine's, as few as the process is allowed to run on
// (taskset, a container's cpuset) or given time for (a container's CPU quota: `docker
// --cpus`, a Kubernetes limit, systemd's CPUQuota). Threads past those only wait for a core.
#pragma once

#include <string>

namespace vrs {

// The cores a CPU quota grants: cgroup v2's cpu.max text ("quota period", or "max period"
// for none) or cgroup v1's quota and period in microseconds (quota -1: none), rounded up;
// 0 for no quota or text that is none of these.
int cores_in_quota(const std::string& cpu_max);
int cores_in_quota(long long quota_us, long long period_us);

} // namespace vrs
