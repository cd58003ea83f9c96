// The NPC view's display list: the clipper's polygons, the faded rest, the cube, and the storage of
// its polygon arrays kept from frame to frame.
#include "app/views/theme.h"
#include "app/views/view_geometry.h"
#include "io/scene_io.h"
#include "pipeline/primitives.h"
#include "tests/support/test_util.h"
#include "tests/views/view_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace vplab {
namespace {

using namespace draw;

// The faded rest, two sets an object: its faces inside the grown cube whole, by reference, then
// those the grown cube cuts, as points; every face clipping cut or rejected is in one of them (or
// has nothing left in the grown cube), in face order, as geometry::fadedNpcPolygon makes it.
// Returns how many faces were whole and how many cut.
std::pair<size_t, size_t> expectFadedSets(const PipelineRun& run, const Fill& faded) {
  EXPECT_EQ(faded.polygons.size(), 2 * run.objects.size());
  if (faded.polygons.size() != 2 * run.objects.size()) return {0, 0};
  size_t wholeFaces = 0, cutFaces = 0;
  for (size_t k = 0; k < run.objects.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    const PolygonSet &whole = faded.polygons[2 * k], &cut = faded.polygons[2 * k + 1];
    EXPECT_EQ(whole.npcOf, &o) << o.name;
    EXPECT_TRUE(whole.wholeFaces) << o.name;
    EXPECT_EQ(cut.npcOf, nullptr) << o.name;
    EXPECT_EQ(whole.color, glm::vec3(o.color));
    EXPECT_EQ(cut.color, glm::vec3(o.color));
    size_t w = 0, c = 0;
    ClipScratch clip;
    std::vector<Vec3> scratch;
    for (size_t face = 0; face < o.faceCount(); ++face) {
      if (o.fate[face] == Fate::accepted) continue;
      const std::vector<Vec3> expected = geometry::fadedNpcPolygon(o, face, clip);
      if (expected.size() < 3) continue;
      const bool isWhole = w < whole.polygonCount() && whole.faces[w] == face;
      const PolygonSet& set = isWhole ? whole : cut;
      if ((isWhole ? w : c) >= set.polygonCount()) {
        ADD_FAILURE() << o.name << " face " << face << " is in neither set";
        break;
      }
      const std::span<const Vec3> got = set.polygon(isWhole ? w++ : c++, scratch);
      EXPECT_EQ(std::vector<Vec3>(got.begin(), got.end()), expected) << o.name << " face " << face;
      // A whole face lies in the grown cube (half the cube's size on every side).
      for (const Vec3& p : isWhole ? expected : std::vector<Vec3>{})
        for (int i = 0; i < 3; ++i) {
          EXPECT_GE(p[i], -geometry::kFadedMargin - 1e-12) << o.name << " face " << face;
          EXPECT_LE(p[i], 1 + geometry::kFadedMargin + 1e-12) << o.name << " face " << face;
        }
    }
    EXPECT_EQ(w, whole.polygonCount()) << o.name;
    EXPECT_EQ(c, cut.polygonCount()) << o.name;
    wholeFaces += w;
    cutFaces += c;
  }
  return {wholeFaces, cutFaces};
}

TEST(NpcView, FilledPolygonsAreTheClippersThenTheFadedRest) {
  test::ViewFixture f(defaultScene(), Style::shaded);
  const DisplayList list = npcView(f.input());
  EXPECT_EQ(list.observer.space, Space::npc);
  const auto fills = test::batchesOf<Fill>(list);
  ASSERT_EQ(fills.size(), 2u);
  const Fill &inside = *fills[0], &faded = *fills[1];
  ASSERT_EQ(inside.polygons.size(), f.run.objects.size());
  for (size_t k = 0; k < f.run.objects.size(); ++k) {
    const ObjectRun& o = f.run.objects[k];
    size_t visible = 0, cut = 0;
    for (size_t face = 0; face < o.faceCount(); ++face) {
      visible += !o.clippedFace(face).empty();
      cut += o.fate[face] != Fate::accepted;
    }
    EXPECT_EQ(inside.polygons[k].polygonCount(), visible) << o.name;
    EXPECT_EQ(inside.polygons[k].color, glm::vec3(o.color));
    // The clipper's polygons are the run's, by reference: polygon i is the i-th face left, in NPC.
    EXPECT_EQ(inside.polygons[k].npcOf, &o) << o.name;
    EXPECT_TRUE(inside.polygons[k].points.empty()) << o.name;
    std::vector<Vec3> scratch;
    size_t i = 0;
    for (size_t face = 0; face < o.faceCount(); ++face) {
      if (o.clippedFace(face).empty()) continue;
      std::vector<Vec3> expected;
      for (uint32_t ref : o.clippedFace(face)) expected.push_back(divideByW(o.clippedNpcH(ref)));
      ASSERT_EQ(inside.polygons[k].polygonSize(i), expected.size()) << o.name << " face " << face;
      const std::span<const Vec3> got = inside.polygons[k].polygon(i++, scratch);
      EXPECT_EQ(std::vector<Vec3>(got.begin(), got.end()), expected) << o.name << " face " << face;
    }
  }
  EXPECT_GT(expectFadedSets(f.run, faded).first, 0u);
  EXPECT_TRUE(inside.lit);
  ASSERT_EQ(inside.lights.size(), 1u);  // one white light by the observer's eye
  EXPECT_EQ(inside.lights[0].position, Vec3(list.observer.camera.eyeWc) + Vec3(0.6, 1.2, 0.4));
  EXPECT_FLOAT_EQ(inside.ambient, 0.3f);
  EXPECT_FLOAT_EQ(faded.alpha, theme::kDark.fadedAlpha);
  // The cube's front face is pushed back, behind the cut faces lying in z = 1.
  const auto triangles = test::batchesOf<Triangles>(list);
  ASSERT_FALSE(triangles.empty());
  EXPECT_TRUE(triangles[0]->pushedBack);
  EXPECT_EQ(triangles[0]->depth, Depth::test);
}

// A scene with objects far outside the view volume: faces the grown cube cuts, as points.
TEST(NpcView, FadedFacesTheGrownCubeCutsAreCopiedTheRestReferred) {
  test::ViewFixture f(loadScene(std::string(VPLAB_ASSETS) + "/scenes/clipping-wc-vs-npc.json"), Style::shaded);
  const DisplayList list = npcView(f.input());
  const auto fills = test::batchesOf<Fill>(list);
  ASSERT_EQ(fills.size(), 2u);
  const auto [whole, cut] = expectFadedSets(f.run, *fills[1]);
  EXPECT_GT(whole, 0u);
  EXPECT_GT(cut, 0u);
}

// The outlines are the clipped polygons' edges, each once (two faces share it; new edges are drawn
// apart): the mesh's edges by reference to the run (issue 42), clipped where the strategy clips. Found
// here from the polygons with a plain ordered set; the segments are the same points worked out
// another way (the edge's t against Sutherland–Hodgman's, then the division), so each is matched
// within 1e-12 in the unit cube: a few roundings of values of order 1.
TEST(NpcView, HiddenLineOutlinesEachEdgeOnceOverAnOccluder) {
  for (ClipStrategy strategy : {ClipStrategy::npc, ClipStrategy::wc, ClipStrategy::divideFirst}) {
    SCOPED_TRACE(std::string(nameIn(kClipStrategyNames, strategy)));
    test::ViewFixture f(defaultScene(), Style::hiddenLine);
    f.run = runPipeline(f.scene, {strategy, false, true});
    f.settings.overlays.fadeOutside = false;
    const DisplayList list = npcView(f.input());
    const Fill& occluder = std::get<Fill>(list.batches[0]);
    EXPECT_TRUE(occluder.depthOnly);
    EXPECT_FALSE(occluder.lit);
    const Lines& visible = std::get<Lines>(list.batches[1]);
    const Lines& hidden = std::get<Lines>(list.batches[2]);
    EXPECT_EQ(visible.depth, Depth::test);
    EXPECT_EQ(hidden.depth, Depth::hiddenOnly);
    EXPECT_EQ(hidden.segmentCount(), visible.segmentCount());
    EXPECT_EQ(visible.runEdges.size(), f.run.objects.size()) << "every object's edges by reference";
    auto key = [](Vec3 a, Vec3 b) {
      if (std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z)) std::swap(a, b);
      return std::array<double, 6>{a.x, a.y, a.z, b.x, b.y, b.z};
    };
    std::set<std::array<double, 6>> expected;
    for (const ObjectRun& o : f.run.objects)
      for (size_t face = 0; face < o.faceCount(); ++face) {
        const auto refs = o.clippedFace(face);
        for (size_t i = 0; i < refs.size(); ++i)
          if (!(f.settings.overlays.newEdges && o.fate[face] == Fate::clipped && o.isNewEdge(face, i)))
            expected.insert(key(o.clippedNpc(refs[i]), o.clippedNpc(refs[(i + 1) % refs.size()])));
      }
    const std::vector<Vertex> segments = test::segmentsOf(visible);
    ASSERT_GT(segments.size(), 0u);
    std::vector<std::array<double, 6>> drawn;
    for (size_t i = 0; i + 1 < segments.size(); i += 2) drawn.push_back(key(segments[i].position, segments[i + 1].position));
    EXPECT_EQ(drawn.size(), expected.size()) << "each edge drawn once";
    std::vector<bool> matched(drawn.size(), false);
    for (const auto& e : expected) {
      bool found = false;
      for (size_t d = 0; d < drawn.size() && !found; ++d) {
        double far = 0;
        for (size_t c = 0; c < 6; ++c) far = std::max(far, std::abs(drawn[d][c] - e[c]));
        if (far <= 1e-12 && !matched[d]) found = matched[d] = true;
      }
      EXPECT_TRUE(found) << "edge (" << e[0] << ", " << e[1] << ", " << e[2] << ") – (" << e[3] << ", " << e[4] << ", " << e[5]
                         << ") is not drawn";
    }
  }
}

