// What the lecturer shows, as the fragment of a link (`#scene=default&vrp=0,0,0&…`): the bundled
// scene, the synthetic camera, each view's style and observer, and the clipping strategy; or a
// bundled lesson's step (`#lesson=02-view-orientation&step=3`), an exercise to practise
// (`#exercise=clipping&seed=7&id=100[&projection=P][&reveal=values|stages|none]`, issue 40), and the
// embed form that shows only some views and the caption (`#embed=camera,world&lesson=…`). The web
// page keeps its address up to date with it, so that a link reproduces exactly the picture; the
// desktop tests check the round trip and hostile fragments (tests/app/document/url_state_test.cpp).
//
// Numbers are written with the fewest digits that read back to the same double, so a link is short
// and exact. A fragment is user input: each key and value is checked, and a link explains itself
// (issue 41): every part that is not understood is named at once, with why, and the rest is used.
#pragma once

#include "app/text/catalogue.h"
#include "app/views/views.h"
#include "course/exercise_file.h"
#include "course/grade_report.h"
#include "pipeline/camera.h"
#include "pipeline/pipeline.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

/// The parts of the synthetic camera a link gives; the others stay the scene's (`#vrp=0.8,0,0`
/// moves only VRP).
struct CameraLink {
  std::optional<Vec3> vrp, prp, vup;  // WC
  std::optional<ViewWindow> window;   // VRC
  std::optional<double> front, back;  // VRC z
  std::optional<Projection> projection;
  std::optional<ObliqueParams> oblique;
  bool operator==(const CameraLink&) const = default;
  bool empty() const { return *this == CameraLink{}; }
  /// `base` with the link's parts. Throws vplab::Error with cameraError's reason when the result
  /// is no valid camera.
  Camera over(const Camera& base) const;
  /// `base` with the link's parts, valid or not.
  Camera applied(const Camera& base) const;
};
/// Every part of `camera` (the oblique parameters only for an oblique projection).
CameraLink cameraLinkOf(const Camera& camera);

/// A part of a link that was not understood or cannot be used, and is left out: its key and value
/// as written and why, in the catalogue's words (app/text/links.inc; {1} is `detail`).
struct LinkProblem {
  std::string key, value;
  text::Text why;
  std::string detail;
  /// `vrp="1,2": 3 numbers separated by commas expected` in `lang`.
  std::string said(Language lang) const;
  bool operator==(const LinkProblem& o) const {
    return key == o.key && value == o.value && why.english() == o.why.english() && detail == o.detail;
  }
};

/// Every problem, one after the other: "scene="nope": …; vrp="1,2": …".
std::string saidTogether(const std::vector<LinkProblem>& problems, Language lang);

/// The parts of a view state a fragment can carry; each is optional (a link may give only a camera).
struct UrlState {
  /// The embed form (`#embed=camera,world&lesson=…`): only these views and a lesson's caption, for a
  /// course page's figure. Empty: the whole lab.
  std::vector<ViewKind> embed;
  /// A bundled lesson (docs/lecturers.md "Lessons") by its name ("02-view-orientation", in the page's
  /// language, or "02-view-orientation.de") and its step from 1 (0: not given, the first). A lesson's step
  /// is the whole state: a link to one carries nothing else.
  std::string lesson;
  size_t step = 0;
  std::string scene;  // a bundled scene's file stem (assets/scenes/NAME.json); empty: not given
  CameraLink camera;
  std::optional<Style> cameraStyle, worldStyle, npcStyle;
  std::optional<Orbit> worldOrbit, npcOrbit;
  std::optional<ClipStrategy> strategy;
  /// An exercise (`vplab exercise`'s topic, seed, student id and projection): the whole state, as a
  /// lesson's step is; `reveal` what Check shows of the reference (default: stages).
  std::optional<ExerciseRef> exercise;
  std::optional<Reveal> reveal;
  /// What the fragment held that was not understood, each part named, in the fragment's order; the
  /// parts above are the rest, used as if the bad parts were not there.
  std::vector<LinkProblem> problems;
  bool operator==(const UrlState&) const = default;
};

/// The longest fragment read: a real one is a few hundred characters.
inline constexpr size_t kMaxUrlStateLength = 4096;

/// The fragment (without '#') for everything in `state` that is given.
std::string encodeUrlState(const UrlState& state);
/// Reads a fragment (a leading '#' is skipped): every part it understands, and a problem for each
/// it does not (UrlState::problems). Whether the camera parts make a camera is known only over the
/// scene's camera (CameraLink::over).
UrlState decodeUrlState(std::string_view fragment);

/// Whether `s` can name a bundled lesson: a bundled scene's name, with ".de" or ".en" or without.
bool isBundledLessonName(std::string_view s);

/// Whether `s` can name a bundled scene (assets/scenes/NAME.json): 1–100 letters, digits, - and _,
/// so that no link or lesson reaches a file elsewhere.
bool isBundledSceneName(std::string_view s);

/// A number as the fewest decimal digits that read back to exactly `v` (finite).
std::string shortestNumber(double v);

}  // namespace vplab
