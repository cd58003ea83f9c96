// `vplab dump`: a pipeline run as JSON, a contract other tools rely on (README "vplab dump").
// Matrices are arrays of 4 rows for column vectors (p' = M · p).
#pragma once

#include "pipeline/pipeline.h"

#include <string>

namespace vplab {

/// The run as JSON text: camera, device, matrices, every polygon of every object through the
/// stages, and the statistics.
std::string dumpJson(const PipelineRun& run, int indent = 2);

}  // namespace vplab