// In the wire styles what clipping cut away is outlined by reference too: the edges with an end
// outside, each once, as far as they lie in the cube grown by half its size. Against the faded
// polygons (geometry::fadedNpcPolygon, face by face through Sutherland–Hodgman): every vertex of
// theirs outside the cube is an end of a faded segment (within 1e-12: a few roundings in the unit cube).
TEST(NpcView, WireOutlinesWhatWasCutAwayEachEdgeOnce) {
  test::ViewFixture f(defaultScene(), Style::wire);
  ASSERT_TRUE(f.settings.overlays.fadeOutside);
  const DisplayList list = npcView(f.input());
  const Lines* faded = nullptr;
  for (const Lines* l : test::batchesOf<Lines>(list))
    if (!l->runEdges.empty() && l->runEdges[0].fadedPart) faded = l;
  ASSERT_TRUE(faded) << "the faded outlines name the run's edges";
  const std::vector<Vertex> segments = test::segmentsOf(*faded);
  ASSERT_GT(segments.size(), 0u);
  std::set<std::array<double, 6>> drawn;
  for (size_t i = 0; i + 1 < segments.size(); i += 2) {
    const Vec3 &a = segments[i].position, &b = segments[i + 1].position;
    EXPECT_LE(std::max(test::outsideCube(a), test::outsideCube(b)), 0.5 + 1e-9) << "within the grown cube";
    const bool swap = std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z);
    const Vec3 &p = swap ? b : a, &q = swap ? a : b;
    EXPECT_TRUE(drawn.insert({p.x, p.y, p.z, q.x, q.y, q.z}).second) << "segment " << i / 2 << " drawn twice";
  }
  ClipScratch scratch;
  size_t checked = 0;
  for (const ObjectRun& o : f.run.objects)
    for (size_t face = 0; face < o.faceCount(); ++face) {
      if (o.fate[face] == Fate::accepted) continue;
      for (const Vec3& v : geometry::fadedNpcPolygon(o, face, scratch)) {
        if (test::outsideCube(v) <= 1e-9 || test::outsideCube(v) >= 0.5 - 1e-9) continue;  // inside, or cut by the grown cube
        bool found = false;
        for (size_t i = 0; i < segments.size() && !found; ++i) found = glm::length(segments[i].position - v) <= 1e-12;
        EXPECT_TRUE(found) << o.name << " face " << face << ": " << format(v) << " ends no faded segment";
        ++checked;
      }
    }
  EXPECT_GT(checked, 10u);
}

