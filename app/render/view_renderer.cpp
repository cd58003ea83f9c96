// Index: 1 construction  2 shared drawing (objects, edges, CPU polygons, lights)
//        3 headless rendering and the "all" composition (the names are in app/views/views.cpp)
#include "app/render/view_renderer.h"

#include "app/views/theme.h"
#include "pipeline/clipping.h"
#include "pipeline/error.h"

#include <algorithm>

namespace vplab {

// ---------------------------------------------------------------- 1 construction

ViewRenderer::ViewRenderer(GlContext& context, float textScale)
    : ctx_(context),
      gl_(context.gl()),
      meshes_(gl_),
      overlay_(gl_),
      text_(std::make_unique<TextRenderer>(gl_, textScale)) {
  for (PolygonBuffer& b : polygonBuffers_) {
    b.vao = gl::makeVertexArray(gl_);
    b.vbo = gl::makeBuffer(gl_);
    gl_.BindVertexArray(b.vao.id());
    gl_.BindBuffer(GL_ARRAY_BUFFER, b.vbo.id());
    gl_.EnableVertexAttribArray(0);
    gl_.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3), nullptr);
    gl_.EnableVertexAttribArray(1);
    gl_.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 2 * sizeof(glm::vec3),
                            reinterpret_cast<void*>(sizeof(glm::vec3)));
  }
  gl_.BindVertexArray(0);
  overlay_.setScale(textScale);  // lines and points grow with the text (lecture mode)
  ctx_.checkErrors("creating the view renderer");
}

void ViewRenderer::setScale(float scale) {
  text_ = std::make_unique<TextRenderer>(gl_, scale);
  overlay_.setScale(scale);
}

// ---------------------------------------------------------------- 2 shared drawing

const gl::Program& ViewRenderer::sceneProgram(bool volumeTest, int lights, bool userPlanes) {
  lights = std::clamp(lights, 0, 4);
  std::optional<gl::Program>& p = scenePrograms_[size_t(volumeTest) + 2 * size_t(lights) + 10 * size_t(userPlanes)];
  if (!p) {
    std::string defines;
    if (volumeTest) defines += "#define VOLUME_TEST\n";
    if (lights > 0) defines += "#define SHADED\n#define LIGHT_COUNT " + std::to_string(lights) + "\n";
    if (userPlanes) defines += "#define USER_PLANES\n";
    p = gl::Program::fromFiles(gl_, {"scene.vert", "scene.frag"}, defines);
  }
  return *p;
}

void ViewRenderer::beginView(gl::RenderTarget& target, const Vec3& background) {
  target.bind();
  gl_.ClearColor(float(background.r), float(background.g), float(background.b), 1.f);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.Disable(GL_BLEND);
  gl_.Disable(GL_CULL_FACE);
}

