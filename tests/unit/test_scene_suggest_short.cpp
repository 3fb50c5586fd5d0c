// Did-you-mean on short words: two edits in four letters change half the
// word, so "size" suggests nothing rather than "time"; one edit still does.
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "core/suggest.h"

namespace {

TEST(SceneSuggestShort, FourLettersGetOneEdit) {
  const std::vector<std::string_view> render{"width", "height", "spp", "time", "exposure", "tonemap"};
  EXPECT_EQ(ms::closest("size", render), "");
  EXPECT_EQ(ms::closest("tme", render), "time");
  EXPECT_EQ(ms::closest("tiem", render), "time");  // one swap
  EXPECT_EQ(ms::closest("expsre", render), "exposure");  // longer words keep two
}

}  // namespace
