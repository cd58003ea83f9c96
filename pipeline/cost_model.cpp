#include "pipeline/cost_model.h"

namespace vplab {

namespace {

constexpr uint64_t kTransformMul = 16, kTransformAdd = 12;   // one 4 × 4 transformation
constexpr uint64_t kNpcTestCmp = 6, kNpcTestAdd = 3;         // 0 ≤ x ≤ w, … with w − x, …
constexpr uint64_t kWcTestMul = 18, kWcTestAdd = 18, kWcTestCmp = 6;  // 6 plane equations
constexpr uint64_t kDivide = 3;                              // x/w, y/w, z/w

void addIntersections(OperationCounts& c, uint64_t created, uint64_t values) {
  c.divisions += created;              // t = BC(in) / (BC(in) − BC(out))
  c.additions += created * (1 + 2 * values);
  c.multiplications += created * values;
}

// lecture notes 15.3.4: the box's 8 corners go through the one transformation to NPC and the inside test.
void addBoxTests(OperationCounts& c, uint64_t boxes) {
  c.multiplications += boxes * 8 * kTransformMul;
  c.additions += boxes * 8 * (kTransformAdd + kNpcTestAdd);
  c.comparisons += boxes * 8 * kNpcTestCmp;
}

}  // namespace

OperationCounts npcStrategyCost(const PipelineStats& s) {
  OperationCounts c;
  c.multiplications = s.verticesTransformed * kTransformMul;      // MC → NPC
  c.additions = s.verticesTransformed * kTransformAdd;
  c.comparisons = s.verticesClassified * kNpcTestCmp;
  c.additions += s.verticesClassified * kNpcTestAdd;
  addIntersections(c, s.verticesCreated, 4 + 6);                  // x, y, z, w and six BCs
  c.divisions += s.verticesOutput * kDivide;                      // then divide
  c.multiplications += s.verticesOutput * kTransformMul;          // NPC → DC
  c.additions += s.verticesOutput * kTransformAdd;
  addBoxTests(c, s.objectsBoxTested);
  return c;
}

OperationCounts wcStrategyCost(const PipelineStats& s) {
  OperationCounts c;
  c.multiplications = s.verticesTransformed * kTransformMul;      // MC → WC
  c.additions = s.verticesTransformed * kTransformAdd;
  c.multiplications += s.verticesClassified * kWcTestMul;
  c.additions += s.verticesClassified * kWcTestAdd;
  c.comparisons = s.verticesClassified * kWcTestCmp;
  addIntersections(c, s.verticesCreated, 3 + 6);                  // x, y, z and six plane values
  c.multiplications += s.verticesOutput * 2 * kTransformMul;      // WC → NPC, NPC → DC
  c.additions += s.verticesOutput * 2 * kTransformAdd;
  c.divisions += s.verticesOutput * kDivide;
  addBoxTests(c, s.objectsBoxTested);
  return c;
}

OperationCounts divideFirstCost(const PipelineStats& s) {
  OperationCounts c;
  c.multiplications = s.verticesTransformed * kTransformMul;      // MC → NPC
  c.additions = s.verticesTransformed * kTransformAdd;
  c.divisions = s.verticesClassified * kDivide;                   // every vertex divided first
  c.comparisons = s.verticesClassified * kNpcTestCmp;
  c.additions += s.verticesClassified * kNpcTestAdd;
  addIntersections(c, s.verticesCreated, 3 + 6);
  c.multiplications += s.verticesOutput * kTransformMul;          // NPC → DC
  c.additions += s.verticesOutput * kTransformAdd;
  addBoxTests(c, s.objectsBoxTested);
  return c;
}

}  // namespace vplab
