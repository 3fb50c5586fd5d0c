// pipeline/guarded_job.h: a job's deadline and watchdog armed and disarmed
// together; finish() is the one place a timeout stops the write.
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <thread>

#include "core/error.h"
#include "pipeline/guarded_job.h"

namespace ms {
namespace {

// The timeout error finish() throws, or none.
std::optional<ErrorInfo> finish_error(GuardedJob& g) {
  try {
    g.finish();
  } catch (const Error& e) {
    return e.info();
  }
  return std::nullopt;
}

TEST(GuardedJob, WithoutATimeoutThereIsNoDeadlineAndNoWatchdog) {
  GuardedJob g(0.0, "the render");
  EXPECT_EQ(g.limit(), nullptr);
  EXPECT_EQ(g.watchdog(), nullptr);
  EXPECT_NO_THROW(g.check());
  EXPECT_FALSE(finish_error(g));
}

TEST(GuardedJob, PastItsDeadlineFinishDisarmsThenNamesTheStep) {
  GuardedJob g(0.01, "the render");
  ASSERT_NE(g.limit(), nullptr);
  ASSERT_NE(g.watchdog(), nullptr);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));  // past the deadline, inside the 0.5 s grace
  const std::optional<ErrorInfo> e = finish_error(g);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->key, "--timeout");
  EXPECT_EQ(e->code, Exit::system);
  EXPECT_NE(e->what.find("the render did not finish within 0.01 s"), std::string::npos) << e->what;
  // Disarmed: the watchdog's grace runs out here and the process goes on.
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  SUCCEED();
}

TEST(GuardedJob, RestartGivesTheNextStepItsOwnBudgetAndName) {
  GuardedJob g(0.3, "loading and compiling");
  const Deadline first = g.deadline();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  g.restart("frame 7");
  EXPECT_EQ(g.what(), "frame 7");
  EXPECT_GT(g.deadline().at(), first.at());  // from now, not from the first step
  EXPECT_EQ(g.limit(), &g.deadline());
  EXPECT_FALSE(finish_error(g));
}

}  // namespace
}  // namespace ms
