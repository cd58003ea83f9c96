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
#include <string_view>

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

/// The counters the dump and the panel show (not the edges' counts), once, in the dump's order: the member, its key in the dump
/// (io/dump.cpp) and its name in the Clipping panel (the catalogue's English, app/text/; nullptr: the
/// panel leaves it out). The dump and the panel both read these two tables.
template <class Counts>
struct CountField {
  uint64_t Counts::*member;
  std::string_view key;
  const char* label;
};
// clang-format off
inline constexpr CountField<PipelineStats> kStatsFields[] = {
    {&PipelineStats::objects,                   "objects",                     nullptr},
    {&PipelineStats::vertices,                  "vertices",                    nullptr},
    {&PipelineStats::verticesTransformed,       "vertices_transformed",        "vertices transformed"},
    {&PipelineStats::verticesClassified,        "vertices_classified",         "vertices classified"},
    {&PipelineStats::polygons,                  "polygons",                    "polygons"},
    {&PipelineStats::polygonsTriviallyAccepted, "polygons_trivially_accepted", "  trivially accepted"},
    {&PipelineStats::polygonsTriviallyRejected, "polygons_trivially_rejected", "  trivially rejected"},
    {&PipelineStats::polygonsClipped,           "polygons_clipped",            "  clipped"},
    {&PipelineStats::polygonsClippedAway,       "polygons_clipped_away",       "  clipped away"},
    {&PipelineStats::verticesCreated,           "vertices_created",            "vertices created"},
    {&PipelineStats::verticesOutput,            "vertices_output",             "vertices divided and mapped"},
    {&PipelineStats::objectsBoxTested,          "objects_box_tested",          "objects box-tested"},
    {&PipelineStats::objectsAcceptedByBox,      "objects_accepted_by_box",     "objects accepted by box"},
    {&PipelineStats::objectsRejectedByBox,      "objects_rejected_by_box",     "objects rejected by box"},
    {&PipelineStats::polygonsDecidedByBox,      "polygons_decided_by_box",     "polygons decided by box"},
};
/// The operations of the cost model (lecture notes 15.3.3): the dump's "operations", the panel's first rows.
inline constexpr CountField<OperationCounts> kOperationFields[] = {
    {&OperationCounts::multiplications, "multiplications", "multiplications"},
    {&OperationCounts::additions,       "additions",       "additions"},
    {&OperationCounts::divisions,       "divisions",       "divisions"},
    {&OperationCounts::comparisons,     "comparisons",     "comparisons"},
};
// clang-format on

/// The operation counts for a strategy, from the events in `stats` (docs/conventions.md stage 4; lecture notes 15.3.3).
OperationCounts npcStrategyCost(const PipelineStats& s);
OperationCounts wcStrategyCost(const PipelineStats& s);
OperationCounts divideFirstCost(const PipelineStats& s);

}  // namespace vplab
