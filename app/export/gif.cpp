#include "app/export/gif.h"

#include "base/error.h"

#include <gif_lib.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

namespace vplab {

namespace {

std::string gifError(int code) {
  const char* text = GifErrorString(code);
  return text ? text : "GIF error " + std::to_string(code);
}

}  // namespace

struct GifWriter::File {
  GifFileType* gif = nullptr;
};

GifWriter::GifWriter(const std::filesystem::path& file, int width, int height)
    : file_(std::make_unique<File>()), target_(file), temporary_(file.string() + ".part"), width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 65535 || height > 65535)
    throw Error(file.string() + ": a GIF is 1 to 65535 pixels a side, not " + std::to_string(width) + " × " + std::to_string(height));
  // Opened here, not by EGifOpenFileName, which makes the file readable by its owner only (0600):
  // a picture for a course page is read by others (0666 less the umask, as any file vplab writes).
  const int fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw Error(file.string() + ": cannot write the GIF: " + std::strerror(errno));
  int error = 0;
  file_->gif = EGifOpenFileHandle(fd, &error);  // owns fd from here, closed by EGifCloseFile
  if (!file_->gif) {
    ::close(fd);
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    throw Error(file.string() + ": cannot write the GIF: " + gifError(error));
  }
  EGifSetGifVersion(file_->gif, true);  // GIF89a: delays and the loop
  if (EGifPutScreenDesc(file_->gif, width, height, 8, 0, nullptr) == GIF_ERROR)
    throw Error(file.string() + ": cannot write the GIF: " + gifError(file_->gif->Error));
  // The Netscape extension: loop for ever.
  const GifByteType netscape[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
  const GifByteType loop[] = {1, 0, 0};
  if (EGifPutExtensionLeader(file_->gif, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(file_->gif, sizeof netscape, netscape) == GIF_ERROR ||
      EGifPutExtensionBlock(file_->gif, sizeof loop, loop) == GIF_ERROR || EGifPutExtensionTrailer(file_->gif) == GIF_ERROR)
    throw Error(file.string() + ": cannot write the GIF: " + gifError(file_->gif->Error));
}

GifWriter::~GifWriter() {
  if (!file_->gif) return;
  int error = 0;
  EGifCloseFile(file_->gif, &error);  // not finished: the partial file goes
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void GifWriter::add(const Image& frame, int centiseconds) {
  if (!file_->gif) throw Error(target_.string() + ": the GIF is already finished");
  if (frame.width != width_ || frame.height != height_)
    throw Error(target_.string() + ": a frame of " + std::to_string(frame.width) + " × " + std::to_string(frame.height) +
                " in a GIF of " + std::to_string(width_) + " × " + std::to_string(height_));
  const size_t n = size_t(width_) * size_t(height_);
  std::vector<GifByteType> r(n), g(n), b(n), indices(n);
  for (size_t i = 0; i < n; ++i) {
    r[i] = frame.pixels[i].r;
    g[i] = frame.pixels[i].g;
    b[i] = frame.pixels[i].b;
  }
  int colors = 256;
  std::vector<GifColorType> palette(256);
  if (GifQuantizeBuffer(unsigned(width_), unsigned(height_), &colors, r.data(), g.data(), b.data(), indices.data(),
                        palette.data()) == GIF_ERROR)
    throw Error(target_.string() + ": cannot reduce a frame to 256 colours");
  ColorMapObject* map = GifMakeMapObject(256, palette.data());
  if (!map) throw Error(target_.string() + ": out of memory for a GIF palette");
  GraphicsControlBlock control{};
  control.DisposalMode = DISPOSE_DO_NOT;
  control.DelayTime = std::max(2, centiseconds);
  control.TransparentColor = NO_TRANSPARENT_COLOR;
  GifByteType extension[4];
  const size_t length = EGifGCBToExtension(&control, extension);
  bool ok = EGifPutExtension(file_->gif, GRAPHICS_EXT_FUNC_CODE, int(length), extension) != GIF_ERROR &&
            EGifPutImageDesc(file_->gif, 0, 0, width_, height_, false, map) != GIF_ERROR;
  for (int y = 0; ok && y < height_; ++y) ok = EGifPutLine(file_->gif, indices.data() + size_t(y) * size_t(width_), width_) != GIF_ERROR;
  GifFreeMapObject(map);
  if (!ok) throw Error(target_.string() + ": cannot write a GIF frame: " + gifError(file_->gif->Error));
  ++frames_;
}

void GifWriter::finish() {
  if (!file_->gif) return;
  int error = 0;
  GifFileType* gif = std::exchange(file_->gif, nullptr);
  if (EGifCloseFile(gif, &error) == GIF_ERROR) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    throw Error(target_.string() + ": cannot finish the GIF: " + gifError(error));
  }
  std::error_code ec;
  std::filesystem::rename(temporary_, target_, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    throw Error(target_.string() + ": cannot put the GIF in place: " + ec.message());
  }
}

GifFrames readGif(const std::filesystem::path& file) {
  int error = 0;
  GifFileType* gif = DGifOpenFileName(file.c_str(), &error);
  if (!gif) throw Error(file.string() + ": cannot read the GIF: " + gifError(error));
  if (DGifSlurp(gif) == GIF_ERROR) {
    const std::string why = gifError(gif->Error);
    DGifCloseFile(gif, &error);
    throw Error(file.string() + ": cannot read the GIF: " + why);
  }
  GifFrames out;
  for (int i = 0; i < gif->ImageCount; ++i) {
    const SavedImage& s = gif->SavedImages[i];
    const ColorMapObject* map = s.ImageDesc.ColorMap ? s.ImageDesc.ColorMap : gif->SColorMap;
    Image image(gif->SWidth, gif->SHeight);
    for (int y = 0; y < s.ImageDesc.Height; ++y)
      for (int x = 0; x < s.ImageDesc.Width; ++x) {
        const GifColorType c = map->Colors[s.RasterBits[size_t(y) * size_t(s.ImageDesc.Width) + size_t(x)]];
        image.at(s.ImageDesc.Left + x, s.ImageDesc.Top + y) = {c.Red, c.Green, c.Blue, 255};
      }
    GraphicsControlBlock control{};
    DGifSavedExtensionToGCB(gif, i, &control);
    out.frames.push_back(std::move(image));
    out.centiseconds.push_back(control.DelayTime);
  }
  DGifCloseFile(gif, &error);
  return out;
}

}  // namespace vplab
