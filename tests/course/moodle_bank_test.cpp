// Issue 38, part 4: the Moodle XML question bank of `vplab exercise --moodle`. The written XML is read
// back by a small parser of the cloze syntax written here (from Moodle's own parser's rules,
// question/type/multianswer/questiontype.php, not from the writer's code) and checked against the
// reference answer and the mistake models computed independently of the bank.
#include "course/exercise.h"
#include "course/exercise_answer.h"
#include "course/grading.h"
#include "course/mistake_models.h"
#include "course/moodle_bank.h"
#include "course/sheet_values.h"
#include "pipeline/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

namespace vplab {
namespace {

using Json = nlohmann::ordered_json;

// ------------------------------------------------------------------ a reader of the written bank

/// A cloze answer as Moodle reads it.
struct Alternative {
  std::string fraction;  // "=" or "%N%"
  std::string answer;    // "0.6:0.001" or "*"
  std::string feedback;  // unescaped as Moodle does
  double value = 0, tolerance = 0;
};
struct SubQuestion {
  int weight = 0;
  std::vector<Alternative> alternatives;
};

bool escapedAt(const std::string& s, size_t i) { return i > 0 && s[i - 1] == '\\'; }

/// Moodle's decoding of a feedback: html_entity_decode, then \} → } and \# → #.
std::string decodeFeedback(std::string s) {
  const std::pair<const char*, const char*> entities[] = {{"&#126;", "~"}, {"&#123;", "{"}, {"&#92;", "\\"}, {"&amp;", "&"},
                                                          {"&lt;", "<"}, {"&gt;", ">"}};
  std::string out;
  for (size_t i = 0; i < s.size();) {
    bool replaced = false;
    for (const auto& [from, to] : entities)
      if (s.compare(i, std::strlen(from), from) == 0) {
        out += to, i += std::strlen(from), replaced = true;
        break;
      }
    if (!replaced) out += s[i++];
  }
  for (const char* esc : {"\\}", "\\#"})
    for (size_t at; (at = out.find(esc)) != std::string::npos;) out.replace(at, 2, esc + 1);
  return out;
}

const std::regex kNumber(R"(^-?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)$)");

std::vector<SubQuestion> subQuestions(const std::string& text) {
  std::vector<SubQuestion> out;
  const std::regex start(R"(\{([0-9]*):NUMERICAL:)");
  std::smatch m;
  for (size_t from = 0; std::regex_search(text.begin() + long(from), text.end(), m, start);) {
    SubQuestion q;
    q.weight = std::stoi(m[1].str());
    size_t i = from + size_t(m.position() + m.length());
    size_t close = i;
    while (close < text.size() && !(text[close] == '}' && !escapedAt(text, close))) ++close;
    EXPECT_LT(close, text.size()) << "an unclosed sub-question";
    const std::string body = text.substr(i, close - i);
    std::vector<std::string> alts{""};
    for (size_t k = 0; k < body.size(); ++k) {
      if (body[k] == '~' && !escapedAt(body, k)) alts.emplace_back();
      else alts.back() += body[k];
    }
    for (const std::string& a : alts) {
      Alternative alt;
      size_t at = 0;
      if (!a.empty() && a[0] == '=') alt.fraction = "=", at = 1;
      else if (!a.empty() && a[0] == '%') at = a.find('%', 1) + 1, alt.fraction = a.substr(0, at);
      size_t hash = at;
      while (hash < a.size() && !(a[hash] == '#' && !escapedAt(a, hash))) ++hash;
      alt.answer = a.substr(at, hash - at);
      if (hash < a.size()) alt.feedback = decodeFeedback(a.substr(hash + 1));
      if (alt.answer != "*") {
        const size_t colon = alt.answer.find(':');
        const std::string v = alt.answer.substr(0, colon), t = colon == std::string::npos ? "0" : alt.answer.substr(colon + 1);
        EXPECT_TRUE(std::regex_match(v, kNumber)) << v;
        EXPECT_TRUE(std::regex_match(t, kNumber)) << t;
        alt.value = std::stod(v), alt.tolerance = std::stod(t);
      }
      q.alternatives.push_back(alt);
    }
    out.push_back(q);
    from = close + 1;  // as Moodle: the next sub-question starts after this one
  }
  return out;
}

/// The texts of the CDATA sections of `xml`, joined per <text> element (a split "]]>" rejoined).
std::string cdataText(const std::string& xml, size_t from, size_t to) {
  std::string out;
  for (size_t at = xml.find("<![CDATA[", from); at != std::string::npos && at < to; at = xml.find("<![CDATA[", at)) {
    const size_t end = xml.find("]]>", at);
    out += xml.substr(at + 9, end - at - 9);
    at = end + 3;
  }
  return out;
}

/// Elements open and close in order (CDATA skipped, <?…?> and self-closing tags allowed).
bool wellFormed(const std::string& xml) {
  std::vector<std::string> open;
  for (size_t i = 0; i < xml.size(); ++i) {
    if (xml.compare(i, 9, "<![CDATA[") == 0) {
      i = xml.find("]]>", i);
      if (i == std::string::npos) return false;
      i += 2;
      continue;
    }
    if (xml[i] != '<') continue;
    const size_t end = xml.find('>', i);
    if (end == std::string::npos) return false;
    std::string tag = xml.substr(i + 1, end - i - 1);
    i = end;
    if (tag[0] == '?' || tag.back() == '/') continue;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return false;
      open.pop_back();
    } else {
      open.push_back(tag.substr(0, tag.find(' ')));
    }
  }
  return open.empty();
}

std::string decodeBase64(const std::string& s) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  uint32_t buf = 0;
  int bits = 0;
  for (char c : s) {
    if (c == '=') break;
    buf = (buf << 6) | uint32_t(alphabet.find(c));
    bits += 6;
    if (bits >= 8) bits -= 8, out += char((buf >> bits) & 0xFF);
  }
  return out;
}

