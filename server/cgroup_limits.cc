#include "server/cgroup_limits.h"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"

namespace meshseg::server {
namespace {

// A limit of 2^60 bytes or more is cgroup v1's way of saying "none".
constexpr int64_t kUnlimitedV1 = int64_t{1} << 60;

std::optional<std::string> ReadSmall(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  return std::string(absl::StripAsciiWhitespace(text.str()));
}

// The cgroup path of this process for `controller` ("" = the v2 unified
// hierarchy), from /proc/self/cgroup; "/" if unknown.
std::string OwnCgroup(const std::string& controller) {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> parts = absl::StrSplit(line, absl::MaxSplits(':', 2));
    if (parts.size() != 3) continue;
    const bool v2 = parts[0] == "0" && parts[1].empty();
    const std::vector<std::string> controllers = absl::StrSplit(parts[1], ',');
    const bool listed =
        std::find(controllers.begin(), controllers.end(), controller) != controllers.end();
    if (controller.empty() ? v2 : listed) return parts[2];
  }
  return "/";
}

// The first readable file of `name` in the process's own cgroup folder
// under `base`, then in `base` itself (a container sees its own cgroup at
// the root of its mount).
std::optional<std::string> ReadCgroupFile(const std::string& base, const std::string& controller,
                                          const std::string& name) {
  const std::string own = OwnCgroup(controller);
  for (const std::string& dir : {base + own, base}) {
    if (std::optional<std::string> text = ReadSmall(dir + "/" + name)) return text;
  }
  return std::nullopt;
}

int AffinityCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

}  // namespace

CpuLimit ReadCpuLimit(const std::string& cgroup_root) {
  CpuLimit limit;
  limit.affinity_cores = AffinityCores();
  limit.source = "none";
  if (std::optional<std::string> max = ReadCgroupFile(cgroup_root, "", "cpu.max")) {
    limit.source = "cgroup v2";
    const std::vector<std::string> parts = absl::StrSplit(*max, ' ', absl::SkipEmpty());
    double quota = 0, period = 0;
    if (parts.size() == 2 && absl::SimpleAtod(parts[0], &quota) &&
        absl::SimpleAtod(parts[1], &period) && quota > 0 && period > 0) {
      limit.quota_cores = quota / period;
    }
  } else if (std::optional<std::string> quota_text =
                 ReadCgroupFile(cgroup_root + "/cpu", "cpu", "cpu.cfs_quota_us")) {
    limit.source = "cgroup v1";
    std::optional<std::string> period_text =
        ReadCgroupFile(cgroup_root + "/cpu", "cpu", "cpu.cfs_period_us");
    double quota = 0, period = 0;
    if (period_text && absl::SimpleAtod(*quota_text, &quota) &&
        absl::SimpleAtod(*period_text, &period) && quota > 0 && period > 0) {
      limit.quota_cores = quota / period;
    }
  }
  limit.workers = limit.affinity_cores;
  if (limit.quota_cores) {
    limit.workers =
        std::clamp(static_cast<int>(std::ceil(*limit.quota_cores - 1e-9)), 1, limit.affinity_cores);
  }
  return limit;
}

CpuLimit ProcessCpuLimit() { return ReadCpuLimit(); }

std::optional<int64_t> ReadMemoryLimitBytes(const std::string& cgroup_root) {
  int64_t bytes = 0;
  if (std::optional<std::string> max = ReadCgroupFile(cgroup_root, "", "memory.max")) {
    if (*max != "max" && absl::SimpleAtoi(*max, &bytes) && bytes > 0) return bytes;
    return std::nullopt;
  }
  if (std::optional<std::string> v1 =
          ReadCgroupFile(cgroup_root + "/memory", "memory", "memory.limit_in_bytes")) {
    if (absl::SimpleAtoi(*v1, &bytes) && bytes > 0 && bytes < kUnlimitedV1) return bytes;
  }
  return std::nullopt;
}

}  // namespace meshseg::server
