// Look-dev outputs: the animated flip (decoded by libwebp's and giflib's readers), the contact
// sheet's layout, the HTML serializer (escaping, sortable values, a page libxml2 parses cleanly),
// and `render --env` and `render --compare` through the CLI, bad environments included.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

#include "documents/html.h"
#include "draw/figures.h"
#include "draw/png.h"
#include "io/exr.h"
#include "io/gif.h"
#include "io/webp.h"
#include "test_util.h"
#include "util/errors.h"

namespace fl {
namespace {

using io::Image8;
using io::Rgb8;
using test::cli;
using test::run_command;

Image8 flat(int w, int h, Rgb8 c) {
  return Image8(w, h, c);
}

TEST(ContactSheet, TilesAreWhereTheLayoutSays) {
  const int n = 21;
  draw::ContactSheet s;
  s.title = "Gold";
  s.notes = {"one", "two"};
  s.truth = flat(n, n, {10, 200, 10});
  std::vector<double> de(static_cast<size_t>(n) * n, 0.5);
  de[0] = std::numeric_limits<double>::quiet_NaN();
  s.rows.push_back({"schlick", flat(n, n, {200, 10, 10}), de, 0.5, 0.5});
  s.rows.push_back(
      {"f82", flat(n, n, {10, 10, 200}), std::vector<double>(de.size(), 2.0), 2.0, 2.0});
  const draw::LabelFont font;
  const auto img = draw::rasterize(draw::contact_sheet_drawing(s, font), font);
  const double scale = draw::heatmap_scale({0.5, 2.0});  // shared by both rows: 2
  for (size_t r = 0; r < 2; ++r) {
    const auto at = [&](int col, int dx, int dy) {
      const auto p = draw::sheet_tile(s, r, col);
      return img.at(int(p.x) + dx, int(p.y) + dy);
    };
    // The truth once, left of the first row; the later rows' first column stays empty.
    EXPECT_EQ(at(0, n / 2, n / 2), (r == 0 ? Rgb8{10, 200, 10} : Rgb8{255, 255, 255}));
    EXPECT_EQ(at(1, n / 2, n / 2), s.rows[r].render.at(0, 0));
    EXPECT_EQ(at(2, n / 2, n / 2), draw::inferno(s.rows[r].de2000[1] / scale));
    EXPECT_EQ(at(2, n - 1, n - 1), draw::inferno(s.rows[r].de2000[1] / scale));
  }
  EXPECT_EQ(img.at(int(draw::sheet_tile(s, 0, 2).x), int(draw::sheet_tile(s, 0, 2).y)),
            (Rgb8{235, 235, 235}));
  EXPECT_GT(draw::sheet_tile(s, 1, 0).y, draw::sheet_tile(s, 0, 0).y + n);
  int truth_pixels = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) truth_pixels += img.at(x, y) == Rgb8{10, 200, 10};
  EXPECT_EQ(truth_pixels, n * n);  // one truth tile on the sheet
}

// Tiles narrower than their labels: every label of a row ends before the next one begins, as the
// font measures it at the size it is set in.
TEST(ContactSheet, LabelsOfSmallTilesDoNotOverlap) {
  const int n = 21;
  draw::ContactSheet s;
  s.title = "Gold";
  s.truth = flat(n, n, {10, 200, 10});
  s.rows.push_back({"generalized_schlick (rendered parameters)", flat(n, n, {200, 10, 10}),
                    std::vector<double>(static_cast<size_t>(n) * n, 0.5), 0.512, 1.234});
  const draw::LabelFont font;
  const auto dr = draw::contact_sheet_drawing(s, font);
  const double label_y = draw::sheet_tile(s, 0, 0).y - 7;  // the label line above the tiles
  std::vector<const draw::Text*> labels;
  for (const auto& shape : dr.shapes)
    if (const auto* t = std::get_if<draw::Text>(&shape); t && t->y == label_y) labels.push_back(t);
  ASSERT_EQ(labels.size(), 3u);
  for (size_t i = 0; i + 1 < labels.size(); ++i)
    EXPECT_LT(labels[i]->x + draw::text_width_px(labels[i]->utf8, labels[i]->size_px, font),
              labels[i + 1]->x)
        << labels[i]->utf8;
  EXPECT_GE(labels[1]->size_px, 8.0);  // shrunk, but no smaller than legible
}

TEST(Html, TableCellsAreEscapedAndSortable) {
  Table t;
  t.name = "x";
  t.title = "A <b> & \"c\"";
  t.columns = {{"name"}, {"value", 3}, {"count"}};
  t.rows = {{std::string("a<b>&'"), 1.23456789, 7LL}, {std::string("z"), std::nan(""), 2LL}};
  t.reading = "See `code` and [the file](x.md).";
  const auto html = documents::table_html(t, "table-x");
  EXPECT_NE(html.find("A &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"t\">a&lt;b&gt;&amp;&#39;</td>"), std::string::npos);
  EXPECT_NE(html.find("<td data-v=\"1.234567890000\">1.235</td>"), std::string::npos);
  EXPECT_NE(html.find("<td data-v=\"\">n/a</td>"), std::string::npos);
  EXPECT_NE(html.find("<td data-v=\"7\">7</td>"), std::string::npos);
  EXPECT_NE(html.find("<code>code</code>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"x.md\">the file</a>"), std::string::npos);
  EXPECT_NE(html.find("<table id=\"table-x\">"), std::string::npos);
  EXPECT_NE(html.find("data-table=\"table-x\""), std::string::npos);
}

documents::HtmlReport sample_page() {
  documents::HtmlReport r;
  r.title = "Report & more";
  r.intro = {"Hello `world`."};
  documents::GalleryEntry e;
  e.key = "gold";
  e.name = "Gold";
  e.material_class = "metal";
  e.source = "main/Au/nk/Johnson";
  e.strip = {{255, 200, 100}, {255, 230, 180}, {255, 255, 255}};
  e.f0 = {255, 200, 100};
  e.f82 = {255, 230, 180};
  e.flags = {"extrapolated"};
  e.facts = {{"RMS", "schlick 0.8"}};
  e.flip = {"figures/flip-gold.png", 97, {"truth", "schlick \"s\""}};
  r.gallery = {e};
  // The page shows its caller's tables (a span): these live as long as the test program.
  static const std::vector<Table> tables = [] {
    Table t;
    t.name = "schlick";
    t.title = "Schlick";
    t.columns = {{"material"}, {"rms", 3}};
    t.rows = {{std::string("Gold"), 0.8}};
    return std::vector<Table>{t};
  }();
  r.tables = tables;
  r.links = {{"README.md", "README.md"}};
  return r;
}

TEST(Html, PageIsSelfContainedAndParses) {
  const auto page = documents::html_report(sample_page());
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("<style>"), std::string::npos);
  EXPECT_NE(page.find("<script>"), std::string::npos);
  for (const char* external : {"http://", "https://", "src=\"//", "href=\"//", "@import"})
    EXPECT_EQ(page.find(external), std::string::npos) << external;
  EXPECT_NE(page.find("linear-gradient(90deg,#ffc864 0.0%,#ffe6b4 50.0%,#ffffff 100.0%)"),
            std::string::npos);
  EXPECT_NE(page.find("id=\"m-gold\""), std::string::npos);
  EXPECT_NE(page.find("id=\"gallery-filter\""), std::string::npos);
  EXPECT_EQ(documents::html_report(sample_page()), page);
  // libxml2's HTML parser (xmllint, libxml2-utils) finds no unclosed or mismatched element; it
  // knows HTML 4 only, so HTML5's sectioning elements are the one complaint allowed.
  test::TempDir tmp;
  const auto path = tmp.file("index.html", page);
  const auto r = run_command("xmllint --html --noout '" + path + "'");
  static const std::regex kHtml5Tag(
      R"(Tag (header|nav|main|section|article|details|summary) invalid)");
  std::istringstream lines(r.err);
  int errors = 0;
  for (std::string line; std::getline(lines, line);)
    if (line.find("parser error") != std::string::npos && !std::regex_search(line, kHtml5Tag)) {
      ++errors;
      ADD_FAILURE() << line;
    }
  EXPECT_EQ(errors, 0);
  EXPECT_NE(r.err.find("Tag details invalid"), std::string::npos)
      << "xmllint did not parse the page: " << r.err;
}

