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
#include <OpenEXR/openexr.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "io/writer.h"
#include "spectral/text_file.h"
#include "util/errors.h"

namespace fl::io {

namespace {

// The most pixel values (pixels × channels) read from one EXR file: 2^28, 1 GiB as float (an
// 8192 × 4096 RGBA environment holds 2^27). A header can claim any size; nothing is allocated for
// one above this.
constexpr std::uint64_t kMaxExrValues = std::uint64_t{1} << 28;

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

// The file's bytes as OpenEXR's input, read once and bounded. OpenEXR 3.1's C++ header reader
// allocates what an attribute's size field claims before reading it (up to 2 GB from a 1 kB file;
// the core library's stricter parse does not always see the same fields). It reads an attribute's
// name and type a byte at a time, each ending in 0, then the size as 4 bytes: a 4-byte read right
// after a 0 byte that claims more than the file has left is refused here. (The one other such read,
// a channel's pixel type, is 0, 1 or 2.)
class MemoryInput : public Imf::IStream {
 public:
  MemoryInput(const std::string& path, const std::string& bytes)
      : Imf::IStream(path.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    // position_ may lie past the end after a seek; compare without forming position_ + n.
    if (n < 0 || position_ > bytes_.size() || static_cast<size_t>(n) > bytes_.size() - position_)
      throw std::runtime_error("early end of file");
    std::memcpy(c, bytes_.data() + position_, static_cast<size_t>(n));
    position_ += static_cast<size_t>(n);
    if (n == 4 && after_zero_byte_) {
      std::int32_t size = 0;
      std::memcpy(&size, c, 4);  // little-endian, as the file and x86-64
      if (size < 0 || static_cast<size_t>(size) > bytes_.size() - position_)
        throw std::runtime_error("an attribute claims " + std::to_string(size) +
                                 " bytes, more than the file holds");
    }
    after_zero_byte_ = n == 1 && c[0] == 0;
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t position) override {
    position_ = static_cast<size_t>(position);
    after_zero_byte_ = false;
  }

