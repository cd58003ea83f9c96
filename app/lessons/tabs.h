// The viewer's tabs by the names the command line (`vplab render --view ui --tab NAME`) and the
// lessons (app/lessons/lesson.h) give them: the controls' camera, scene, clipping, display, lecture and
// the inspector's probe, matrices, depth (app/ui/viewer_state.h brings one forward).
#pragma once

#include <string_view>

namespace vplab {

inline constexpr std::string_view kTabNames[] = {"camera", "scene",  "clipping", "display",
                                                 "lecture", "probe", "matrices", "depth"};

}  // namespace vplab
