// Index: 1 construction and programs  2 lists and pictures  3 fills (meshes, volume partition,
// CPU polygons)  4 lines, points, triangles
#include "app/render/gl_backend.h"

#include "pipeline/clipping.h"
#include "base/error.h"
#include "pipeline/pipeline.h"

#include <algorithm>
#include <string>
#include <utility>
#include <variant>

namespace vplab {

// ---------------------------------------------------------------- 1 construction and programs

GlBackend::GlBackend(GlContext& context, float textScale)
    : ctx_(context),
      gl_(context.gl()),
      es_(gl::dialectOf(context.gl()) == gl::GlslDialect::es300),
      meshes_(gl_),
      overlay_(gl_),
      text_(std::make_unique<TextRenderer>(gl_, textScale)),
      partitions_(gl_) {
  ctx_.checkErrors("creating the GL backend");
}

const gl::Program& GlBackend::sceneProgram(bool volumeTest, int lights, bool userPlanes, bool faceNormal) {
  lights = std::clamp(lights, 0, 4);
  faceNormal = faceNormal && lights > 0;  // unlit, no normal is read
  std::optional<gl::Program>& p =
      scenePrograms_[size_t(volumeTest) + 2 * size_t(lights) + 10 * size_t(userPlanes) + 20 * size_t(faceNormal)];
  if (!p) {
    std::string defines;
    if (volumeTest) defines += "#define VOLUME_TEST\n";
    if (lights > 0) defines += "#define SHADED\n#define LIGHT_COUNT " + std::to_string(lights) + "\n";
    if (userPlanes) defines += "#define USER_PLANES\n";
    if (faceNormal) defines += "#define FACE_NORMAL\n";
    p = gl::Program::fromFiles(gl_, {"scene.vert", "scene.frag"}, defines);
  }
  return *p;
}

void GlBackend::setClipDistances(int planes) {
  if (es_) return;  // the shaders discard by their own distances
  for (int i = 0; i < kMaxUserPlanes; ++i) (i < planes ? gl_.Enable : gl_.Disable)(GL_CLIP_DISTANCE0 + GLenum(i));
}

// ---------------------------------------------------------------- 2 lists and pictures

const ViewCamera& GlBackend::View::cameraFor(draw::Space s) const {
  if (s == space) return observer;
  if (s == draw::Space::pixels) return pixels;
  throw Error("display list: a batch in " + std::string(toString(s)) + " in a view of " +
              std::string(toString(space)) + " (batches are in the observer's space or in pixels)");
}

void GlBackend::draw(const draw::DisplayList& list, gl::RenderTarget& target) {
  Cursor cursor;
  size_t all = SIZE_MAX;
  drawSlice(list, target, cursor, all, polygonBuffers_);
}

bool GlBackend::drawSlice(const draw::DisplayList& list, gl::RenderTarget& target, Cursor& c, size_t& triangles,
                          PolygonBuffers& polygons) {
  // In parts of at most kTrianglesAtOnce, each handed to the rasterizer (glFlush) while the next is
  // binned, and waited for (a fence) before the one after it: llvmpipe keeps every binned triangle
  // (~130 B of setup data) until its scene is rasterized, and binning runs ahead of the rasterizer
  // threads: a 1M-triangle view held ~140 MB of bins besides its CPU polygons' buffer, which now
  // holds two parts (issue 42, heaptrack). Each part waited for at once (glFinish) left the
  // rasterizer threads idle while this thread shaded and binned the next (the NPC view of the
  // million triangles 93 → 72 ms). Parts draw what one slice does (the ViewSlices tests). WebGL gets
  // neither: the browser batches a frame anyway.
  PartFence before(gl_);  // the part before the last one drawn
  for (;;) {
    const size_t given = std::min(triangles, kTrianglesAtOnce);
    size_t part = given;
    const bool done = drawPart(list, target, c, part, polygons);
    triangles -= given - part;
    if (!es_ && part < given) {
      PartFence last(gl_);
      last.put();
      gl_.Flush();
      before.wait();
      before = std::move(last);
    }
    if (done || triangles == 0 || part == given) {
      if (before) gl_.Finish();  // a window's next frame bins more
      return done;
    }
  }
}

GlBackend::PartFence::~PartFence() {
  if (sync_) gl_->DeleteSync(sync_);
}

GlBackend::PartFence& GlBackend::PartFence::operator=(PartFence&& o) noexcept {
  if (this != &o) {
    if (sync_) gl_->DeleteSync(sync_);
    gl_ = o.gl_;
    sync_ = std::exchange(o.sync_, nullptr);
  }
  return *this;
}

void GlBackend::PartFence::put() { sync_ = gl_->FenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0); }

