// The student's numbers in the views (issue 40): what Highlights::Student (app/views/views.h) draws of
// the fields of an exercise, read as the grader reads them (fractions, decimal commas): their P1 in
// WC, VRC, NPC and DC; their polygon after a Sutherland–Hodgman pass; their clipped polygon in DC;
// the polygon placed by their wcFromMc and the view volume their matrices make. A value not given, or
// not readable, is not drawn. The lab's P1 is added only when the exercise reveals values.
#pragma once

#include "app/practice/practice.h"
#include "app/views/views.h"

#include <optional>

namespace vplab {

/// `pass`: the pass (1 left … 6 front) whose polygon the NPC view shows, as the step-through shows
/// it; nullopt or 0: the last pass the student gave. `rowVectorForm`: the matrices were given in the
/// lecture notes' row-vector form (NumbersGrade::rowVectorForm): read transposed.
Highlights::Student practiceMarks(const Practice& p, std::optional<int> pass, bool rowVectorForm = false);

}  // namespace vplab
