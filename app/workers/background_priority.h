// The window's helpers (the pipeline's worker, the views' render thread) run below the window's own
// thread: its frames come first when both want a core (a frame takes a few ms; a run of a large scene
// 0.2 s, a view of a million triangles seconds).
#pragma once

namespace vplab {

/// Gives the calling thread a nice value of 5 (Linux: each thread has its own). Nothing where threads
/// have no nice value of their own (the browser build starts no such thread).
void runBelowTheWindow();

}  // namespace vplab