const std::string kHdri = std::string(FL_SHARED_TESTDATA) + "/hdri";

TEST(RenderCli, CompareUnderAnHdrEnvironment) {
  test::TempDir tmp;
  const std::string out = tmp.path() + "/g.exr";
  const auto r = run_command(cli() + " render gold --env '" + kHdri +
                             "/studio.exr' --compare schlick,f82 --size 41 "
                             "--samples 8 --out '" +
                             out + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("lin_rec709 (OpenEXR's default"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ΔE2000 truth vs f82"), std::string::npos);
  for (const char* f : {"g.truth.png", "g.schlick.png", "g.schlick.de2000.png", "g.f82.png",
                        "g.f82.de2000.png", "g.flip.webp", "g.sheet.png"})
    EXPECT_TRUE(std::filesystem::exists(tmp.path() + "/" + f)) << f;
  const auto exr = io::read_exr(out);
  for (const char* ch :
       {"R", "G", "B", "A", "schlick.R", "schlick.B", "schlick.de2000", "f82.G", "f82.de2000"})
    EXPECT_NE(std::find(exr.channels.begin(), exr.channels.end(), ch), exr.channels.end()) << ch;
  ASSERT_TRUE(exr.chromaticities.has_value());
  EXPECT_NEAR((*exr.chromaticities)[0], 0.713, 1e-4);  // ACEScg's red primary
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/g.flip.gif"));
  // Per model the truth, the model and its difference frame; the truth frame's render is the truth
  // PNG's codes exactly (lossless), above the label band.
  std::ifstream in(tmp.path() + "/g.flip.webp", std::ios::binary);
  const auto flip =
      io::decode_webp(std::string(std::istreambuf_iterator<char>(in), {}), "g.flip.webp");
  ASSERT_EQ(flip.frames.size(), 6u);
  EXPECT_EQ(flip.delays_ms, std::vector<int>(6, 900));
  EXPECT_EQ(flip.loop_count, 0);
  const Image8 truth = draw::read_png(tmp.path() + "/g.truth.png"),
               schlick = draw::read_png(tmp.path() + "/g.schlick.png");
  const auto top = [](const Image8& frame, int size) {
    return Image8(
        size, size,
        std::vector<std::uint8_t>(frame.pixels.begin(), frame.pixels.begin() + 3 * size * size));
  };
  EXPECT_EQ(flip.frames[0].width, 41);
  EXPECT_GT(flip.frames[0].height, 41);
  EXPECT_EQ(top(flip.frames[0], 41).pixels, truth.pixels);
  EXPECT_EQ(top(flip.frames[1], 41).pixels, schlick.pixels);
  EXPECT_EQ(flip.frames[3].pixels, flip.frames[0].pixels);
  EXPECT_NE(flip.frames[2].pixels, flip.frames[0].pixels);
  EXPECT_NE(flip.frames[5].pixels, flip.frames[2].pixels);  // f82's difference, not schlick's
}

// Without --size a comparison renders at kCompareSizePx: 512-px flip frames and PNGs; --size wins.
TEST(RenderCli, CompareDefaultsTo512PxFrames) {
  test::TempDir tmp;
  const auto r = run_command(cli() + " render gold --compare schlick --samples 1 --out '" +
                             tmp.path() + "/g.exr'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("render: 512 × 512 px"), std::string::npos) << r.err;
  EXPECT_EQ(draw::read_png(tmp.path() + "/g.truth.png").width, 512);
  std::ifstream in(tmp.path() + "/g.flip.webp", std::ios::binary);
  const auto flip =
      io::decode_webp(std::string(std::istreambuf_iterator<char>(in), {}), "g.flip.webp");
  ASSERT_EQ(flip.frames.size(), 3u);
  for (const auto& f : flip.frames) EXPECT_EQ(f.width, 512);
  const auto single =
      run_command(cli() + " render gold --samples 1 --out '" + tmp.path() + "/s.exr'");
  EXPECT_NE(single.err.find("render: 255 × 255 px"), std::string::npos) << single.err;
}

// --flip gif writes the dithered GIF instead (same frames); another format is exit 2 with one line.
TEST(RenderCli, FlipFormats) {
  test::TempDir tmp;
  const auto run = [&](const std::string& flip) {
    return run_command(cli() + " render gold --compare schlick --size 21 --samples 2 --flip " +
                       flip + " --out '" + tmp.path() + "/g.exr'");
  };
  const auto gif = run("gif");
  ASSERT_EQ(gif.status, 0) << gif.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/g.flip.webp"));
  std::ifstream in(tmp.path() + "/g.flip.gif", std::ios::binary);
  const auto decoded =
      io::decode_gif(std::string(std::istreambuf_iterator<char>(in), {}), "g.flip.gif");
  EXPECT_EQ(decoded.frames.size(), 3u);
  EXPECT_EQ(decoded.delays_cs, std::vector<int>(3, 90));
  const auto bad = run("png");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err,
            "fresnel-lab: error: --flip: unknown flip format 'png' (expected webp or gif)\n");
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/g.flip.png"));
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The view and exposure change the pictures only: the EXR (scene-linear, with its ΔE2000 layers)
// is the same bytes under any view, and the stderr ΔE2000 figures are the same.
TEST(RenderCli, ViewChangesPicturesNotTheExr) {
  test::TempDir tmp;
  const auto render = [&](const std::string& name, const std::string& view) {
    const auto r = run_command(cli() + " render gold --env '" + kHdri +
                               "/sunset.exr' --compare schlick --size 31 --samples 4 " + view +
                               " --out '" + tmp.path() + "/" + name + ".exr'");
    EXPECT_EQ(r.status, 0) << r.err;
    return r.err;
  };
  const auto aces = render("a", "");
  const auto clipped = render("c", "--view Un-tone-mapped --exposure 1");
  EXPECT_NE(aces.find("view ACES 1.0 - SDR Video (OpenColorIO built-in)"), std::string::npos);
  EXPECT_NE(clipped.find("view Un-tone-mapped (OpenColorIO built-in), exposure +1 EV"),
            std::string::npos);
  EXPECT_EQ(file_bytes(tmp.path() + "/a.exr"), file_bytes(tmp.path() + "/c.exr"));
  EXPECT_NE(file_bytes(tmp.path() + "/a.truth.png"), file_bytes(tmp.path() + "/c.truth.png"));
  const auto de = [](const std::string& err) {
    const auto from = err.find("ΔE2000 truth vs");
    return err.substr(from, err.find("render: wrote") - from);
  };
  EXPECT_EQ(de(aces), de(clipped));
  const auto bad = run_command(cli() +
                               " render gold --compare schlick --size 31 --samples 4 "
                               "--view Filmic --out '" +
                               tmp.path() + "/b.exr'");
  EXPECT_EQ(bad.status, 2) << bad.err;
}

// An EXR written by the tool's own encoder, for the bad-input cases.
std::string exr_file(const test::TempDir& tmp, const std::string& name, int w, int h,
                     std::vector<std::string> channels, float value) {
  io::ExrImage img;
  img.width = w;
  img.height = h;
  img.channels = std::move(channels);
  img.pixels.assign(static_cast<size_t>(w) * h * img.channels.size(), 1.0f);
  img.pixels[1] = value;
  const std::string path = tmp.path() + "/" + name;
  io::write_exr_atomic(path, img);
  return path;
}

TEST(RenderCli, BadEnvironmentsExitTwoWithOneLine) {
  test::TempDir tmp;
  const std::string out = " --size 9 --samples 2 --out '" + tmp.path() + "/o.exr'";
  const std::vector<std::pair<std::string, std::string>> cases{
      {tmp.path() + "/missing.exr", "no such file"},
      {tmp.file("junk.exr", "not an exr"), "cannot read EXR"},
      {exr_file(tmp, "square.exr", 8, 8, {"B", "G", "R"}, 1.0f), "not a latitude-longitude map"},
      {exr_file(tmp, "no_green.exr", 8, 4, {"B", "R"}, 1.0f), "no G channel"},
      {exr_file(tmp, "nan.exr", 8, 4, {"B", "G", "R"}, std::nanf("")), "non-finite"},
  };
  for (const auto& [file, problem] : cases) {
    const auto r = run_command(cli() + " render gold --env '" + file + "'" + out);
    EXPECT_EQ(r.status, 2) << file << ": " << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const auto good = exr_file(tmp, "good.exr", 8, 4, {"B", "G", "R"}, 1.0f);
  EXPECT_EQ(
      run_command(cli() + " render gold --env '" + good + "' --env-space nowhere" + out).status, 2);
  EXPECT_EQ(run_command(cli() + " render gold --compare schlick,bogus" + out).status, 2);
  EXPECT_EQ(run_command(cli() + " render gold --model f82 --compare schlick" + out).status, 2);
  EXPECT_FALSE(std::filesystem::exists(tmp.path() + "/o.exr"));
  EXPECT_EQ(run_command(cli() + " -q render gold --env '" + good + "'" + out).status, 0);
}

}  // namespace
}  // namespace fl