void ViewRenderer::depthOnly(const std::function<void()>& draw) {
  gl_.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  gl_.Enable(GL_POLYGON_OFFSET_FILL);
  gl_.PolygonOffset(1.f, 2.f);
  draw();
  gl_.Disable(GL_POLYGON_OFFSET_FILL);
  gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void ViewRenderer::setLights(const Scene& scene, const ViewCamera& view) {
  std::vector<Light> lights = scene.lights;
  if (lights.empty()) lights.push_back({scene.camera.prp, {1, 1, 1}});  // a light at the eye
  const int count = int(std::min<size_t>(lights.size(), 4));
  for (int i = 0; i < count; ++i) {
    const std::string k = std::to_string(i);
    scene_->set(("lightPositions[" + k + "]").c_str(), lights[size_t(i)].position);
    scene_->set(("lightColors[" + k + "]").c_str(), lights[size_t(i)].color);
  }
  scene_->set("ambient", 0.28f);
  scene_->set("eyeWc", glm::vec4(view.eyeWc));
}

void ViewRenderer::drawObjects(const Scene& scene, const ViewCamera& view, const ObjectPass& pass) {
  int planes = 0;
  if (pass.userPlanes)
    for (const UserClipPlane& p : scene.clipPlanes) planes += p.enabled;
  planes = std::min(planes, kMaxUserPlanes);
  const int lights = pass.shaded ? int(std::min<size_t>(std::max<size_t>(scene.lights.size(), 1), 4)) : 0;
  const gl::Program& program = sceneProgram(pass.volumeMode != 0, lights, planes > 0);
  // The partitioned inside pass draws each object's faces inside the volume by the margin first,
  // with the program that has no fragment test: without a discard the renderer keeps its early
  // depth test and does not shade what lies behind.
  const gl::Program* early = pass.partitioned && pass.volumeMode == 1 ? &sceneProgram(false, lights, planes > 0) : nullptr;
  auto configure = [&](const gl::Program& chosen) {
    scene_ = &chosen;
    scene_->use();
    scene_->set("vrcFromWc", view.vrcFromWc);
    scene_->set("npcFromVrc", view.npcFromVrc);
    scene_->set("glClipFromNpc", glClipFromNpc());
    scene_->set("volumeMode", pass.volumeMode);
    scene_->set("volumeNpcFromWc", pass.volumeNpcFromWc);
    // The user clip planes in WC (DGL wiki), the same enabled planes the CPU pipeline clips with.
    if (planes > 0) {
      int k = 0;
      for (const UserClipPlane& p : scene.clipPlanes)
        if (p.enabled && k < planes) scene_->set(("userPlanesWc[" + std::to_string(k++) + "]").c_str(), glm::vec4(p.coefficients()));
      scene_->set("userPlaneCount", planes);
    }
    scene_->set("alpha", pass.alpha);
    if (pass.shaded) setLights(scene, view);
  };
  if (early) configure(*early);
  configure(program);
  for (int i = 0; i < kMaxUserPlanes; ++i) (i < planes ? gl_.Enable : gl_.Disable)(GL_CLIP_DISTANCE0 + GLenum(i));
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    if (!o.visible || !o.mesh) continue;
    const Mat4 m = wcFromMc(o.transform);
    const GpuMesh& g = meshes_.get(o.mesh);
    auto setObject = [&] {
      scene_->set("wcFromMc", m);
      scene_->set("wcNormalFromMc", normalMatrix(m));
      scene_->set("color", o.color);
    };
    gl_.BindVertexArray(g.faces.id());
    const VolumePart* part = pass.partitioned && pass.volumeMode != 0 && i < volumeParts_.size() && volumeParts_[i].valid
                                 ? &volumeParts_[i]
                                 : nullptr;
    if (!part) {
      setObject();
      gl_.DrawElements(GL_TRIANGLES, g.faceIndexCount, GL_UNSIGNED_INT, nullptr);
      continue;
    }
    // The VAO's element buffer is the part's until restored below.
    auto drawPart = [&](size_t list) {
      if (part->count[list] == 0) return;
      gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, part->indices[list].id());
      gl_.DrawElements(GL_TRIANGLES, part->count[list], GL_UNSIGNED_INT, nullptr);
    };
    if (early && part->count[kInsideFaces] > 0) {
      scene_ = early;
      scene_->use();
      setObject();
      drawPart(kInsideFaces);
      scene_ = &program;
      scene_->use();
    }
    setObject();
    drawPart(pass.volumeMode == 1 ? kInsidePass : kOutsidePass);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.faceIndices.id());
  }
  gl_.BindVertexArray(0);
  for (int i = 0; i < planes; ++i) gl_.Disable(GL_CLIP_DISTANCE0 + GLenum(i));
}

