// Did-you-mean: the edit distance and when a suggestion is offered.
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "core/suggest.h"

namespace {

TEST(SceneSuggest, EditDistance) {
  EXPECT_EQ(ms::edit_distance("fov", "fov"), 0u);
  EXPECT_EQ(ms::edit_distance("", "abc"), 3u);
  EXPECT_EQ(ms::edit_distance("abc", ""), 3u);
  EXPECT_EQ(ms::edit_distance("fvo", "fov"), 1u);      // one adjacent swap
  EXPECT_EQ(ms::edit_distance("lihgt", "lights"), 2u); // swap + insert
  EXPECT_EQ(ms::edit_distance("colr", "color"), 1u);
  EXPECT_EQ(ms::edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(ms::edit_distance("FOV", "fov"), 0u);      // case-insensitive
  EXPECT_EQ(ms::edit_distance("ca", "abc"), 3u);       // OSA, not full Damerau (which says 2)
}

TEST(SceneSuggest, ClosestWithinThreshold) {
  const std::vector<std::string_view> keys{"position", "target", "up", "fov"};
  EXPECT_EQ(ms::closest("fvo", keys), "fov");
  EXPECT_EQ(ms::closest("postion", keys), "position");
  EXPECT_EQ(ms::closest("trgte", keys), "target");   // 2 edits on a long word
  EXPECT_EQ(ms::closest("x", keys), "");             // short words get 1 edit only
  EXPECT_EQ(ms::closest("banana", keys), "");
  EXPECT_EQ(ms::did_you_mean("upp", keys), "did you mean 'up'?");
  EXPECT_EQ(ms::did_you_mean("zzzzzz", keys), "");
}

TEST(SceneSuggest, FirstOfEquallyCloseCandidatesWins) {
  const std::vector<std::string_view> keys{"ao", "up"};
  EXPECT_EQ(ms::closest("a", keys), "ao");
  const std::vector<std::string_view> none;
  EXPECT_EQ(ms::closest("a", none), "");
}

}  // namespace
