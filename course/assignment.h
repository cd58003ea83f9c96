// An assignment (issue 21): what `vplab grade` checks in an answer and what each part is worth, so
// that an answer that leaves out what the sheet asks for fails, named, instead of passing on the
// little it gives. `vplab exercise` writes one beside each sheet (assignment.json); a course may
// write its own for any scene.
//
//   {
//     "vplab_assignment": 1,
//     "title": "The viewing pipeline, perspective, sheet 3",
//     "scene": "scene.json",          the scene, relative to the assignment's folder
//     "tolerance": 0.001,             optional (docs/course-staff.md)
//     "row_vector_form": "accepted",  optional: "accepted" (the default) or "wrong" (issue 38)
//     "pass_mark": 7.5,               optional: passed with at least these points; without it, passed
//                                     when every value given is right and every required item given
//     "items": [
//       {"path": "/camera/n", "title": "N", "points": 1},
//       {"path": "/objects/0/polygons/0/wc/0", "title": "P1 in WC", "points": 1, "required": false},
//       {"path": "/objects/0/polygons/0/clip_steps/1/polygon", "title": "…", "points": 1,
//        "no_follow_through_after": ["divide-first"]}
//     ]
//   }
//
// An item's path is a JSON pointer into the answer (the `vplab dump` format, answer.json's keys);
// every value below it belongs to the item. Items are required unless they say otherwise.
//
// Row-vector form: the lecture notes write matrices for row vectors (p' = p · M), the dump for
// column vectors. An answer that writes every matrix it gives in row form uses a notation, not a
// mistake: "accepted" grades it as if transposed; "wrong" grades each transposed matrix wrong.
//
// Follow-through (Folgefehler, course/follow_through.h): a wrong item whose values follow from the
// student's own earlier values earns its points, unless the mistake named for the answer is one
// its "no_follow_through_after" lists (mistake keys, course/mistake_models.h): a mistake that
// removes the item's subject (dividing by w first removes homogeneous clipping) earns no credit for
// what it made easier.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

struct AssignmentItem {
  std::string path;   // "/matrices/vrc_from_wc"
  std::string title;  // what the sheet calls it: "vrcFromWc"
  double points = 1;
  bool required = true;
  std::vector<std::string> noFollowThroughAfter;  // mistake keys ("divide-first")
};

struct Assignment {
  std::string title;
  std::filesystem::path scene;  // as the file gives it (relative to the assignment's folder)
  double tolerance = 1e-3;
  bool rowVectorFormAccepted = true;
  std::optional<double> passMark;
  std::vector<AssignmentItem> items;
};

/// Reads an assignment as strictly as a scene: unknown keys, wrong types, points that are not a
/// finite number from 0 to 1000, a tolerance outside [0, 0.5], no items, more than 10 000 items,
/// paths that are not JSON pointers or given twice are errors "SOURCE: /json/path: …".
Assignment parseAssignment(std::string_view text, std::string_view source);
/// The assignment as the JSON text parseAssignment reads.
std::string assignmentJson(const Assignment& assignment);

/// Whether `path` (a JSON pointer) is `item` or lies below it.
bool isWithin(std::string_view path, std::string_view item);

}  // namespace vplab