void GlBackend::PartFence::wait() {
  if (!sync_) return;
  GLenum r = GL_TIMEOUT_EXPIRED;
  while (r == GL_TIMEOUT_EXPIRED) r = gl_->ClientWaitSync(sync_, 0, GLuint64(1'000'000'000));  // flushed already
  if (r == GL_WAIT_FAILED) gl_->Finish();
  gl_->DeleteSync(std::exchange(sync_, nullptr));
}

bool GlBackend::drawPart(const draw::DisplayList& list, gl::RenderTarget& target, Cursor& c, size_t& triangles,
                         PolygonBuffers& polygons) {
  View view;
  view.width = target.width();
  view.height = target.height();
  view.samples = target.samples();
  view.space = list.observer.space;
  view.observer = list.observer.camera;
  view.pixels.vrcFromWc = Mat4(1.0);
  view.pixels.npcFromVrc = glm::inverse(dcFromNpc(Device{view.width, view.height}));

  target.bind();
  if (!c.started) {
    c = Cursor{};
    c.started = true;
    c.serial = ++lastSerial_;
    labelsPlaced_.clear();
    gl_.ClearColor(list.background.r, list.background.g, list.background.b, 1.f);
    gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  serial_ = c.serial;
  polygonSlot_ = c.polygonSlot;
  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LESS);
  gl_.Disable(GL_BLEND);
  gl_.Disable(GL_CULL_FACE);

  std::vector<const draw::Batch*> marks;  // a run of x-ray batches, drawn together
  auto flush = [&] {
    if (!marks.empty()) drawMarks(marks, draw::Depth::xray, view);
    marks.clear();
  };
  // A slice ends only inside a fill, mesh edges or a batch of marks that is no x-ray, after the x-ray
  // run before it was drawn: the next slice starts at that batch with nothing of an x-ray run pending.
  for (size_t i = c.batch; i < list.batches.size(); ++i) {
    const draw::Batch& b = list.batches[i];
    if (const auto* fill = std::get_if<draw::Fill>(&b)) {
      flush();
      if (!drawFill(*fill, view, c, triangles, polygons)) {
        c.batch = i;
        c.polygonSlot = polygonSlot_;
        return false;
      }
      c.mesh = 0;
      c.pass = 0;
      c.index = 0;
    } else if (const auto* text = std::get_if<draw::Text>(&b)) {
      flush();
      text_->draw(text->labels, text->outline, view.width, view.height);
      labelsPlaced_.insert(labelsPlaced_.end(), text_->placed().begin(), text_->placed().end());
    } else {
      draw::Depth depth = draw::Depth::ignore;
      std::visit([&](const auto& m) {
        if constexpr (!std::is_same_v<std::decay_t<decltype(m)>, draw::Fill> &&
                      !std::is_same_v<std::decay_t<decltype(m)>, draw::Text>)
          depth = m.depth;
      }, b);
      const auto* lines = std::get_if<draw::Lines>(&b);
      auto stop = [&] {
        c.batch = i;
        c.polygonSlot = polygonSlot_;
        return false;
      };
      if (lines && !lines->meshEdges.empty() && c.primitive == 0) {
        flush();
        if (!drawMeshEdges(*lines, view, c, triangles)) return stop();
        c.mesh = 0;
        c.pass = 0;
        c.index = 0;
        if (lines->segmentCount() == 0) continue;
      }
      if (depth == draw::Depth::xray) {
        marks.push_back(&b);
        continue;
      }
      flush();
      if (!drawMarksSlice(b, depth, view, c, triangles)) return stop();
      c.primitive = 0;
    }
  }
  flush();
  c.batch = list.batches.size();
  c.polygonSlot = polygonSlot_;
  return true;
}

Image GlBackend::render(const draw::Picture& picture) {
  const glm::vec3 bg = glm::clamp(picture.background, 0.f, 1.f) * 255.f + 0.5f;
  Image out(picture.width, picture.height, Rgba{uint8_t(bg.r), uint8_t(bg.g), uint8_t(bg.b), 255});
  for (const draw::Panel& panel : picture.panels) {
    gl::RenderTarget target(gl_);
    target.resize(panel.list.width, panel.list.height, panel.list.antialiased ? 4 : 1);
    draw(panel.list, target);
    blit(target.read(), out, panel.x, panel.y);
  }
  return out;
}

// ---------------------------------------------------------------- 3 fills

void GlBackend::setFillProgram(const gl::Program& p, const draw::Fill& fill, const ViewCamera& camera, int planes) {
  p.use();
  p.set("vrcFromWc", camera.vrcFromWc);
  p.set("npcFromVrc", camera.npcFromVrc);
  p.set("glClipFromNpc", glClipFromNpc());
  p.set("volumeMode", int(fill.volume.keep == draw::VolumeTest::Keep::inside   ? 1
                          : fill.volume.keep == draw::VolumeTest::Keep::outside ? 2
                                                                                : 0));
  p.set("volumeNpcFromWc", fill.volume.npcFromSpace);
  for (int k = 0; k < planes; ++k)
    p.set(("userPlanesWc[" + std::to_string(k) + "]").c_str(), glm::vec4(fill.clipPlanes[size_t(k)]));
  if (planes > 0) p.set("userPlaneCount", planes);
  p.set("alpha", fill.alpha);
  if (fill.lit) {
    const int count = int(std::min<size_t>(fill.lights.size(), 4));
    for (int i = 0; i < count; ++i) {
      const std::string k = std::to_string(i);
      p.set(("lightPositions[" + k + "]").c_str(), fill.lights[size_t(i)].position);
      p.set(("lightColors[" + k + "]").c_str(), fill.lights[size_t(i)].color);
    }
    p.set("ambient", fill.ambient);
    p.set("eyeWc", glm::vec4(camera.eyeWc));
  }
}

bool GlBackend::drawFill(const draw::Fill& fill, const View& view, Cursor& cursor, size_t& triangles,
                         PolygonBuffers& polygons) {
  const ViewCamera& camera = view.cameraFor(fill.space);
  const bool blended = fill.alpha < 1.f && !fill.depthOnly;
  if (fill.depthOnly) {  // lecture notes 16.1: the faces fill only the depth buffer, pushed back
    gl_.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl_.Enable(GL_POLYGON_OFFSET_FILL);
    gl_.PolygonOffset(1.f, 2.f);
  }
  if (blended) {
    // Colour blended over what is there; alpha accumulated (1 over the opaque background), so a
    // PNG of a view is opaque everywhere and looks the same on a slide of any colour.
    gl_.Enable(GL_BLEND);
    gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl_.DepthMask(GL_FALSE);
  }
  bool drawn = cursor.pass == 2 || fill.meshes.empty() || drawMeshes(fill, camera, view.samples, cursor, triangles);
  if (drawn && !fill.polygons.empty()) drawn = drawPolygons(fill, camera, cursor, triangles, polygons);
  if (blended) {
    gl_.DepthMask(GL_TRUE);
    gl_.Disable(GL_BLEND);
  }
  if (fill.depthOnly) {
    gl_.Disable(GL_POLYGON_OFFSET_FILL);
    gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  return drawn;
}

bool GlBackend::drawMeshes(const draw::Fill& fill, const ViewCamera& camera, int samples, Cursor& c,
                           size_t& triangles) {
  const int planes = int(std::min<size_t>(fill.clipPlanes.size(), size_t(kMaxUserPlanes)));
  const int lights = fill.lit ? int(std::clamp<size_t>(fill.lights.size(), 1, 4)) : 0;
  const bool volume = fill.volume.keep != draw::VolumeTest::Keep::all;
  const gl::Program& program = sceneProgram(volume, lights, planes > 0);
  // Partitioned (single-sampled targets only: with multisampling a fragment's inputs are evaluated
  // at the pixel centre even where the triangle covers only some samples, beyond any vertex margin).
  const bool partitioned = partitioned_ && volume && samples == 1;
  // The inside pass draws the faces inside the volume by the margin first, with the program that
  // has no fragment test: without a discard the renderer keeps its early depth test.
  const gl::Program* early =
      partitioned && fill.volume.keep == draw::VolumeTest::Keep::inside ? &sceneProgram(false, lights, planes > 0) : nullptr;
  if (early) setFillProgram(*early, fill, camera, planes);
  setFillProgram(program, fill, camera, planes);
  setClipDistances(planes);
  bool done = true;
  for (size_t i = c.mesh; i < fill.meshes.size() && done; ++i) {
    if (i != c.mesh) {
      c.mesh = i;
      c.pass = 0;
      c.index = 0;
    }
    const draw::MeshInstance& m = fill.meshes[i];
    if (!m.mesh) continue;
    // A mesh not on the GPU yet goes there first, as much of it as the slice's triangles allow (a
    // million triangles took a second of one frame in the page).
    const GpuMesh* uploaded = meshes_.upload(m.mesh, triangles);
    if (!uploaded) {
      done = false;
      break;
    }
    const GpuMesh& g = *uploaded;
    // Draws the elements [c.index, …) of a list kept per chunk (chunk k's `count(k)` elements, at 0
    // in `elements(k)`, or in the chunk's own index buffer for 0), as many triangles as are left.
    auto drawList = [&](auto count, auto elements) {
      GLsizei start = 0;
      for (size_t k = 0; k < g.chunks.size(); ++k) {
        const GLsizei end = start + count(k), begin = std::max(c.index, start), local = begin - start;
        start = end;
        if (begin >= end) continue;
        if (triangles == 0) return false;
        const size_t now = std::min(size_t(end - begin) / 3, triangles);
        const GLuint own = g.chunks[k].indices.id(), list = elements(k);
        gl_.BindVertexArray(g.chunks[k].vao.id());
        if (list) gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, list);  // the VAO's until restored
        const GpuMeshChunk& chunk = g.chunks[k];  // its lists' indices are as wide as its own
        gl_.DrawElements(GL_TRIANGLES, GLsizei(3 * now), chunk.indexType,
                         reinterpret_cast<const void*>(size_t(local) * chunk.indexSize()));
        if (list) gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, own);
        c.index = begin + GLsizei(3 * now);
        triangles -= now;
        if (c.index < end) return false;
      }
      return true;
    };
    const gl::Program* current = &program;
    auto setObject = [&] {
      current->set("wcFromMc", m.spaceFromMc);
      current->set("wcNormalFromMc", normalMatrix(m.spaceFromMc));
      current->set("color", glm::vec3(m.color));
    };
    using Part = VolumePartitions::Part;
    const Part* part = partitioned && m.run ? partitions_.get(serial_, i, m, fill.volume.npcFromSpace, g, triangles) : nullptr;
    if (!part) {
      setObject();
      done = drawList([&](size_t k) { return g.indexStart[k + 1] - g.indexStart[k]; }, [](size_t) { return GLuint(0); });
      continue;
    }
    if (!part->ready()) {  // the slice's budget went into the partition
      done = false;
      break;
    }
    auto listOf = [&](VolumePartitions::List l) {
      return std::pair([part, l](size_t k) { return part->chunks[k].count[l]; },
                       [part, l](size_t k) { return part->chunks[k].indices[l].id(); });
    };
    if (c.pass == 0) {
      if (early && part->count(VolumePartitions::kInsideFaces) > 0) {
        current = early;
        current->use();
        setObject();
        const auto [count, elements] = listOf(VolumePartitions::kInsideFaces);
        done = drawList(count, elements);
        current = &program;
        current->use();
      }
      if (done) {
        c.pass = 1;
        c.index = 0;
      }
    }
    const auto list = fill.volume.keep == draw::VolumeTest::Keep::inside ? VolumePartitions::kInsidePass : VolumePartitions::kOutsidePass;
    if (done && part->count(list) > 0) {
      setObject();
      const auto [count, elements] = listOf(list);
      done = drawList(count, elements);
    }
  }
  gl_.BindVertexArray(0);
  setClipDistances(0);
  return done;
}

void* GlBackend::startWriting(GLenum target, GLsizeiptr bytes, GLsizeiptr& capacity) {
  if (bytes > capacity || bytes < capacity / 4) {
    capacity = bytes + bytes / 4;
    gl_.BufferData(target, capacity, nullptr, GL_STREAM_DRAW);
  }
  void* out = nullptr;
  if (es_) {
    polygonStaging_.resize(size_t(bytes));
    out = polygonStaging_.data();
  } else {
    out = gl_.MapBufferRange(target, 0, bytes, GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT);
  }
  if (!out) throw Error("could not map a polygon buffer (" + std::to_string(bytes) + " bytes)");
  return out;
}

void GlBackend::doneWriting(GLenum target, GLsizeiptr bytes) {
  if (es_) gl_.BufferSubData(target, 0, bytes, polygonStaging_.data());
  else gl_.UnmapBuffer(target);
}

GlBackend::PolygonBuffer& GlBackend::polygonSlot(const draw::Fill& fill, bool newSlot, PolygonBuffers& polygons) {
  if (!polygons.vertices) polygons.vertices = gl::makeBuffer(gl_);
  if (newSlot && polygonSlot_ >= polygons.slots.size()) {
    PolygonBuffer b{gl::makeVertexArray(gl_), gl::makeBuffer(gl_), 0, gl::makeVertexArray(gl_), gl::makeBuffer(gl_), 0, {}};
    gl_.BindVertexArray(b.vao.id());
    gl_.BindBuffer(GL_ARRAY_BUFFER, b.vbo.id());
    gl_.EnableVertexAttribArray(0);
    gl_.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    gl_.BindVertexArray(b.indexedVao.id());
    gl_.BindBuffer(GL_ARRAY_BUFFER, polygons.vertices.id());
    gl_.EnableVertexAttribArray(0);
    gl_.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.indices.id());  // the vertex array's own binding
    gl_.BindVertexArray(0);
    polygons.slots.push_back(std::move(b));
  }
  if (!newSlot) return polygons.slots[polygonSlot_ - 1];
  PolygonBuffer& slot = polygons.slots[polygonSlot_++];
  writeRunVertices(fill, polygons, slot);
  return slot;
}

