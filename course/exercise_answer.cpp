#include "course/exercise_answer.h"

#include "pipeline/clipping.h"
#include "base/error.h"

#include <string>

namespace vplab {

using Json = nlohmann::ordered_json;

bool exerciseShows(ExerciseTopic topic, ExerciseTopic part) {
  // The pipeline sheet follows P1 through every stage; the polygon's clipping is a week of its own.
  if (topic == ExerciseTopic::pipeline) return part != ExerciseTopic::clipping;
  return topic == part;
}

std::vector<ExerciseTask> exerciseTasks(const Exercise& e, const ExerciseSolution& s, Language lang) {
  auto L = [&](const std::string& en, const std::string& de) { return lang == Language::de ? de : en; };
  auto shows = [&](ExerciseTopic part) { return exerciseShows(e.spec.topic, part); };
  const std::string polygon = "/objects/0/polygons/0";
  std::vector<ExerciseTask> tasks;
  auto task = [&](std::string text) -> ExerciseTask& { return tasks.emplace_back(ExerciseTask{std::move(text), {}}); };
  auto item = [](ExerciseTask& t, std::string path, std::string title, double points) {
    t.items.push_back({std::move(path), std::move(title), points, true, {}});
  };
  // The items whose subject is clipping in homogeneous coordinates: dividing by w first removes it,
  // so no follow-through after that mistake (issue 38, course/assignment.h).
  auto homogeneous = [](ExerciseTask& t) { t.items.back().noFollowThroughAfter = {"divide-first"}; };
  if (shows(ExerciseTopic::orientation)) {
    ExerciseTask& modeling = task(L("Compute $\\mathit{wcFromMc}$ and $P_1$ in WC.", "Berechnen Sie $\\mathit{wcFromMc}$ und $P_1$ in WC."));
    item(modeling, "/objects/0/wc_from_mc", "wcFromMc", 2);
    item(modeling, polygon + "/wc/0", L("P1 in WC", "P1 in WC"), 1);
    ExerciseTask& orientation = task(L("Compute $N$, $U$, $V$ and VPD, the matrix $\\mathit{vrcFromWc}$ and $P_1$ in VRC.",
                                       "Berechnen Sie $N$, $U$, $V$ und VPD, die Matrix $\\mathit{vrcFromWc}$ und $P_1$ in VRC."));
    item(orientation, "/camera/n", "N", 1);
    item(orientation, "/camera/u", "U", 1);
    item(orientation, "/camera/v", "V", 1);
    item(orientation, "/camera/vpd", "VPD", 1);
    item(orientation, "/matrices/vrc_from_wc", "vrcFromWc", 2);
    item(orientation, polygon + "/vrc/0", L("P1 in VRC", "P1 in VRC"), 1);
  }
  if (shows(ExerciseTopic::mapping)) {
    ExerciseTask& mapping = task(L("Compute the view mapping $\\mathit{npcFromVrc}$ and $P_1$ in homogeneous NPC.",
                                   "Berechnen Sie das View Mapping $\\mathit{npcFromVrc}$ und $P_1$ in homogenen NPC."));
    item(mapping, "/matrices/npc_from_vrc", "npcFromVrc", 2);
    item(mapping, polygon + "/npc_h/0", L("P1 in homogeneous NPC", "P1 in homogenen NPC"), 1);
    ExerciseTask& test = task(L("Give the boundary coordinates and the outcode of $P_1$; where it is inside, its NPC, "
                                "$\\mathit{dcFromNpc}$ and its DC.",
                                "Geben Sie die Randkoordinaten und den Outcode von $P_1$ an; falls innen, seine NPC, "
                                "$\\mathit{dcFromNpc}$ und seine DC."));
    item(test, polygon + "/boundary/0", L("the boundary coordinates of P1", "die Randkoordinaten von P1"), 1);
    homogeneous(test);
    item(test, polygon + "/outcodes/0", L("the outcode of P1", "der Outcode von P1"), 1);
    homogeneous(test);
    if (s.point.outcode == 0) {  // "where it is inside, its NPC and DC" (DC by dcFromNpc, which the grader follows)
      item(test, polygon + "/npc/0", L("P1 in NPC", "P1 in NPC"), 1);
      item(test, "/matrices/dc_from_npc", "dcFromNpc", 1);
      item(test, polygon + "/dc/0", L("P1 in DC", "P1 in DC"), 1);
    }
  }
  if (shows(ExerciseTopic::clipping)) {
    ExerciseTask& clip = task(L("Clip the polygon in homogeneous NPC with Sutherland–Hodgman, plane by plane "
                                "(left, right, bottom, top, back, front): each edge's boundary values, $t$ and the new vertex.",
                                "Clippen Sie das Polygon in homogenen NPC mit Sutherland–Hodgman, Ebene für Ebene "
                                "(links, rechts, unten, oben, hinten, vorne): Randwerte jeder Kante, $t$ und der neue Punkt."));
    static constexpr const char* kPlanesDe[] = {"links", "rechts", "unten", "oben", "hinten", "vorne"};
    for (int plane = 0; plane < kPlaneCount; ++plane)
      item(clip, polygon + "/clip_steps/" + std::to_string(plane) + "/polygon",
           L("the polygon after the " + std::string(planeName(plane)) + " plane",
             "das Polygon nach der Ebene " + std::string(kPlanesDe[plane])),
           1);
    for (AssignmentItem& i : clip.items) i.noFollowThroughAfter = {"divide-first"};
    ExerciseTask& device = task(L("Divide the clipped polygon by $w$ and map it to DC with $\\mathit{dcFromNpc}$.",
                                  "Dividieren Sie das geclippte Polygon durch $w$ und bilden Sie es mit $\\mathit{dcFromNpc}$ auf DC ab."));
    item(device, "/matrices/dc_from_npc", "dcFromNpc", 1);
    item(device, polygon + "/clipped_dc", L("the clipped polygon in DC", "das geclippte Polygon in DC"), 2);
    homogeneous(device);
  }
  return tasks;
}

double points(const ExerciseTask& task) {
  double sum = 0;
  for (const AssignmentItem& i : task.items) sum += i.points;
  return sum;
}

Assignment exerciseAssignment(const Exercise& e, const ExerciseSolution& s, Language lang) {
  Assignment a;
  a.title = (lang == Language::de ? "Übung " : "Exercise ") + std::to_string(e.spec.seed) + " (" +
            std::string(toString(e.spec.topic)) + ", " + std::string(toString(e.spec.projection)) + ")";
  a.scene = "scene.json";
  for (ExerciseTask& t : exerciseTasks(e, s, lang))
    for (AssignmentItem& i : t.items) a.items.push_back(std::move(i));
  // Passed with half the points, the common rule of a weekly sheet; a course writes its own.
  double total = 0;
  for (const AssignmentItem& i : a.items) total += i.points;
  a.passMark = total / 2;
  return a;
}

namespace {

Json blanked(const Json& j) {
  if (j.is_primitive()) return nullptr;
  if (j.is_array()) {
    Json out = Json::array();
    for (const Json& e : j) out.push_back(blanked(e));
    return out;
  }
  if (j.is_object()) {
    Json out = Json::object();
    for (const auto& [k, v] : j.items()) out[k] = blanked(v);
    return out;
  }
  return j;
}

std::vector<std::string> keysOf(const std::string& pointer) {
  std::vector<std::string> keys;
  size_t from = 1;
  while (from <= pointer.size()) {
    const size_t slash = pointer.find('/', from);
    keys.push_back(pointer.substr(from, slash == std::string::npos ? std::string::npos : slash - from));
    if (slash == std::string::npos) break;
    from = slash + 1;
  }
  return keys;
}

bool isIndex(const std::string& k) { return !k.empty() && k.find_first_not_of("0123456789") == std::string::npos; }

}  // namespace

Json answerTemplate(const Assignment& assignment, const Json& reference) {
  Json answer = Json::object();
  for (const AssignmentItem& item : assignment.items) {
    const std::vector<std::string> keys = keysOf(item.path);
    const Json* ref = &reference;
    Json* out = &answer;
    for (size_t i = 0; i < keys.size(); ++i) {
      const std::string& k = keys[i];
      const bool last = i + 1 == keys.size();
      if (isIndex(k)) {
        const size_t index = std::stoul(k);
        if (!ref->is_array() || index >= ref->size()) throw Error("answer template: " + item.path + " is not in the reference");
        const Json& parent = *ref;
        ref = &parent[index];
        if (out->is_null()) *out = Json::array();
        // Entries before `index` are given as empty entries of their shape (P1 is index 0: none).
        while (out->size() <= index) {
          const size_t j = out->size();
          out->push_back(j == index && !last ? Json(nullptr) : blanked(parent[j]));
        }
      } else {
        if (!ref->is_object() || !ref->contains(k)) throw Error("answer template: " + item.path + " is not in the reference");
        ref = &(*ref)[k];
        if (out->is_null()) *out = Json::object();
      }
      Json& next = isIndex(k) ? (*out)[std::stoul(k)] : (*out)[k];
      // A polygon's vertex count is part of the answer: the template does not give it away (null).
      if (last) next = k == "clipped_dc" || k == "polygon" ? Json(nullptr) : blanked(*ref);
      out = &next;
    }
  }
  return answer;
}

Json answerKey(const Assignment& assignment, const Json& reference) {
  Json key = answerTemplate(assignment, reference);
  for (const AssignmentItem& item : assignment.items) {
    const Json::json_pointer at(item.path);
    key[at] = reference[at];
  }
  return key;
}

}  // namespace vplab
