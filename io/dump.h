// `vplab dump`: a pipeline run as JSON, a contract other tools rely on (docs/formats.md "vplab dump").
// Matrices are arrays of 4 rows for column vectors (p' = M · p).
#pragma once

#include "pipeline/pipeline.h"

#include <optional>
#include <ostream>
#include <string>

namespace vplab {

/// The run as JSON text: camera, device, matrices, every polygon of every object through the
/// stages, and the statistics.
/// Throws vplab::Error when a value the dump would print is not finite (nonFiniteError).
std::string dumpJson(const PipelineRun& run, int indent = 2);

/// The same text written to `out` as it is made (constant memory beyond the run itself).
/// Checks every value first, so an error leaves nothing half written.
void writeDump(std::ostream& out, const PipelineRun& run, int indent = 2);

/// Why the run cannot be dumped: the first value of any stage that is not finite (coordinates so
/// large that a product overflows), naming the object, the vertex and the stage; nullopt when all are.
std::optional<std::string> nonFiniteError(const PipelineRun& run);

}  // namespace vplab
