#include "app/inspect/picking.h"

namespace vplab {

namespace {

const ObjectRun* objectOf(const PipelineRun& run, size_t sceneIndex) {
  for (size_t i = 0; i < run.sceneIndex.size(); ++i)
    if (run.sceneIndex[i] == sceneIndex) return &run.objects[i];
  return nullptr;
}

// WC size of one pixel at the depth of p, for an observer of `height` pixels.
double wcPerPixel(const ViewCamera& observer, const Vec3& p, int height) {
  const Vec3 vrc = transformAffine(observer.vrcFromWc, p);
  const double distance = std::max(1e-9, glm::length(observer.camera.prp - observer.camera.vrp) - vrc.z);
  const double vpd = glm::length(observer.camera.prp - observer.camera.vrp);
  return observer.camera.window.height() * distance / vpd / height;
}

}  // namespace

Vec3 handlePosition(const PipelineRun& run, Handle h) {
  const ViewWindow& w = run.camera.window;
  const Mat4& wcFromVrc = run.wcFromVrc;
  const double cx = (w.xmin + w.xmax) / 2, cy = (w.ymin + w.ymax) / 2;
  switch (h) {
    case Handle::vrp: return run.camera.vrp;
    case Handle::prp: return run.camera.prp;
    case Handle::windowLeft: return transformAffine(wcFromVrc, {w.xmin, cy, 0});
    case Handle::windowRight: return transformAffine(wcFromVrc, {w.xmax, cy, 0});
    case Handle::windowBottom: return transformAffine(wcFromVrc, {cx, w.ymin, 0});
    case Handle::windowTop: return transformAffine(wcFromVrc, {cx, w.ymax, 0});
    case Handle::front: return run.wcOfNpc({0.5, 0.5, 1});
    case Handle::back: return run.wcOfNpc({0.5, 0.5, 0});
    case Handle::none: break;
  }
  return run.camera.vrp;
}

Handle pickHandle(const PipelineRun& run, const ViewCamera& view, int width, int height, Vec2 pixel, double radiusPx) {
  Handle best = Handle::none;
  double bestDistance = radiusPx;
  for (Handle h : kHandles) {
    const Projected p = projectToPixels(view, handlePosition(run, h), width, height);
    if (!p.visible) continue;
    const double d = glm::length(p.pixel - pixel);
    if (d <= bestDistance) {
      bestDistance = d;
      best = h;
    }
  }
  return best;
}

std::optional<Vec3> probePosition(const PipelineRun& run, const Probe& probe, ViewKind view) {
  const ObjectRun* o = objectOf(run, probe.object);
  if (!o || probe.vertex >= o->vertexCount()) return std::nullopt;
  const Vec4 h = o->npcH[probe.vertex];
  switch (view) {
    case ViewKind::world: return o->wc(probe.vertex);
    case ViewKind::npc:
      if (h.w <= 0) return std::nullopt;
      return Vec3(h) / h.w;
    case ViewKind::camera:
      if (h.w <= 0) return std::nullopt;
      return Vec3(run.dcFromNpc * Vec4(Vec3(h) / h.w, 1.0));
    case ViewKind::all:
    case ViewKind::morph:
    case ViewKind::divideFirst:
    case ViewKind::depth: break;
  }
  return std::nullopt;
}

std::optional<Probe> pickVertex(const PipelineRun& run, ViewKind view, const ViewCamera& observer, int width, int height,
                                Vec2 pixel, double radiusPx) {
  std::optional<Probe> best;
  double bestDistance = radiusPx;
  // The camera view shows DC at the device's size, scaled to the image it is drawn in.
  const Vec2 dcScale(double(width) / run.device.width, double(height) / run.device.height);
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    for (uint32_t v = 0; v < o.vertexCount(); ++v) {
      const Probe candidate{run.sceneIndex[k], v};
      const auto p = probePosition(run, candidate, view);
      if (!p) continue;
      Vec2 screen;
      if (view == ViewKind::camera) {
        screen = Vec2(p->x, p->y) * dcScale;
      } else {
        const Projected q = projectToPixels(observer, *p, width, height);
        if (!q.visible) continue;
        screen = q.pixel;
      }
      const double d = glm::length(screen - pixel);
      if (d <= bestDistance) {
        bestDistance = d;
        best = candidate;
      }
    }
  }
  return best;
}

