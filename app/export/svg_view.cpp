// The views' pictures as SVG documents (svg.h): buildPicture's picture of a view, drawn by the SVG
// backend (svg.cpp), the estimate of its size that greys the viewer's menu entry out, the file.
#include <fstream>

#include "app/export/svg.h"
#include "app/fonts/font_atlas.h"
#include "app/views/render_request.h"
#include "base/error.h"

namespace vplab {

std::optional<std::string> svgExportError(ViewKind view, const Scene& scene, const DisplaySettings& settings) {
  // An estimate from the scene's faces (svgOfPicture counts the picture's): each filled panel draws
  // every face once, the world view's faded outside part once more.
  size_t sceneFaces = 0;
  for (const SceneObject& o : scene.objects)
    if (o.visible && o.mesh) sceneFaces += o.mesh->faceCount();
  size_t faces = 0;
  auto panel = [&](Style style, size_t passes) {
    if (isFilled(style)) faces += passes * sceneFaces;
  };
  const size_t worldPasses = settings.overlays.fadeOutside ? 2 : 1;
  if (view == ViewKind::camera || view == ViewKind::all) panel(settings.camera.style, 1);
  if (view == ViewKind::world || view == ViewKind::all) panel(settings.world.style, worldPasses);
  if (view == ViewKind::npc || view == ViewKind::all) panel(settings.npc.style, 1);
  if (view == ViewKind::morph) panel(settings.morph.style, 1);
  if (faces <= kMaxSvgFaces) return std::nullopt;
  return "SVG export: the " + std::string(toString(view)) + " view draws about " + std::to_string(faces) +
         " filled faces, more than the " + std::to_string(kMaxSvgFaces) +
         " an SVG document can hold and still open; export a PNG instead";
}

std::string svgOfView(ViewKind view, const Scene& scene, const PipelineRun& run,
                      const DisplaySettings& settings, const Highlights& highlights, int width, int height,
                      float scale) {
  if (width < 1 || height < 1)
    throw Error("SVG export: the size " + std::to_string(width) + " x " + std::to_string(height) +
                " is not at least 1 x 1 pixels");
  const FontAtlas fonts(scale);
  const draw::Picture picture = buildPicture(view, ViewInput{scene, run, settings, highlights, width, height, fonts});
  return svgOfPicture(
      picture, fonts,
      "vplab " + std::string(toString(view)) + " view" + (scene.title.empty() ? "" : ": " + scene.title));
}

std::string svgOfRequest(const Scene& scene, const RenderRequest& request) {
  const PixelSize size = pixelSizeOf(request, scene);
  const PipelineRun run = runPipeline(scene, pipelineOptionsOf(request));
  return svgOfView(request.view, scene, run, displaySettingsOf(request, scene), request.highlights, size.width,
                   size.height, request.scale);
}

void writeSvg(const std::string& svg, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw Error(file.string() + ": cannot open the SVG file for writing");
  out.write(svg.data(), std::streamsize(svg.size()));
  out.close();
  if (!out) throw Error(file.string() + ": cannot write the SVG file");
}

}  // namespace vplab
