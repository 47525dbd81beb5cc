// Any material, first class: lists of catalog names, database pages, page globs and files in every
// command; coverage in the outputs and --min-coverage; `pages`; `library`; fits that never publish
// worse than their best start. Run through the CLI on the database pages named in each test.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "csv_reader.h"
#include "fresnel/registered_models.h"
#include "test_util.h"

namespace fl {
namespace {

using test::cli;
using test::run_command;

using test::csv_rows;

using test::csv_records;

int lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

TEST(MaterialsCli, PresetsTakeDatabasePagesCatalogNamesAndFiles) {
  test::TempDir tmp;
  const auto csv = tmp.file("glass.csv", "Wavelength (nm),n\n350,1.53\n850,1.51\n");
  const auto r = run_command(cli() + " -q presets main/Co/nk/Werner-DFT gold '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = csv_records(r.out);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].at("material"), "main/Co/nk/Werner-DFT");
  EXPECT_EQ(rows[1].at("material"), "Gold");
  EXPECT_EQ(rows[2].at("material"), "glass");
  EXPECT_EQ(rows[2].at("class"), "dielectric");
  // A lossless dielectric's fitted κ stays 0.
  for (const char* c : {"kappa_r", "kappa_g", "kappa_b"})
    EXPECT_EQ(std::stod(rows[2].at(c)), 0.0) << c;
}

// `presets --basis K` carries basis K's coefficients c0..c(K−1) per channel. A
// wavelength-independent index reflects the same at every wavelength, so its three channels'
// coefficients are equal; the option is refused where a format has no place for it.
TEST(MaterialsCli, PresetsCarryTheBasisModelAsked) {
  test::TempDir tmp;
  const auto csv = tmp.file("grey.csv", "Wavelength (nm),n\n350,1.5\n850,1.5\n");
  for (const int k : {3, 4, 5}) {
    const auto r = run_command(cli() + fmt::format(" -q presets --basis {} '{}'", k, csv));
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = csv_records(r.out);
    ASSERT_EQ(rows.size(), 1u);
    for (int c = 0; c < 5; ++c) {
      const auto name = fmt::format("basis{}_c{}_", k, c);
      if (c >= k) {
        EXPECT_EQ(rows[0].count(name + "r"), 0u) << name;
        continue;
      }
      const double red = std::stod(rows[0].at(name + "r"));
      EXPECT_NEAR(std::stod(rows[0].at(name + "g")), red, 1e-5) << name;
      EXPECT_NEAR(std::stod(rows[0].at(name + "b")), red, 1e-5) << name;
    }
  }
  for (const char* bad : {"--basis 6", "--basis 4 --format gltf", "--basis 4 --openpbr"}) {
    const auto r = run_command(cli() + " -q presets gold " + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_EQ(lines(r.err), 1) << bad << ": " << r.err;
  }
}

TEST(MaterialsCli, EveryModelsErrorForOneFileInOneRun) {
  test::TempDir tmp;
  const auto csv = tmp.file("metal.csv", "lambda_um,n,k\n0.35,1.2,1.9\n0.85,0.3,5.0\n");
  const auto r = run_command(cli() + " -q table models '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  // The header, then every model × {derived, fitted}.
  EXPECT_EQ(lines(r.out), 1 + 2 * static_cast<int>(fresnel::model_specs().size()));
}

// Every input format through `curve`, in one run: a table, refractiveindex.info's CSV download, a
// SOPRA file (nm) and a .spd pair, all holding the same gold-like data, give the same first row.
TEST(MaterialsCli, EveryInputFormatThroughTheCli) {
  test::TempDir tmp;
  const auto table = tmp.file("t.tsv", "wl [um]\tn\tk\n0.35\t1.5\t1.9\n0.85\t0.2\t5.4\n");
  const auto download = tmp.file("d.csv", "wl,n\n0.35,1.5\n0.85,0.2\nwl,k\n0.35,1.9\n0.85,5.4\n");
  const auto sopra = tmp.file("s.nk", "4 350 850 1\n1.5 1.9\n0.2 5.4\n");
  tmp.file("p.eta.spd", "350 1.5\n850 0.2\n");
  const auto spd = tmp.file("p.k.spd", "350 1.9\n850 5.4\n");
  const auto r = run_command(cli() + " -q curve '" + table + "' '" + download + "' '" + sopra +
                             "' '" + spd + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = csv_records(r.out);
  ASSERT_EQ(rows.size(), 4u * 91);
  for (size_t m = 1; m < 4; ++m)
    for (const char* c : {"truth_r", "truth_g", "truth_b"})
      EXPECT_EQ(rows[91 * m].at(c), rows[0].at(c)) << m << c;
  EXPECT_EQ(rows[91 * 3].at("material"), "p");
}

TEST(MaterialsCli, GlobsExpandToSortedPagesAndAGlobMatchingNothingIsAnError) {
  const auto r = run_command(cli() + " -q table schlick 'main/Ti/nk/Rakic-*'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = csv_records(r.out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("material"), "main/Ti/nk/Rakic-BB");
  EXPECT_EQ(rows[1].at("material"), "main/Ti/nk/Rakic-LD");
  const auto none = run_command(cli() + " table schlick 'main/Xx/**'");
  EXPECT_EQ(none.status, 2);
  EXPECT_EQ(lines(none.err), 1) << none.err;
  EXPECT_NE(none.err.find("'main/Xx/**' matches no database page"), std::string::npos) << none.err;
}

// main/Au/nk/Ordal measures 667 nm and up: its gold is held grey below. Every output says so.
TEST(MaterialsCli, CoverageIsDataAndMinCoverageRefusesNamedMaterials) {
  const auto r =
      run_command(cli() + " -q --min-coverage 0 presets main/Au/nk/Ordal main/Au/nk/Johnson");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = csv_records(r.out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_LT(std::stod(rows[0].at("coverage")), 0.5);
  EXPECT_EQ(rows[0].at("extrapolated"), "yes");
  EXPECT_EQ(rows[1].at("coverage"), "1.0000");
  EXPECT_EQ(rows[1].at("extrapolated"), "no");
  const auto json =
      run_command(cli() + " -q --min-coverage 0 presets main/Au/nk/Ordal --format json");
  EXPECT_NE(json.out.find("\"extrapolated\": \"yes\""), std::string::npos) << json.out;
  const auto md = run_command(cli() + " -q --min-coverage 0 curve main/Au/nk/Ordal --format md");
  EXPECT_NE(md.out.find("main/Au/nk/Ordal: extrapolated, n and k data does not cover 360-665 nm"),
            std::string::npos);

  const auto one = run_command(cli() + " --min-coverage 0.9 curve main/Au/nk/Ordal");
  EXPECT_EQ(one.status, 2);
  EXPECT_EQ(lines(one.err), 1) << one.err;
  EXPECT_NE(
      one.err.find("main/Au/nk/Ordal: covers 0.004 of the visible range, below --min-coverage 0.9"),
      std::string::npos)
      << one.err;
  EXPECT_EQ(one.out, "");
  // Named among others, it is still refused; --skip-unusable skips it with the reason.
  const auto many =
      run_command(cli() + " --min-coverage 0.9 presets main/Au/nk/Ordal main/Au/nk/Johnson");
  EXPECT_EQ(many.status, 2);
  EXPECT_EQ(many.out, "");
  const auto skipped = run_command(
      cli() + " --min-coverage 0.9 --skip-unusable presets main/Au/nk/Ordal main/Au/nk/Johnson");
  ASSERT_EQ(skipped.status, 0) << skipped.err;
  EXPECT_EQ(csv_records(skipped.out).size(), 1u);
  EXPECT_NE(skipped.err.find("skipped main/Au/nk/Ordal: covers 0.004"), std::string::npos)
      << skipped.err;
}

TEST(MaterialsCli, CurveOverSeveralMaterialsNamesEachRowsMaterial) {
  const auto r = run_command(cli() + " -q curve gold main/Cu/nk/Johnson");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = csv_records(r.out);
  ASSERT_EQ(rows.size(), 2u * 91);
  EXPECT_EQ(rows.front().at("material"), "Gold");
  EXPECT_EQ(rows.back().at("material"), "main/Cu/nk/Johnson");
  EXPECT_EQ(csv_rows(r.out)[0][0], "theta_deg");  // the original columns keep their places
}

TEST(MaterialsCli, CatalogEntryMayPointAtAFile) {
  test::TempDir tmp;
  tmp.file("catalog/data/silver.csv", "wl,n\n0.35,0.2\n0.85,0.15\nwl,k\n0.35,1.6\n0.85,5.8\n");
  tmp.file("catalog/my_silver.yml", "name: My silver\nclass: metal\nfile: data/silver.csv\n");
  const auto r = run_command(std::string("'") + FL_CLI + "' -q --db '" + FL_DEFAULT_DB +
                             "' --materials '" + tmp.path() + "/catalog' presets");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = csv_records(r.out);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("material"), "My silver");
}

TEST(MaterialsCli, PlotsOfSeveralMaterialsNeedANamePlaceholder) {
  test::TempDir tmp;
  const auto bad = run_command(cli() + " plot strip gold silver --out '" + tmp.path() + "/s.png'");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(lines(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("2 materials need '{name}' in --out"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/s.png"));
  const auto ok =
      run_command(cli() + " -q plot strip gold main/Au/nk/Babar --models schlick --out '" +
                  tmp.path() + "/{name}.png'");
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(tmp.path() + "/gold.png"));
  EXPECT_TRUE(std::filesystem::exists(tmp.path() + "/main_Au_nk_Babar.png"));
}

TEST(MaterialsCli, ScenesTakePageGlobs) {
  test::TempDir tmp;
  const auto scene = tmp.file("s.yaml", "materials: [gold, 'main/Ti/nk/Rakic-*']\n");
  const auto r = run_command(cli() + " -q plan '" + scene + "' --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("main/Ti/nk/Rakic-BB"), std::string::npos);
  EXPECT_NE(r.out.find("main/Ti/nk/Rakic-LD"), std::string::npos);
}

// The class comes from the data: caesium (mean k 0.67-0.95) and tungsten (n > k) are metals,
// silicon (k 0.08) is not.
TEST(MaterialsCli, PagesListsBookClassCoverageAndReference) {
  const auto r = run_command(cli() +
                             " -q pages 'main/Cs/nk/*' main/Si/nk/Aspnes main/W/nk/Werner-DFT "
                             "main/Au/nk/Ordal 'main/AgBr/n2/*'");
  ASSERT_EQ(r.status, 0) << r.err;
  std::map<std::string, std::map<std::string, std::string>> by_page;
  for (const auto& row : csv_records(r.out)) by_page[row.at("page")] = row;
  ASSERT_TRUE(by_page.count("main/Cs/nk/Smith")) << r.out;
  EXPECT_EQ(by_page["main/Cs/nk/Smith"].at("class"), "metal");
  EXPECT_EQ(by_page["main/Cs/nk/Smith"].at("book"), "Cs");
  EXPECT_EQ(by_page["main/Cs/nk/Smith"].at("status"), "ok");
  EXPECT_EQ(by_page["main/Si/nk/Aspnes"].at("class"), "dielectric");
  EXPECT_EQ(by_page["main/W/nk/Werner-DFT"].at("class"), "metal");
  EXPECT_EQ(by_page["main/Au/nk/Ordal"].at("book_name"), "Au (Gold)");
  EXPECT_EQ(by_page["main/Au/nk/Ordal"].at("extrapolated"), "yes");
  EXPECT_NE(by_page["main/Au/nk/Ordal"].at("reference").find("Ordal"), std::string::npos);
  for (const auto& [page, row] : by_page)
    if (page.find("/n2/") != std::string::npos) {
      EXPECT_NE(row.at("status").find("nonlinear index, not n, k data"), std::string::npos) << page;
    }
}

// A small database: one good metal page, one extrapolated, one that cannot be read, one glass.
std::string small_db(const test::TempDir& tmp) {
  const std::string rows = "        0.30 0.5 2.0\n        0.90 0.4 6.0\n";
  tmp.file("db/data/main/M/nk/Good.yml",
           "REFERENCES: A. Author 2024\nDATA:\n  - type: tabulated nk\n    data: |\n" + rows);
  tmp.file(
      "db/data/main/M/nk/Red.yml",
      "DATA:\n  - type: tabulated nk\n    data: |\n        0.70 0.3 4.0\n        0.90 0.4 6.0\n");
  tmp.file("db/data/main/M/nk/Bad.yml",
           "DATA:\n  - type: tabulated nk\n    data: |\n        0.50 -1 2.0\n");
  tmp.file("db/data/main/G/nk/Glass.yml",
           "DATA:\n  - type: formula 5\n    wavelength_range: 0.3 1.0\n    coefficients: 1.5\n");
  return tmp.path() + "/db";
}

TEST(MaterialsCli, LibraryListsEveryPageInOrSkippedWithItsReasonAndFlagsExtrapolation) {
  test::TempDir tmp;
  const auto db = small_db(tmp);
  const auto out = tmp.path() + "/lib";
  const auto base =
      std::string("'") + FL_CLI + "' --db '" + db + "' --materials '" + tmp.path() + "/none'";
  const auto r = run_command(base + " --min-coverage 0 library --out '" + out + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto lib = csv_records(test::run_command("cat '" + out + "/library.csv'").out);
  ASSERT_EQ(lib.size(), 2u);  // Good and Red; Glass is a dielectric, Bad cannot be read
  EXPECT_EQ(lib[1].at("material"), "main/M/nk/Red");
  EXPECT_NE(lib[1].at("flags").find("extrapolated"), std::string::npos);
  EXPECT_NE(lib[1].at("uncovered").find("360-695 nm"), std::string::npos) << lib[1].at("uncovered");
  const auto skipped = csv_records(test::run_command("cat '" + out + "/skipped.csv'").out);
  ASSERT_EQ(skipped.size(), 2u);
  EXPECT_EQ(skipped[0].at("page"), "main/G/nk/Glass");
  EXPECT_EQ(skipped[0].at("reason_class"), "class dielectric");
  EXPECT_EQ(skipped[1].at("page"), "main/M/nk/Bad");
  EXPECT_NE(skipped[1].at("reason").find("Bad.yml:4: n = -1 is not physical"), std::string::npos);
  for (const char* f : {"models.csv", "gallery.md", "README.md", "spread.md"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
  // Every preset format (documents/preset_formats.h), glTF and Standard Surface included.
  for (const char* f : {"library.csv", "library.md", "library.json", "library.mtlx",
                        "library_openpbr.mtlx", "library_standard_surface.mtlx", "library.gltf"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;
  const auto gallery = test::run_command("cat '" + out + "/gallery.md'").out;
  EXPECT_NE(gallery.find("**Extrapolated**: n and k data does not cover 360-695 nm"),
            std::string::npos);
  // Progress when stderr is not a terminal: periodic lines, not a live counter.
  EXPECT_NE(r.err.find("library: fitting 2/2"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);

  // (-q: the progress lines that precede it are not part of the error.)
  const auto strict = run_command(base + " -q library --strict --out '" + tmp.path() + "/strict'");
  EXPECT_EQ(strict.status, 2);
  EXPECT_EQ(lines(strict.err), 1) << strict.err;
  EXPECT_NE(strict.err.find("Bad.yml:4: n = -1 is not physical"), std::string::npos) << strict.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/strict"));
  // By default the library keeps pages covering the visible range: Red is skipped, with its
  // coverage.
  const auto def = run_command(base + " -q library --out '" + tmp.path() + "/def'");
  ASSERT_EQ(def.status, 0) << def.err;
  EXPECT_EQ(csv_records(test::run_command("cat '" + tmp.path() + "/def/library.csv'").out).size(),
            1u);
}

// main/Zn/nk/Querry has RGB η ≈ 13.7: the fit box no longer pins it, and the fit ends no worse than
// the derived parameters it starts from.
TEST(MaterialsCli, FittedRgbEtaKappaOfZincQuerryIsNoWorseThanDerived) {
  const auto r = run_command(cli() + " -q table models main/Zn/nk/Querry");
  ASSERT_EQ(r.status, 0) << r.err;
  double derived = -1, fitted = -1;
  std::string flags;
  for (const auto& row : csv_records(r.out))
    if (row.at("model") == "fresnel_rgb") {
      (row.at("parameters") == "derived" ? derived : fitted) = std::stod(row.at("rms_de00"));
      if (row.at("parameters") == "fitted") flags = row.at("fit_flags");
    }
  ASSERT_GT(derived, 0);
  EXPECT_LE(fitted, derived);
  EXPECT_EQ(flags.find("at_bound"), std::string::npos) << flags;
}

// Every model's derived parameters are one of its fit's starts, so no fitted error may exceed the
// derived one (to the table's 3 decimals), over the whole catalog.
TEST(MaterialsCli, NoFitPublishesWorseThanItsDerivedStart) {
  const auto r = run_command(cli() + " -q table models");
  ASSERT_EQ(r.status, 0) << r.err;
  std::map<std::string, double> derived;
  int checked = 0;
  for (const auto& row : csv_records(r.out)) {
    const std::string key = row.at("material") + "|" + row.at("model");
    if (row.at("parameters") == "derived")
      derived[key] = std::stod(row.at("rms_de00"));
    else {
      EXPECT_LE(std::stod(row.at("rms_de00")), derived.at(key) + 5e-4) << key;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 28 * static_cast<int>(fresnel::model_specs().size()));
}

// A database with a catalog: three bulk pages of one metal whose k differ by a constant (so B lies
// between A and C at every wavelength, in both reflectances), and a model far from them.
std::string consensus_db(const test::TempDir& tmp) {
  const auto page = [&](const std::string& name, double n, double k) {
    tmp.file("db/data/main/M/nk/" + name + ".yml",
             fmt::format("DATA:\n  - type: tabulated nk\n    data: |\n        0.30 {} {}\n"
                         "        0.90 {} {}\n",
                         n, k, n + 0.1, k + 1.0));
  };
  page("A", 0.5, 2.0);
  page("B", 0.5, 2.2);
  page("C", 0.5, 2.4);
  page("D", 1.5, 1.0);
  tmp.file("db/catalog-nk.yml",
           "- SHELF: main\n  content:\n    - BOOK: M\n      name: \"M (Metallium)\"\n"
           "      content:\n        - DIVIDER: \"Experimental data\"\n"
           "        - PAGE: A\n          name: \"A 1990: n,k\"\n          data: main/M/nk/A.yml\n"
           "        - PAGE: B\n          name: \"B 2001: n,k\"\n          data: main/M/nk/B.yml\n"
           "        - PAGE: C\n          name: \"C 2010: n,k\"\n          data: main/M/nk/C.yml\n"
           "        - DIVIDER: \"Models and simulations\"\n"
           "        - PAGE: D\n          name: \"D 2000: Drude model\"\n"
           "          data: main/M/nk/D.yml\n");
  return tmp.path() + "/db";
}

// The consensus' F0 and F82 from the pages' output: the median page's (B's) own values.
constexpr double kPrintedTolerance = 2e-6;  // the CSV's 6 decimals

TEST(MaterialsCli, ConsensusOfThreePagesIsTheMiddleOneWithTheirSpreadAndTheModelAnOutlier) {
  test::TempDir tmp;
  const auto db = consensus_db(tmp);
  const auto base =
      std::string("'") + FL_CLI + "' -q --db '" + db + "' --materials '" + tmp.path() + "/none'";
  const auto c = run_command(base + " presets --consensus metallium");
  ASSERT_EQ(c.status, 0) << c.err;
  const auto rows = csv_records(c.out);
  ASSERT_EQ(rows.size(), 1u);
  const auto& r = rows[0];
  EXPECT_EQ(r.at("material"), "Metallium");  // the book's common name, "M (Metallium)"
  EXPECT_EQ(r.at("page_kind"), "consensus");
  EXPECT_EQ(r.at("pages_used"), "3");
  EXPECT_EQ(r.at("recommended"), "main/M/nk/B");
  EXPECT_EQ(r.at("outliers"), "1");
  EXPECT_NE(r.at("outlier_pages").find("D (model:"), std::string::npos) << r.at("outlier_pages");
  const auto b = csv_records(run_command(base + " presets main/M/nk/B").out).at(0);
  EXPECT_EQ(b.at("page_kind"), "bulk");
  for (const char* q : {"f0_r", "f0_g", "f0_b", "f82_r", "f82_g", "f82_b"})
    EXPECT_NEAR(std::stod(r.at(q)), std::stod(b.at(q)), kPrintedTolerance) << q;
  for (const char* ch : {"r", "g", "b"}) {
    const double f0 = std::stod(r.at(std::string("f0_") + ch));
    EXPECT_LT(std::stod(r.at(std::string("f0_") + ch + "_lo")), f0) << ch;
    EXPECT_GT(std::stod(r.at(std::string("f0_") + ch + "_hi")), f0) << ch;
  }
  EXPECT_GT(std::stod(r.at("f0_de00_max")), 0.0);
  EXPECT_GE(std::stod(r.at("f0_de00_max")), std::stod(r.at("f0_de00_median")));

  const auto pages = csv_records(run_command(base + " consensus M --table pages").out);
  ASSERT_EQ(pages.size(), 4u);
  EXPECT_EQ(pages[3].at("page"), "main/M/nk/D");
  EXPECT_EQ(pages[3].at("kind"), "model");
  EXPECT_EQ(pages[3].at("used"), "no");
  EXPECT_EQ(pages[3].at("outlier"), "yes");
  EXPECT_EQ(pages[1].at("f0_de00"), "0.000");

  const auto bad = run_command(base + " presets --consensus Unobtainium");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(lines(bad.err), 1) << bad.err;
  const auto kinds = csv_records(run_command(base + " pages").out);
  ASSERT_EQ(kinds.size(), 4u);
  EXPECT_EQ(kinds[0].at("kind"), "bulk");
  EXPECT_EQ(kinds[3].at("kind"), "model");
}

}  // namespace
}  // namespace fl