std::optional<std::pair<size_t, size_t>> pickFace(const PipelineRun& run, Vec2 dc) {
  std::optional<std::pair<size_t, size_t>> best;
  double bestZ = -1e300;
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    for (size_t f = 0; f < o.faceCount(); ++f) {
      const auto face = o.clippedFace(f);
      if (face.size() < 3) continue;
      // Inside a convex polygon of either orientation: the point is on one side of every edge.
      int sign = 0;
      bool inside = true;
      double z = 0;
      for (size_t i = 0; i < face.size() && inside; ++i) {
        const Vec3 a = o.clippedDc(face[i]), b = o.clippedDc(face[(i + 1) % face.size()]);
        const double cross = (b.x - a.x) * (dc.y - a.y) - (b.y - a.y) * (dc.x - a.x);
        const int s = cross > 0 ? 1 : cross < 0 ? -1 : 0;
        if (s != 0 && sign != 0 && s != sign) inside = false;
        if (s != 0) sign = s;
        z += a.z;
      }
      z /= double(face.size());  // DC z: larger is nearer (1 at the front plane)
      if (inside && z > bestZ) {
        bestZ = z;
        best = std::pair{run.sceneIndex[k], f};
      }
    }
  }
  return best;
}

void keepWindowAspect(ViewWindow& w, double aspect, bool xChanged) {
  if (!(w.width() > 0 && w.height() > 0 && aspect > 0)) return;
  if (xChanged) {
    const double cy = (w.ymin + w.ymax) / 2, half = w.width() / aspect / 2;
    w.ymin = cy - half;
    w.ymax = cy + half;
  } else {
    const double cx = (w.xmin + w.xmax) / 2, half = w.height() * aspect / 2;
    w.xmin = cx - half;
    w.xmax = cx + half;
  }
}

void dragHandle(Camera& camera, const PipelineRun& run, Handle h, const ViewCamera& observer, int height, Vec2 deltaPx,
                std::optional<double> aspect) {
  const Vec3 at = handlePosition(run, h);
  const double scale = wcPerPixel(observer, at, height);
  const Mat4 wcFromObserver = glm::inverse(observer.vrcFromWc);
  // The mouse motion as a WC vector parallel to the observer's view plane (DC y points down).
  const Vec3 motion = (Vec3(wcFromObserver[0]) * deltaPx.x - Vec3(wcFromObserver[1]) * deltaPx.y) * scale;
  const VrcAxes& f = run.vrc;
  switch (h) {
    case Handle::vrp: camera.vrp += motion; break;
    case Handle::prp: camera.prp += motion; break;
    case Handle::windowLeft: camera.window.xmin += glm::dot(motion, f.u); break;
    case Handle::windowRight: camera.window.xmax += glm::dot(motion, f.u); break;
    case Handle::windowBottom: camera.window.ymin += glm::dot(motion, f.v); break;
    case Handle::windowTop: camera.window.ymax += glm::dot(motion, f.v); break;
    case Handle::front: camera.front += glm::dot(motion, f.n); break;
    case Handle::back: camera.back += glm::dot(motion, f.n); break;
    case Handle::none: break;
  }
  const bool x = h == Handle::windowLeft || h == Handle::windowRight;
  const bool y = h == Handle::windowBottom || h == Handle::windowTop;
  if (aspect && (x || y)) keepWindowAspect(camera.window, *aspect, x);
}

}  // namespace vplab
