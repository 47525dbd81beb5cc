// fl::edit_distance and fl::closest_match (src/util/suggest.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "util/suggest.h"

namespace {

TEST(EditDistance, LevenshteinTextbookPairs) {
  // Wagner & Fischer's distance on the usual worked examples (Jurafsky & Martin; Wikipedia,
  // "Levenshtein distance"): no transposition helps in any of them.
  EXPECT_EQ(fl::edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(fl::edit_distance("Saturday", "Sunday"), 3u);
  EXPECT_EQ(fl::edit_distance("flaw", "lawn"), 2u);
  EXPECT_EQ(fl::edit_distance("", "abc"), 3u);
  EXPECT_EQ(fl::edit_distance("abc", ""), 3u);
  EXPECT_EQ(fl::edit_distance("", ""), 0u);
}

TEST(EditDistance, AdjacentSwapIsOneEditButSwapsDoNotOverlap) {
  EXPECT_EQ(fl::edit_distance("teh", "the"), 1u);
  EXPECT_EQ(fl::edit_distance("ab", "ba"), 1u);
  // The restricted (optimal string alignment) distance: "ca" -> "ac" -> "abc" edits a swapped pair
  // again, which it does not allow (Wikipedia, "Damerau-Levenshtein distance": OSA 3, DL 2).
  EXPECT_EQ(fl::edit_distance("ca", "abc"), 3u);
}

TEST(EditDistance, IgnoresAsciiCaseAndIsSymmetric) {
  EXPECT_EQ(fl::edit_distance("GOLD", "gold"), 0u);
  EXPECT_EQ(fl::edit_distance("Refrence", "reference"), 1u);
  for (const auto& [a, b] : std::vector<std::pair<std::string, std::string>>{
           {"kitten", "sitting"}, {"ca", "abc"}, {"lights", "lighting"}, {"x", "materials"}})
    EXPECT_EQ(fl::edit_distance(a, b), fl::edit_distance(b, a)) << a << " / " << b;
}

TEST(ClosestMatch, FindsNearKeysOnly) {
  const std::vector<std::string> keys{"name",   "class", "order",   "reference",
                                      "source", "file",  "constant"};
  EXPECT_EQ(fl::closest_match("refrence", keys), "reference");
  EXPECT_EQ(fl::closest_match("Source", keys), "source");
  EXPECT_EQ(fl::closest_match("clas", keys), "class");
  EXPECT_EQ(fl::closest_match("constnat", keys), "constant");
  EXPECT_FALSE(fl::closest_match("colour", keys));
  EXPECT_FALSE(fl::closest_match("", keys));
  EXPECT_FALSE(fl::closest_match("name", {}));
  const std::vector<std::string> lighting{"punctual", "ibl", "area"};
  EXPECT_FALSE(fl::closest_match("abc", lighting));  // 2 edits from "ibl": too far for 3 letters
  EXPECT_EQ(fl::closest_match("lights", {"materials", "lighting"}), "lighting");
}

TEST(ClosestMatch, TiesGoToTheEarlierCandidate) {
  EXPECT_EQ(fl::closest_match("cat", {"bat", "hat"}), "bat");
  EXPECT_EQ(fl::closest_match("cat", {"hat", "bat"}), "hat");
  EXPECT_EQ(fl::did_you_mean("cat", {"hat"}), " (did you mean 'hat'?)");
  EXPECT_EQ(fl::did_you_mean("zebra", {"hat"}), "");
}

}  // namespace
