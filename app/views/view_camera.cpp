#include "app/views/view_camera.h"

#include "pipeline/view_mapping.h"

namespace vplab {

ViewCamera viewCameraOf(const Camera& camera) {
  const VrcAxes frame = vrcAxes(camera);
  ViewCamera v;
  v.camera = camera;
  v.vrcFromWc = vrcFromWc(frame, camera.vrp);
  v.npcFromVrc = npcFromVrc(camera, frame);
  v.eyeWc = camera.projection == Projection::perspective ? Vec4(camera.prp, 1.0) : Vec4(frame.n, 0.0);
  return v;
}

Mat4 glClipFromPixels(int width, int height) {
  return glClipFromNpc() * glm::inverse(dcFromNpc(Device{width, height}));
}

Projected projectToPixels(const ViewCamera& view, const Vec3& p, int width, int height) {
  const Vec4 npcH = view.npcFromWc() * Vec4(p, 1.0);
  if (!(npcH.w > 1e-12)) return {{0, 0}, false};
  const Vec4 dc = dcFromNpc(Device{width, height}) * Vec4(Vec3(npcH) / npcH.w, 1.0);
  return {{dc.x, dc.y}, true};
}

}  // namespace vplab
