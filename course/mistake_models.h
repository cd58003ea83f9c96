// The common mistakes of viewing-pipeline assignments as mistake models (issue 14): each is a
// variant of the reference pipeline, run on the same scene, whose dump (io/dump.h format) is
// what a student making that mistake would print. `vplab grade` compares a student's numbers with
// every model and names the one they match.
//
//   transposed          a matrix written in the lecture notes' row-vector form (p' = p · M, the
//                       transpose) among matrices in the dump's column form (p' = M · p); points
//                       computed correctly. Every matrix in row form is a notation, not this mistake,
//                       unless the assignment says otherwise (course/assignment.h).
//   y-not-flipped       device mapping y_dc = H · y instead of H · (1 − y) (docs/conventions.md stage 5)
//   divide-first        dividing by w before clipping (Hill 7.4): the pipeline's divide-first strategy
//   front-back-swapped  front → z = 0 and back → z = 1 (F and B exchanged in the view mapping, or the
//                       seed's mirrored system not mirrored back, 15.2.4: the same numbers)
//   left-handed-n       N = normalize(VRP − PRP) (lecture notes 15.2.2 has PRP − VRP): the pipeline
//                       run with PRP mirrored about VRP, which yields exactly that N, U and V
//   degrees-as-radians  rotation angles and the oblique φ taken as radians
//   oblique-shear-sign  the oblique shear with the opposite sign (lecture notes 14.3.2): φ + 180°
//   forgot-t-vrp        vrcFromWc = R without T(−VRP) (docs/conventions.md stage 2): the pipeline
//                       run with VRP at the origin and PRP − VRP as PRP, which keeps U, V, N and PRP
//                       in VRC and drops only the translation
//   outcode-reversed    the outcode's six bits in reverse order (bit 0 the front plane, bit 5 the left)
//
// Dividing first also changes the sheet's values after the division (course/sheet_values.h): the
// boundary coordinates and the outcode of the divided point, the clipper's passes over the divided
// polygon (w = 1).
//
// The variants change the scene (left-handed N, degrees, shear sign, forgot T(−VRP)) or the strategy (divide first)
// and run the real pipeline, or transform the reference dump where the mistake sits in the last
// stage or is a relabelling (transposed, y not flipped, front/back: the cube is symmetric under
// z → w − z, so clipping commutes with it).
#pragma once
#include "base/language.h"
#include "pipeline/scene.h"

#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

namespace vplab {

enum class Mistake { transposed, yNotFlipped, divideFirst, frontBackSwapped, leftHandedN, degreesAsRadians,
                     obliqueShearSign, forgotTranslation, outcodeReversed };

struct MistakeModel {
  Mistake id;
  std::string_view key;          // "divide-first"
  std::string_view description;  // what the student did
  std::string_view hint;         // where to read about it
  std::string_view descriptionDe, hintDe;  // the same in German (the lecture's terms)
  std::string_view descriptionIn(Language lang) const { return lang == Language::de ? descriptionDe : description; }
  std::string_view hintIn(Language lang) const { return lang == Language::de ? hintDe : hint; }
};

/// All models, in the order above.
const std::vector<MistakeModel>& mistakeModels();
const MistakeModel& mistakeModel(Mistake m);
/// The model of that key ("divide-first"), or nullptr.
const MistakeModel* mistakeModelOf(std::string_view key);

/// The reference run's dump as JSON (`vplab dump` of the scene, strategy npc).
nlohmann::ordered_json referenceDump(const Scene& scene);
/// The dump of the pipeline variant that makes the mistake. Throws vplab::Error when the variant's
/// camera is invalid (it never is for a valid scene).
nlohmann::ordered_json mistakeDump(const Scene& scene, Mistake m);

}  // namespace vplab