void ViewRenderer::partitionByVolume(const Scene& scene, const PipelineRun& run) {
  volumeParts_.resize(scene.objects.size());
  for (VolumePart& p : volumeParts_) p.valid = false;
  // Bits 0–5: the vertex lies outside plane i by the margin; bit 6: inside every plane by it.
  constexpr uint8_t kInside = 1u << 6;
  // The GPU's value of a boundary coordinate (float matrices, float MC positions, interpolated)
  // differs from the CPU's double by far less than these margins: 1e-3 of the vertex's own
  // coordinates, and 1e-5 of the largest value the float products can reach for this object (the
  // float rounding of the products is about 1e-7 of that).
  constexpr double kRelativeMargin = 1e-3, kProductMargin = 1e-5;
  for (size_t k = 0; k < run.objects.size() && k < run.sceneIndex.size(); ++k) {
    const ObjectRun& o = run.objects[k];
    const size_t i = run.sceneIndex[k];
    if (i >= scene.objects.size()) continue;
    const SceneObject& so = scene.objects[i];
    if (!so.visible || so.mesh != o.mesh || !o.mesh || o.npcH.size() != o.mesh->vertexCount() ||
        o.fate.size() != o.mesh->faceCount() || wcFromMc(so.transform) != o.wcFromMc)
      continue;  // not this scene's run of the object: drawn whole
    const Mesh& mesh = *o.mesh;
    double wcMax = 0;
    for (const Vec3& c : bounds(mesh).corners()) {
      const Vec3 wc = transformAffine(o.wcFromMc, c);
      wcMax = std::max({wcMax, std::abs(wc.x), std::abs(wc.y), std::abs(wc.z)});
    }
    double rowMax = 0;
    for (int r = 0; r < 4; ++r) {
      double sum = 0;
      for (int c = 0; c < 4; ++c) sum += std::abs(run.npcFromWc[c][r]);
      rowMax = std::max(rowMax, sum);
    }
    const double productMargin = kProductMargin * rowMax * (wcMax + 1);

    vertexSides_.resize(o.npcH.size());
    for (size_t v = 0; v < o.npcH.size(); ++v) {
      const Vec4& p = o.npcH[v];
      const double margin =
          std::max(kRelativeMargin * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z) + std::abs(p.w)), productMargin);
      const Boundary bc = boundaryCoordinates(p);
      uint8_t sides = kInside;
      for (int b = 0; b < kPlaneCount; ++b) {
        if (bc[size_t(b)] < -margin) sides |= uint8_t(1u << b);
        if (!(bc[size_t(b)] > margin)) sides &= uint8_t(~kInside);  // NaN: not inside either
      }
      vertexSides_[v] = sides;
    }
    // Face f's corners are the GPU vertices faceStart[f] … (GpuMesh), fanned from the first.
    size_t capacity = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f) capacity += 3 * (std::max<uint32_t>(mesh.face(f).size(), 2) - 2);
    std::array<uint32_t*, kPartLists> out{};
    for (size_t list = 0; list < kPartLists; ++list) {
      partIndices_[list].resize(capacity);  // scratch: only what the loop writes is read
      out[list] = partIndices_[list].data();
    }
    const uint8_t* sides = vertexSides_.data();
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      const auto face = mesh.face(f);
      uint8_t all = 0xff;
      for (uint32_t v : face) all &= sides[v];
      const bool outsideOnePlane = all & 0x3f, insideAll = all & kInside;
      const uint32_t first = mesh.faceStart[f], n = uint32_t(face.size());
      auto add = [&](size_t list) {
        for (uint32_t c = 1; c + 1 < n; ++c) {
          out[list][0] = first;
          out[list][1] = first + c;
          out[list][2] = first + c + 1;
          out[list] += 3;
        }
      };
      if (insideAll) add(kInsideFaces);  // the inside pass without its fragment test
      else if (!outsideOnePlane) add(kInsidePass);
      if (!insideAll) add(kOutsidePass);
    }
    VolumePart& part = volumeParts_[i];
    for (size_t l = 0; l < kPartLists; ++l) {
      const std::vector<uint32_t>& list = partIndices_[l];  // its first count[l] entries
      part.count[l] = GLsizei(out[l] - list.data());
      if (part.count[l] == 0) continue;
      if (!part.indices[l]) part.indices[l] = gl::makeBuffer(gl_);
      // Bound as an array buffer: the element binding belongs to whichever VAO is bound.
      gl_.BindBuffer(GL_ARRAY_BUFFER, part.indices[l].id());
      const GLsizeiptr bytes = GLsizeiptr(part.count[l]) * GLsizeiptr(sizeof(uint32_t));
      if (bytes > part.capacity[l] || bytes < part.capacity[l] / 4) {
        part.capacity[l] = bytes + bytes / 4;
        gl_.BufferData(GL_ARRAY_BUFFER, part.capacity[l], nullptr, GL_STREAM_DRAW);
      }
      gl_.BufferSubData(GL_ARRAY_BUFFER, 0, bytes, list.data());
    }
    gl_.BindBuffer(GL_ARRAY_BUFFER, 0);
    part.valid = true;
  }
}

