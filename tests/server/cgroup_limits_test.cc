// Worker sizing from a fake cgroup tree: v2 cpu.max and memory.max, v1
// cfs quota and memory limit, and no limit at all.
#include "server/cgroup_limits.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scratch_dir.h"

namespace meshseg::server {
namespace {

namespace fs = std::filesystem;

std::string Root() {
  const fs::path dir =
      testing_files::ScratchPath(::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

void Write(const std::string& path, const std::string& text) {
  fs::create_directories(fs::path(path).parent_path());
  std::ofstream(path) << text;
}

TEST(CgroupLimits, V2QuotaRoundsUpAndIsCappedByTheCoresWeMayRunOn) {
  const std::string root = Root();
  Write(root + "/cpu.max", "150000 100000\n");
  Write(root + "/memory.max", "4294967296\n");
  const CpuLimit cpu = ReadCpuLimit(root);
  EXPECT_EQ(cpu.source, "cgroup v2");
  ASSERT_TRUE(cpu.quota_cores.has_value());
  EXPECT_DOUBLE_EQ(*cpu.quota_cores, 1.5);
  EXPECT_EQ(cpu.workers, std::min(2, cpu.affinity_cores));
  EXPECT_EQ(ReadMemoryLimitBytes(root), int64_t{4294967296});
}

TEST(CgroupLimits, V2WithoutQuotaUsesTheAffinityCores) {
  const std::string root = Root();
  Write(root + "/cpu.max", "max 100000\n");
  Write(root + "/memory.max", "max\n");
  const CpuLimit cpu = ReadCpuLimit(root);
  EXPECT_FALSE(cpu.quota_cores.has_value());
  EXPECT_EQ(cpu.workers, cpu.affinity_cores);
  EXPECT_FALSE(ReadMemoryLimitBytes(root).has_value());
}

TEST(CgroupLimits, V1QuotaAndMemoryLimit) {
  const std::string root = Root();
  Write(root + "/cpu/cpu.cfs_quota_us", "50000\n");
  Write(root + "/cpu/cpu.cfs_period_us", "100000\n");
  Write(root + "/memory/memory.limit_in_bytes", "1073741824\n");
  const CpuLimit cpu = ReadCpuLimit(root);
  EXPECT_EQ(cpu.source, "cgroup v1");
  EXPECT_DOUBLE_EQ(*cpu.quota_cores, 0.5);
  EXPECT_EQ(cpu.workers, 1) << "half a core still gets one worker";
  EXPECT_EQ(ReadMemoryLimitBytes(root), int64_t{1073741824});
}

TEST(CgroupLimits, V1UnlimitedValuesMeanNoLimit) {
  const std::string root = Root();
  Write(root + "/cpu/cpu.cfs_quota_us", "-1\n");
  Write(root + "/cpu/cpu.cfs_period_us", "100000\n");
  Write(root + "/memory/memory.limit_in_bytes", "9223372036854771712\n");
  EXPECT_FALSE(ReadCpuLimit(root).quota_cores.has_value());
  EXPECT_FALSE(ReadMemoryLimitBytes(root).has_value());
}

TEST(CgroupLimits, NoCgroupAtAll) {
  const CpuLimit cpu = ReadCpuLimit(Root());
  EXPECT_EQ(cpu.source, "none");
  EXPECT_GE(cpu.workers, 1);
}

}  // namespace
}  // namespace meshseg::server
