// File: cgroup_limits.h
// -----------------------------------------------------------------------------
// What the container may use, from its cgroup (v2: cpu.max, memory.max; v1:
// cpu.cfs_quota_us / cpu.cfs_period_us, memory.limit_in_bytes), so workers
// size themselves from the quota a scheduler gave the pod, not from the
// node's core count. The memory budget is exposed for job admission (which
// jobs fit); this file only reads it.
#ifndef MESHSEG_SERVER_CGROUP_LIMITS_H_
#define MESHSEG_SERVER_CGROUP_LIMITS_H_

#include <cstdint>
#include <optional>
#include <string>

namespace meshseg::server {

struct CpuLimit {
  // Cores the quota allows (quota / period), if a quota is set.
  std::optional<double> quota_cores;
  // Cores this process may run on (sched_getaffinity), at least 1.
  int affinity_cores = 1;
  // Worker threads to run: the quota rounded up (a 1.5-core quota keeps two
  // workers busy 75 % each), capped by the affinity cores.
  int workers = 1;
  // "cgroup v2", "cgroup v1" or "none".
  std::string source;
};

// Reads the CPU limit of this process. `cgroup_root` is where the cgroup
// file system is mounted (a parameter so tests can point at a fake tree).
CpuLimit ReadCpuLimit(const std::string& cgroup_root = "/sys/fs/cgroup");

// Returns the CPU limit of this process (ReadCpuLimit() at the default root).
CpuLimit ProcessCpuLimit();

// Returns the memory limit of this process's cgroup in bytes, or nullopt if
// none is set ("max", or no cgroup). For job admission: a job is admitted
// only while its estimated peak memory fits this budget.
std::optional<int64_t> ReadMemoryLimitBytes(const std::string& cgroup_root = "/sys/fs/cgroup");

}  // namespace meshseg::server

#endif  // MESHSEG_SERVER_CGROUP_LIMITS_H_
