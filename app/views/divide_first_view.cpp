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

// A clipped polygon. The CPU raster fans it from its first vertex and skips
// the fan's triangles that have a non-finite vertex; a polygon with such a vertex is therefore
// given as its finite fan triangles, so that every backend fills what the raster fills.
void addPolygon(std::span<const Vec3> polygon, PolygonSet& out) {
  bool finite = true;
  for (const Vec3& p : polygon) finite = finite && isFinite(p);
  if (polygon.size() < 3) return;
  if (finite) {
    out.add(polygon);
    return;
  }
  for (size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Vec3 triangle[3] = {polygon[0], polygon[i], polygon[i + 1]};
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
  // The polygons are in the run's DC; the view looks at DC through the device mapping undone
  // (npcFromDc = dcFromNpc⁻¹, z_npc = z_dc), so a backend puts DC scaled to its pixels and keeps
  // z_dc as the depth its depth test compares.
  list.observer.space = Space::dc;
  list.observer.camera.camera = run.camera;
  list.observer.camera.vrcFromWc = Mat4(1.0);
  list.observer.camera.npcFromVrc = glm::inverse(run.dcFromNpc);
  list.observer.camera.eyeWc = Vec4(0, 0, 1, 0);  // toward the viewer: z_dc grows toward the front plane
  list.antialiased = false;  // pixel-aligned with DC, as the camera view beside it

  Fill fill;
  fill.space = Space::dc;
  fill.lit = false;
  fill.polygons.resize(run.objects.size());
  std::vector<Vec3> dc;
  // Scene order, then face order: the order the raster fills in, which decides depth ties.
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    PolygonSet& set = fill.polygons[k];
    set.color = glm::vec3(o.color);
    for (size_t f = 0; f < o.faceCount(); ++f) {
      dc.clear();
      for (uint32_t ref : o.clippedFace(f)) dc.push_back(o.clippedDc(ref));
      addPolygon(dc, set);
    }
  }
  list.add(std::move(fill));
  return list;
}

void divideFirstView(const ViewInput& in, DisplayList& out) { out = divideFirstView(in); }

}  // namespace vplab
