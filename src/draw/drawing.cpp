#include "draw/drawing.h"

#include <cairo-ft.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/format.h>
#include <fontconfig/fontconfig.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <numbers>
#include <regex>
#include <stdexcept>

#include "draw/cairo_pixels.h"
#include "draw/png.h"
#include "io/writer.h"
#include "util/errors.h"

namespace fl::draw {

// Owns one reference to the Cairo face.
struct LabelFont::Face {
  cairo_font_face_t* cairo;
  explicit Face(cairo_font_face_t* face) : cairo(face) {}
  ~Face() { cairo_font_face_destroy(cairo); }
  Face(const Face&) = delete;
  Face& operator=(const Face&) = delete;
};

namespace {

constexpr const char* kLabelFamily = "DejaVu Sans";

// The file fontconfig gives for DejaVu Sans; InputError when it gives another family (a fallback
// font would change every figure).
std::string dejavu_file() {
  const auto fail = [] {
    return InputError(kLabelFamily, 0,
                      "label font not found (install fonts-dejavu-core or set FRESNEL_LAB_FONT)");
  };
  std::unique_ptr<FcPattern, void (*)(FcPattern*)> want(
      FcNameParse(reinterpret_cast<const FcChar8*>(kLabelFamily)), FcPatternDestroy);
  if (!want || !FcConfigSubstitute(nullptr, want.get(), FcMatchPattern)) throw fail();
  FcDefaultSubstitute(want.get());
  FcResult result = FcResultNoMatch;
  std::unique_ptr<FcPattern, void (*)(FcPattern*)> got(FcFontMatch(nullptr, want.get(), &result),
                                                       FcPatternDestroy);
  FcChar8 *family = nullptr, *file = nullptr;
  if (!got || FcPatternGetString(got.get(), FC_FAMILY, 0, &family) != FcResultMatch ||
      FcPatternGetString(got.get(), FC_FILE, 0, &file) != FcResultMatch ||
      std::string(reinterpret_cast<const char*>(family)) != kLabelFamily)
    throw fail();
  return reinterpret_cast<const char*>(file);
}

// A Cairo FreeType face for one font file. The pattern holds only the file, so no fontconfig
// rendering preferences of this machine apply: set_font_options decides.
cairo_font_face_t* load_face(const std::string& path) {
  const auto fail = [&] {
    return InputError(path, 0, "cannot load the label font (a TrueType or OpenType file)");
  };
  if (!std::filesystem::is_regular_file(path)) throw fail();
  FcPattern* pattern = FcPatternCreate();
  FcPatternAddString(pattern, FC_FILE, reinterpret_cast<const FcChar8*>(path.c_str()));
  FcPatternAddInteger(pattern, FC_INDEX, 0);
  cairo_font_face_t* face = cairo_ft_font_face_create_for_pattern(pattern);
  FcPatternDestroy(pattern);
  cairo_matrix_t size, identity;
  cairo_matrix_init_scale(&size, 12, 12);
  cairo_matrix_init_identity(&identity);
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_scaled_font_t* probe = cairo_scaled_font_create(face, &size, &identity, options);
  const bool ok = cairo_scaled_font_status(probe) == CAIRO_STATUS_SUCCESS;
  cairo_scaled_font_destroy(probe);
  cairo_font_options_destroy(options);
  if (!ok) {
    cairo_font_face_destroy(face);
    throw fail();
  }
  return face;
}

void set_colour(cairo_t* cr, io::Rgb8 c) {
  cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
}

void paint(cairo_t* cr, const Rect& r, const LabelFont*) {
  set_colour(cr, r.fill);
  cairo_rectangle(cr, r.x, r.y, r.w, r.h);
  cairo_fill(cr);
}

void paint(cairo_t* cr, const Polyline& l, const LabelFont*) {
  if (l.points.empty()) return;
  set_colour(cr, l.colour);
  cairo_set_line_width(cr, l.width_px);
  cairo_set_dash(cr, l.dash.data(), static_cast<int>(l.dash.size()), 0.0);
  cairo_move_to(cr, l.points[0].x, l.points[0].y);
  for (size_t i = 1; i < l.points.size(); ++i) cairo_line_to(cr, l.points[i].x, l.points[i].y);
  cairo_stroke(cr);
}

void paint(cairo_t* cr, const Circle& c, const LabelFont*) {
  cairo_new_path(cr);  // an arc would otherwise start with a line from the current point
  set_colour(cr, c.colour);
  if (c.ring_px > 0) {
    cairo_set_line_width(cr, c.ring_px);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    cairo_arc(cr, c.cx, c.cy, c.radius_px - 0.5 * c.ring_px, 0, 2 * std::numbers::pi);
    cairo_stroke(cr);
  } else {
    cairo_arc(cr, c.cx, c.cy, c.radius_px, 0, 2 * std::numbers::pi);
    cairo_fill(cr);
  }
}

// Text needs a font; the other shapes ignore it.
void paint(cairo_t* cr, const Text& t, const LabelFont* font) {
  if (!font) throw std::logic_error("a drawing's text needs a font");
  cairo_set_font_face(cr, font->face().cairo);
  set_colour(cr, t.colour);
  cairo_set_font_size(cr, t.size_px);
  cairo_text_extents_t te;
  cairo_text_extents(cr, t.utf8.c_str(), &te);
  cairo_save(cr);
  cairo_translate(cr, t.x, t.y);
  double x = 0, y = 0;
  if (t.vertical) {
    cairo_rotate(cr, -0.5 * std::numbers::pi);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    x = -0.5 * te.x_advance;
    y = 0.5 * (fe.ascent - fe.descent);
  } else if (t.align != Align::Left) {
    x = t.align == Align::Center ? -0.5 * te.x_advance : -te.x_advance;
  }
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, t.utf8.c_str());
  cairo_new_path(cr);
  cairo_restore(cr);
}

void paint(cairo_t* cr, const Picture& p, const LabelFont*) {
  const io::Image8& img = p.image;
  if (img.width <= 0 || img.height <= 0) return;
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, img.width, img.height);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < img.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<size_t>(y) * stride);
    for (int x = 0; x < img.width; ++x) {
      const io::Rgb8 c = img.at(x, y);
      row[x] = (std::uint32_t{c.r} << 16) | (std::uint32_t{c.g} << 8) | c.b;
    }
  }
  cairo_surface_mark_dirty(s);
  cairo_set_source_surface(cr, s, p.x, p.y);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
  cairo_rectangle(cr, p.x, p.y, img.width, img.height);
  cairo_fill(cr);
  cairo_surface_destroy(s);
}