void GlBackend::writeRunVertices(const draw::Fill& fill, PolygonBuffers& polygons, PolygonBuffer& slot) {
  // The runs this draw wrote already serve its other fills (the NPC view's faded faces refer to
  // the runs its clipped ones do): written again only for a new draw or a run not among them.
  auto firstVertex = [&](const ObjectRun* run) -> const GLuint* {
    for (const auto& [r, first] : polygons.runs)
      if (r == run) return &first;
    return nullptr;
  };
  bool written = polygons.serial == serial_;
  for (const draw::PolygonSet& set : fill.polygons) written = written && (!set.npcOf || firstVertex(set.npcOf));
  if (!written) {
    if (polygons.serial != serial_) polygons.runs.clear();
    polygons.serial = serial_;
    for (const draw::PolygonSet& set : fill.polygons)
      if (set.npcOf && !firstVertex(set.npcOf)) polygons.runs.push_back({set.npcOf, 0});
    GLuint count = 0;
    for (auto& [run, first] : polygons.runs) {
      first = count;
      count += GLuint(run->vertexCount() + run->createdNpcH.size());
    }
    if (count > 0) {
      gl_.BindBuffer(GL_ARRAY_BUFFER, polygons.vertices.id());
      const GLsizeiptr bytes = GLsizeiptr(count) * GLsizeiptr(sizeof(glm::vec3));
      auto* out = static_cast<glm::vec3*>(startWriting(GL_ARRAY_BUFFER, bytes, polygons.verticesCapacity));
      for (const auto& [run, first] : polygons.runs) {
        const uint32_t n = uint32_t(run->vertexCount() + run->createdNpcH.size());
        for (uint32_t ref = 0; ref < n; ++ref) *out++ = glm::vec3(run->clippedNpc(ref));
      }
      doneWriting(GL_ARRAY_BUFFER, bytes);
    }
  }
  slot.bases.assign(fill.polygons.size(), 0);
  for (size_t i = 0; i < fill.polygons.size(); ++i)
    if (const GLuint* first = fill.polygons[i].npcOf ? firstVertex(fill.polygons[i].npcOf) : nullptr) slot.bases[i] = *first;
}

