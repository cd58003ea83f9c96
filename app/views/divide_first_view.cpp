// The divide-first comparison: what a pipeline that divides by w before clipping draws (the
// Clipping lesson's "wrong" picture beside the camera view). Dividing first flips x/w and y/w of
// every point behind the eye (w < 0), so an edge reaching behind the eye wraps around through
// infinity (Hill 7.4; Blinn & Newell 1978; docs/sources.md). The GPU always clips correctly: the
// wrong picture exists only as the CPU pipeline's clipped polygons, which this view fills flat as
// the CPU raster (app/export/cpu_raster.h, the independent oracle of the tests) does.
#include "app/views/views.h"

#include <stdexcept>
#include <string>

namespace vplab {

namespace {

using namespace draw;

// A clipped polygon in the view's pixels. The CPU raster fans it from its first vertex and skips
// the fan's triangles that have a non-finite vertex; a polygon with such a vertex is therefore
// given as its finite fan triangles, so that every backend fills what the raster fills.
void addPolygon(std::span<const Vec3> pixels, PolygonSet& out) {
  bool finite = true;
  for (const Vec3& p : pixels) finite = finite && isFinite(p);
  if (pixels.size() < 3) return;
  if (finite) {
    out.add(pixels);
    return;
  }
  for (size_t i = 1; i + 1 < pixels.size(); ++i) {
    const Vec3 triangle[3] = {pixels[0], pixels[i], pixels[i + 1]};
    if (isFinite(triangle[0]) && isFinite(triangle[1]) && isFinite(triangle[2])) out.add(triangle);
  }
}

}  // namespace

DisplayList divideFirstView(const ViewInput& in) {
  const PipelineRun& run = in.run;
  if (run.options.strategy != ClipStrategy::divideFirst)
    throw std::invalid_argument("divideFirstView: the run's clipping strategy is " +
                                std::string(toString(run.options.strategy)) + ", not divide-first");
  DisplayList list;
  list.width = in.width;
  list.height = in.height;
  list.background = glm::vec3(in.scene.background);
  list.observer.space = Space::pixels;
  list.antialiased = false;  // pixel-aligned with DC, as the camera view beside it

  // DC of the run's device → the view's pixels (both y down, z_dc kept for the depth test).
  const Vec2 scale(double(in.width) / run.device.width, double(in.height) / run.device.height);
  Fill fill;
  fill.space = Space::pixels;
  fill.lit = false;
  fill.polygons.resize(run.objects.size());
  std::vector<Vec3> pixels;
  // Scene order, then face order: the order the raster fills in, which decides depth ties.
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    PolygonSet& set = fill.polygons[k];
    set.color = glm::vec3(o.color);
    for (size_t f = 0; f < o.faceCount(); ++f) {
      pixels.clear();
      for (uint32_t ref : o.clippedFace(f)) {
        const Vec3 dc = o.clippedDc(ref);
        pixels.push_back({dc.x * scale.x, dc.y * scale.y, dc.z});
      }
      addPolygon(pixels, set);
    }
  }
  list.add(std::move(fill));
  return list;
}

}  // namespace vplab
