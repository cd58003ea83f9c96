// Issue 38, "Done when": a generated class of 300 over the four topics, graded end to end through the
// built program (`vplab exercise --roster`, then `vplab grade batch --exercises`), each student's grade
// against the points the test expects for the answer it handed in.
//
// The answers are made independently of the code under test: from each student's own given scene
// (students/ID/scene.json, what the student gets) with GLM and the conventions of the domain notes
// (/work/shared/domain.md: column vectors, N = normalize(PRP − VRP), U = normalize(VUP × N),
// V = N × U, the perspective npcFromVrc with front → z = 1, DC with y down) and a Sutherland–Hodgman
// clipper of the test's own (the lecture notes' 15.3). Nothing of staff/ID/solution.json is read:
// the staff folder gives only assignment.json, the items and their points, from which the expected
// points are computed (scenario by scenario, below) — never by calling the grader.
//
// The scenarios are the mix a real class shows (chosen from the student's index): right; rounded to 3
// decimals (the sheet's precision: full points); decimal commas as text and outcodes as bit strings;
// an unknown key (a warning); one malformed item (its points lost); one wrong leaf value (its item's
// points lost); an honest slip carried through (only the slipped item lost); every matrix in the
// lecture notes' row form (accepted); no submission (0, "no submission"); another student's variant
// (graded against the own: at most the points its values earn there, less than full, the report names
// whose variant it was); a file that is not JSON (0, could not be graded, named with line and column).
// Three topics come as A/ID.json with a CSV roster; clipping as Moodle's grading worksheet and
// "Download all submissions" folders.
//
// Time: the exercises are generated without PDFs — pdflatex is looked up by app/course_kit/
// class_exercise.cpp with `command -v pdflatex` in /bin/sh, so the command runs with a PATH where it
// cannot be found (the sheets' PDFs are checked by other tests). And each variant's figures are
// rendered with llvmpipe, whose shaders are compiled again for every variant when the shader cache is
// off (`vplab` runs with the user's settings; Mesa's default cache is the user's): ~1.6 s a variant. The
// generation runs with a shader cache of its own in the test's fresh folder (compiled once by the
// first variant, then reused: ~0.5 s a variant), which no other test and no later run sees; the
// figures are not what this test checks. Under the sanitizers (the ASan CI
// stage, close to its time limit) the class is 40 instead of 300 (VPLAB_SANITIZED, tests/CMakeLists.txt).
#include "course/roster.h"
#include "tests/course/clip_oracle.h"
#include "tests/support/files.h"
#include "tests/support/process.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using Ptr = Json::json_pointer;
using test::boundary;
using test::clipPass;
using test::jsonOf;
using test::needsCut;
using test::P4;
using test::Polygon;
using test::readFile;
using test::shellQuoted;

#ifdef VPLAB_SANITIZED
constexpr size_t kPerTopic = 10;  // 40 under ASan + UBSan: the whole class there would cost the CI stage minutes
#else
constexpr size_t kPerTopic = 75;  // 300 in all
#endif

const std::string kPolygon = "/objects/0/polygons/0";

// ---------------------------------------------------------------- the test's own pipeline