void GlBackend::uploadPolygons(const draw::Fill& fill, const std::vector<PolygonSegment>& segments, GLsizei vertices,
                               GLsizei indices, PolygonBuffer& slot) {
  if (vertices > 0) {
    gl_.BindBuffer(GL_ARRAY_BUFFER, slot.vbo.id());
    const GLsizeiptr bytes = GLsizeiptr(vertices) * GLsizeiptr(sizeof(glm::vec3));
    auto* out = static_cast<glm::vec3*>(startWriting(GL_ARRAY_BUFFER, bytes, slot.capacity));
    std::vector<Vec3> scratch;
    for (const PolygonSegment& segment : segments) {
      if (segment.indexed) continue;
      const draw::PolygonSet& set = fill.polygons[segment.set];
      for (size_t k = segment.begin; k < segment.end; ++k) {
        const std::span<const Vec3> poly = set.polygon(k, scratch);
        for (size_t i = 1; i + 1 < poly.size(); ++i) {
          *out++ = glm::vec3(poly[0]);
          *out++ = glm::vec3(poly[i]);
          *out++ = glm::vec3(poly[i + 1]);
        }
      }
    }
    doneWriting(GL_ARRAY_BUFFER, bytes);
  }
  if (indices > 0) {
    gl_.BindVertexArray(slot.indexedVao.id());  // the element array buffer is the vertex array's
    const GLsizeiptr bytes = GLsizeiptr(indices) * GLsizeiptr(sizeof(GLuint));
    auto* out = static_cast<GLuint*>(startWriting(GL_ELEMENT_ARRAY_BUFFER, bytes, slot.indicesCapacity));
    for (const PolygonSegment& segment : segments) {
      if (!segment.indexed) continue;
      const draw::PolygonSet& set = fill.polygons[segment.set];
      const GLuint base = slot.bases[segment.set];
      for (size_t k = segment.begin; k < segment.end; ++k) {
        const std::span<const uint32_t> refs = set.refs(k);
        for (size_t i = 1; i + 1 < refs.size(); ++i) {
          *out++ = base + refs[0];
          *out++ = base + refs[i];
          *out++ = base + refs[i + 1];
        }
      }
    }
    doneWriting(GL_ELEMENT_ARRAY_BUFFER, bytes);
  }
}

