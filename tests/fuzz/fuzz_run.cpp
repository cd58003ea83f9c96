#include "tests/fuzz/fuzz_run.h"

#include "io/dump.h"
#include "base/error.h"
#include "pipeline/mesh.h"
#include "pipeline/pipeline.h"


namespace vplab::fuzz {

Limits fuzzLimits() {
  Limits l;
  l.sceneFileBytes = 1 << 20;
  l.objFileBytes = 1 << 20;
  l.segments = 256;
  l.faces = 40000;
  l.vertices = 40000;
  l.corners = 160000;
  return l;
}

void runEverything(const Scene& scene) {
  PipelineRun run;
  for (ClipStrategy strategy : {ClipStrategy::npc, ClipStrategy::wc, ClipStrategy::divideFirst}) {
    PipelineOptions options;
    options.strategy = strategy;
    options.boundingBoxTest = strategy == ClipStrategy::wc;
    options.clipEdges = true;
    runPipeline(scene, options, run);  // reuses the buffers, as the viewer does
    // What `vplab dump` checks before it writes anything: every value of every stage is finite.
    // (The dump's text itself is not written here: formatting costs four times the three runs, and
    // its layout is tested against nlohmann's in tests/io/dump_stream_test.cpp.)
    if (auto e = nonFiniteError(run)) throw Error(*e);
  }
  for (const SceneObject& o : scene.objects) {  // what the GPU path and the wireframes use
    if (!o.mesh) continue;
    (void)uniqueEdges(*o.mesh);
    (void)triangulated(*o.mesh);
    (void)bounds(*o.mesh);
  }
}

}  // namespace vplab::fuzz