// Greyscale antialiasing with full hinting on pixel output (crisp small labels); vector output
// keeps Cairo's unhinted outlines.
void set_font_options(cairo_t* cr, FileType type) {
  cairo_font_options_t* o = cairo_font_options_create();
  cairo_font_options_set_antialias(o, CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_subpixel_order(o, CAIRO_SUBPIXEL_ORDER_DEFAULT);
  const bool pixels = type == FileType::Png;
  cairo_font_options_set_hint_style(o, pixels ? CAIRO_HINT_STYLE_FULL : CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(o, pixels ? CAIRO_HINT_METRICS_ON : CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, o);
  cairo_font_options_destroy(o);
}

void check(cairo_status_t status) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(status));
}

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

void paint_drawing(cairo_surface_t* surface, const Drawing& d, FileType type,
                   const LabelFont* font) {
  const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> owner(cairo_create(surface),
                                                                 cairo_destroy);
  cairo_t* cr = owner.get();
  set_font_options(cr, type);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  set_colour(cr, d.background);
  cairo_paint(cr);
  for (const auto& shape : d.shapes)
    std::visit([cr, font](const auto& s) { paint(cr, s, font); }, shape);
  check(cairo_status(cr));
}

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// Cairo names SVG surfaces and images after process-wide surface counters; numbering them in order
// of first appearance instead makes the file depend on the drawing alone.
std::string renumber_svg_ids(const std::string& svg) {
  static const std::regex kId(R"((id="|href="#)(surface|image)(\d+))");
  std::map<std::string, int> numbers;
  std::string out;
  auto last = svg.cbegin();
  for (std::sregex_iterator it(svg.begin(), svg.end(), kId), end; it != end; ++it) {
    const auto& m = *it;
    const auto [entry, added] =
        numbers.try_emplace(m[2].str() + m[3].str(), static_cast<int>(numbers.size()) + 1);
    out.append(last, m[0].first);
    out += m[1].str() + m[2].str() + std::to_string(entry->second);
    last = m[0].second;
  }
  out.append(last, svg.cend());
  return out;
}

