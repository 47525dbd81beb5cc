// The device's inputs from files: the tables' EXR files as textures, GLSL and HLSL as SPIR-V.
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "io/exr.h"
#include "test_util.h"
#include "vulkan/vk_compute.h"

namespace fl::test::vk {

const char* storage_name(Storage s) {
  return s == Storage::Half ? "half" : "float";
}

Texture read_texture(const std::string& exr_path) {
  const auto img = io::read_exr(exr_path);
  Texture t{img.width, img.height, std::vector<float>(size_t(img.width) * img.height * 4, 1.0f)};
  const size_t nc = img.channels.size();
  for (size_t c = 0; c < nc; ++c) {
    const std::string& name = img.channels[c];
    const int k = name == "R" ? 0 : name == "G" ? 1 : name == "B" ? 2 : name == "A" ? 3 : -1;
    if (k < 0) throw std::runtime_error(exr_path + ": unexpected channel " + name);
    for (size_t p = 0; p < size_t(img.width) * img.height; ++p)
      t.rgba[4 * p + k] = img.pixels[p * nc + c];
  }
  return t;
}

std::vector<std::uint32_t> compile_compute(const std::string& source, bool hlsl,
                                           const std::string& name) {
  TempDir dir;
  const std::string src = dir.file(name + (hlsl ? ".hlsl" : ".comp"), source),
                    spv = dir.path() + "/" + name + ".spv";
  const auto r =
      run_command(std::string("'") + FL_GLSLANG + "' -V --target-env vulkan1.1 " +
                  (hlsl ? "-D -e main " : "") + "-S comp -o '" + spv + "' '" + src + "'");
  if (r.status != 0)
    throw std::runtime_error("glslangValidator failed on " + name + ":\n" + r.out + r.err);
  std::ifstream in(spv, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), words.size() * 4);
  return words;
}

}  // namespace fl::test::vk
