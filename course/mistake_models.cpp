#include "course/mistake_models.h"

#include "io/dump.h"
#include "pipeline/clipping.h"
#include "base/error.h"

namespace vplab {

using Json = nlohmann::ordered_json;

const std::vector<MistakeModel>& mistakeModels() {
  static const std::vector<MistakeModel> models = {
      {Mistake::transposed, "transposed",
       "a matrix is transposed: the lecture notes' row-vector form (p' = p · M) among matrices in the column form (p' = M · p)",
       "docs/conventions.md \"Notation\"; the matrix panel shows both forms",
       "eine Matrix ist transponiert: die Zeilenvektor-Form der Vorlesung (p' = p · M) zwischen Matrizen in Spaltenform (p' = M · p)",
       "docs/conventions.md „Notation“; das Matrix-Panel zeigt beide Formen"},
      {Mistake::yNotFlipped, "y-not-flipped", "y is not flipped in the device mapping: y_dc = H·y instead of H·(1 − y)",
       "lecture notes 15.2.5: DC has its origin top-left, y down",
       "y wird bei der Gerätetransformation nicht gespiegelt: y_dc = H·y statt H·(1 − y)",
       "Skript 15.2.5: DC hat den Ursprung oben links, y zeigt nach unten"},
      {Mistake::divideFirst, "divide-first",
       "the division by w comes before clipping: points behind the eye flip into view",
       "Hill 7.4 (clipping in homogeneous coordinates) and the divide-first demo (Clipping panel, strategy divide first)",
       "die Division durch w kommt vor dem Clipping: Punkte hinter dem Auge klappen ins Bild",
       "Hill 7.4 (Clipping in homogenen Koordinaten) und die Vorführung im Clipping-Panel (Strategie „erst dividieren“)"},
      {Mistake::frontBackSwapped, "front-back-swapped",
       "front and back planes are swapped: front → z = 0, back → z = 1",
       "lecture notes 15.2.4: front → z = 1, back → z = 0 after mirroring back",
       "vordere und hintere Clippingebene sind vertauscht: vorne → z = 0, hinten → z = 1",
       "Skript 15.2.4: vordere Clippingebene → z = 1, hintere → z = 0 nach dem Zurückspiegeln"},
      {Mistake::leftHandedN, "left-handed-n", "N points from PRP to VRP (VRP − PRP): a left-handed U, V, N",
       "lecture notes 15.2.2: N = (PRP − VRP)/|PRP − VRP|, the eye on +N",
       "N zeigt vom Projektionszentrum zum VRP (VRP − PRP): ein linkshändiges U, V, N",
       "Skript 15.2.2: N = (PRP − VRP)/|PRP − VRP|, das Auge liegt auf +N"},
      {Mistake::degreesAsRadians, "degrees-as-radians", "angles in degrees were used as radians",
       "the scene gives rotations and the oblique φ in degrees",
       "Winkel in Grad wurden als Bogenmaß verwendet",
       "die Szene gibt Drehungen und das schiefe φ in Grad an"},
      {Mistake::obliqueShearSign, "oblique-shear-sign",
       "the oblique shear has the wrong sign: x + z·d·cos φ, y − z·d·sin φ is right",
       "lecture notes 14.3.2: a point behind the view plane moves by (−d·cos φ, d·sin φ)",
       "die schiefe Scherung hat das falsche Vorzeichen: richtig ist x + z·d·cos φ, y − z·d·sin φ",
       "Skript 14.3.2: ein Punkt hinter der Sichtebene verschiebt sich um (−d·cos φ, d·sin φ)"},
      {Mistake::forgotTranslation, "forgot-t-vrp",
       "T(−VRP) is missing: vrcFromWc rotates about the origin instead of moving VRP there first",
       "lecture notes 15.2.2 and docs/conventions.md stage 2: vrcFromWc = R · T(−VRP)",
       "T(−VRP) fehlt: vrcFromWc dreht um den Ursprung, statt zuerst den VRP dorthin zu verschieben",
       "Skript 15.2.2 und docs/conventions.md Stufe 2: vrcFromWc = R · T(−VRP)"},
      {Mistake::outcodeReversed, "outcode-reversed",
       "the outcode's bits are in reverse order: bit 0 is the left plane (x < 0), bit 5 the front plane (z > w)",
       "lecture notes 15.3.2 and docs/conventions.md stage 4: bits left, right, bottom, top, back, front from bit 0",
       "die Bits des Outcodes stehen in umgekehrter Reihenfolge: Bit 0 ist die linke Ebene (x < 0), Bit 5 die vordere (z > w)",
       "Skript 15.3.2 und docs/conventions.md Stufe 4: Bits links, rechts, unten, oben, hinten, vorne ab Bit 0"},
  };
  return models;
}

const MistakeModel& mistakeModel(Mistake m) { return mistakeModels().at(size_t(m)); }

const MistakeModel* mistakeModelOf(std::string_view key) {
  for (const MistakeModel& m : mistakeModels())
    if (m.key == key) return &m;
  return nullptr;
}

namespace {

Json dumpOf(const Scene& scene, ClipStrategy strategy = ClipStrategy::npc) {
  PipelineOptions options;
  options.strategy = strategy;
  return Json::parse(dumpJson(runPipeline(scene, options), -1));
}

void transpose(Json& m) {
  Json t = m;
  for (size_t r = 0; r < 4; ++r)
    for (size_t c = 0; c < 4; ++c) t[r][c] = m[c][r];
  m = t;
}

template <class F>
void forEachPolygon(Json& dump, F&& f) {
  for (Json& o : dump["objects"])
    for (Json& p : o["polygons"]) f(p);
}

}  // namespace

Json referenceDump(const Scene& scene) { return dumpOf(scene); }

Json mistakeDump(const Scene& scene, Mistake m) {
  switch (m) {
    case Mistake::divideFirst: return dumpOf(scene, ClipStrategy::divideFirst);
    case Mistake::leftHandedN: {
      Scene s = scene;
      s.camera.prp = 2.0 * s.camera.vrp - s.camera.prp;
      return dumpOf(s);
    }
    case Mistake::degreesAsRadians: {
      Scene s = scene;
      for (SceneObject& o : s.objects)
        for (Rotation& r : o.transform.rotations) r.deg = r.deg * 180.0 / kPi;
      s.camera.oblique.phiDeg = s.camera.oblique.phiDeg * 180.0 / kPi;
      return dumpOf(s);
    }
    case Mistake::obliqueShearSign: {
      Scene s = scene;
      s.camera.oblique.phiDeg += 180.0;
      return dumpOf(s);
    }
    case Mistake::forgotTranslation: {
      Scene s = scene;
      s.camera.prp = s.camera.prp - s.camera.vrp;
      s.camera.vrp = Vec3(0.0);
      return dumpOf(s);
    }
    default: break;
  }
  Json dump = referenceDump(scene);
  const double height = dump["device"]["height"].get<double>();
  switch (m) {
    case Mistake::transposed:
      for (auto& [key, matrix] : dump["matrices"].items()) transpose(matrix);
      for (Json& o : dump["objects"]) transpose(o["wc_from_mc"]);
      break;
    case Mistake::yNotFlipped:
      dump["matrices"]["dc_from_npc"][1] = Json::array({0.0, height, 0.0, 0.0});
      forEachPolygon(dump, [&](Json& p) {
        for (Json& v : p["clipped_dc"]) v[1] = height - v[1].get<double>();
      });
      break;
    case Mistake::frontBackSwapped: {
      // z' = w − z: row 2 of npcFromVrc becomes row 3 − row 2.
      Json& npc = dump["matrices"]["npc_from_vrc"];
      for (size_t c = 0; c < 4; ++c) npc[2][c] = npc[3][c].get<double>() - npc[2][c].get<double>();
      forEachPolygon(dump, [&](Json& p) {
        for (Json& v : p["npc_h"]) v[2] = v[3].get<double>() - v[2].get<double>();
        for (Json& code : p["outcodes"]) {
          const int c = code.get<int>();
          code = (c & ~0x30) | ((c & 0x10) << 1) | ((c & 0x20) >> 1);  // back (bit 4) ↔ front (bit 5)
        }
        for (Json& v : p["clipped_dc"]) v[2] = 1.0 - v[2].get<double>();
      });
      break;
    }
    case Mistake::outcodeReversed:
      forEachPolygon(dump, [&](Json& p) {
        for (Json& code : p["outcodes"]) {
          const unsigned c = code.get<unsigned>();
          unsigned r = 0;
          for (int bit = 0; bit < kPlaneCount; ++bit) r |= ((c >> bit) & 1u) << (kPlaneCount - 1 - bit);
          code = int(r);
        }
      });
      break;
    default: break;
  }
  return dump;
}

}  // namespace vplab
