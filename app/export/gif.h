// Animated GIF through giflib (Debian's libgif): a lesson's moves and the stage morph as animations
// for slides and web pages (app/commands/lesson_export.h). Each frame gets its own palette of at most
// 256 colours (giflib's median-cut quantizer, GifQuantizeBuffer), so the flat colours of the views
// stay exact and only shading bands.
#pragma once

#include "app/views/image.h"

#include <filesystem>
#include <memory>
#include <vector>

namespace vplab {

/// Writes frames as they come, so that a long animation is never held in memory whole. The file is
/// written beside the target and renamed over it by finish(): an animation that fails or is given
/// up never leaves half a file.
class GifWriter {
 public:
  /// Opens `file` for frames of width × height, played in a loop. Throws vplab::Error.
  GifWriter(const std::filesystem::path& file, int width, int height);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  /// Adds a frame shown for `centiseconds` (GIF's unit; at least 2: browsers show shorter delays as
  /// 10). The frame must be width × height. Throws vplab::Error.
  void add(const Image& frame, int centiseconds);
  /// Ends the file and puts it in place. Throws vplab::Error.
  void finish();
  int frames() const { return frames_; }

 private:
  struct File;
  std::unique_ptr<File> file_;
  std::filesystem::path target_, temporary_;
  int width_, height_, frames_ = 0;
};

/// The frames of a GIF file, each as RGBA, and their delays in centiseconds (the tests' reader).
struct GifFrames {
  std::vector<Image> frames;
  std::vector<int> centiseconds;
};
/// Reads every frame of a GIF written by GifWriter. Throws vplab::Error naming the file.
GifFrames readGif(const std::filesystem::path& file);

}  // namespace vplab
