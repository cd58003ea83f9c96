#include "app/course/grade_image.h"

#include "app/render/headless.h"
#include "app/export/cpu_raster.h"
#include "pipeline/error.h"

namespace vplab {

namespace {

Image flipped(const Image& src, bool vertically) {
  Image out(src.width, src.height);
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x)
      out.at(x, y) = vertically ? src.at(x, src.height - 1 - y) : src.at(src.width - 1 - x, y);
  return out;
}

}  // namespace

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
  g.comparison = compareImages(student, g.reference, t.maxDiff);
  g.difference = differenceImage(student, g.reference, t.maxDiff);
  if (g.passed()) return g;
  struct Candidate {
    const char *key, *description, *hint;
    Image picture;
  };
  std::vector<Candidate> candidates;
  candidates.push_back({"upside-down", "the picture is upside down: y was not flipped (GL's window y points up, DC's down)",
                        "lecture notes 15.2.5; read-back rows must be flipped", flipped(g.reference, true)});
  candidates.push_back({"mirrored", "the picture is mirrored left to right: x flipped (U = N × VUP instead of VUP × N, or x_dc = W·(1 − x))",
                        "lecture notes 15.2.2 (U = VUP × N) and 15.2.5 (x_dc = W·x)", flipped(g.reference, false)});
  if (view == ViewKind::camera && style == Style::flat) {
    PipelineOptions options;
    options.strategy = ClipStrategy::divideFirst;
    candidates.push_back({"divide-first", "divided by w before clipping: what lies behind the eye wraps around into view",
                          "Hill 7.4 and the divide-first demo (Clipping panel)",
                          rasterizeClippedPolygons(runPipeline(s, options), s.background, s.device.width, s.device.height)});
  }
  double best = 1e300;
  for (Candidate& c : candidates) {
    // A model whose picture looks like the reference cannot be told apart from a right answer.
    if (t.passes(compareImages(c.picture, g.reference, t.maxDiff))) continue;
    ImageModelResult r{c.key, c.description, c.hint, compareImages(student, c.picture, t.maxDiff), false};
    r.matches = t.passes(r.comparison);
    if (r.matches && r.comparison.meanChannelDelta < best) best = r.comparison.meanChannelDelta, g.mistake = g.models.size();
    g.models.push_back(std::move(r));
  }
  return g;
}

}  // namespace vplab
