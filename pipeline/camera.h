// The synthetic camera (lecture notes 15.1) and stage 2, view orientation WC → VRC (lecture notes 15.2.2).
//
// VRP is the point looked at and the origin of VRC; PRP is the eye (projection reference point);
// VUP the view-up vector. The window lies in the view plane z = 0 of VRC, the front and back planes
// are z = F and z = B in VRC with B < F (docs/conventions.md, stages 2 and 3).
#pragma once

#include "base/enum_table.h"
#include "pipeline/math.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace vplab {

enum class Projection { perspective, parallel, oblique };
inline constexpr EnumTable<Projection, 3> kProjectionNames = {{
    {Projection::perspective, "perspective"}, {Projection::parallel, "parallel"}, {Projection::oblique, "oblique"}}};
constexpr const auto& namesOf(Projection) { return kProjectionNames; }

/// The window in the view plane z = 0, in VRC.
struct ViewWindow {
  double xmin = -1, xmax = 1, ymin = -1, ymax = 1;
  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }
  bool operator==(const ViewWindow&) const = default;
};

/// Oblique parallel projection (lecture notes 14.3.2): shortening factor d = 1 / tan α and angle φ.
struct ObliqueParams {
  double d = 0.5;
  double phiDeg = 50;
  bool operator==(const ObliqueParams&) const = default;
};
inline constexpr ObliqueParams kCavalier{1.0, 35.0};  // α = 45°: depth at full length
inline constexpr ObliqueParams kCabinet{0.5, 50.0};   // α = 63.43°: depth at half length

struct Camera {
  Vec3 vrp{0, 0, 0};  // WC
  Vec3 prp{0, 0, 5};  // WC
  Vec3 vup{0, 1, 0};  // WC, direction
  ViewWindow window{-1, 1, -0.75, 0.75};
  double front = 2;   // F, VRC z of the front plane
  double back = -2;   // B, VRC z of the back plane, B < F
  Projection projection = Projection::perspective;
  ObliqueParams oblique = kCabinet;  // used when projection == oblique
  bool operator==(const Camera&) const = default;
};

/// The VRC axes and distances derived from a valid camera (lecture notes 15.2.2, docs/conventions.md stage 2).
struct VrcAxes {
  Vec3 u, v, n;  // WC; U, V, N right-handed, the eye on +N
  double vpd;    // |PRP − VRP|: the eye is at VRC (0, 0, VPD)
  double dmin;   // VPD − F: distance eye → front plane (perspective)
  double dmax;   // VPD − B: distance eye → back plane (perspective)
};

/// What makes a camera invalid, as data: cameraError says it in English, naming the camera's values;
/// the viewer says it in its language from the same data (app/inspect/camera_text.h).
struct CameraProblem {
  enum class Kind {
    vectorsNotFinite,    // VRP, PRP or VUP has a NaN or infinite component
    planesNotFinite,     // the window, F or B is not finite
    prpOnVrp,            // PRP = VRP: N = PRP − VRP is undefined
    vupZero,             // VUP = 0: no up direction
    vupAlongN,           // VUP ∥ N: U = VUP × N is undefined
    windowX,             // not xmin < xmax
    windowY,             // not ymin < ymax
    backNotBehindFront,  // not B < F
    frontBehindEye,      // perspective: not F < VPD
    obliqueFactors,      // oblique: d < 0, or d or φ not finite
    mappingNotFinite,    // finite values whose view mapping overflows
  };
  Kind kind;
  Vec3 n{0};       // vupAlongN: the view plane normal N
  double vpd = 0;  // frontBehindEye, mappingNotFinite: |PRP − VRP|
};

/// What makes the camera invalid; nullopt when it is valid. A valid camera never leads to NaN or
/// infinity in any stage matrix.
std::optional<CameraProblem> cameraProblem(const Camera& camera);

/// Why the camera is invalid, in English naming the offending values (cameraProblem's); nullopt
/// when it is valid.
std::optional<std::string> cameraError(const Camera& camera);

/// U, V, N, VPD, dmin, dmax. Throws vplab::Error with cameraError's message when invalid.
VrcAxes vrcAxes(const Camera& camera);

/// Stage 2: vrcFromWc = [U 0; V 0; N 0; 0 0 0 1] · T(−VRP) (lecture notes 15.2.2; rows are U, V, N).
Mat4 vrcFromWc(const VrcAxes& frame, const Vec3& vrp);
Mat4 vrcFromWc(const Camera& camera);

}  // namespace vplab
