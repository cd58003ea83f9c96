// What makes a camera invalid (pipeline/camera.h's CameraProblem), said in the viewer's language with
// the camera's values: the camera panel's message while a student drags a camera into an invalid one.
// In English it is cameraError's text, word for word (tests/app/inspect/camera_text_test.cpp).
#pragma once

#include "pipeline/camera.h"
#include "base/language.h"

#include <string>

namespace vplab {

std::string cameraProblemText(const CameraProblem& problem, const Camera& camera, Language lang);

}  // namespace vplab
