// Text inside XML (the Moodle question bank, course/moodle_bank.h; the JUnit report of `vplab grade`,
// app/course_kit/grade_report.cpp): one escape for element text and double-quoted attribute values.
#pragma once

#include <string>
#include <string_view>

namespace vplab {

/// `s` with & < > " as &amp; &lt; &gt; &quot; (element text and "…" attribute values alike).
std::string xmlEscape(std::string_view s);

}  // namespace vplab
