// An assignment (issue 21): what `vplab grade` checks in an answer and what each part is worth, so
// that an answer that leaves out what the sheet asks for fails, named, instead of passing on the
// little it gives. `vplab exercise` writes one beside each sheet (assignment.json); a course may
// write its own for any scene.
//
//   {
//     "vplab_assignment": 1,
//     "title": "The viewing pipeline, perspective, sheet 3",
//     "scene": "scene.json",          the scene, relative to the assignment's folder
//     "tolerance": 0.001,             optional (README "For course staff")
//     "items": [
//       {"path": "/camera/n", "title": "N", "points": 1},
//       {"path": "/objects/0/polygons/0/wc/0", "title": "P1 in WC", "points": 1, "required": false}
//     ]
//   }
//
// An item's path is a JSON pointer into the answer (the `vplab dump` format, answer.json's keys);
// every value below it belongs to the item. Items are required unless they say otherwise.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vplab {

struct AssignmentItem {
  std::string path;   // "/matrices/vrc_from_wc"
  std::string title;  // what the sheet calls it: "vrcFromWc"
  double points = 1;
  bool required = true;
};

struct Assignment {
  std::string title;
  std::filesystem::path scene;  // as the file gives it (relative to the assignment's folder)
  double tolerance = 1e-3;
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
