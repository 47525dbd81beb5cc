// The YAML reader (libyaml events into YamlNode): the forms the database, the catalog and scene
// files use, the lines errors name, and the conversions a document refuses.
#include <gtest/gtest.h>

#include "spectral/yaml_file.h"

namespace fl::spectral {
namespace {

TEST(Yaml, ScalarsMapsSequencesAndLines) {
  const YamlNode root = parse_yaml(
      "# comment\n"
      "REFERENCES: \"<a href=x>Johnson</a> 1972\"\n"
      "DATA:\n"
      "  - type: tabulated nk\n"
      "    data: |\n"
      "        0.5 1.2 3.4\n"
      "        0.6 1.3 3.5\n"
      "  - type: 'formula 2'\n"
      "    coefficients: 0 1.5 0.01\n");
  ASSERT_TRUE(root.is_map());
  EXPECT_EQ(root["REFERENCES"].scalar(), "<a href=x>Johnson</a> 1972");
  const YamlNode& data = root["DATA"];
  ASSERT_TRUE(data.is_sequence());
  ASSERT_EQ(data.size(), 2u);
  EXPECT_EQ(data.line(), 3);  // 0-based: the first '-'
  EXPECT_EQ(data.items()[0]["type"].scalar(), "tabulated nk");
  EXPECT_EQ(data.items()[0]["data"].scalar(), "0.5 1.2 3.4\n0.6 1.3 3.5\n");
  EXPECT_EQ(data.items()[0]["data"].line(), 4);  // the literal's indicator, on its key's line
  EXPECT_EQ(data.items()[1]["type"].scalar(), "formula 2");
  EXPECT_EQ(data.items()[1].line(), 7);
  EXPECT_FALSE(root["MISSING"]);
  EXPECT_FALSE(data["type"]);  // a sequence has no keys
  ASSERT_EQ(root.fields().size(), 2u);
  EXPECT_EQ(root.fields()[1].first.scalar(), "DATA");
  EXPECT_EQ(root.fields()[1].first.line(), 2);
}

TEST(Yaml, NullsAreThePlainEmptyTildeAndNullForms) {
  const YamlNode root = parse_yaml("a:\nb: ~\nc: null\nd: ''\ne: \"null\"\n");
  for (const char* key : {"a", "b", "c"}) {
    EXPECT_TRUE(root[key]) << key;
    EXPECT_TRUE(root[key].is_null()) << key;
    EXPECT_EQ(root[key].as_string(), "null") << key;
  }
  EXPECT_TRUE(root["d"].is_scalar());
  EXPECT_EQ(root["d"].scalar(), "");
  EXPECT_TRUE(root["e"].is_scalar());
  EXPECT_EQ(root["e"].scalar(), "null");
  EXPECT_TRUE(parse_yaml("# only a comment\n").is_null());
}

TEST(Yaml, AliasesCopyTheirAnchorsNode) {
  const YamlNode root = parse_yaml("base: &b {n: 1.5, k: 0}\ncopy: *b\nlist: [&x 2, *x]\n");
  EXPECT_EQ(root["copy"]["n"].scalar(), "1.5");
  EXPECT_EQ(root["copy"].line(), 1);
  EXPECT_EQ(root["list"].items()[1].scalar(), "2");
}

TEST(Yaml, ConversionsADocumentRefuses) {
  const YamlNode root = parse_yaml("n: [1, 2]\n");
  try {
    root["n"].as_string();
    FAIL() << "a list read as text";
  } catch (const YamlError& e) {
    EXPECT_EQ(e.line, 0);
    EXPECT_STREQ(e.what(), "bad conversion");
  }
}

TEST(Yaml, SyntaxErrorsNameTheirLine) {
  try {
    parse_yaml("name: x\nclass: [metal\nother: 1\n");
    FAIL() << "unterminated flow sequence";
  } catch (const YamlError& e) {
    EXPECT_EQ(e.line, 2);  // 0-based: the line of "other: 1", where a , or ] was expected
    EXPECT_NE(std::string(e.what()).find("did not find expected ',' or ']'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fl::spectral
