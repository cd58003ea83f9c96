// What every fuzz target does with what it could read: the whole pipeline under each clipping
// strategy (with the bounding-box test and edge clipping) and the dump's check of its values.
#pragma once

#include "io/limits.h"
#include "pipeline/scene.h"

namespace vplab::fuzz {

/// The limits of the fuzz targets: the default ones, smaller, so that one input runs in
/// milliseconds (what exceeds them is refused before anything is allocated, which is what they
/// test); the defaults themselves are tested in tests/io/hardening_test.cpp.
Limits fuzzLimits();

/// Runs the pipeline and the dump's finiteness check over the scene; vplab::Error (a user error) is the only
/// exception allowed through, and the fuzz target ignores it.
void runEverything(const Scene& scene);

}  // namespace vplab::fuzz