// The GL backend works out a batch's segments in parts ([first, end) of segmentCount()): every cut
// of the range gives the segments of the whole, in order, whichever run's edges a part begins or
// ends in (a part that ended before a run's edges once read far past them).
TEST(NpcView, RunEdgesInPartsAreTheWhole) {
  test::ViewFixture f(defaultScene(), Style::wire);
  const DisplayList list = npcView(f.input());
  size_t batches = 0;
  for (const Lines* l : test::batchesOf<Lines>(list)) {
    if (l->runEdges.size() < 2) continue;
    ++batches;
    const std::vector<Vertex> whole = test::segmentsOf(*l);
    const size_t n = l->segmentCount();
    for (size_t part : {size_t(1), size_t(7), size_t(100), n}) {
      std::vector<Vertex> parts;
      for (size_t first = 0; first < n; first += part) l->segmentsInto(first, std::min(n, first + part), parts);
      ASSERT_EQ(parts.size(), whole.size()) << "parts of " << part;
      for (size_t i = 0; i < whole.size(); ++i) EXPECT_EQ(parts[i].position, whole[i].position) << i;
    }
  }
  EXPECT_GE(batches, 1u);
}

// Where a polygon set keeps its polygons: the run's face numbers, or its own points.
const void* storageOf(const PolygonSet& s) {
  return s.npcOf ? static_cast<const void*>(s.faces.data()) : static_cast<const void*>(s.points.data());
}