glm::dvec3 vec3Of(const Json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

// Rows as the answer writes them (p' = M · p: row r is M[.][r] in GLM's column-major storage).
Json rowsOf(const glm::dmat4& m) {
  Json out = Json::array();
  for (int r = 0; r < 4; ++r) out.push_back(Json::array({m[0][r], m[1][r], m[2][r], m[3][r]}));
  return out;
}

int outcodeOf(const P4& p) {
  int code = 0;
  for (int k = 0; k < 6; ++k) code |= boundary(p, k) < 0 ? 1 << k : 0;
  return code;
}
P4 p4Of(const glm::dvec4& v) { return {v.x, v.y, v.z, v.w}; }

struct Pipeline {
  glm::dmat4 wcFromMc{1}, vrcFromWc{1}, npcFromVrc{1}, dcFromNpc{1};
  glm::dvec3 n{}, u{}, v{};
  double vpd = 0;
  std::vector<glm::dvec3> mc;  // the polygon in MC
};

Pipeline pipelineOf(const Json& scene) {
  Pipeline p;
  const Json& cam = scene.at("camera");
  const glm::dvec3 vrp = vec3Of(cam.at("vrp")), prp = vec3Of(cam.at("prp")), vup = vec3Of(cam.at("vup"));
  EXPECT_EQ(cam.value("projection", "perspective"), "perspective");
  const Json& obj = scene.at("objects").at(0);
  for (const Json& v : obj.at("vertices")) p.mc.push_back(vec3Of(v));
  // Modeling: T · R_k · … · R_1 · S (the first rotation listed acts first; one through a point as
  // T(point) · R · T(−point)).
  glm::dmat4 m(1);
  if (obj.contains("translate")) m = glm::translate(m, vec3Of(obj["translate"]));
  if (obj.contains("rotate")) {
    const Json& rs = obj["rotate"];
    for (size_t i = rs.size(); i-- > 0;) {
      const Json& r = rs[i];
      const glm::dmat4 rot = glm::rotate(glm::dmat4(1), glm::radians(r.at("deg").get<double>()), vec3Of(r.at("axis")));
      if (r.contains("through")) {
        const glm::dvec3 c = vec3Of(r["through"]);
        m = m * glm::translate(glm::dmat4(1), c) * rot * glm::translate(glm::dmat4(1), -c);
      } else {
        m = m * rot;
      }
    }
  }
  if (obj.contains("scale"))
    m = glm::scale(m, obj["scale"].is_number() ? glm::dvec3(obj["scale"].get<double>()) : vec3Of(obj["scale"]));
  p.wcFromMc = m;
  // View orientation.
  p.n = glm::normalize(prp - vrp);
  p.u = glm::normalize(glm::cross(vup, p.n));
  p.v = glm::cross(p.n, p.u);
  p.vpd = glm::length(prp - vrp);
  glm::dmat4 rot(1);
  for (int c = 0; c < 3; ++c) rot[c][0] = p.u[c], rot[c][1] = p.v[c], rot[c][2] = p.n[c];
  p.vrcFromWc = rot * glm::translate(glm::dmat4(1), -vrp);
  // View mapping (perspective): x' = (d·x − xmin·ze)/(xmax − xmin), …, z' = dmin·(dmax − ze)/(dmax − dmin), w' = ze.
  const Json& w = cam.at("window");
  const double xmin = w.at("xmin"), xmax = w.at("xmax"), ymin = w.at("ymin"), ymax = w.at("ymax");
  const double d = p.vpd, dmin = d - cam.at("front").get<double>(), dmax = d - cam.at("back").get<double>();
  const double k = dmin / (dmax - dmin);
  glm::dmat4 q(0);  // q[col][row]
  q[0][0] = d / (xmax - xmin), q[2][0] = xmin / (xmax - xmin), q[3][0] = -xmin * d / (xmax - xmin);
  q[1][1] = d / (ymax - ymin), q[2][1] = ymin / (ymax - ymin), q[3][1] = -ymin * d / (ymax - ymin);
  q[2][2] = k, q[3][2] = k * (dmax - d);
  q[2][3] = -1, q[3][3] = d;
  p.npcFromVrc = q;
  // Device mapping: x = W·x, y = H·(1 − y), z = z.
  const double W = scene.at("device").at("width"), H = scene.at("device").at("height");
  glm::dmat4 dc(1);
  dc[0][0] = W, dc[1][1] = -H, dc[3][1] = H;
  p.dcFromNpc = dc;
  return p;
}

// P1's values from its WC (a slip starts there) or from its homogeneous NPC.
void p1FromNpcH(const Pipeline& p, const P4& h, Json& poly) {
  poly["npc_h"] = Json::array({jsonOf(h)});
  Json bc = Json::array();
  for (int k = 0; k < 6; ++k) bc.push_back(boundary(h, k));
  poly["boundary"] = Json::array({bc});
  poly["outcodes"] = Json::array({outcodeOf(h)});
  const glm::dvec4 npc(h[0] / h[3], h[1] / h[3], h[2] / h[3], 1);
  const glm::dvec4 dc = p.dcFromNpc * npc;
  poly["npc"] = Json::array({Json::array({npc.x, npc.y, npc.z})});
  poly["dc"] = Json::array({Json::array({dc.x, dc.y, dc.z})});
}
void p1FromWc(const Pipeline& p, const glm::dvec4& wc, Json& poly) {
  const glm::dvec4 vrc = p.vrcFromWc * wc;
  poly["wc"] = Json::array({Json::array({wc.x, wc.y, wc.z})});
  poly["vrc"] = Json::array({Json::array({vrc.x, vrc.y, vrc.z})});
  p1FromNpcH(p, p4Of(p.npcFromVrc * vrc), poly);
}

Json dcOf(const Pipeline& p, const Polygon& poly) {
  Json out = Json::array();
  for (const P4& v : poly) {
    const glm::dvec4 dc = p.dcFromNpc * glm::dvec4(v[0] / v[3], v[1] / v[3], v[2] / v[3], 1);
    out.push_back(Json::array({dc.x, dc.y, dc.z}));
  }
  return out;
}

// Every value any sheet asks, in the answer's layout.
Json fullAnswerOf(const Pipeline& p) {
  Json a;
  a["objects"][0]["wc_from_mc"] = rowsOf(p.wcFromMc);
  Json& poly = a["objects"][0]["polygons"][0];
  p1FromWc(p, p.wcFromMc * glm::dvec4(p.mc.at(0), 1), poly);
  Polygon h;
  for (const glm::dvec3& v : p.mc) h.push_back(p4Of(p.npcFromVrc * p.vrcFromWc * p.wcFromMc * glm::dvec4(v, 1)));
  for (int k = 0; k < 6; ++k) poly["clip_steps"][size_t(k)]["polygon"] = jsonOf(h = clipPass(h, k));
  poly["clipped_dc"] = dcOf(p, h);
  a["camera"] = {{"n", {p.n.x, p.n.y, p.n.z}}, {"u", {p.u.x, p.u.y, p.u.z}}, {"v", {p.v.x, p.v.y, p.v.z}}, {"vpd", p.vpd}};
  a["matrices"] = {{"vrc_from_wc", rowsOf(p.vrcFromWc)}, {"npc_from_vrc", rowsOf(p.npcFromVrc)}, {"dc_from_npc", rowsOf(p.dcFromNpc)}};
  return a;
}

Polygon polygonOf(const Json& j) {
  Polygon p;
  for (const Json& v : j) p.push_back({v[0].get<double>(), v[1].get<double>(), v[2].get<double>(), v[3].get<double>()});
  return p;
}

// ---------------------------------------------------------------- the class

enum class Scenario { right, rounded3, commas, extraKey, malformed, wrongLeaf, slip, rowForm, none, otherVariant, notJson };
const char* nameOf(Scenario s) {
  switch (s) {
    case Scenario::right: return "right";
    case Scenario::rounded3: return "rounded-3";
    case Scenario::commas: return "commas+bits";
    case Scenario::extraKey: return "extra-key";
    case Scenario::malformed: return "malformed-item";
    case Scenario::wrongLeaf: return "wrong-leaf";
    case Scenario::slip: return "slip-carried";
    case Scenario::rowForm: return "row-form";
    case Scenario::none: return "no-submission";
    case Scenario::otherVariant: return "other-variant";
    default: return "not-json";
  }
}
// 20 slots, the weights of a class: most right in some form, a few of each mistake.
constexpr Scenario kSlots[20] = {Scenario::right,     Scenario::rounded3,  Scenario::commas,       Scenario::extraKey,
                                 Scenario::malformed, Scenario::wrongLeaf, Scenario::slip,         Scenario::rowForm,
                                 Scenario::none,      Scenario::otherVariant, Scenario::notJson,   Scenario::right,
                                 Scenario::rounded3,  Scenario::commas,    Scenario::slip,         Scenario::wrongLeaf,
                                 Scenario::malformed, Scenario::rowForm,   Scenario::right,        Scenario::right};

struct Topic {
  std::string name;
  uint64_t seed;
  std::string prefix;  // of the CSV roster's ids
  bool moodle;         // the roster as Moodle's worksheet, the answers as "Download all submissions"
};

struct Student {
  std::string id, name;
  size_t topic = 0, index = 0;
  Scenario scenario = Scenario::right;
  double maxPoints = 0, expected = 0;
  std::string other;                   // otherVariant: whose variant was handed in
};

class ClassOf300 : public test::ProcessTest {
 protected:
  test::ProcessResult vplab(const std::string& args) { return sh(shellQuoted(VPLAB_EXE) + " " + args); }
};

Json readJson(const fs::path& f) { return Json::parse(readFile(f)); }

double pointsAt(const Json& assignment, const std::string& path) {
  for (const Json& i : assignment.at("items"))
    if (i.at("path") == path) return i.at("points").get<double>();
  return -1;
}
bool hasItem(const Json& assignment, const std::string& path) { return pointsAt(assignment, path) >= 0; }

void roundAll(Json& j) {
  if (j.is_number_float()) j = std::round(j.get<double>() * 1000) / 1000;
  if (j.is_structured())  // (a number iterates as itself)
    for (Json& e : j) roundAll(e);
}
void commasAll(Json& j) {
  if (j.is_number_float()) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f", j.get<double>());
    std::string s = buf;
    for (char& c : s) c = c == '.' ? ',' : c;
    j = s;
  } else if (j.is_number_integer()) {  // only the outcodes are integers: six bits, bit 5 first (as the solution prints them)
    std::string bits;
    for (int b = 5; b >= 0; --b) bits += (j.get<int>() >> b & 1) ? '1' : '0';
    j = bits;
  }
  if (j.is_structured())
    for (Json& e : j) commasAll(e);
}
void transposeMatrices(Json& j) {
  if (j.is_object())
    for (auto& [key, value] : j.items()) {
      if (key == "wc_from_mc" || key == "vrc_from_wc" || key == "npc_from_vrc" || key == "dc_from_npc") {
        Json t = value;
        for (size_t r = 0; r < 4; ++r)
          for (size_t c = 0; c < 4; ++c) t[r][c] = value[c][r];
        value = t;
      } else {
        transposeMatrices(value);
      }
    }
  else if (j.is_array())
    for (Json& e : j) transposeMatrices(e);
}

