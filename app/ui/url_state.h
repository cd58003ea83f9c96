// What the lecturer shows, as the fragment of a link (`#scene=default&vrp=0,0,0&…`): the bundled
// scene, the synthetic camera, each view's style and observer, and the clipping strategy. The web
// page keeps its address up to date with it, so that a link reproduces exactly the picture; the
// desktop tests check the round trip and hostile fragments (tests/app/url_state_test.cpp).
//
// Numbers are written with the fewest digits that read back to the same double, so a link is short
// and exact. A fragment is user input: each key and value is checked, and an error names them.
#pragma once

#include "app/views/views.h"
#include "pipeline/camera.h"
#include "pipeline/pipeline.h"

#include <optional>
#include <string>
#include <string_view>

namespace vplab {

/// The parts of a view state a fragment can carry; each is optional (a link may give only a camera).
struct UrlState {
  std::string scene;  // a bundled scene's file stem (assets/scenes/NAME.json); empty: not given
  std::optional<Camera> camera;
  std::optional<Style> cameraStyle, worldStyle, npcStyle;
  std::optional<Orbit> worldOrbit, npcOrbit;
  std::optional<ClipStrategy> strategy;
  bool operator==(const UrlState&) const = default;
};

/// The longest fragment read: a real one is a few hundred characters.
inline constexpr size_t kMaxUrlStateLength = 4096;

/// The fragment (without '#') for everything in `state` that is given.
std::string encodeUrlState(const UrlState& state);
/// Reads a fragment (a leading '#' is skipped). Throws vplab::Error naming the key and value that
/// are not understood, or the camera's problem (cameraError) when its values make no camera.
UrlState decodeUrlState(std::string_view fragment);

/// A number as the fewest decimal digits that read back to exactly `v` (finite).
std::string shortestNumber(double v);

}  // namespace vplab
