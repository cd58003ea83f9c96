// The matrices a view is seen through. Every view, including the observers of the world and NPC
// views, is a synthetic camera of the pipeline itself (VRP, PRP, VUP, window, F, B), so the GPU
// only ever receives matrices made by pipeline/: no other projection matrix exists.
#pragma once

#include "pipeline/camera.h"
#include "pipeline/device_mapping.h"

namespace vplab {

struct ViewCamera {
  Camera camera;
  Mat4 vrcFromWc{1.0};
  Mat4 npcFromVrc{1.0};
  Vec4 eyeWc{0, 0, 1, 0};  // PRP (w = 1) for perspective; the direction to the viewer (w = 0) otherwise

  Mat4 npcFromWc() const { return npcFromVrc * vrcFromWc; }
};

/// The view camera of a valid synthetic camera. Throws vplab::Error for an invalid one.
ViewCamera viewCameraOf(const Camera& camera);

/// The pixel space of a view (origin top-left, y down) as a device: glClipFromNpc · npcFromDc.
Mat4 glClipFromPixels(int width, int height);

/// Where a point of the space the camera looks at lands in the view's pixels (x right, y down),
/// and whether it lies in front of the camera (w > 0).
struct Projected {
  Vec2 pixel;
  bool visible;
};
Projected projectToPixels(const ViewCamera& view, const Vec3& p, int width, int height);

}  // namespace vplab
