// server/redis_connection.cc against a real redis-server on loopback
// (Debian's; redis_process.h), killed and restarted under the connections.
#include "server/redis_connection.h"

#include <gtest/gtest.h>

#include <memory>

#include "tests/server/redis_process.h"
#include "tests/server/test_server.h"

namespace meshseg::server {
namespace {

using testing_server::FreshDir;
using testing_server::RedisProcess;

class RedisConnectionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    redis_ = std::make_unique<RedisProcess>(FreshDir("redis"));
    ASSERT_TRUE(redis_->ok()) << "redis-server did not start";
    absl::StatusOr<RedisAddress> address = ParseRedisUrl(redis_->url());
    ASSERT_TRUE(address.ok()) << address.status();
    address_ = *address;
  }

  std::unique_ptr<RedisProcess> redis_;
  RedisAddress address_;
};

// A pooled connection Redis closed while it sat idle (a restart) is replaced
// on the next command; the first command after the restart must not fail.
TEST_F(RedisConnectionTest, APooledConnectionClosedByARestartIsReplacedNotFailed) {
  RedisPool pool(address_, absl::Seconds(2));
  ASSERT_TRUE(pool.Command({"PING"}).ok());  // leaves one idle connection
  ASSERT_TRUE(redis_->Restart()) << "redis-server did not come back";
  const absl::StatusOr<RedisValue> pong = pool.Command({"PING"});
  ASSERT_TRUE(pong.ok()) << pong.status();
  EXPECT_EQ(pong->str, "PONG");
}

TEST_F(RedisConnectionTest, ADirectConnectionReconnectsAfterARestart) {
  RedisConnection connection(address_, absl::Seconds(2));
  ASSERT_TRUE(connection.Command({"SET", "k", "v"}).ok());
  ASSERT_TRUE(redis_->Restart()) << "redis-server did not come back";
  const absl::StatusOr<RedisValue> pong = connection.Command({"PING"});
  ASSERT_TRUE(pong.ok()) << pong.status();
  EXPECT_EQ(pong->str, "PONG");
}

// While Redis is down a command fails UNAVAILABLE naming the address (the
// server maps it to the client's UNAVAILABLE), and succeeds once it is back.
TEST_F(RedisConnectionTest, ACommandWhileRedisIsDownIsUnavailableNamingTheAddress) {
  RedisPool pool(address_, absl::Seconds(1));
  ASSERT_TRUE(pool.Command({"PING"}).ok());
  redis_->Kill9();
  const absl::StatusOr<RedisValue> down = pool.Command({"PING"});
  EXPECT_EQ(down.status().code(), absl::StatusCode::kUnavailable) << down.status();
  EXPECT_NE(down.status().message().find(address_.text), std::string::npos) << down.status();
  ASSERT_TRUE(redis_->Restart()) << "redis-server did not come back";
  EXPECT_TRUE(pool.Command({"PING"}).ok());
}

}  // namespace
}  // namespace meshseg::server
