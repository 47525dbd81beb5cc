// Every input is bounded and strict: only regular files of at most kMaxInputBytes are read (FIFOs
// and devices refused without being opened), folders that cannot be listed are input errors, a
// YAML map may not repeat a key, and catalog entries name only known keys and unique names.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "spectral/material.h"
#include "spectral/text_file.h"
#include "spectral/yaml_file.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl::spectral {
namespace {

// The message of the InputError `f` throws ("" when it throws none).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BoundedInputs, OnlyRegularFilesAreRead) {
  test::TempDir tmp;
  const std::string fifo = tmp.path() + "/pipe.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // No writer ever opens the FIFO: a reader that opened it would block here for ever.
  EXPECT_EQ(input_error([&] { read_text_file(fifo); }),
            fifo + ": is a FIFO (named pipe), expected a regular file");
  EXPECT_EQ(input_error([] { read_text_file("/dev/zero"); }),
            "/dev/zero: is a character device, expected a regular file");
  EXPECT_EQ(input_error([&] { read_text_file(tmp.path()); }),
            tmp.path() + ": is a directory, expected a file");
  EXPECT_EQ(input_error([&] { check_input_file(tmp.path() + "/none.csv"); }),
            tmp.path() + "/none.csv: no such file");
  EXPECT_EQ(input_error([&] { check_input_file(tmp.file("a/b.csv", "x") + "/c"); }),
            tmp.path() + "/a/b.csv/c: no such file");
}

TEST(BoundedInputs, FilesAboveTheLimitAreRefusedBeforeReading) {
  test::TempDir tmp;
  // A sparse file one byte over the limit: its size is known without writing 64 MiB.
  const std::string big = tmp.path() + "/big.csv";
  {
    std::ofstream(big) << "wl,n,k\n";
    std::filesystem::resize_file(big, kMaxInputBytes + 1);
  }
  EXPECT_EQ(input_error([&] { read_text_file(big); }),
            big + ": is 67108865 bytes, more than the 64 MiB an input file may hold");
  std::filesystem::resize_file(big, kMaxInputBytes);
  EXPECT_EQ(input_error([&] { check_input_file(big); }), "");
  const std::string small = tmp.file("small.csv", "0123456789");
  EXPECT_EQ(input_error([&] { read_input_bytes(small, 9); }),
            small + ": is 10 bytes, more than the 9 bytes an input file may hold");
  EXPECT_EQ(read_input_bytes(small, 10), "0123456789");
}

TEST(BoundedInputs, FoldersThatCannotBeListedAreInputErrors) {
  test::TempDir tmp;
  tmp.file("cat/b.yml", "");
  tmp.file("cat/a.yml", "");
  EXPECT_EQ(list_folder(tmp.path() + "/cat", "catalog"),
            (std::vector<std::string>{tmp.path() + "/cat/a.yml", tmp.path() + "/cat/b.yml"}));
  EXPECT_EQ(input_error([&] { list_folder(tmp.path() + "/none", "material catalog folder"); }),
            tmp.path() + "/none: material catalog folder not found");
  EXPECT_EQ(input_error([&] { list_folder(tmp.path() + "/cat/a.yml", "material catalog folder"); }),
            tmp.path() + "/cat/a.yml: material catalog folder is not a folder");
  if (::geteuid() == 0) return;  // permissions do not bind root; the CLI test runs as nobody
  ASSERT_EQ(::chmod((tmp.path() + "/cat").c_str(), 0), 0);
  EXPECT_EQ(input_error([&] { list_folder(tmp.path() + "/cat", "material catalog folder"); }),
            tmp.path() + "/cat: material catalog folder cannot be listed (Permission denied)");
  ::chmod((tmp.path() + "/cat").c_str(), 0700);
}

TEST(StrictYaml, ARepeatedKeyIsAnErrorAtItsLine) {
  try {
    parse_yaml("REFERENCES: x\nDATA:\n  - type: tabulated nk\nDATA: []\n");
    FAIL() << "a repeated key was accepted";
  } catch (const YamlError& e) {
    EXPECT_EQ(e.line, 3);  // 0-based
    EXPECT_STREQ(e.what(), "repeated key 'DATA' (first at line 2)");
  }
  // Nested maps too, and keys that are equal only after YAML's quoting is removed.
  EXPECT_THROW(parse_yaml("a: {n: 1, 'n': 2}\n"), YamlError);
  // The same key in different maps, and keys that differ in case, are fine.
  EXPECT_NO_THROW(parse_yaml("a: {n: 1}\nb: {n: 1, N: 2}\n"));
  test::TempDir tmp;
  const std::string page = tmp.file("page.yml",
                                    "DATA:\n  - type: tabulated n\n    data: |\n        0.5 1.5\n"
                                    "DATA:\n  - type: tabulated n\n    data: |\n        0.5 2.5\n");
  EXPECT_EQ(input_error([&] { read_refractiveindex_file(page); }),
            page + ":5: invalid YAML: repeated key 'DATA' (first at line 1)");
}

TEST(StrictCatalog, UnknownKeysNameTheLineAndTheNearestKnownKey) {
  test::TempDir tmp;
  const DataPaths paths{tmp.path(), tmp.path()};
  const std::string typo =
      tmp.file("typo.yml", "name: T\nclass: dielectric\nconstant: {n: 1.5}\nrefrence: somebody\n");
  EXPECT_EQ(input_error([&] { read_catalog_entry(typo, paths); }),
            typo + ":4: unknown key 'refrence' in a catalog entry (did you mean 'reference'?)");
  const std::string far = tmp.file("far.yml", "name: T\nclass: dielectric\ncolour: red\n");
  EXPECT_EQ(
      input_error([&] { read_catalog_entry(far, paths); }),
      far +
          ":3: unknown key 'colour' in a catalog entry (expected name, class, aliases, reference, "
          "order, talk_schlick_rms_de00, source, file, constant)");
  const std::string inner =
      tmp.file("inner.yml", "name: T\nclass: dielectric\nconstant:\n  n: 1.5\n  kappa: 0\n");
  EXPECT_EQ(input_error([&] { read_catalog_entry(inner, paths); }),
            inner + ":5: unknown key 'kappa' in 'constant' (expected n, k)");
}

TEST(StrictCatalog, TwoEntriesMayNotShareANameOrAKey) {
  test::TempDir tmp;
  const DataPaths paths{tmp.path(), tmp.path() + "/cat"};
  const std::string a =
      tmp.file("cat/a.yml", "name: Glass\nclass: dielectric\nconstant: {n: 1.5}\n");
  const std::string b =
      tmp.file("cat/b.yml", "class: dielectric\nname: glass\nconstant: {n: 1.6}\n");
  EXPECT_EQ(
      input_error([&] { read_catalog(paths); }),
      b + ":2: name 'glass' is already the name of " + a + ":1 (names are compared ignoring case)");
  std::filesystem::remove(b);
  const std::string a2 =
      tmp.file("cat/a.yaml", "name: Other\nclass: dielectric\nconstant: {n: 1.6}\n");
  EXPECT_EQ(
      input_error([&] { read_catalog(paths); }),
      a + ": catalog key 'a' is also the key of " + a2 + " (keys are compared ignoring case)");
}

}  // namespace
}  // namespace fl::spectral
