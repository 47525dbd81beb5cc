#include "io/exr.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticitiesAttribute.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <fmt/format.h>

#include <cstring>

#include "io/writer.h"
#include "spectral/errors.h"

namespace fl::report {

namespace {

// An in-memory output stream; OpenEXR seeks back to fill in the line offset table.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (position_ + n > bytes.size()) bytes.resize(position_ + n);
    std::memcpy(bytes.data() + position_, c, static_cast<size_t>(n));
    position_ += static_cast<size_t>(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t position) override { position_ = static_cast<size_t>(position); }
  std::string bytes;

 private:
  size_t position_ = 0;
};

}  // namespace

std::uint16_t half_bits(float v) {
  return Imath::half(v).bits();
}

std::string encode_exr(const ExrImage& image) {
  const size_t nc = image.channels.size();
  if (image.width <= 0 || image.height <= 0 || nc == 0 ||
      image.pixels.size() != static_cast<size_t>(image.width) * image.height * nc)
    throw std::runtime_error(fmt::format("inconsistent EXR image ({}x{}, {} channels, {} values)",
                                         image.width, image.height, nc, image.pixels.size()));
  MemoryStream stream;
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const auto& [name, value] : image.string_attributes)
      header.insert(name, Imf::StringAttribute(value));
    for (const auto& [name, value] : image.float_attributes)
      header.insert(name, Imf::FloatAttribute(value));
    if (const auto& c = image.chromaticities)
      Imf::addChromaticities(header, Imf::Chromaticities({(*c)[0], (*c)[1]}, {(*c)[2], (*c)[3]},
                                                         {(*c)[4], (*c)[5]}, {(*c)[6], (*c)[7]}));
    Imf::FrameBuffer fb;
    const size_t x_stride = sizeof(float) * nc;
    const size_t y_stride = x_stride * image.width;
    for (size_t c = 0; c < nc; ++c) {
      header.channels().insert(image.channels[c], Imf::Channel(Imf::FLOAT));
      // OpenEXR only reads through the slice base pointer when writing.
      char* base = reinterpret_cast<char*>(const_cast<float*>(image.pixels.data() + c));
      fb.insert(image.channels[c], Imf::Slice(Imf::FLOAT, base, x_stride, y_stride));
    }
    Imf::OutputFile out(stream, header);
    out.setFrameBuffer(fb);
    out.writePixels(image.height);
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("EXR encoding failed: {}", e.what()));
  }
  return std::move(stream.bytes);
}

void write_exr_atomic(const std::string& path, const ExrImage& image) {
  write_file_atomic(path, encode_exr(image));
}

ExrImage read_exr(const std::string& path) {
  try {
    Imf::InputFile in(path.c_str());
    const auto& header = in.header();
    const auto dw = header.dataWindow();
    ExrImage image;
    image.width = dw.max.x - dw.min.x + 1;
    image.height = dw.max.y - dw.min.y + 1;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
      image.channels.push_back(it.name());
    for (auto it = header.begin(); it != header.end(); ++it) {
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        image.string_attributes.emplace_back(it.name(), s->value());
      else if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&it.attribute()))
        image.float_attributes.emplace_back(it.name(), f->value());
    }
    if (Imf::hasChromaticities(header)) {
      const auto& c = Imf::chromaticities(header);
      image.chromaticities = std::array<float, 8>{c.red.x,  c.red.y,  c.green.x, c.green.y,
                                                  c.blue.x, c.blue.y, c.white.x, c.white.y};
    }
    const size_t nc = image.channels.size();
    image.pixels.assign(static_cast<size_t>(image.width) * image.height * nc, 0.0f);
    Imf::FrameBuffer fb;
    const size_t x_stride = sizeof(float) * nc;
    const size_t y_stride = x_stride * image.width;
    for (size_t c = 0; c < nc; ++c) {
      char* base = reinterpret_cast<char*>(image.pixels.data() + c) -
                   static_cast<std::ptrdiff_t>(dw.min.x * x_stride + dw.min.y * y_stride);
      fb.insert(image.channels[c], Imf::Slice(Imf::FLOAT, base, x_stride, y_stride));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return image;
  } catch (const std::exception& e) {
    throw InputError(path, 0, fmt::format("cannot read EXR: {}", e.what()));
  }
}

}  // namespace fl::report
