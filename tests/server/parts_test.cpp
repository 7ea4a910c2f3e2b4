// The server's parts alone: the cache's bound, tags, the worker queue's bound, signals, how it
// measures work-precision.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <future>
#include <thread>

#include "server/etag.h"
#include "server/response_cache.h"
#include "server/run_scene.h"
#include "server/stop_signals.h"
#include "server/worker_pool.h"

namespace vibro::server {
namespace {

std::shared_ptr<const CachedResponse> answer(std::size_t bytes) {
  return std::make_shared<const CachedResponse>(
      CachedResponse{std::string(bytes, 'x'), "application/json", "\"t\"", {}});
}

// Each point of the server's work-precision diagram is a median of runs, not one run's time
// (which zig-zagged with the machine's load), the whole within one simulation's deadline.
TEST(WorkPrecisionOptions, TheServerTakesMediansOfThreeRuns) {
  Limits limits;
  limits.deadline_ms = 2000.0;
  const WorkPrecisionOptions o = server_work_precision_options(limits);
  EXPECT_EQ(o.repeats, 3);
  EXPECT_EQ(o.deadline_ms, 2000.0);
}

TEST(ResponseCache, DropsTheLeastRecentlyUsedBeyondItsBytes) {
  ResponseCache cache(1000);
  cache.insert("a", answer(200));
  cache.insert("b", answer(200));
  cache.insert("c", answer(200));
  ASSERT_TRUE(cache.find("a"));  // a is now the most recent
  cache.insert("d", answer(200));
  cache.insert("e", answer(200));  // 1000 + keys: b goes first
  EXPECT_TRUE(cache.find("a"));
  EXPECT_FALSE(cache.find("b"));
  EXPECT_TRUE(cache.find("e"));
  EXPECT_LE(cache.size_bytes(), 1000u);
}

TEST(ResponseCache, KeepsNothingLargerThanAQuarter) {
  ResponseCache cache(1000);
  cache.insert("big", answer(300));
  EXPECT_FALSE(cache.find("big"));
  ResponseCache off(0);
  off.insert("a", answer(1));
  EXPECT_FALSE(off.find("a"));
}

TEST(Etag, IsStableQuotedAndMatchesLists) {
  const std::string tag = etag_of("key");
  EXPECT_EQ(tag, etag_of("key"));
  EXPECT_NE(tag, etag_of("key2"));
  EXPECT_EQ(tag.front(), '"');
  EXPECT_EQ(tag.back(), '"');
  EXPECT_TRUE(etag_matches(tag, tag));
  EXPECT_TRUE(etag_matches("\"x\", W/" + tag, tag));
  EXPECT_TRUE(etag_matches("*", tag));
  EXPECT_FALSE(etag_matches("", tag));
  EXPECT_FALSE(etag_matches("\"x\"", tag));
}

TEST(WorkerPool, RefusesWorkBeyondItsQueue) {
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<int> ran{0};
  {
    WorkerPool pool(1, 2);
    std::promise<void> started;
    ASSERT_TRUE(pool.try_post([&] {
      started.set_value();
      released.wait();
      ++ran;
    }));
    started.get_future().wait();  // the worker holds the first job
    EXPECT_TRUE(pool.try_post([&] { ++ran; }));
    EXPECT_TRUE(pool.try_post([&] { ++ran; }));
    EXPECT_FALSE(pool.try_post([&] { ++ran; }));
    release.set_value();
  }  // the destructor runs what was queued
  EXPECT_EQ(ran, 3);
}

TEST(StopOnSignals, SigtermCallsStopOutsideTheHandler) {
  std::promise<void> stopped;
  auto done = stopped.get_future();
  {
    StopOnSignals on_signal([&] { stopped.set_value(); });
    std::raise(SIGTERM);
    EXPECT_EQ(done.wait_for(std::chrono::seconds(5)), std::future_status::ready);
  }
}

}  // namespace
}  // namespace vibro::server
