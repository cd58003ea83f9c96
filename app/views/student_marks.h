// An exercise's numbers as the student gave them (Highlights::Student, issue 40), in the views: the
// student's colour, the lab's P1 (when revealed) a translucent halo so that both stay visible where they
// agree, polygons and the view volume dashed (over the lab's solid ones, a wrong one is seen beside it).
#pragma once

#include "app/views/batches.h"
#include "app/views/theme.h"
#include "app/views/views.h"

#include <functional>

namespace vplab::draw {

/// The dash of the student's polygons and view volume, in pixels.
inline constexpr float kStudentDashPx = 8.f;

/// The world view's: their P1 (from WC and from VRC), the polygon by their wcFromMc, their view volume;
/// the lab's P1 when revealed.
void studentWorldMarks(const Highlights::Student& s, const theme::Palette& pal, Marks& marks);
/// The NPC view's: their P1 in NPC, their polygon after the pass shown; the lab's P1 when revealed.
void studentNpcMarks(const Highlights::Student& s, const theme::Palette& pal, Marks& marks);
/// The camera view's: their P1 in DC and their clipped polygon, through `pixels` (DC → the view's pixels).
void studentDcMarks(const Highlights::Student& s, const theme::Palette& pal, const std::function<Vec3(const Vec3&)>& pixels,
                    Marks& marks);

}  // namespace vplab::draw
