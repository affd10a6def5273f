// The /metrics listener over loopback: GET and HEAD of /metrics answer 200
// with the text format's content type, anything else a clear 4xx, and a
// bad address is refused with a message naming it.
#include "server/metrics_listener.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>

#include "absl/strings/numbers.h"
#include "tests/server/http_get.h"

namespace meshseg::server {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using testing_server::HttpBody;
using testing_server::HttpExchange;
using testing_server::HttpGet;

int PortOf(const MetricsListener& listener) {
  int port = 0;
  EXPECT_TRUE(absl::SimpleAtoi(listener.address().substr(listener.address().rfind(':') + 1), &port));
  return port;
}

TEST(MetricsListener, ServesTheBodyAtMetricsFreshOnEveryScrape) {
  std::atomic<int> scrapes = 0;
  auto listener = MetricsListener::Start("127.0.0.1:0", [&] {
    return "up " + std::to_string(++scrapes) + "\n";
  });
  ASSERT_TRUE(listener.ok()) << listener.status();
  const int port = PortOf(**listener);
  ASSERT_GT(port, 0);
  const std::string first = HttpGet(port, "/metrics");
  EXPECT_THAT(first, StartsWith("HTTP/1.1 200 OK\r\n"));
  EXPECT_THAT(first, HasSubstr("Content-Type: text/plain; version=0.0.4; charset=utf-8\r\n"));
  EXPECT_THAT(first, HasSubstr("Content-Length: 5\r\n"));
  EXPECT_EQ(HttpBody(first), "up 1\n");
  EXPECT_EQ(HttpBody(HttpGet(port, "/metrics?name[]=x")), "up 2\n");
  const std::string head = HttpExchange(port, "HEAD /metrics HTTP/1.1\r\n\r\n");
  EXPECT_THAT(head, StartsWith("HTTP/1.1 200 OK\r\n"));
  EXPECT_EQ(HttpBody(head), "");
}

TEST(MetricsListener, RefusesOtherPathsMethodsAndOversizedRequests) {
  auto listener = MetricsListener::Start("127.0.0.1:0", [] { return std::string("x 1\n"); });
  ASSERT_TRUE(listener.ok()) << listener.status();
  const int port = PortOf(**listener);
  EXPECT_THAT(HttpGet(port, "/"), StartsWith("HTTP/1.1 404 Not Found\r\n"));
  const std::string post = HttpExchange(port, "POST /metrics HTTP/1.1\r\nContent-Length: 0\r\n\r\n");
  EXPECT_THAT(post, StartsWith("HTTP/1.1 405 Method Not Allowed\r\n"));
  EXPECT_THAT(post, HasSubstr("Allow: GET, HEAD\r\n"));
  EXPECT_THAT(HttpExchange(port, "GET /metrics HTTP/1.1\r\nX: " + std::string(10000, 'a')),
              StartsWith("HTTP/1.1 400 Bad Request\r\n"));
  EXPECT_THAT(HttpExchange(port, "nonsense\r\n\r\n"), StartsWith("HTTP/1.1 400 Bad Request\r\n"));
  // Still serving after the bad requests.
  EXPECT_EQ(HttpBody(HttpGet(port, "/metrics")), "x 1\n");
}

TEST(MetricsListener, BadAddressesAreRefusedNamingThem) {
  const auto body = [] { return std::string(); };
  absl::StatusOr<std::unique_ptr<MetricsListener>> no_port = MetricsListener::Start("localhost", body);
  EXPECT_EQ(no_port.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(no_port.status().message(), HasSubstr("\"localhost\""));
  EXPECT_EQ(MetricsListener::Start("127.0.0.1:70000", body).status().code(),
            absl::StatusCode::kInvalidArgument);
  auto first = MetricsListener::Start("127.0.0.1:0", body);
  ASSERT_TRUE(first.ok());
  absl::StatusOr<std::unique_ptr<MetricsListener>> taken =
      MetricsListener::Start((*first)->address(), body);
  EXPECT_EQ(taken.status().code(), absl::StatusCode::kUnavailable);
  EXPECT_THAT(taken.status().message(), HasSubstr("cannot listen"));
}

}  // namespace
}  // namespace meshseg::server