// The drawing's pixels, painted on Cairo's RGB24 image surface.
io::Image8 raster(const Drawing& d, const LabelFont* font) {
  if (d.width <= 0 || d.height <= 0)
    throw std::logic_error("rasterize: a drawing needs a positive size");
  const SurfacePtr s(cairo_image_surface_create(CAIRO_FORMAT_RGB24, d.width, d.height),
                     cairo_surface_destroy);
  paint_drawing(s.get(), d, FileType::Png, font);
  cairo_surface_flush(s.get());
  check(cairo_surface_status(s.get()));
  return surface_pixels(s.get());
}

cairo_surface_t* vector_surface(FileType type, const Drawing& d, std::string& out) {
  if (type == FileType::Svg) {
    cairo_surface_t* s = cairo_svg_surface_create_for_stream(append_bytes, &out, d.width, d.height);
    cairo_svg_surface_set_document_unit(s, CAIRO_SVG_UNIT_PX);
    return s;
  }
  cairo_surface_t* s = cairo_pdf_surface_create_for_stream(append_bytes, &out, d.width, d.height);
  // An empty creation date leaves the date out, so the same drawing gives the same file.
  cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATE_DATE, "");
  return s;
}

std::string encode_with(const Drawing& d, FileType type, const LabelFont* font) {
  if (d.width <= 0 || d.height <= 0)
    throw std::logic_error("encode: a drawing needs a positive size");
  if (type == FileType::Png) return encode_png(raster(d, font));
  std::string out;
  const SurfacePtr s(vector_surface(type, d, out), cairo_surface_destroy);
  paint_drawing(s.get(), d, type, font);
  cairo_surface_finish(s.get());
  check(cairo_surface_status(s.get()));
  return type == FileType::Svg ? renumber_svg_ids(out) : out;
}

}  // namespace

io::Image8 surface_pixels(cairo_surface_t* s) {
  io::Image8 img(cairo_image_surface_get_width(s), cairo_image_surface_get_height(s));
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < img.height; ++y) {
    const auto* row =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<size_t>(y) * stride);
    for (int x = 0; x < img.width; ++x)
      img.set(x, y,
              {static_cast<std::uint8_t>(row[x] >> 16), static_cast<std::uint8_t>(row[x] >> 8),
               static_cast<std::uint8_t>(row[x])});
  }
  return img;
}

LabelFont::LabelFont(const std::string& file)
    : file_(file.empty() ? dejavu_file() : file),
      face_(std::make_shared<const Face>(load_face(file_))) {}

FileType file_type(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".png") return FileType::Png;
  if (ext == ".svg") return FileType::Svg;
  if (ext == ".pdf") return FileType::Pdf;
  throw InputError(path, 0,
                   fmt::format("unknown output type '{}' (expected .png, .svg or .pdf)",
                               ext.empty() ? "(none)" : ext));
}

std::string encode(const Drawing& d, FileType type, const LabelFont& font) {
  return encode_with(d, type, &font);
}

io::Image8 rasterize(const Drawing& d, const LabelFont& font) {
  return raster(d, &font);
}

double text_width_px(const std::string& utf8, double size_px, const LabelFont& font) {
  const SurfacePtr s(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1), cairo_surface_destroy);
  const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(s.get()), cairo_destroy);
  set_font_options(cr.get(), FileType::Png);
  cairo_set_font_face(cr.get(), font.face().cairo);
  cairo_set_font_size(cr.get(), size_px);
  cairo_text_extents_t te;
  cairo_text_extents(cr.get(), utf8.c_str(), &te);
  check(cairo_status(cr.get()));
  return te.x_advance;
}

double text_size_to_fit(const std::string& utf8, double size_px, double min_px, double width_px,
                        const LabelFont& font) {
  double size = size_px;
  while (size > min_px && text_width_px(utf8, size, font) > width_px)
    size = std::max(min_px, size - 0.5);
  return size;
}

void write_drawing(const std::string& path, const Drawing& d, const LabelFont& font) {
  io::write_file_atomic(path, encode(d, file_type(path), font));
}

}  // namespace fl::draw
