// RGBA8 images as the views produce them: row 0 is the top row (DC's y points down; GL's read-back
// rows are flipped on the way in). PNG through stb_image_write / stb_image.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vplab {

struct Rgba {
  uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba&) const = default;
};

struct Image {
  int width = 0, height = 0;
  std::vector<Rgba> pixels;  // row-major, top row first

  Image() = default;
  Image(int w, int h, Rgba fill = {}) : width(w), height(h), pixels(size_t(w) * size_t(h), fill) {}
  Rgba& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const Rgba& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  Rgba* row(int y) { return &pixels[size_t(y) * size_t(width)]; }
  const Rgba* row(int y) const { return &pixels[size_t(y) * size_t(width)]; }
  bool empty() const { return pixels.empty(); }
};

/// Writes a PNG (deterministic: the same image gives the same bytes). Throws vplab::Error.
void writePng(const Image& image, const std::filesystem::path& file);
/// The PNG as bytes in memory.
std::vector<uint8_t> encodePng(const Image& image);
/// Reads a PNG as RGBA8. Throws vplab::Error naming the file.
Image readPng(const std::filesystem::path& file);

/// Copies `src` into `dst` with its top-left corner at (x, y), clipped to `dst`.
void blit(const Image& src, Image& dst, int x, int y);

}  // namespace vplab
