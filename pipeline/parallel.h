// Work shared between the cores: a range cut into chunks, each chunk's work written only to what
// belongs to it, so that the result does not depend on which core did which chunk (or in which
// order): the run on every core is the serial run bit for bit.
#pragma once

#include <cstddef>
#include <functional>

namespace vplab {

/// The number of chunks of at most `grain` units that cover `count` units.
constexpr size_t chunkCount(size_t count, size_t grain) { return (count + grain - 1) / grain; }

/// Whether this build can share work between cores (natively: oneTBB; the page: never, it has one
/// thread unless cross-origin isolated).
bool parallelAvailable();

/// The threads forEachChunk shares work between (1 without parallelAvailable).
unsigned parallelThreads();

/// Calls body(k) for every chunk k in [0, chunks): on every core when `parallel` is set and this
/// build can (parallelAvailable), else in order on this thread. The threads that help run at the
/// calling thread's nice value (Linux; the window's helpers run below it, and their helpers with
/// them). Returns when every chunk is done; an exception from a body reaches the caller.
void forEachChunk(size_t chunks, bool parallel, const std::function<void(size_t)>& body);

}  // namespace vplab
