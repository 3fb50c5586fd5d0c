// live/session.h's shown_error(): the viewer shows a compile error's whole
// log below its line (the red box's log node, stderr), so the line's hint
// points there and never to -v, a flag of the command line's.
#include <gtest/gtest.h>

#include "core/error.h"
#include "live/session.h"

namespace ms::live {
namespace {

ErrorInfo compile_error(std::string hint, std::string detail) {
  return ErrorInfo{Exit::bad_input, "x.frag", 4, {}, "shader compile error: 'foo' undeclared", std::move(hint),
                   std::move(detail)};
}

TEST(LiveErrorLine, TheHintPointsToTheLogBelowNotToVerbose) {
  const ErrorInfo e = compile_error("did you mean 'for'?; +2 more; " + std::string(kVerboseHint),
                                    "x.frag:4: error: 'foo' undeclared\nx.frag:5: error: 'bar' undeclared\n");
  EXPECT_NE(format_error(e).find("-v prints them all"), std::string::npos);  // the command line's, unchanged
  const std::string line = shown_error(e);
  EXPECT_EQ(line.find("-v"), std::string::npos) << line;
  EXPECT_EQ(line, "x.frag:4: shader compile error: 'foo' undeclared (did you mean 'for'?; +2 more; the full log is below)");
  // Other errors read as the command line shows them.
  const ErrorInfo single = compile_error("did you mean 'for'?", {});
  EXPECT_EQ(shown_error(single), format_error(single));
}

}  // namespace
}  // namespace ms::live
