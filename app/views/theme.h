// Colours, line styles and sizes of the views' overlays, in one place, for two themes:
//   dark   the screen's: light lines on a dark ground, told apart by colour;
//   light  print and a bright lecture hall: dark lines on white, told apart without colour too (a
//          sheet printed in grey keeps the view volume thin and solid, the window thick and
//          dashed, the projectors dotted, the objects' edges thick and solid).
#pragma once

#include <glm/glm.hpp>

#include "base/enum_table.h"

#include <optional>
#include <string_view>

namespace vplab {

enum class Theme { dark, light };
/// The command line's --theme, the scene's "theme".
inline constexpr EnumTable<Theme, 2> kThemeNames = {{{Theme::dark, "dark"}, {Theme::light, "light"}}};
constexpr const auto& namesOf(Theme) { return kThemeNames; }

}  // namespace vplab

namespace vplab::theme {

/// What every view draws its marks with in one theme (widths in pixels before the text scale).
struct Palette {
  glm::vec3 viewBackground;   // world, NPC, morph views and the depth plot
  glm::vec3 stripBackground;  // the title strip of a picture of all views
  glm::vec3 panelGap;         // between its panels
  glm::vec4 u, v, n, vup, vrp, prp;
  glm::vec4 frustum, frontPlane, backPlane;
  glm::vec4 window, windowFill;
  glm::vec4 newEdge, cube, cubeFront, text, cpuPolygon, clipPlane, stepPlane;
  glm::vec4 probe, handle, handleHot;
  glm::vec4 student;       // an exercise's numbers as the student gave them (app/practice/practice_marks.h)
  glm::vec3 labelOutline;  // the outline that keeps labels readable on the ground
  float frustumWidthPx, windowWidthPx, windowDashPx, projectorDashPx;
  float edgeWidthPx;       // the scene objects' edges
  float inkScale;          // an object's line colour: its colour × inkScale (yellow stays visible on white)
  float fadedAlpha;        // what lies outside the view volume (a printed sheet must still show it)
};

// clang-format off
inline constexpr Palette kDark{
  /* viewBackground */ {0.085f, 0.09f, 0.11f}, /* stripBackground */ {0.0595f, 0.063f, 0.077f},
  /* panelGap */ {20.f / 255, 21.f / 255, 26.f / 255},
  /* u   */ {0.95f, 0.35f, 0.3f, 1.f},  /* v   */ {0.4f, 0.85f, 0.35f, 1.f}, /* n */ {0.35f, 0.6f, 1.f, 1.f},
  /* vup */ {0.9f, 0.45f, 0.95f, 1.f},  /* vrp */ {1.f, 0.85f, 0.25f, 1.f},  /* prp */ {1.f, 0.55f, 0.15f, 1.f},
  /* frustum */ {0.55f, 0.85f, 0.95f, 0.9f}, /* front */ {0.55f, 0.85f, 0.95f, 0.10f}, /* back */ {0.55f, 0.85f, 0.95f, 0.06f},
  /* window  */ {1.f, 0.95f, 0.6f, 0.95f},   /* fill  */ {1.f, 0.95f, 0.6f, 0.07f},
  /* newEdge */ {1.f, 0.93f, 0.2f, 1.f},     /* cube  */ {0.75f, 0.78f, 0.85f, 0.9f},
  /* cubeFront */ {0.55f, 0.85f, 0.95f, 0.08f}, /* text */ {0.93f, 0.94f, 0.96f, 1.f},
  /* cpuPolygon */ {1.f, 0.93f, 0.2f, 0.95f}, /* clipPlane */ {0.95f, 0.45f, 0.75f, 0.13f},
  /* stepPlane */ {1.f, 0.35f, 0.3f, 0.22f},
  /* probe */ {1.f, 1.f, 1.f, 1.f}, /* handle */ {0.95f, 0.95f, 0.95f, 0.55f}, /* handleHot */ {1.f, 0.85f, 0.25f, 1.f},
  /* student */ {1.f, 0.35f, 0.85f, 1.f},
  /* labelOutline */ {0.f, 0.f, 0.f},
  /* frustumWidthPx */ 2.f, /* windowWidthPx */ 2.f, /* windowDashPx */ 0.f, /* projectorDashPx */ 5.f,
  /* edgeWidthPx */ 1.5f, /* inkScale */ 1.f, /* fadedAlpha */ 0.22f,
};

inline constexpr Palette kLight{
  /* viewBackground */ {1.f, 1.f, 1.f}, /* stripBackground */ {0.93f, 0.93f, 0.94f},
  /* panelGap */ {0.75f, 0.75f, 0.77f},
  /* u   */ {0.75f, 0.1f, 0.08f, 1.f},  /* v   */ {0.1f, 0.5f, 0.1f, 1.f},   /* n */ {0.1f, 0.25f, 0.75f, 1.f},
  /* vup */ {0.5f, 0.15f, 0.55f, 1.f},  /* vrp */ {0.7f, 0.45f, 0.f, 1.f},   /* prp */ {0.8f, 0.3f, 0.f, 1.f},
  /* frustum */ {0.3f, 0.38f, 0.5f, 1.f}, /* front */ {0.2f, 0.45f, 0.7f, 0.10f}, /* back */ {0.2f, 0.45f, 0.7f, 0.06f},
  /* window  */ {0.05f, 0.05f, 0.05f, 1.f}, /* fill  */ {0.75f, 0.6f, 0.1f, 0.10f},
  /* newEdge */ {0.85f, 0.4f, 0.f, 1.f},     /* cube  */ {0.3f, 0.32f, 0.38f, 1.f},
  /* cubeFront */ {0.2f, 0.45f, 0.7f, 0.08f}, /* text */ {0.08f, 0.08f, 0.1f, 1.f},
  /* cpuPolygon */ {0.85f, 0.4f, 0.f, 0.95f}, /* clipPlane */ {0.7f, 0.1f, 0.45f, 0.13f},
  /* stepPlane */ {0.8f, 0.1f, 0.1f, 0.18f},
  /* probe */ {0.f, 0.f, 0.f, 1.f}, /* handle */ {0.2f, 0.2f, 0.2f, 0.55f}, /* handleHot */ {0.85f, 0.4f, 0.f, 1.f},
  /* student */ {0.75f, 0.f, 0.6f, 1.f},
  /* labelOutline */ {1.f, 1.f, 1.f},
  /* frustumWidthPx */ 1.5f, /* windowWidthPx */ 3.5f, /* windowDashPx */ 9.f, /* projectorDashPx */ 2.5f,
  /* edgeWidthPx */ 2.5f, /* inkScale */ 0.55f, /* fadedAlpha */ 0.5f,
};
// clang-format on

inline const Palette& palette(Theme t) { return t == Theme::light ? kLight : kDark; }

/// An object's line colour in the theme (its fill keeps the scene's colour).
inline glm::vec4 ink(const Palette& p, const glm::vec4& color) {
  return {glm::vec3(color) * p.inkScale, color.a};
}

inline constexpr float kLineWidth = 2.f;
inline constexpr float kDashPx = 5.f;
inline constexpr float kPointSize = 11.f;

}  // namespace vplab::theme
