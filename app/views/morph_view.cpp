// The stage morph view (pipeline/stage_morph.h): the visible part of the scene (the CPU clipper's
// polygons) and the view volume move together from MC (t = 0) through WC, VRC, homogeneous NPC and
// NPC to DC (t = 4). The observer keeps its angles and follows the morphing scene to keep it framed.
#include "app/text/catalogue.h"
#include "app/views/batches.h"
#include "app/views/theme.h"
#include "app/views/views.h"

#include "pipeline/stage_morph.h"

#include <cstdio>

namespace vplab {

namespace {

using namespace draw;

// Every stage of a vertex of a clipped polygon. Created vertices exist only in homogeneous NPC;
// the inverse matrices give their other stages exactly.
struct Inverses {
  Mat4 vrcFromNpc, wcFromVrc;
};

StageValues stagesOf(const ObjectRun& o, uint32_t ref, const Inverses& inv, const Mat4& mcFromWc) {
  if (!o.isCreated(ref)) return {o.mesh->positions[ref], o.wc(ref), o.vrc(ref), o.npcH[ref], o.dc(ref)};
  const Vec4 npcH = o.clippedNpcH(ref);
  const Vec4 vrcH = inv.vrcFromNpc * npcH;
  const Vec3 vrc = Vec3(vrcH) / vrcH.w;
  const Vec3 wc = transformAffine(inv.wcFromVrc, vrc);
  return {transformAffine(mcFromWc, wc), wc, vrc, npcH, o.clippedDc(ref)};
}

// The view volume's corners: the unit cube's corners in every stage (no MC: shown at WC for t < 1).
StageValues cornerStages(const PipelineRun& run, const Inverses& inv, int i) {
  const Vec3 npc(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const Vec4 vrcH = inv.vrcFromNpc * Vec4(npc, 1.0);
  const Vec3 vrc = Vec3(vrcH) / vrcH.w;
  const Vec3 wc = transformAffine(inv.wcFromVrc, vrc);
  return {wc, wc, vrc, run.npcFromVrc * Vec4(vrc, 1.0), Vec3(run.dcFromNpc * Vec4(npc, 1.0))};
}

// The stage's name at t in the language: pipeline/stage_morph.h names the stages in English, most
// of them by their symbols alone (MC, WC → VRC), which both languages use.
std::string stageName(double t, Language lang) {
  const std::string_view en = morphStageName(t);
  for (const text::Text name : {text::Text("homogeneous NPC (before ÷ w)"), text::Text("VRC → homogeneous NPC"),
                                text::Text("÷ w: homogeneous NPC → NPC")})
    if (name.english() == en) return name.in(lang);
  return std::string(en);
}

}  // namespace

void morphView(const ViewInput& in, DisplayList& list) {
  const PipelineRun& run = in.run;
  const DisplaySettings& s = in.settings;
  const int w = in.width, h = in.height;
  const float scale = in.text.scale();

  Recycled recycled(list);  // the previous frame's polygon arrays, with their capacity
  list.width = w;
  list.height = h;
  const theme::Palette& pal = theme::palette(in.settings.theme);
  list.background = pal.viewBackground;
  list.antialiased = true;

  const double t = s.morphing.t;
  const Inverses inv{glm::inverse(run.npcFromVrc), run.wcFromVrc};
  std::vector<PolygonSet> sets = recycled.polygonSets(run.objects.size());
  std::vector<Vec3> all;
  Marks lines;
  std::vector<Vec3> poly;
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    const Mat4 mcFromWc = glm::inverse(o.wcFromMc);
    PolygonSet& set = sets[k];
    set.color = glm::vec3(o.color);
    for (size_t f = 0; f < o.faceCount(); ++f) {
      poly.clear();
      for (uint32_t ref : o.clippedFace(f)) poly.push_back(morphPosition(stagesOf(o, ref, inv, mcFromWc), t, run.device));
      if (poly.size() < 3) continue;
      lines.polyline(poly, true, glm::vec4(glm::vec3(o.color) * 0.45f, 1.f), 1.f);
      all.insert(all.end(), poly.begin(), poly.end());
      set.add(poly);
    }
  }
  std::array<Vec3, 8> c;
  for (int i = 0; i < 8; ++i) c[size_t(i)] = morphPosition(cornerStages(run, inv, i), std::max(t, 1.0), run.device);
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) lines.line(c[size_t(i)], c[size_t(i | bit)], pal.frustum, theme::kLineWidth);
  all.insert(all.end(), c.begin(), c.end());

  // The axes of the space the scene is in at t (of the nearest stage), from its origin.
  Vec3 lo = all.empty() ? Vec3(0) : all[0], hi = lo;
  for (const Vec3& p : all) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double axis = 0.25 * std::max(1e-6, glm::length(hi - lo));
  lines.line({0, 0, 0}, {axis, 0, 0}, pal.u, theme::kLineWidth);
  lines.line({0, 0, 0}, {0, t > 3.5 ? -axis : axis, 0}, pal.v, theme::kLineWidth);  // DC's y points down
  lines.line({0, 0, 0}, {0, 0, axis}, pal.n, theme::kLineWidth);
  all.push_back({0, 0, 0});

  const Orbit o = framed(s.morphing.orbit, all, double(w) / h);
  const ViewCamera view = viewCameraOf(observerCamera(o, double(w) / h));
  list.observer = {Space::morph, view};
  Fill polygons;
  polygons.space = Space::morph;
  polygons.polygons = std::move(sets);
  polygons.lit = s.morph.style == Style::shaded;
  if (polygons.lit) polygons.lights = polygonLights(view);
  polygons.ambient = kPolygonAmbient;
  list.add(std::move(polygons));
  lines.emit(list, Space::morph, Depth::xray, scale);

  std::vector<TextLabel> labels;
  char title[160];
  std::snprintf(title, sizeof title, "t = %.2f   %s", t, stageName(t, s.language).c_str());
  // The stage and the step are the view's heading: fixed in its corner, the axes' names place around them.
  const double lineGap = 28.0 * scale;
  labels.push_back({{10, 10}, title, pal.text, TextSize::title, Anchor::topLeft, true, false});
  labels.push_back({{10, 10 + lineGap}, text::fill(s.language, "step: {1}", {morphStepName(std::min(t, 3.999))}),
                    pal.frustum, TextSize::label, Anchor::topLeft, true, false});
  auto axisLabel = [&](const Vec3& p, const char* text, const glm::vec4& color) {
    const Projected q = projectToPixels(view, p, w, h);
    if (q.visible) labels.push_back({q.pixel + Vec2(6, 0) * double(scale), text, color, TextSize::label, Anchor::left, true, true, q.pixel});
  };
  axisLabel({axis, 0, 0}, "x", pal.u);
  axisLabel({0, t > 3.5 ? -axis : axis, 0}, "y", pal.v);
  axisLabel({0, 0, axis}, "z", pal.n);
  list.add(Text{placeLabels(labels, in.text, w, h), pal.labelOutline});
}

DisplayList morphView(const ViewInput& in) {
  DisplayList list;
  morphView(in, list);
  return list;
}

}  // namespace vplab
