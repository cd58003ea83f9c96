// Statistics of a pipeline run and the lecture notes' cost model for them (lecture notes 15.3.3):
//
//   a 4 × 4 transformation          16 multiplications, 12 additions
//   inside test in NPC              6 comparisons (+ 3 subtractions for w − x, w − y, w − z)
//   inside test in WC               18 multiplications, 18 additions, 6 comparisons (6 planes)
//   perspective division            3 divisions
//   a new vertex on an edge         1 division for t, then every interpolated value (coordinates
//                                   and boundary values) 1 multiplication and 2 additions
//   a bounding-box test             its 8 corners transformed to NPC and tested (lecture notes 15.3.4)
//
// Clipping in WC saves the NPC transformation of invisible points but costs 2 more multiplications
// per inside test, and one more MC → WC transformation per point when WC is not stored.
// The counts are derived from the events the run counted, not counted inside the hot loops.
#pragma once

#include <cstdint>

namespace vplab {

struct OperationCounts {
  uint64_t multiplications = 0;
  uint64_t additions = 0;
  uint64_t divisions = 0;
  uint64_t comparisons = 0;
};

struct PipelineStats {
  uint64_t objects = 0;
  uint64_t vertices = 0;             // mesh vertices of the visible objects
  uint64_t verticesTransformed = 0;  // MC → homogeneous NPC (each once, however many faces use it)
  uint64_t verticesClassified = 0;   // boundary values and outcode computed
  uint64_t polygons = 0;
  uint64_t polygonsTriviallyAccepted = 0;
  uint64_t polygonsTriviallyRejected = 0;
  uint64_t polygonsClipped = 0;      // cut, something remains
  uint64_t polygonsClippedAway = 0;  // cut, nothing remains
  uint64_t verticesCreated = 0;      // new vertices on clip planes
  uint64_t verticesOutput = 0;       // divided and mapped to DC
  uint64_t objectsBoxTested = 0;     // lecture notes 15.3.4: each costs 8 corner transformations and tests
  uint64_t objectsAcceptedByBox = 0;
  uint64_t objectsRejectedByBox = 0;
  uint64_t polygonsDecidedByBox = 0;
  uint64_t edges = 0;
  uint64_t edgesAccepted = 0;
  uint64_t edgesRejected = 0;
  uint64_t edgesClipped = 0;
  OperationCounts operations;
};

/// The operation counts for a strategy, from the events in `stats` (docs/conventions.md stage 4; lecture notes 15.3.3).
OperationCounts npcStrategyCost(const PipelineStats& s);
OperationCounts wcStrategyCost(const PipelineStats& s);
OperationCounts divideFirstCost(const PipelineStats& s);

}  // namespace vplab
