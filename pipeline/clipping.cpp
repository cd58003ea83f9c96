#include "pipeline/clipping.h"

namespace vplab {

std::string_view planeName(int plane) {
  static constexpr std::string_view names[] = {"left",         "right",        "bottom",       "top",
                                               "back",         "front",        "user plane 1", "user plane 2",
                                               "user plane 3", "user plane 4", "user plane 5", "user plane 6"};
  return names[plane];
}

std::string_view planeInequality(int plane) {
  static constexpr std::string_view names[] = {"x ≥ 0", "x ≤ w", "y ≥ 0", "y ≤ w", "z ≥ 0", "z ≤ w"};
  return plane < kPlaneCount ? names[plane] : "a·x + b·y + c·z + d ≥ 0 (WC)";
}

ClipValues clipValues(const Boundary& cube, std::span<const double> user) {
  ClipValues v;
  for (int i = 0; i < kPlaneCount; ++i) v[size_t(i)] = cube[size_t(i)];
  for (int i = 0; i < kMaxUserPlanes; ++i) v[size_t(kPlaneCount + i)] = size_t(i) < user.size() ? user[size_t(i)] : 1.0;
  return v;
}

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
  ClipVertex v;
  v.p = a.p + t * (b.p - a.p);
  for (int i = 0; i < kMaxClipPlanes; ++i) v.bc[i] = a.bc[i] + t * (b.bc[i] - a.bc[i]);
  v.source = ClipVertex::kCreated;
  v.onPlanes = a.onPlanes & b.onPlanes;
  return v;
}

namespace {

// The new vertex on the edge from an inside vertex to an outside one, snapped onto the plane:
// its boundary value is exactly 0 (its coordinates are snapped by the caller, who knows the space).
ClipVertex intersect(const ClipVertex& inside, const ClipVertex& outside, int plane) {
  const double t = inside.bc[plane] / (inside.bc[plane] - outside.bc[plane]);
  ClipVertex v = lerp(inside, outside, t);
  v.bc[plane] = 0;
  v.onPlanes |= uint16_t(1u << plane);
  return v;
}

}  // namespace

void clipPolygonAgainstPlane(std::span<const ClipVertex> in, int plane, std::vector<ClipVertex>& out) {
  out.clear();
  if (in.empty()) return;
  const ClipVertex* s = &in.back();
  for (const ClipVertex& p : in) {
    const bool sInside = s->bc[plane] >= 0;
    const bool pInside = p.bc[plane] >= 0;
    // An inside endpoint exactly on the plane is its own intersection: it is not created twice.
    if (pInside) {
      if (!sInside && p.bc[plane] > 0) out.push_back(intersect(p, *s, plane));
      out.push_back(p);
    } else if (sInside && s->bc[plane] > 0) {
      out.push_back(intersect(*s, p, plane));
    }
    s = &p;
  }
}

std::span<const ClipVertex> clipPolygon(Outcode planes, ClipScratch& scratch) {
  std::vector<ClipVertex>* in = &scratch.a;
  std::vector<ClipVertex>* out = &scratch.b;
  for (int plane = 0; plane < kMaxClipPlanes && in->size() >= 3; ++plane) {
    if (!(planes >> plane & 1)) continue;
    clipPolygonAgainstPlane(*in, plane, *out);
    std::swap(in, out);
  }
  if (in->size() < 3) return {};
  return *in;
}

EdgeRange clipEdge(const ClipValues& bc0, const ClipValues& bc1, Outcode planes) {
  EdgeRange r;
  for (int plane = 0; plane < kMaxClipPlanes; ++plane) {
    if (!(planes >> plane & 1)) continue;
    const double b0 = bc0[plane], b1 = bc1[plane];
    if (b0 < 0 && b1 < 0) return {0, 0, false};
    if (b0 < 0) r.t0 = std::max(r.t0, b0 / (b0 - b1));  // entering
    else if (b1 < 0) r.t1 = std::min(r.t1, b0 / (b0 - b1));  // leaving
  }
  r.visible = r.t0 <= r.t1;
  return r;
}

namespace {

ClipVertex formVertex(const Vec4& p, std::span<const Vec4> forms, uint32_t source) {
  ClipVertex v{p, {}, source};
  v.bc.fill(1.0);
  for (size_t k = 0; k < forms.size(); ++k) v.bc[k] = glm::dot(forms[k], p);
  return v;
}

Outcode allForms(size_t count) { return Outcode((1u << count) - 1); }

}  // namespace

std::vector<Vec4> clipPolygonByForms(std::span<const Vec4> polygon, std::span<const Vec4> forms, ClipScratch& scratch) {
  scratch.a.clear();
  for (size_t i = 0; i < polygon.size(); ++i) scratch.a.push_back(formVertex(polygon[i], forms, uint32_t(i)));
  std::vector<Vec4> out;
  for (const ClipVertex& c : clipPolygon(allForms(forms.size()), scratch)) out.push_back(c.p);
  return out;
}

EdgeRange clipEdgeByForms(const Vec4& a, const Vec4& b, std::span<const Vec4> forms) {
  return clipEdge(formVertex(a, forms, 0).bc, formVertex(b, forms, 1).bc, allForms(forms.size()));
}

}  // namespace vplab