bool GlBackend::drawPolygons(const draw::Fill& fill, const ViewCamera& camera, Cursor& c, size_t& triangles,
                             PolygonBuffers& polygons) {
  // The polygons of this slice: whole polygons from the cursor's (set c.mesh, polygon c.index) on
  // while the triangles last, at least one. They are fan-triangulated (a polygon of n corners gives
  // n − 2 triangles) into the fill's slot and drawn: a slice writes only its own corners or indices
  // (the clipped polygons of a million triangles were 70 MB of GPU vertices).
  const bool resumed = c.pass == 2;
  size_t set = resumed ? c.mesh : 0, k = resumed ? size_t(c.index) : 0;
  std::vector<PolygonSegment> segments;
  GLsizei vertices = 0, indices = 0;
  bool more = false;  // polygons left for the next slice
  for (; set < fill.polygons.size() && !more; ++set, k = 0) {
    const draw::PolygonSet& s = fill.polygons[set];
    const bool indexed = s.npcOf != nullptr;
    GLsizei& used = indexed ? indices : vertices;
    PolygonSegment segment{set, k, k, indexed, used, 0};
    for (; k < s.polygonCount(); ++k) {
      const size_t n = s.polygonSize(k), t = n >= 3 ? n - 2 : 0;
      if (t > triangles && (vertices + indices > 0 || triangles == 0)) {
        more = true;
        break;
      }
      triangles -= std::min(triangles, t);
      used += GLsizei(3 * t);
    }
    segment.end = k;
    segment.count = used - segment.first;
    if (segment.count > 0) segments.push_back(segment);
    if (more) break;
  }
  if (more) {
    c.pass = 2;
    c.mesh = set;
    c.index = GLsizei(k);
  }
  PolygonBuffer& slot = polygonSlot(fill, !resumed, polygons);
  if (vertices + indices == 0) {  // a slice with no triangles left: only the slot taken
    gl_.BindVertexArray(0);
    return !more;
  }
  uploadPolygons(fill, segments, vertices, indices, slot);
  const int lights = fill.lit ? int(std::clamp<size_t>(fill.lights.size(), 1, 4)) : 0;
  const gl::Program& p = sceneProgram(false, lights, false, true);
  draw::Fill state;  // the fill's uniforms without volume test and user planes (CPU polygons are clipped)
  state.lit = fill.lit;
  state.lights = fill.lights;
  state.ambient = fill.ambient;
  state.alpha = fill.alpha;
  setFillProgram(p, state, camera, 0);
  p.set("wcFromMc", Mat4(1.0));
  p.set("wcNormalFromMc", Mat3(1.0));
  for (const PolygonSegment& segment : segments) {
    p.set("color", fill.polygons[segment.set].color);
    if (segment.indexed) {
      gl_.BindVertexArray(slot.indexedVao.id());
      gl_.DrawElements(GL_TRIANGLES, segment.count, GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(uintptr_t(segment.first) * sizeof(GLuint)));
    } else {
      gl_.BindVertexArray(slot.vao.id());
      gl_.DrawArrays(GL_TRIANGLES, segment.first, segment.count);
    }
  }
  gl_.BindVertexArray(0);
  return !more;
}