// Wire: every edge. Hidden line (seed figures 16.1 and 16.3): the faces fill the depth buffer only,
// pushed back a little so their own edges pass; visible edges solid, hidden ones dashed or not at all.
void ViewRenderer::drawEdges(const Scene& scene, const ViewCamera& view, int width, int height, Style style) {
  const bool hidden = style == Style::hiddenLine || style == Style::hiddenRemoved;
  std::vector<Vec4> planes;
  for (const UserClipPlane& p : scene.clipPlanes)
    if (p.enabled) planes.push_back(p.coefficients());
  overlay_.setUserPlanes(planes);
  if (hidden) {
    depthOnly([&] { drawObjects(scene, view, {0, Mat4(1.0), 1.f, false, true}); });
  }
  gl_.Enable(GL_BLEND);
  gl_.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl_.DepthMask(GL_FALSE);
  struct Pass {
    GLenum depthFunc;
    float dash;
    float alpha;
  };
  std::vector<Pass> passes;
  if (!hidden) passes.push_back({GL_ALWAYS, 0.f, 1.f});
  if (hidden) passes.push_back({GL_LEQUAL, 0.f, 1.f});
  if (style == Style::hiddenLine) passes.push_back({GL_GREATER, theme::kDashPx, 0.8f});
  for (const Pass& p : passes) {
    gl_.DepthFunc(p.depthFunc);
    for (const SceneObject& o : scene.objects) {
      if (!o.visible || !o.mesh) continue;
      const GpuMesh& g = meshes_.get(o.mesh);
      overlay_.drawMeshEdges(g.edges.id(), g.edgeCount, view, wcFromMc(o.transform), width, height,
                             glm::vec4(glm::vec3(o.color), p.alpha), theme::kEdgeWidth, p.dash);
    }
  }
  gl_.DepthFunc(GL_LESS);
  gl_.DepthMask(GL_TRUE);
  overlay_.setUserPlanes({});
}

void ViewRenderer::drawPolygons(const std::vector<PolygonSet>& sets, const ViewCamera& view, const ObjectPass& pass,
                                PolygonSlot slot) {
  // Fan triangulation: a polygon of n corners gives n − 2 triangles, three GPU vertices each.
  std::vector<std::pair<GLint, GLsizei>> ranges;  // per set: first vertex, vertex count
  GLsizei vertices = 0;
  for (const PolygonSet& set : sets) {
    const GLint first = vertices;
    for (size_t k = 0; k < set.ends.size(); ++k) {
      const uint32_t n = set.ends[k] - (k ? set.ends[k - 1] : 0);
      if (n >= 3) vertices += GLsizei(3 * (n - 2));
    }
    ranges.push_back({first, vertices - first});
  }
  if (vertices == 0) return;

  PolygonBuffer& buffer = polygonBuffers_[slot];
  gl_.BindVertexArray(buffer.vao.id());
  gl_.BindBuffer(GL_ARRAY_BUFFER, buffer.vbo.id());
  const GLsizeiptr bytes = GLsizeiptr(vertices) * GLsizeiptr(2 * sizeof(glm::vec3));
  // Storage grows by a quarter more than asked (a scene that grows a little does not reallocate
  // every frame) and shrinks when a quarter of it would do.
  if (bytes > buffer.capacity || bytes < buffer.capacity / 4) {
    buffer.capacity = bytes + bytes / 4;
    gl_.BufferData(GL_ARRAY_BUFFER, buffer.capacity, nullptr, GL_STREAM_DRAW);
  }
  auto* out = static_cast<glm::vec3*>(
      gl_.MapBufferRange(GL_ARRAY_BUFFER, 0, bytes, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT));
  if (!out) throw Error("could not map the polygon buffer (" + std::to_string(bytes) + " bytes)");
  for (const PolygonSet& set : sets) {
    for (size_t k = 0; k < set.ends.size(); ++k) {
      const uint32_t begin = k ? set.ends[k - 1] : 0;
      const std::span<const Vec3> poly(set.points.data() + begin, set.ends[k] - begin);
      if (poly.size() < 3) continue;
      Vec3 n{0};  // Newell's normal
      for (size_t i = 0; i < poly.size(); ++i) {
        const Vec3 &p = poly[i], &q = poly[(i + 1) % poly.size()];
        n += Vec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
      }
      const double len = glm::length(n);
      const glm::vec3 normal = len > 0 ? glm::vec3(n / len) : glm::vec3(0, 0, 1);
      const glm::vec3 corner0(poly[0]);
      for (size_t i = 1; i + 1 < poly.size(); ++i) {
        out[0] = corner0;
        out[1] = normal;
        out[2] = glm::vec3(poly[i]);
        out[3] = normal;
        out[4] = glm::vec3(poly[i + 1]);
        out[5] = normal;
        out += 6;
      }
    }
  }
  gl_.UnmapBuffer(GL_ARRAY_BUFFER);

  scene_ = &sceneProgram(false, pass.shaded ? 1 : 0, false);
  scene_->use();
  scene_->set("wcFromMc", Mat4(1.0));
  scene_->set("wcNormalFromMc", Mat3(1.0));
  scene_->set("vrcFromWc", view.vrcFromWc);
  scene_->set("npcFromVrc", view.npcFromVrc);
  scene_->set("glClipFromNpc", glClipFromNpc());
  scene_->set("volumeMode", 0);
  scene_->set("alpha", pass.alpha);
  scene_->set("lightPositions[0]", Vec3(view.eyeWc) + Vec3(0.6, 1.2, 0.4));
  scene_->set("lightColors[0]", glm::vec3(1));
  scene_->set("ambient", 0.3f);
  scene_->set("eyeWc", glm::vec4(view.eyeWc));
  for (size_t i = 0; i < sets.size(); ++i) {
    if (ranges[i].second == 0) continue;
    scene_->set("color", sets[i].color);
    gl_.DrawArrays(GL_TRIANGLES, ranges[i].first, ranges[i].second);
  }
  gl_.BindVertexArray(0);
}