 private:
  const std::string& bytes_;
  size_t position_ = 0;
  bool after_zero_byte_ = false;
};

// The header as OpenEXR's C++ reader reads it (Imf::InputFile reads the same way, then allocates
// its line buffers): the 4-byte magic number and 4-byte version field, then the attributes.
Imf::Header cpp_header(const std::string& path, const std::string& bytes) {
  MemoryInput stream(path, bytes);
  char start[8];
  stream.read(start, 8);
  int version = 0;
  std::memcpy(&version, start + 4, 4);  // little-endian, as the file and x86-64
  Imf::Header header;
  header.readFrom(stream, version);
  return header;
}

// The most values a compressed EXR decodes to per byte of file: 4096, four times deflate's
// limit (a constant image in ZIP compresses about 500:1).
constexpr std::int64_t kMaxExrExpansion = 4096;

// OpenEXR's core library (C) parses a header strictly, every attribute's size against the file
// included; the C++ reader allocates whatever an unknown attribute claims (up to 2 GB from a 1 kB
// file). So the core reads the header first, from the same bytes.
struct CoreInput {
  const std::string& bytes;
  std::string error;
};

int64_t core_read(exr_const_context_t, void* user, void* buffer, uint64_t size, uint64_t offset,
                  exr_stream_error_func_ptr_t) {
  const std::string& bytes = static_cast<CoreInput*>(user)->bytes;
  if (offset >= bytes.size()) return 0;
  const uint64_t n = std::min<uint64_t>(size, bytes.size() - offset);
  std::memcpy(buffer, bytes.data() + offset, n);
  return static_cast<int64_t>(n);
}

int64_t core_size(exr_const_context_t, void* user) {
  return static_cast<int64_t>(static_cast<CoreInput*>(user)->bytes.size());
}

void core_error(exr_const_context_t ctxt, exr_result_t, const char* message) {
  void* user = nullptr;
  if (exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && user)
    if (static_cast<CoreInput*>(user)->error.empty())
      static_cast<CoreInput*>(user)->error = message;
}

// InputError when `width` × `height` pixels of `nc` channels (and `chunks` chunk offsets) cannot
// come from `file_bytes` bytes: uncompressed, 2 bytes per value at least; compressed, at most
// kMaxExrExpansion values per byte.
void require_room(const std::string& path, std::int64_t width, std::int64_t height, std::int64_t nc,
                  bool compressed, std::int64_t chunks, std::int64_t file_bytes) {
  const std::int64_t values = width * height * nc;
  if ((compressed ? values / kMaxExrExpansion : values * 2) > file_bytes || chunks * 8 > file_bytes)
    throw InputError(
        path, 0,
        fmt::format("EXR header claims {} × {} pixels of {} channels{}, more than "
                    "the file's {} bytes can hold",
                    width, height, nc, chunks > 0 ? fmt::format(" in {} chunks", chunks) : "",
                    file_bytes));
}

// What OpenEXR would allocate from the header's word, bounded before the C++ reader reads it: a
// header the core library accepts, one part of flat (scanline or tiled) pixels, a data window of at
// most kMaxExrValues values, no more decoded values than the file can hold (uncompressed: 2 bytes
// each at least; compressed: kMaxExrExpansion per byte), and no more chunks than the file has room
// for their offsets (8 bytes each).
void check_exr_header(const std::string& bytes, const std::string& path) {
  CoreInput input{bytes, {}};
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.user_data = &input;
  init.read_fn = core_read;
  init.size_fn = core_size;
  init.error_handler_fn = core_error;
  exr_context_t ctxt = nullptr;
  if (exr_start_read(&ctxt, path.c_str(), &init) != EXR_ERR_SUCCESS) {
    exr_finish(&ctxt);
    throw InputError(path, 0, "cannot read EXR: " + input.error);
  }
  int parts = 0, chunks = 0;
  exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
  exr_attr_box2i_t window{};
  const exr_attr_chlist_t* channels = nullptr;
  exr_compression_t compression = EXR_COMPRESSION_NONE;
  const bool read = exr_get_count(ctxt, &parts) == EXR_ERR_SUCCESS && parts == 1 &&
                    exr_get_storage(ctxt, 0, &storage) == EXR_ERR_SUCCESS &&
                    exr_get_data_window(ctxt, 0, &window) == EXR_ERR_SUCCESS &&
                    exr_get_channels(ctxt, 0, &channels) == EXR_ERR_SUCCESS &&
                    exr_get_compression(ctxt, 0, &compression) == EXR_ERR_SUCCESS &&
                    exr_get_chunk_count(ctxt, 0, &chunks) == EXR_ERR_SUCCESS;
  const int channel_count = channels ? channels->num_channels : 0;  // freed by exr_finish
  exr_finish(&ctxt);
  if (!read || (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED))
    throw InputError(path, 0, "multi-part or deep EXR: an image must be one part of flat pixels");
  const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1,
                     height = std::int64_t{window.max.y} - window.min.y + 1,
                     nc = std::max(channel_count, 1);
  const auto max_values = static_cast<std::int64_t>(kMaxExrValues);
  const auto room = static_cast<std::int64_t>(bytes.size());
  if (width <= 0 || height <= 0 || width > max_values / height / nc)
    throw InputError(path, 0,
                     fmt::format("data window {} × {} with {} channels is empty or holds more "
                                 "than {} values",
                                 width, height, nc, kMaxExrValues));
  require_room(path, width, height, nc, compression != EXR_COMPRESSION_NONE, chunks, room);
}

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
    // OpenEXR writes a channel from a slice of its own type: half channels from half values.
    std::vector<Imath::half> halves;
    if (image.half) halves.assign(image.pixels.begin(), image.pixels.end());
    const Imf::PixelType type = image.half ? Imf::HALF : Imf::FLOAT;
    Imf::FrameBuffer fb;
    const size_t x_stride = (image.half ? sizeof(Imath::half) : sizeof(float)) * nc;
    const size_t y_stride = x_stride * image.width;
    for (size_t c = 0; c < nc; ++c) {
      header.channels().insert(image.channels[c], Imf::Channel(type));
      // OpenEXR only reads through the slice base pointer when writing.
      char* base = image.half
                       ? reinterpret_cast<char*>(halves.data() + c)
                       : reinterpret_cast<char*>(const_cast<float*>(image.pixels.data() + c));
      fb.insert(image.channels[c], Imf::Slice(type, base, x_stride, y_stride));
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

namespace {

// The header's string and float attributes and its chromaticities, into `image`. Chromaticities
// with a NaN or an infinity say nothing about the pixels' space: an InputError, not a guess.
void copy_attributes(const Imf::Header& header, ExrImage& image, const std::string& path) {
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
    for (const float v : *image.chromaticities)
      if (!std::isfinite(v))
        throw InputError(path, 0,
                         "the chromaticities attribute holds a NaN or an infinity: the file's "
                         "colour space is unknown (write finite chromaticities, or none)");
  }
}

}  // namespace

ExrImage read_exr(const std::string& path) {
  const std::string bytes = spectral::read_input_bytes(path);
  check_exr_header(bytes, path);
  try {
    // The C++ reader's own view of the header, read alone before any pixel buffer exists (it may
    // differ from the core's where the file is malformed, e.g. a garbled attribute name): bound
    // what the reader would allocate and decode.
    const Imf::Header header = cpp_header(path, bytes);
    const auto dw = header.dataWindow();
    ExrImage image;
    const std::int64_t width = std::int64_t{dw.max.x} - dw.min.x + 1,
                       height = std::int64_t{dw.max.y} - dw.min.y + 1;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
      image.channels.push_back(it.name());
    const std::int64_t channel_count = std::max<std::int64_t>(std::ssize(image.channels), 1);
    if (width <= 0 || height <= 0 ||
        width > static_cast<std::int64_t>(kMaxExrValues) / height / channel_count)
      throw InputError(path, 0,
                       fmt::format("data window {} × {} with {} channels is empty or holds more "
                                   "than {} values",
                                   width, height, image.channels.size(), kMaxExrValues));
    require_room(path, width, height, channel_count, header.compression() != Imf::NO_COMPRESSION, 0,
                 std::ssize(bytes));
    MemoryInput stream(path, bytes);
    Imf::InputFile in(stream);
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    copy_attributes(header, image, path);
    const size_t nc = image.channels.size();
    image.pixels.assign(static_cast<size_t>(image.width) * image.height * nc, 0.0f);
    Imf::FrameBuffer fb;
    const size_t x_stride = sizeof(float) * nc;
    const size_t y_stride = x_stride * image.width;
    // The slice's origin is the data window's: Slice::Make offsets the buffer by it in integer
    // arithmetic (a window far from the origin would overflow a pointer computed here).
    for (size_t c = 0; c < nc; ++c)
      fb.insert(image.channels[c],
                Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c, dw, x_stride, y_stride));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, 0, fmt::format("cannot read EXR: {}", e.what()));
  }
}

}  // namespace fl::io
