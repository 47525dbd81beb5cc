// The YAML reader (libyaml events into YamlNode): the forms the database, the catalog and scene
// files use, the lines errors name, and the conversions a document refuses.
#include <gtest/gtest.h>

#include <string>

#include "spectral/material.h"
#include "spectral/yaml_file.h"
#include "test_util.h"
#include "util/errors.h"

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
    EXPECT_NE(std::string(e.what()).find("did not find expected ',' or ']'"), std::string::npos)
        << e.what();
  }
}

TEST(Yaml, TaggedNullSpellingsAreText) {
  const YamlNode root = parse_yaml("a: !!str null\nb: !!str ~\nc: ! ~\n");
  for (const char* key : {"a", "b", "c"}) EXPECT_TRUE(root[key].is_scalar()) << key;
  EXPECT_EQ(root["a"].scalar(), "null");
}

// Inputs that would exhaust the stack or memory are refused like any other broken document.
TEST(Yaml, DeepNestingAndAliasBombsAreRefused) {
  const std::string deep =
      std::string(kMaxYamlDepth + 5, '[') + std::string(kMaxYamlDepth + 5, ']');
  EXPECT_THROW(parse_yaml(deep), YamlError);
  const std::string fine = std::string(50, '[') + std::string(50, ']');
  EXPECT_NO_THROW(parse_yaml(fine));
  std::string lines = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i <= 9; ++i) {
    std::string refs;
    for (int k = 0; k < 10; ++k) refs += (k ? ", *a" : "*a") + std::to_string(i - 1);
    lines += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + refs + "]\n";
  }
  try {
    parse_yaml(lines);  // 10^10 nodes once copied; refused past kMaxYamlNodes
    FAIL() << "an alias bomb";
  } catch (const YamlError& e) {
    EXPECT_NE(std::string(e.what()).find("nodes"), std::string::npos) << e.what();
  }
}

TEST(Yaml, TextThatIsNotUtf8NamesItsLine) {
  try {
    parse_yaml("name: ok\nreference: caf\xe9 1999\n");
    FAIL() << "Latin-1 text";
  } catch (const YamlError& e) {
    EXPECT_EQ(e.line, 1);
  }
}

// A catalog entry found by its display name is read with every error it has, not passed over.
TEST(Yaml, ABrokenCatalogEntryFoundByNameReportsItsOwnError) {
  test::TempDir tmp;
  tmp.file("materials/shiny.yml", "name: Shiny Metal\nclass: metal\nsource: main/Xx/nk/Missing\n");
  const DataPaths paths{tmp.path() + "/db", tmp.path() + "/materials"};
  try {
    resolve_material("shiny metal", paths);
    FAIL() << "a missing page";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Missing.yml"), std::string::npos) << e.what();
  }
}

// An entry whose YAML does not parse is still selected by its key, and a name that selects nothing
// names the broken entry and its line instead of passing over it.
TEST(Yaml, AnUnreadableCatalogEntryIsNamedWhenANameSelectsNothing) {
  test::TempDir tmp;
  tmp.file("materials/shiny.yml", "name: Shiny Metal\nclass: metal\nsource: main/Au/nk/Johnson\n");
  tmp.file("materials/broken.yml", "name: [Broken\nclass: metal\n");
  const DataPaths paths{tmp.path() + "/db", tmp.path() + "/materials"};
  const auto index = read_catalog_index(paths.materials);
  ASSERT_EQ(index.entries.size(), 2u);
  EXPECT_EQ(index.entries[0].names, std::vector<std::string>{"broken"});
  EXPECT_NE(index.entries[0].error.find("broken.yml"), std::string::npos) << index.entries[0].error;
  EXPECT_EQ(index.entries[1].names, (std::vector<std::string>{"shiny", "Shiny Metal"}));
  EXPECT_TRUE(index.entries[1].error.empty());
  try {
    resolve_material("Brokenn Metal", paths);
    FAIL() << "an unknown name";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unreadable catalog entries: "), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("broken.yml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fl::spectral
