#include "app/views/student_marks.h"

#include <cmath>

namespace vplab::draw {

namespace {

// Points of one size are drawn together, smaller first: the lab's P1 is a larger translucent halo,
// so that where the student is right their point shows inside it.
constexpr float kStudentPointPx = 12.f;
constexpr float kLabPointPx = 20.f;
glm::vec4 halo(const glm::vec4& c) { return {glm::vec3(c), 0.45f}; }

bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

void points(const std::vector<Vec3>& ps, const glm::vec4& color, float size, Marks& marks) {
  for (const Vec3& p : ps)
    if (finite(p)) marks.point(p, color, size);
}

void polygon(const std::vector<Vec3>& ps, const glm::vec4& color, Marks& marks) {
  for (const Vec3& p : ps)
    if (!finite(p)) return;
  if (ps.size() >= 2) marks.polyline(ps, true, color, theme::kLineWidth + 0.5f, kStudentDashPx);
}

}  // namespace

void studentWorldMarks(const Highlights::Student& s, const theme::Palette& pal, Marks& marks) {
  polygon(s.polygonWc, pal.student, marks);
  if (s.volumeWc.size() == 8) {
    // The twelve edges of the cube, each between corners differing in one coordinate.
    bool ok = true;
    for (const Vec3& c : s.volumeWc) ok &= finite(c);
    for (int i = 0; ok && i < 8; ++i)
      for (int bit : {1, 2, 4})
        if (!(i & bit)) marks.line(s.volumeWc[size_t(i)], s.volumeWc[size_t(i | bit)], pal.student, 1.5f, kStudentDashPx);
  }
  points(s.labWc, halo(pal.probe), kLabPointPx, marks);
  points(s.pointsWc, pal.student, kStudentPointPx, marks);
}

void studentNpcMarks(const Highlights::Student& s, const theme::Palette& pal, Marks& marks) {
  polygon(s.polygonNpc, pal.student, marks);
  points(s.labNpc, halo(pal.probe), kLabPointPx, marks);
  points(s.pointsNpc, pal.student, kStudentPointPx, marks);
}

void studentDcMarks(const Highlights::Student& s, const theme::Palette& pal, const std::function<Vec3(const Vec3&)>& pixels,
                    Marks& marks) {
  std::vector<Vec3> poly;
  for (const Vec3& p : s.polygonDc) poly.push_back(pixels(p));
  polygon(poly, pal.student, marks);
  for (const Vec3& p : s.labDc)
    if (finite(p)) marks.point(pixels(p), halo(pal.probe), kLabPointPx);
  for (const Vec3& p : s.pointsDc)
    if (finite(p)) marks.point(pixels(p), pal.student, kStudentPointPx);
}

}  // namespace vplab::draw