// ---------------------------------------------------------------- 4 lines, points, triangles

bool GlBackend::drawMeshEdges(const draw::Lines& lines, const View& view, Cursor& c, size_t& triangles) {
  const ViewCamera& camera = view.cameraFor(lines.space);
  overlay_.setUserPlanes(lines.clipPlanes);
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl_.DepthMask(GL_FALSE);
  // An x-ray draws every instance's hidden part faint first, then the visible part: two passes.
  const bool xray = lines.depth == draw::Depth::xray;
  auto depthOf = [&](int pass) -> std::pair<GLenum, float> {
    switch (lines.depth) {
      case draw::Depth::ignore: return {GL_ALWAYS, 1.f};
      case draw::Depth::hiddenOnly: return {GL_GREATER, 1.f};
      case draw::Depth::xray: return pass == 0 ? std::pair{GLenum(GL_GREATER), draw::kXrayAlpha} : std::pair{GLenum(GL_LEQUAL), 1.f};
      case draw::Depth::test: break;
    }
    return {GL_LEQUAL, 1.f};
  };
  bool drawn = false;  // something in this slice: a slice always draws (or uploads) something
  bool done = true;
  for (; c.pass < (xray ? 2 : 1) && done; ++c.pass, c.mesh = 0) {
    const auto [depthFunc, alphaScale] = depthOf(c.pass);
    gl_.DepthFunc(depthFunc);
    for (; c.mesh < lines.meshEdges.size() && done; ++c.mesh, c.index = 0) {
      const draw::MeshInstance& m = lines.meshEdges[c.mesh];
      if (!m.mesh) continue;
      const size_t before = triangles;
      const GpuMesh* g = meshes_.uploadEdges(m.mesh, triangles);
      drawn = drawn || triangles != before;
      if (!g) {
        done = false;
        break;
      }
      for (const GpuEdgeChunk& chunk : g->edgeChunks) {
        if (c.index >= chunk.first + chunk.count) continue;
        if (triangles < 2 && drawn) {
          done = false;
          break;
        }
        const GLsizei first = c.index - chunk.first;
        const GLsizei count = std::max<GLsizei>(1, GLsizei(std::min<size_t>(size_t(chunk.count - first), triangles / 2)));
        pointEdgesAt(gl_, chunk, first);
        overlay_.drawMeshEdges(chunk.vao.id(), count, camera, m.spaceFromMc, view.width, view.height,
                               glm::vec4(glm::vec3(m.color), m.color.a * alphaScale), lines.widthPx, lines.dashPx);
        triangles -= std::min(triangles, 2 * size_t(count));
        c.index += count;
        drawn = true;
      }
      if (c.index < g->edgeCount) done = false;
      if (!done) break;
    }
    if (!done) break;
  }
  gl_.DepthFunc(GL_LESS);
  gl_.DepthMask(GL_TRUE);
  overlay_.setUserPlanes({});
  return done;
}

