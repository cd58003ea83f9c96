// Rasterising an SVG document with rsvg-convert (Debian librsvg2-bin, scripts/setup.sh) for the SVG
// backend's tests.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/views/image.h"
#include "base/error.h"

namespace vplab::test {

/// The document as rsvg-convert draws it (at its own size), RGBA8. Throws vplab::Error when the
/// tool fails.
inline Image rasteriseSvg(const std::string& svg, const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("vplab-svg-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path in = dir / (name + ".svg"), out = dir / (name + ".png");
  std::ofstream(in, std::ios::binary) << svg;
  const std::string command =
      "rsvg-convert --format=png --output='" + out.string() + "' '" + in.string() + "'";
  if (std::system(command.c_str()) != 0) throw Error("rsvg-convert failed on " + in.string());
  Image image = readPng(out);
  std::filesystem::remove(in);
  std::filesystem::remove(out);
  return image;
}

}  // namespace vplab::test
