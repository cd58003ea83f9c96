// Consequential-error credit (issue 21): a value that is wrong only because an earlier value was
// wrong earns its points. Each item of an exercise sheet is recomputed from the student's own
// earlier values (the lecture notes' formulas, the pipeline's own functions):
//
//   P1 in WC      = wcFromMc · P1 (MC, given)          U   = normalize(VUP × N)      (15.2.2)
//   vrcFromWc     = [U; V; N] · T(−VRP)                 V   = N × U
//   P1 in VRC     = vrcFromWc · P1 in WC
//   P1 in NPC_h   = npcFromVrc · P1 in VRC              its boundary coordinates and outcode from it
//   P1 in NPC     = P1 in NPC_h / w                      P1 in DC = dcFromNpc · P1 in NPC
//   each Sutherland–Hodgman pass from the student's previous one (the first from the given polygon),
//     when that pass had the work the key's had: a plane that cuts the key's polygon must cut the
//     student's too (the German exam's Folgefehler: no credit where the earlier error made the
//     later work essentially easier, issue 38)
//   the clipped polygon in DC = dcFromNpc · (the last pass / w)
//
// Values given by the sheet (the camera, the polygon in MC, npcFromVrc's inputs) are the reference's.
#pragma once

#include "pipeline/scene.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace vplab {

/// The value at `path` recomputed from the student's `answer` where the values it follows from are
/// given there; nullopt for a path no earlier value leads to, or when one of those is missing.
/// `reference`: the reference answer (course/sheet_values.h), for the values the sheet gives.
std::optional<nlohmann::ordered_json> followingValue(const std::string& path, const nlohmann::ordered_json& answer,
                                                      const nlohmann::ordered_json& reference, const Scene& scene);

}  // namespace vplab
