#include "pipeline/stage_morph.h"

#include <algorithm>

namespace vplab {

namespace {

Vec3 dcShown(const Vec3& dc, const Device& device) {
  const double h = device.height;
  return {dc.x / h, -dc.y / h, dc.z};
}

}  // namespace

Vec3 morphPosition(const StageValues& v, double t, const Device& device) {
  t = std::clamp(t, 0.0, kMorphEnd);
  if (t <= 1) return glm::mix(v.mc, v.wc, t);
  if (t <= 2) return glm::mix(v.wc, v.vrc, t - 1);
  if (t <= 2.5) return glm::mix(v.vrc, Vec3(v.npcH), (t - 2) * 2);  // the linear part of npcFromVrc
  const Vec3 npc = Vec3(v.npcH) / v.npcH.w;
  if (t <= 3) return Vec3(v.npcH) / glm::mix(1.0, v.npcH.w, (t - 2.5) * 2);  // the division, gradually
  return glm::mix(npc, dcShown(v.dc, device), t - 3);
}

std::string_view morphStageName(double t) {
  constexpr double eps = 1e-6;
  if (std::abs(t - 0) < eps) return "MC";
  if (std::abs(t - 1) < eps) return "WC";
  if (std::abs(t - 2) < eps) return "VRC";
  if (std::abs(t - 2.5) < eps) return "homogeneous NPC (before ÷ w)";
  if (std::abs(t - 3) < eps) return "NPC";
  if (std::abs(t - 4) < eps) return "DC";
  if (t < 1) return "MC → WC";
  if (t < 2) return "WC → VRC";
  if (t < 2.5) return "VRC → homogeneous NPC";
  if (t < 3) return "÷ w: homogeneous NPC → NPC";
  return "NPC → DC";
}

std::string_view morphStepName(double t) {
  if (t < 1) return "wcFromMc";
  if (t < 2) return "vrcFromWc";
  if (t < 2.5) return "npcFromVrc";
  if (t < 3) return "÷ w";
  return "dcFromNpc";
}

}  // namespace vplab