// The answer a student hands in: the template (students/ID/answer.json) with the item paths filled in
// from `full`.
Json fill(const Json& templ, const Json& assignment, const Json& full, const std::string& who) {
  Json a = templ;
  for (const Json& i : assignment.at("items")) {
    const Ptr at(i.at("path").get<std::string>());
    if (!full.contains(at)) {
      ADD_FAILURE() << who << ": the test's pipeline has no value for " << at.to_string();
      continue;
    }
    a[at] = full[at];
  }
  return a;
}

size_t sameValues(const Json& a, const Json& b) {  // leaves equal within the grader's tolerance
  const Json fa = a.flatten(), fb = b.flatten();
  size_t n = 0;
  for (const auto& [k, v] : fa.items()) {
    if (!fb.contains(k) || !v.is_number() || !fb[k].is_number()) continue;
    const double r = fb[k].get<double>();
    n += std::abs(v.get<double>() - r) <= 1e-3 * std::max(1.0, std::abs(r));
  }
  return n;
}

// The slip of `s.scenario == slip`: one item wrong, everything after it computed right from it.
// Returns the item's path (its points are lost), or "" when no fair slip was found.
std::string slip(const Topic& t, const Pipeline& p, const Json& assignment, Json& full) {
  Json& poly = full[Ptr("/objects/0/polygons/0")];
  const int outcode = poly["outcodes"][0].get<int>();
  if (t.name == "orientation" || t.name == "pipeline") {
    // P1 in WC: a sign or a digit wrong in one coordinate; VRC, NPC … from it. The outcode must stay
    // (a slip that moves P1 in or out of the volume changes which items the sheet asks).
    const glm::dvec4 wc = p.wcFromMc * glm::dvec4(p.mc.at(0), 1);
    for (double d : {0.5, -0.5, 0.25, -0.25, 0.1, -0.1})
      for (int c = 0; c < 3; ++c) {
        glm::dvec4 w = wc;
        w[c] += d;
        Json q = poly;
        p1FromWc(p, w, q);
        if (q["outcodes"][0] == outcode) return poly = q, kPolygon + "/wc/0";
      }
  } else if (t.name == "mapping") {
    const P4 h = polygonOf(poly["npc_h"])[0];
    for (double d : {0.3, -0.3, 0.1, -0.1, 0.05, -0.05})
      for (size_t c = 0; c < 3; ++c) {
        P4 s = h;
        s[c] += d * std::max(1.0, std::abs(h[3]));
        Json q = poly;
        p1FromNpcH(p, s, q);
        if (q["outcodes"][0] == outcode) return poly = q, kPolygon + "/npc_h/0";
      }
  } else {
    // Clipping: in a pass that cuts, one vertex moved (a wrong t, or a slip in interpolating), the
    // later passes and the DC computed right on the slipped polygon. Every later pass must still cut
    // where the key's does (else the slip made the work easier: not this case). Tried: each cutting
    // pass, each vertex of it moved a tenth along its edge to the next.
    Polygon start;
    for (const glm::dvec3& v : p.mc) start.push_back(p4Of(p.npcFromVrc * p.vrcFromWc * p.wcFromMc * glm::dvec4(v, 1)));
    for (int at = 0; at < 6; ++at)
      for (size_t moved = 0; moved < 8; ++moved) {
        Polygon key = start, mine = start;
        Json steps = Json::array();
        bool fair = true, slipped = false;
        for (int k = 0; k < 6 && fair; ++k) {
          const bool keyCuts = needsCut(key, k);
          if (k > at && keyCuts != needsCut(mine, k)) fair = false;
          key = clipPass(key, k);
          mine = clipPass(mine, k);
          if (k == at) {
            if (!keyCuts || moved >= mine.size()) break;
            P4& v = mine[moved];
            const P4& next = mine[(moved + 1) % mine.size()];
            for (size_t j = 0; j < 4; ++j) v[j] += 0.1 * (next[j] - v[j]);
            slipped = true;
          }
          steps.push_back({{"polygon", jsonOf(mine)}});
        }
        if (!fair || !slipped || steps.size() != 6 || mine.size() < 3) continue;
        for (size_t k = 0; k < 6; ++k) poly["clip_steps"][k] = steps[k];
        poly["clipped_dc"] = dcOf(p, mine);
        const std::string path = kPolygon + "/clip_steps/" + std::to_string(at) + "/polygon";
        return hasItem(assignment, path) ? path : "";
      }
  }
  return "";
}

