#include "app/views/image.h"

#include "base/error.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <fstream>

namespace vplab {

namespace {

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<uint8_t> encodePng(const Image& image) {
  std::vector<uint8_t> bytes;
  if (image.empty() ||
      !stbi_write_png_to_func(appendBytes, &bytes, image.width, image.height, 4, image.pixels.data(), image.width * 4))
    throw Error("encoding a " + std::to_string(image.width) + " × " + std::to_string(image.height) + " PNG failed");
  return bytes;
}

void writePng(const Image& image, const std::filesystem::path& file) {
  const std::vector<uint8_t> bytes = encodePng(image);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw Error(file.string() + ": cannot write the PNG file");
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out.flush()) throw Error(file.string() + ": writing the PNG file failed");
}

Image readPng(const std::filesystem::path& file) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(file.string().c_str(), &w, &h, &channels, 4);
  if (!data) throw Error(file.string() + ": cannot read the PNG file (" + stbi_failure_reason() + ")");
  Image image(w, h);
  std::memcpy(image.pixels.data(), data, size_t(w) * size_t(h) * 4);
  stbi_image_free(data);
  return image;
}

void blit(const Image& src, Image& dst, int x0, int y0) {
  for (int y = 0; y < src.height; ++y) {
    const int dy = y0 + y;
    if (dy < 0 || dy >= dst.height) continue;
    for (int x = 0; x < src.width; ++x) {
      const int dx = x0 + x;
      if (dx >= 0 && dx < dst.width) dst.at(dx, dy) = src.at(x, y);
    }
  }
}

}  // namespace vplab
