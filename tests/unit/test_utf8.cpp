// core/utf8.h: well-formed UTF-8 passes unchanged; every byte outside a
// well-formed sequence (a stray 0xff, a cut sequence, overlong forms,
// surrogates, code points past U+10FFFF) becomes U+FFFD.
#include <gtest/gtest.h>

#include <vector>

#include "core/utf8.h"

namespace ms {
namespace {

const std::string kFffd = "\xef\xbf\xbd";

TEST(Utf8, WellFormedTextIsUnchanged) {
  const std::vector<std::string> good = {"", "plain ascii", "caf\xc3\xa9", "\xe2\x82\xac 5", "\xf0\x9f\x98\x80",
                                         "\xf4\x8f\xbf\xbf", "\xed\x9f\xbf", std::string("nul\0inside", 10)};
  for (const std::string& s : good) {
    EXPECT_TRUE(is_valid_utf8(s)) << s;
    EXPECT_EQ(valid_utf8(s), s);
  }
}

TEST(Utf8, EveryBadByteBecomesFffd) {
  EXPECT_EQ(valid_utf8("caf\xff"), "caf" + kFffd);
  EXPECT_EQ(valid_utf8("\xc3"), kFffd);                        // cut at the end
  EXPECT_EQ(valid_utf8("\xe2\x82x"), kFffd + kFffd + "x");     // cut in the middle
  EXPECT_EQ(valid_utf8("\xc0\xaf"), kFffd + kFffd);            // overlong '/'
  EXPECT_EQ(valid_utf8("\xe0\x80\xaf"), kFffd + kFffd + kFffd);  // overlong, three bytes
  EXPECT_EQ(valid_utf8("\xed\xa0\x80"), kFffd + kFffd + kFffd);  // a surrogate
  EXPECT_EQ(valid_utf8("\xf4\x90\x80\x80"), kFffd + kFffd + kFffd + kFffd);  // past U+10FFFF
  EXPECT_EQ(valid_utf8("\x80z"), kFffd + "z");                 // a lone continuation byte
  for (const std::string& s : std::initializer_list<std::string>{"caf\xff", "\xc3", "\xc0\xaf", "\xed\xa0\x80"}) {
    EXPECT_FALSE(is_valid_utf8(s)) << s;
    EXPECT_TRUE(is_valid_utf8(valid_utf8(s))) << s;
  }
}

}  // namespace
}  // namespace ms