// ---------------------------------------------------------------- 3 headless rendering

Image ViewRenderer::render(ViewKind kind, const Scene& scene, const PipelineRun& run, const FrameSettings& s,
                           int width, int height) {
  auto one = [&](ViewKind k, int samples) {
    gl::RenderTarget target(gl_);
    target.resize(width, height, samples);
    if (k == ViewKind::camera) drawCamera(scene, run, s, target);
    if (k == ViewKind::world) drawWorld(scene, run, s, target);
    if (k == ViewKind::npc) drawNpc(scene, run, s, target);
    if (k == ViewKind::morph) drawMorph(scene, run, s, target);
    Image image = target.read();
    ctx_.checkErrors("rendering the " + std::string(toString(k)) + " view");
    return image;
  };
  // The camera view is pixel-aligned with DC: no multisampling. The others are antialiased.
  if (kind != ViewKind::all) return one(kind, kind == ViewKind::camera ? 1 : 4);
  return compose(one(ViewKind::camera, 1), one(ViewKind::world, 4), one(ViewKind::npc, 4), width, height);
}

Image ViewRenderer::compose(const Image& camera, const Image& world, const Image& npc, int width, int height) {
  const int titleHeight = int(text_->measure("Ag", TextSize::title).y) + 14;
  const int gap = 6;
  gl::RenderTarget strip(gl_);
  strip.resize(3 * width + 2 * gap, titleHeight, 4);
  strip.bind();
  gl_.ClearColor(theme::kViewBackground.r * 0.7f, theme::kViewBackground.g * 0.7f, theme::kViewBackground.b * 0.7f, 1);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // The long titles where they fit the panel, else the short ones.
  const char* titles[][2] = {{"camera: what the synthetic camera sees (DC)", "camera (DC)"},
                             {"world: scene, camera and view volume (WC)", "world (WC)"},
                             {"npc: after view mapping, clipping and division (NPC)", "NPC"}};
  std::vector<TextLabel> labels;
  for (int i = 0; i < 3; ++i) {
    const bool fits = text_->measure(titles[i][0], TextSize::title).x <= width - 12;
    TextLabel title{{i * (width + gap) + width * 0.5, titleHeight * 0.5}, titles[i][fits ? 0 : 1], theme::kText,
                    TextSize::title, Anchor::center, false};
    title.avoid = false;
    labels.push_back(title);
  }
  text_->draw(labels, strip.width(), strip.height());
  const Image titleImage = strip.read();
  ctx_.checkErrors("drawing the titles");

  Image all(3 * width + 2 * gap, titleHeight + height, Rgba{20, 21, 26, 255});
  blit(titleImage, all, 0, 0);
  blit(camera, all, 0, titleHeight);
  blit(world, all, width + gap, titleHeight);
  blit(npc, all, 2 * (width + gap), titleHeight);
  return all;
}

}  // namespace vplab