TEST_F(ClassOf300, GradesMatchTheExpectedPointsForEveryStudent) {
  const std::vector<Topic> topics = {{"orientation", 11, "o", false},
                                     {"mapping", 12, "m", false},
                                     {"clipping", 13, "c", true},
                                     {"pipeline", 14, "p", false}};
  std::vector<Student> students;
  double generateSeconds = 0, gradeSeconds = 0;
  using Clock = std::chrono::steady_clock;

  // 1. The rosters and the exercises.
  for (size_t t = 0; t < topics.size(); ++t) {
    const Topic& topic = topics[t];
    std::string roster;
    if (topic.moodle)
      roster = "\xEF\xBB\xBFIdentifier,\"Full name\",\"Email address\",Status,Grade,\"Maximum Grade\",\"Grade can be changed\","
               "\"Last modified (submission)\",\"Last modified (grade)\",\"Feedback comments\"\r\n";
    else
      roster = "id,name\n";
    for (size_t i = 0; i < kPerTopic; ++i) {
      Student s;
      s.topic = t, s.index = i;
      s.scenario = kSlots[(i * 7 + t * 10) % 20];
      char buf[32];
      if (topic.moodle) {
        s.id = std::to_string(1001 + i);
        s.name = "Student " + s.id;
        roster += "\"Participant " + s.id + "\",\"" + s.name + "\",s" + s.id + "@uni.example,\"Submitted for grading\",,10.00,Yes,-,-,\r\n";
      } else {
        std::snprintf(buf, sizeof buf, "%s%03zu", topic.prefix.c_str(), i + 1);
        s.id = buf;
        s.name = "Student " + s.id;
        roster += s.id + "," + s.name + "\n";
      }
      students.push_back(s);
    }
    std::ofstream(dir_ / (topic.name + "-roster.csv"), std::ios::binary) << roster;
  }
  // The four topics two at a time (the machine's two cores), each command's status in its own file.
  std::string generate;
  for (size_t t = 0; t < topics.size(); ++t) {
    const std::string& name = topics[t].name;
    // No PDFs: pdflatex cannot be found on this PATH; a shader cache of the run's own (the head of the file).
    generate += "(PATH=/nonexistent-no-pdflatex MESA_SHADER_CACHE_DISABLE=false MESA_SHADER_CACHE_DIR=mesa-shader-cache " +
                shellQuoted(VPLAB_EXE) + " exercise --topic " + name + " --seed " + std::to_string(topics[t].seed) +
                " --roster " + name + "-roster.csv --out " + name + " >" + name + ".log 2>&1; echo $? >" + name + ".rc) & " +
                (t % 2 == 1 ? "wait; " : "");
  }
  const auto start = Clock::now();
  const auto generated = sh("{ " + generate + "true; }");  // (sh() runs "cd DIR && COMMAND": all of it in DIR)
  generateSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  ASSERT_EQ(generated.exitCode, 0) << generated.err;
  for (size_t t = 0; t < topics.size(); ++t) {
    const std::string& name = topics[t].name;
    ASSERT_EQ(readFile(dir_ / (name + ".rc")), "0\n") << name << ": " << readFile(dir_ / (name + ".log"));
    const std::string& last = students[(t + 1) * kPerTopic - 1].id;
    ASSERT_TRUE(fs::exists(dir_ / name / "staff" / last / "assignment.json")) << name;
    ASSERT_FALSE(fs::exists(dir_ / name / "students" / last / "sheet.pdf")) << name << ": pdflatex was found";
  }

  // 2. The answers, and the points each should earn.
  std::map<std::string, const Student*> byId;
  for (const Student& s : students) byId[s.id] = &s;
  for (Student& s : students) {
    const Topic& topic = topics[s.topic];
    const fs::path ex = dir_ / topic.name;
    const Json assignment = readJson(ex / "staff" / s.id / "assignment.json");
    for (const Json& i : assignment.at("items")) s.maxPoints += i.at("points").get<double>();
    const Pipeline pipe = pipelineOf(readJson(ex / "students" / s.id / "scene.json"));
    Json full = fullAnswerOf(pipe);
    const Json templ = readJson(ex / "students" / s.id / "answer.json");
    const std::string who = topic.name + " " + s.id + " (" + nameOf(s.scenario) + ")";
    std::string text;
    s.expected = s.maxPoints;
    auto lose = [&](const std::string& path) {
      const double pts = pointsAt(assignment, path);
      EXPECT_GT(pts, 0) << who << ": no item " << path;
      s.expected -= pts;
    };
    switch (s.scenario) {
      case Scenario::right: text = fill(templ, assignment, full, who).dump(2); break;
      case Scenario::rounded3: {
        Json a = fill(templ, assignment, full, who);
        roundAll(a);
        text = a.dump(2);
        break;
      }
      case Scenario::commas: {
        Json a = fill(templ, assignment, full, who);
        commasAll(a);
        text = a.dump(2);
        break;
      }
      case Scenario::extraKey: {
        Json a = fill(templ, assignment, full, who);
        a["note"] = "I was not sure about the sign of U";
        text = a.dump(2);
        break;
      }
      case Scenario::malformed: {
        Json a = fill(templ, assignment, full, who);
        if (hasItem(assignment, "/camera/vpd") && s.index % 2 == 0) {
          a["camera"]["vpd"] = Json::array({a["camera"]["vpd"]});  // "vpd": [5]
          lose("/camera/vpd");
        } else {
          const std::string m = hasItem(assignment, "/objects/0/wc_from_mc") ? "/objects/0/wc_from_mc" : "/matrices/dc_from_npc";
          Json& mat = a[Ptr(m)];
          mat.erase(3);
          for (Json& row : mat) row.erase(3);  // a 3 × 3 matrix
          lose(m);
        }
        text = a.dump(2);
        break;
      }
      case Scenario::wrongLeaf: {
        Json a = fill(templ, assignment, full, who);
        // A leaf: nothing on the sheet is computed from it.
        if (hasItem(assignment, kPolygon + "/dc/0")) {
          a[Ptr(kPolygon + "/dc/0/0")] = a[Ptr(kPolygon + "/dc/0/0")].get<double>() + 17;
          lose(kPolygon + "/dc/0");
        } else if (hasItem(assignment, kPolygon + "/clipped_dc")) {
          a[Ptr(kPolygon + "/clipped_dc/0/1")] = a[Ptr(kPolygon + "/clipped_dc/0/1")].get<double>() + 17;
          lose(kPolygon + "/clipped_dc");
        } else if (hasItem(assignment, kPolygon + "/outcodes/0")) {
          a[Ptr(kPolygon + "/outcodes/0")] = a[Ptr(kPolygon + "/outcodes/0")].get<int>() ^ 4;
          lose(kPolygon + "/outcodes/0");
        } else {
          a[Ptr(kPolygon + "/vrc/0/2")] = a[Ptr(kPolygon + "/vrc/0/2")].get<double>() - 1.5;
          lose(kPolygon + "/vrc/0");
        }
        text = a.dump(2);
        break;
      }
      case Scenario::slip: {
        const std::string at = slip(topic, pipe, assignment, full);
        EXPECT_NE(at, "") << who << ": no fair slip found";
        if (!at.empty()) lose(at);
        text = fill(templ, assignment, full, who).dump(2);
        break;
      }
      case Scenario::rowForm: {
        Json a = fill(templ, assignment, full, who);
        transposeMatrices(a);
        text = a.dump(2);
        break;
      }
      case Scenario::none: s.expected = 0; break;
      case Scenario::otherVariant: {
        // The next student of the topic: the values the test computes for that scene, handed in here.
        // Graded against the own variant without follow-through (the values were not worked out from
        // the own data): exactly the items all of whose values coincide with the own.
        const Student& other = students[s.topic * kPerTopic + (s.index + 1) % kPerTopic];
        s.other = other.id;
        const Json otherFull = fullAnswerOf(pipelineOf(readJson(ex / "students" / other.id / "scene.json")));
        text = fill(templ, assignment, otherFull, who).dump(2);
        s.expected = 0;
        for (const Json& i : assignment.at("items")) {
          const Ptr at(i.at("path").get<std::string>());
          if (sameValues(otherFull[at], full[at]) == Json(full[at]).flatten().size()) s.expected += i.at("points").get<double>();
        }
        break;
      }
      case Scenario::notJson: text = "{\"objects\": [{\"wc_from_mc\": [[1, 0, 0, 2],\n   [0, 1, 0 3]]}]\n"; s.expected = 0; break;
    }
    if (s.scenario == Scenario::none) continue;
    fs::path file;
    if (topic.moodle) {
      const fs::path folder = dir_ / (topic.name + "-answers") / (s.name + "_" + s.id + "_assignsubmission_file_");
      fs::create_directories(folder);
      file = folder / "answer.json";
    } else {
      fs::create_directories(dir_ / (topic.name + "-answers"));
      file = dir_ / (topic.name + "-answers") / (s.id + ".json");
    }
    std::ofstream(file, std::ios::binary) << text;
  }

  // 3. Grading, topic by topic, and each grade against the expected points.
  std::map<std::string, std::map<std::string, std::array<double, 4>>> table;  // topic → scenario → n, expected, got, max
  size_t checked = 0;
  for (size_t t = 0; t < topics.size(); ++t) {
    const Topic& topic = topics[t];
    if (topic.moodle) fs::create_directories(dir_ / (topic.name + "-answers"));
    const auto gradeStart = Clock::now();
    const auto r = vplab("grade batch --exercises " + topic.name + " --answers " + topic.name + "-answers --out " + topic.name + "-grades");
    gradeSeconds += std::chrono::duration<double>(Clock::now() - gradeStart).count();
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(readFile(dir_ / (topic.name + "-grades") / "unmatched.txt"), "") << topic.name;
    const CsvTable grades = parseCsv(readFile(dir_ / (topic.name + "-grades") / "grades.csv"), "grades.csv");
    ASSERT_EQ(grades.rows.size(), kPerTopic) << topic.name;
    // student, name, file, status, points, max_points, passed, other_variant, error
    const CsvTable worksheet = parseCsv(readFile(dir_ / (topic.name + "-grades") / "moodle-grading-worksheet.csv"), "worksheet");
    for (const auto& row : grades.rows) {
      const Student& s = *byId.at(row[0]);
      const std::string who = topic.name + " " + s.id + " (" + nameOf(s.scenario) + ")";
      const double got = std::stod(row[4]);
      auto& cell = table[topic.name][nameOf(s.scenario)];
      cell[0] += 1, cell[1] += s.expected, cell[2] += got, cell[3] += s.maxPoints;
      EXPECT_NEAR(std::stod(row[5]), s.maxPoints, 0.005) << who;
      ++checked;
      if (s.scenario == Scenario::otherVariant) {
        EXPECT_NEAR(got, s.expected, 0.005) << who << ": only the items equal to its own earn";
        EXPECT_EQ(row[7], s.other) << who << ": the report should name whose variant it was";
        const Json report = readJson(dir_ / (topic.name + "-grades") / "reports" / (s.id + ".json"));
        EXPECT_EQ(report.value("other_variant", ""), s.other) << who;
      } else {
        EXPECT_NEAR(got, s.expected, 0.005) << who << ": expected " << s.expected << " points, got " << got
                                            << "\n" << readFile(dir_ / (topic.name + "-grades") / "reports" / (s.id + ".txt"));
        EXPECT_EQ(row[7], "") << who;
      }
      if (s.scenario == Scenario::none) {
        EXPECT_EQ(row[3], "no submission") << who;
      } else if (s.scenario == Scenario::notJson) {
        EXPECT_EQ(row[3], "could not be graded") << who;
        EXPECT_NE(row[8].find(".json:2:13: JSON syntax error"), std::string::npos) << who << ": " << row[8];  // line 2, column 13
      } else {
        EXPECT_EQ(row[3], "graded") << who;
      }
      if (s.scenario == Scenario::extraKey) {
        EXPECT_NE(readFile(dir_ / (topic.name + "-grades") / "reports" / (s.id + ".txt")).find("/note"), std::string::npos) << who;
      }
      // The worksheet's Grade (2 decimals) for the Moodle roster.
      if (topic.moodle) {
        bool found = false;
        for (const auto& w : worksheet.rows)
          if (w[0] == "Participant " + s.id) {
            found = true;
            EXPECT_NEAR(std::stod(w[4]), got, 0.005) << who;
          }
        EXPECT_TRUE(found) << who;
      }
    }
  }
  EXPECT_EQ(checked, 4 * kPerTopic);

  // 4. The grade table for the closing note.
  std::printf("\nClassOf300: %zu students, generated in %.1f s, graded in %.1f s\n", checked, generateSeconds, gradeSeconds);
  for (const Topic& topic : topics)
    for (const auto& [scenario, c] : table[topic.name])
      std::printf("  %-12s %-15s %3.0f students  expected %7.2f  got %7.2f  (of %.2f)\n", topic.name.c_str(),
                  scenario.c_str(), c[0], c[1], c[2], c[3]);
  std::fflush(stdout);
}

}  // namespace
}  // namespace vplab
