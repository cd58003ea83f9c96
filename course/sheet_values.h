// The values an exercise sheet asks for beyond `vplab dump` (issue 21: the answer template holds every
// task of the sheet), added to a dump in the answer format: per polygon vertex its boundary
// coordinates (Blinn & Newell; Hill 7.4), NPC after the division and DC; per polygon the
// Sutherland–Hodgman passes, each the polygon in homogeneous NPC after one plane (left, right,
// bottom, top, back, front: lecture notes 15.3). They are computed from the dump's own npc_h and
// dc_from_npc, so a mistake model's dump gets the values that follow from its mistake.
//
//   "boundary":   [[BC0 … BC5], …]          per vertex, like npc_h
//   "npc":        [[x, y, z], …]            per vertex: npc_h / w
//   "dc":         [[x, y, z], …]            per vertex: dc_from_npc · (npc, 1)
//   "clip_steps": [{"plane": "left", "polygon": [[x, y, z, w], …]}, …]   all six passes
#pragma once

#include "pipeline/scene.h"

#include <nlohmann/json.hpp>

namespace vplab {

/// Adds the sheet's values to every polygon of `dump`. `matricesTransposed`: the dump's matrices
/// are written transposed (the transposed mistake model: its points are right, so DC is mapped with
/// the matrix as it should be). `dividedFirst`: the divide-first mistake model's values: the
/// boundary coordinates, outcodes and passes of the divided points (x/w, y/w, z/w, 1).
void addSheetValues(nlohmann::ordered_json& dump, bool matricesTransposed = false, bool dividedFirst = false);

/// The reference answer of a scene: its dump (strategy npc) with the sheet's values.
nlohmann::ordered_json referenceAnswer(const Scene& scene);

}  // namespace vplab