// A frame of a large scene must not allocate its polygon arrays anew (as the old renderer kept them).
TEST(NpcView, BuildingIntoThePreviousListKeepsThePolygonArrays) {
  Scene scene = defaultScene();
  scene.objects[3].mesh = std::make_shared<const Mesh>(sphere(90));
  test::ViewFixture f(scene, Style::shaded);
  DisplayList list;
  npcView(f.input(), list);
  std::vector<const void*> before;
  for (const Fill* fill : test::batchesOf<Fill>(list))
    for (const PolygonSet& s : fill->polygons) before.push_back(storageOf(s));
  ASSERT_EQ(before.size(), 3 * f.run.objects.size());  // inside, faded whole and faded cut
  npcView(f.input(), list);
  std::vector<const void*> after;
  for (const Fill* fill : test::batchesOf<Fill>(list))
    for (const PolygonSet& s : fill->polygons) after.push_back(storageOf(s));
  EXPECT_EQ(after, before);
  // and the picture's NPC panel likewise
  Picture picture;
  buildPicture(ViewKind::all, f.input(), picture);
  const void* panel = storageOf(std::get<Fill>(picture.panels[3].list.batches[0]).polygons[3]);
  buildPicture(ViewKind::all, f.input(), picture);
  EXPECT_EQ(storageOf(std::get<Fill>(picture.panels[3].list.batches[0]).polygons[3]), panel);
}

}  // namespace
}  // namespace vplab