bool GlBackend::drawMarksSlice(const draw::Batch& b, draw::Depth depth, const View& view, Cursor& c,
                               size_t& triangles) {
  // A line or a point is a quad: two triangles. At least one primitive a slice.
  size_t count = 0, cost = 2;
  if (const auto* l = std::get_if<draw::Lines>(&b)) count = l->segmentCount();
  else if (const auto* p = std::get_if<draw::Points>(&b)) count = p->points.size();
  else if (const auto* t = std::get_if<draw::Triangles>(&b)) count = t->vertices.size() / 3, cost = 1;
  const size_t first = std::min(c.primitive, count);
  const size_t end = first + std::min(count - first, std::max<size_t>(1, triangles / cost));
  // In parts of at most kMarksAtOnce: the overlay's vertices of a million edges are not made at once
  // (56 MB beside the list's run they are read from, issue 42). The order, and so every pixel, is kept.
  for (size_t part = first; part < end; part += kMarksAtOnce)
    drawMarks({&b}, depth, view, part, std::min(end, part + kMarksAtOnce));
  triangles -= std::min(triangles, cost * (end - first));
  c.primitive = end;
  return end >= count;
}

void GlBackend::drawMarks(const std::vector<const draw::Batch*>& batches, draw::Depth depth, const View& view,
                          size_t first, size_t end) {
  OverlayBatch marks;
  std::optional<draw::Space> space;
  bool pushedBack = false;
  auto useSpace = [&](draw::Space s) {
    if (space && *space != s) throw Error("display list: an x-ray run of batches in two spaces");
    space = s;
  };
  for (const draw::Batch* b : batches) {
    if (const auto* l = std::get_if<draw::Lines>(b)) {
      useSpace(l->space);
      segmentScratch_.clear();
      l->segmentsInto(first, end, segmentScratch_);
      for (size_t i = 0; i + 1 < segmentScratch_.size(); i += 2)
        marks.line(segmentScratch_[i].position, segmentScratch_[i + 1].position, segmentScratch_[i].color, l->widthPx,
                   l->dashPx);
    } else if (const auto* p = std::get_if<draw::Points>(b)) {
      useSpace(p->space);
      for (size_t i = first; i < p->points.size() && i < end; ++i)
        marks.point(p->points[i].position, p->points[i].color, p->sizePx);
    } else if (const auto* t = std::get_if<draw::Triangles>(b)) {
      useSpace(t->space);
      pushedBack = pushedBack || t->pushedBack;
      for (size_t i = 3 * first; i + 2 < t->vertices.size() && i / 3 < end; i += 3)
        marks.triangle(t->vertices[i].position, t->vertices[i + 1].position, t->vertices[i + 2].position,
                       t->vertices[i].color);
    }
  }
  if (marks.empty() || !space) return;
  if (pushedBack) {  // loses every depth tie (the NPC cube's front face in z = 1)
    gl_.Enable(GL_POLYGON_OFFSET_FILL);
    gl_.PolygonOffset(1.f, 2.f);
  }
  const OverlayDepth d = depth == draw::Depth::ignore       ? OverlayDepth::ignore
                         : depth == draw::Depth::test       ? OverlayDepth::test
                         : depth == draw::Depth::hiddenOnly ? OverlayDepth::hiddenOnly
                                                            : OverlayDepth::xray;
  overlay_.draw(marks, view.cameraFor(*space), view.width, view.height, d);
  if (pushedBack) gl_.Disable(GL_POLYGON_OFFSET_FILL);
}

}  // namespace vplab
