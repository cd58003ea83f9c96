#include "app/course_kit/grade_image.h"

#include "app/render/headless.h"
#include "app/export/cpu_raster.h"
#include "base/error.h"

#include <algorithm>
#include <cmath>

namespace vplab {

namespace {

// The pictures graded are compared row by row, never copied (issue 38: an 8K picture is 128 MiB):
// the student's picture moved back by a shift, and the models' pictures that flip the reference,
// are each made one row at a time into a row buffer.

/// Row y of `student` moved back by `s` (unshifted's row): outside the student's picture, the reference's.
void unshiftedRow(const Image& student, const Image& reference, ImageShift s, int y, std::vector<Rgba>& out) {
  out.assign(reference.row(y), reference.row(y) + reference.width);
  if (y + s.dy < 0 || y + s.dy >= student.height) return;
  const Rgba* from = student.row(y + s.dy);
  for (int x = std::max(0, -s.dx); x < std::min(reference.width, student.width - s.dx); ++x) out[size_t(x)] = from[x + s.dx];
}

/// Row y of the reference flipped upside down (vertically) or left to right.
const Rgba* flippedRow(const Image& reference, bool vertically, int y, std::vector<Rgba>& buffer) {
  if (vertically) return reference.row(reference.height - 1 - y);
  buffer.assign(reference.row(y), reference.row(y) + reference.width);
  std::reverse(buffer.begin(), buffer.end());
  return buffer.data();
}

// The mean channel difference over the pixels both cover at the shift, on a grid of `stride`.
double meanDifferenceAt(const Image& student, const Image& reference, ImageShift s, int stride) {
  double sum = 0;
  size_t n = 0;
  for (int y = std::max(0, -s.dy); y < std::min(reference.height, reference.height - s.dy); y += stride)
    for (int x = std::max(0, -s.dx); x < std::min(reference.width, reference.width - s.dx); x += stride) {
      const Rgba a = student.at(x + s.dx, y + s.dy), b = reference.at(x, y);
      sum += std::abs(int(a.r) - int(b.r)) + std::abs(int(a.g) - int(b.g)) + std::abs(int(a.b) - int(b.b));
      ++n;
    }
  return n ? sum / (3.0 * double(n)) : 1e300;
}

}  // namespace

ImageShift bestShift(const Image& student, const Image& reference) {
  if (student.width != reference.width || student.height != reference.height) return {};
  // A grid of about 64k samples keeps the search (33 × 33 shifts) under a second at any size.
  const int stride = std::max(1, int(std::sqrt(double(reference.width) * reference.height / 65536.0)));
  const double atZero = meanDifferenceAt(student, reference, {}, stride);
  ImageShift best;
  double bestMean = atZero;
  for (int dy = -kShiftSearch; dy <= kShiftSearch; ++dy)
    for (int dx = -kShiftSearch; dx <= kShiftSearch; ++dx) {
      if (std::abs(dx) * 4 >= reference.width || std::abs(dy) * 4 >= reference.height) continue;
      const double m = meanDifferenceAt(student, reference, {dx, dy}, stride);
      if (m < bestMean - 1e-12 ||
          (m <= bestMean + 1e-12 && std::abs(dx) + std::abs(dy) < std::abs(best.dx) + std::abs(best.dy)))
        bestMean = m, best = {dx, dy};
    }
  return bestMean < 0.5 * atZero ? best : ImageShift{};
}

Image unshifted(const Image& student, const Image& reference, ImageShift s) {
  Image out(reference.width, reference.height);
  std::vector<Rgba> row;
  for (int y = 0; y < reference.height; ++y) {
    unshiftedRow(student, reference, s, y, row);
    std::copy(row.begin(), row.end(), out.row(y));
  }
  return out;
}

ImageGrade gradeImage(ViewRenderer& renderer, const Scene& scene, const Image& student, ViewKind view, Style style,
                      const ImageThresholds& t) {
  if (student.width < 1 || student.height < 1 || student.width > 16384 || student.height > 16384)
    throw Error("the student's image is " + std::to_string(student.width) + " × " + std::to_string(student.height) +
                " pixels; 1 to 16384 each are expected");
  Scene s = scene;
  s.device = {student.width, student.height};
  RenderRequest request;
  request.view = view;
  request.style = style;
  ImageGrade g;
  g.thresholds = t;
  g.reference = renderImage(renderer, s, request);
  g.shift = bestShift(student, g.reference);
  g.shiftTolerated = std::abs(g.shift.dx) <= t.maxShift && std::abs(g.shift.dy) <= t.maxShift;
  // The student's picture at a tolerated shift against the reference, and the difference picture,
  // row by row.
  const ImageShift back = g.shiftTolerated ? g.shift : ImageShift{};
  const int w = g.reference.width, h = g.reference.height;
  RowComparer rows(w, h, t.maxDiff);
  g.difference = Image(w, h);
  std::vector<Rgba> row;
  for (int y = 0; y < h; ++y) {
    unshiftedRow(student, g.reference, back, y, row);
    rows.add(y, row.data(), g.reference.row(y));
    differenceRow(row.data(), g.reference.row(y), w, t.maxDiff, g.difference.row(y));
  }
  g.comparison = std::move(rows).result();
  if (g.passed()) return g;
  // Each model's picture is compared row by row: the flipped references are never made whole, the
  // divide-first raster is made, compared and dropped in turn.
  double best = 1e300;
  auto consider = [&](const char* key, const char* description, const char* hint, const char* descriptionDe,
                      const char* hintDe, const auto& modelRow) {
    // A model whose picture looks like the reference cannot be told apart from a right answer.
    RowComparer asReference(w, h, t.maxDiff), asStudent(w, h, t.maxDiff);
    for (int y = 0; y < h; ++y) {
      const Rgba* m = modelRow(y);
      asReference.add(y, m, g.reference.row(y));
      asStudent.add(y, student.row(y), m);
    }
    if (t.passes(std::move(asReference).result())) return;
    ImageModelResult r{key, description, hint, descriptionDe, hintDe, std::move(asStudent).result(), false};
    r.matches = t.passes(r.comparison);
    if (r.matches && r.comparison.meanChannelDelta < best) best = r.comparison.meanChannelDelta, g.mistake = g.models.size();
    g.models.push_back(std::move(r));
  };
  std::vector<Rgba> flip;
  consider("upside-down", "the picture is upside down: y was not flipped (GL's window y points up, DC's down)",
           "lecture notes 15.2.5; read-back rows must be flipped",
           "das Bild steht auf dem Kopf: y wurde nicht gespiegelt (y im GL-Fenster zeigt nach oben, in DC nach unten)",
           "Skript 15.2.5; zurückgelesene Zeilen müssen gespiegelt werden",
           [&](int y) { return flippedRow(g.reference, true, y, flip); });
  consider("mirrored", "the picture is mirrored left to right: x flipped (U = N × VUP instead of VUP × N, or x_dc = W·(1 − x))",
           "lecture notes 15.2.2 (U = VUP × N) and 15.2.5 (x_dc = W·x)",
           "das Bild ist links-rechts gespiegelt: x gespiegelt (U = N × VUP statt VUP × N, oder x_dc = W·(1 − x))",
           "Skript 15.2.2 (U = VUP × N) und 15.2.5 (x_dc = W·x)",
           [&](int y) { return flippedRow(g.reference, false, y, flip); });
  if (view == ViewKind::camera && style == Style::flat) {
    PipelineOptions options;
    options.strategy = ClipStrategy::divideFirst;
    consider("divide-first", "divided by w before clipping: what lies behind the eye wraps around into view",
             "Hill 7.4 and the divide-first demo (Clipping panel)",
             "vor dem Clipping durch w dividiert: was hinter dem Auge liegt, klappt ins Bild",
             "Hill 7.4 und die Vorführung im Clipping-Panel (Strategie „erst dividieren“)",
             [picture = rasterizeClippedPolygons(runPipeline(s, options), s.background, s.device.width,
                                                 s.device.height)](int y) { return picture.row(y); });
  }
  return g;
}

}  // namespace vplab