// ------------------------------------------------------------------ an exercise and its bank

std::string asHtml(std::string_view text) {
  std::string out;
  for (char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

struct Built {
  Exercise exercise;
  Assignment assignment;
  Json reference;
  std::vector<std::pair<Mistake, Json>> models;  // computed here, independently of the bank
  std::string xml;
};

Built build(ExerciseSpec spec, const std::string& id, Language lang = Language::en) {
  Built b;
  b.exercise = generateExercise(spec, id);
  const ExerciseSolution s = solveExercise(b.exercise);
  b.assignment = exerciseAssignment(b.exercise, s, lang);
  b.reference = referenceAnswer(b.exercise.scene);
  for (const MistakeModel& m : mistakeModels()) {
    try {
      Json dump = mistakeDump(b.exercise.scene, m.id);
      addSheetValues(dump, m.id == Mistake::transposed);
      b.models.emplace_back(m.id, dump);
    } catch (const Error&) {
    }
  }
  MoodleQuestion q;
  q.name = "Exercise for " + id;
  q.lang = lang;
  q.sheetMarkdown = "# Sheet\n\nGiven $x = \\frac{1}{2}$ & more ]]> here.\n\n![The world.](world.svg)\n";
  q.figures.push_back({"world.png", std::string("\x89PNG\r\n\x1a\n\0\xff", 10)});
  q.values = clozeValues(b.assignment, answerKey(b.assignment, b.reference), b.models, lang);
  b.xml = moodleBankXml("vplab/test", {q});
  return b;
}

/// Every number of the reference under the assignment's items, in order, with its path.
std::vector<std::pair<std::string, double>> expectedValues(const Assignment& a, const Json& reference) {
  std::vector<std::pair<std::string, double>> out;
  for (const AssignmentItem& item : a.items) {
    // nlohmann's flatten: {"/0/1": x, …}; a number alone: {"": x}.
    const Json flat = Json(reference.at(Json::json_pointer(item.path))).flatten();
    for (const auto& [path, v] : flat.items())
        if (v.is_number()) out.emplace_back(item.path + path, v.get<double>());
  }
  return out;
}

TEST(MoodleBank, IsWellFormedWithACategoryFirstAndTheFigureEmbedded) {
  const Built b = build({5, ExerciseTopic::pipeline, Projection::perspective}, "alice");
  EXPECT_TRUE(wellFormed(b.xml));
  EXPECT_EQ(b.xml.find("<quiz>"), b.xml.find('\n') + 1);
  const size_t category = b.xml.find("<question type=\"category\">"), cloze = b.xml.find("<question type=\"cloze\">");
  ASSERT_NE(category, std::string::npos);
  ASSERT_NE(cloze, std::string::npos);
  EXPECT_LT(category, cloze);
  EXPECT_NE(b.xml.find("<text>$course$/top/vplab/test</text>"), std::string::npos);
  // The figure: referenced in the text, its bytes in a base64 <file>.
  const std::string text = cdataText(b.xml, cloze, b.xml.size());
  EXPECT_NE(text.find("<img src=\"@@PLUGINFILE@@/world.png\""), std::string::npos);
  const std::string open = "<file name=\"world.png\" path=\"/\" encoding=\"base64\">";
  const size_t file = b.xml.find(open);
  ASSERT_NE(file, std::string::npos);
  const size_t end = b.xml.find("</file>", file);
  EXPECT_EQ(decodeBase64(b.xml.substr(file + open.size(), end - file - open.size())), std::string("\x89PNG\r\n\x1a\n\0\xff", 10));
  // "]]>" in the sheet is split across CDATA sections and comes back whole; & < are HTML-escaped.
  EXPECT_NE(text.find("&amp; more ]]&gt; here"), std::string::npos) << text.substr(0, 300);
  EXPECT_NE(text.find("\\(x = \\frac{1}{2}\\)"), std::string::npos);
}

TEST(MoodleBank, EveryCorrectAnswerIsTheSolutionsValueWithinTheTolerance) {
  for (const ExerciseSpec& spec : {ExerciseSpec{5, ExerciseTopic::pipeline, Projection::perspective},
                                   ExerciseSpec{2, ExerciseTopic::clipping, Projection::parallel},
                                   ExerciseSpec{7, ExerciseTopic::orientation, Projection::oblique}}) {
    const Built b = build(spec, "bob");
    const std::vector<SubQuestion> subs = subQuestions(cdataText(b.xml, b.xml.find("type=\"cloze\""), b.xml.size()));
    const auto expected = expectedValues(b.assignment, b.reference);
    ASSERT_EQ(subs.size(), expected.size()) << toString(spec.topic);
    for (size_t i = 0; i < subs.size(); ++i) {
      const Alternative& right = subs[i].alternatives.at(0);
      EXPECT_EQ(right.fraction, "=");
      const double ref = expected[i].second;
      const double tol = b.assignment.tolerance * std::max(1.0, std::abs(ref));
      EXPECT_NEAR(right.value, ref, tol) << expected[i].first;
      EXPECT_LE(right.tolerance, tol * (1 + 1e-9)) << expected[i].first;
      EXPECT_EQ(subs[i].weight, 1);
      // Then the mistakes at 0 %, and last "any other answer" at 0 %.
      EXPECT_EQ(subs[i].alternatives.back().answer, "*");
      for (size_t k = 1; k < subs[i].alternatives.size(); ++k) EXPECT_EQ(subs[i].alternatives[k].fraction, "%0%");
    }
  }
}

TEST(MoodleBank, EachMistakeAnswerIsTheModelsPredictedValueAndNamesIt) {
  const Built b = build({5, ExerciseTopic::pipeline, Projection::perspective}, "carol", Language::de);
  const std::vector<SubQuestion> subs = subQuestions(cdataText(b.xml, b.xml.find("type=\"cloze\""), b.xml.size()));
  const auto expected = expectedValues(b.assignment, b.reference);
  ASSERT_EQ(subs.size(), expected.size());
  size_t mistakesSeen = 0;
  for (size_t i = 0; i < subs.size(); ++i) {
    const auto& [path, ref] = expected[i];
    const double tol = b.assignment.tolerance * std::max(1.0, std::abs(ref));
    // Every model that predicts another value here has a 0 % answer with that value, naming it (in German).
    for (const auto& [mistake, dump] : b.models) {
      const Json::json_pointer p(path);
      if (!dump.contains(p) || !dump.at(p).is_number()) continue;
      const double m = dump.at(p).get<double>();
      if (std::abs(m - ref) <= tol) continue;
      bool found = false;
      for (size_t k = 1; k + 1 < subs[i].alternatives.size(); ++k) {
        const Alternative& a = subs[i].alternatives[k];
        // The decoded feedback is HTML (Moodle shows it as such): the description with < > & escaped.
        if (std::abs(a.value - m) <= tol && a.feedback.find(asHtml(mistakeModel(mistake).descriptionDe)) != std::string::npos) {
          found = true;
          EXPECT_EQ(a.feedback.rfind("Fehler: ", 0), 0u) << a.feedback;
        }
      }
      EXPECT_TRUE(found) << path << ": " << mistakeModel(mistake).key << " predicts " << m;
      mistakesSeen += found;
    }
    // And no 0 % answer that no model predicts.
    for (size_t k = 1; k + 1 < subs[i].alternatives.size(); ++k) {
      bool predicted = false;
      for (const auto& [mistake, dump] : b.models) {
        const Json::json_pointer p(path);
        predicted |= dump.contains(p) && dump.at(p).is_number() &&
                     std::abs(dump.at(p).get<double>() - subs[i].alternatives[k].value) <= tol;
      }
      EXPECT_TRUE(predicted) << path;
    }
  }
  EXPECT_GT(mistakesSeen, 20u);  // the pipeline sheet's matrices and points: many values models get wrong
}

TEST(MoodleBank, FeedbackEscapesSurviveMoodlesParser) {
  const std::string hostile = "a}b#c~d\\e<f>g&h \"i\" /j {1:NUMERICAL:=1}";
  ClozeValue v;
  v.label = "x";
  v.value = -0.25;
  v.tolerance = 0.001;
  v.mistakes.push_back({1e-7, hostile});
  v.mistakes.push_back({-12345678.5, "plain"});
  const std::vector<SubQuestion> subs = subQuestions(clozeSubquestion(v, Language::en));
  ASSERT_EQ(subs.size(), 1u);  // the sub-question inside the feedback does not start another
  ASSERT_EQ(subs[0].alternatives.size(), 4u);
  // Moodle decodes it once more as HTML: the feedback decoded here is HTML whose text is `hostile`.
  std::string html = subs[0].alternatives[1].feedback;
  EXPECT_EQ(html, "a}b#c~d\\e&lt;f&gt;g&amp;h \"i\" /j {1:NUMERICAL:=1}");
  EXPECT_DOUBLE_EQ(subs[0].alternatives[0].value, -0.25);
  EXPECT_DOUBLE_EQ(subs[0].alternatives[1].value, 1e-7);
  EXPECT_DOUBLE_EQ(subs[0].alternatives[2].value, -12345678.5);
  EXPECT_EQ(clozeNumber(-0.0), "0");
  EXPECT_EQ(clozeNumber(0.6), "0.6");
  EXPECT_THROW(clozeNumber(std::nan("")), Error);
  EXPECT_THROW(clozeNumber(INFINITY), Error);
}

TEST(MoodleBank, RejectsHostileFigureNamesAndEmptyQuestions) {
  MoodleQuestion q;
  q.name = "q";
  q.values.push_back({"/camera/vpd", "VPD", 5, 0.005, {}});
  q.figures.push_back({"../x.png", "x"});
  EXPECT_THROW(moodleBankXml("c", {q}), Error);
  q.figures = {{"a\" onload=\"x.png", "x"}};
  EXPECT_THROW(moodleBankXml("c", {q}), Error);
  q.figures.clear();
  q.values.clear();
  EXPECT_THROW(moodleBankXml("c", {q}), Error);
}

TEST(MoodleBank, Base64FollowsRfc4648) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}

// ------------------------------------------------------------------ equally hard variants (part 3)

TEST(ExerciseVariants, NoVariantHasTheIdentityOrientation) {
  // Several hundred seeds and student ids over the topics whose sheets ask for U, V, N.
  size_t checked = 0;
  const Projection projections[] = {Projection::perspective, Projection::parallel, Projection::oblique};
  for (ExerciseTopic topic : {ExerciseTopic::orientation, ExerciseTopic::pipeline, ExerciseTopic::mapping,
                              ExerciseTopic::clipping})
    for (uint64_t seed = 1; seed <= 120; ++seed) {
      const std::string id = seed % 3 == 0 ? "" : "s" + std::to_string(seed * 7);
      const Exercise e = generateExercise({seed, topic, projections[seed % 4 == 0 ? 1 + seed % 2 : 0]}, id);
      const VrcAxes axes = vrcAxes(e.scene.camera);
      const bool identity = std::abs(axes.n.z - 1) < 1e-9 && std::abs(axes.u.x - 1) < 1e-9 && std::abs(axes.v.y - 1) < 1e-9;
      EXPECT_FALSE(identity) << toString(topic) << " seed " << seed << " id " << id;
      EXPECT_FALSE(identityOrientation(e.scene.camera));
      ++checked;
    }
  EXPECT_EQ(checked, 480u);
  // The check itself: the lecture's default orientation is the identity.
  Camera c;
  c.vrp = {0, 0, 0}, c.prp = {0, 0, 5}, c.vup = {0, 1, 0};
  EXPECT_TRUE(identityOrientation(c));
}

}  // namespace
}  // namespace vplab
