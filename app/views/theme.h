// Colours and sizes of the views' overlays, in one place.
#pragma once

#include <glm/glm.hpp>

namespace vplab::theme {

inline constexpr glm::vec3 kViewBackground{0.085f, 0.09f, 0.11f};  // world and NPC views
inline constexpr glm::vec4 kU{0.95f, 0.35f, 0.3f, 1.f};
inline constexpr glm::vec4 kV{0.4f, 0.85f, 0.35f, 1.f};
inline constexpr glm::vec4 kN{0.35f, 0.6f, 1.f, 1.f};
inline constexpr glm::vec4 kVup{0.9f, 0.45f, 0.95f, 1.f};
inline constexpr glm::vec4 kVrp{1.f, 0.85f, 0.25f, 1.f};
inline constexpr glm::vec4 kPrp{1.f, 0.55f, 0.15f, 1.f};
inline constexpr glm::vec4 kFrustum{0.55f, 0.85f, 0.95f, 0.9f};
inline constexpr glm::vec4 kFrontPlane{0.55f, 0.85f, 0.95f, 0.10f};
inline constexpr glm::vec4 kBackPlane{0.55f, 0.85f, 0.95f, 0.06f};
inline constexpr glm::vec4 kWindow{1.f, 0.95f, 0.6f, 0.95f};
inline constexpr glm::vec4 kWindowFill{1.f, 0.95f, 0.6f, 0.07f};
inline constexpr glm::vec4 kNewEdge{1.f, 0.93f, 0.2f, 1.f};
inline constexpr glm::vec4 kCube{0.75f, 0.78f, 0.85f, 0.9f};
inline constexpr glm::vec4 kCubeFront{0.55f, 0.85f, 0.95f, 0.08f};
inline constexpr glm::vec4 kText{0.93f, 0.94f, 0.96f, 1.f};
inline constexpr glm::vec4 kCpuPolygon{1.f, 0.93f, 0.2f, 0.95f};
inline constexpr glm::vec4 kClipPlane{0.95f, 0.45f, 0.75f, 0.13f};
inline constexpr glm::vec4 kStepPlane{1.f, 0.35f, 0.3f, 0.22f};
inline constexpr glm::vec4 kProbe{1.f, 1.f, 1.f, 1.f};
inline constexpr glm::vec4 kHandle{0.95f, 0.95f, 0.95f, 0.55f};
inline constexpr glm::vec4 kHandleHot{1.f, 0.85f, 0.25f, 1.f};
inline constexpr float kFadedAlpha = 0.22f;
inline constexpr float kLineWidth = 2.f;
inline constexpr float kEdgeWidth = 1.5f;
inline constexpr float kDashPx = 5.f;
inline constexpr float kPointSize = 11.f;

}  // namespace vplab::theme
