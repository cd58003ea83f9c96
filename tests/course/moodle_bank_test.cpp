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
#include "base/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <map>
#include <numeric>
#include <regex>
#include <set>

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
      EXPECT_GE(subs[i].weight, 1);  // the item's share (MoodleBank.EachItemWeighsItsPoints)
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
  q.values.push_back({"/camera/vpd", "VPD", 5, 0.005, {}, 1, "/camera/vpd"});
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

// ------------------------------------------------------------------ weights and the vertex order

/// The variants the weight and order tests read: every topic, every projection, several seeds.
std::vector<ExerciseSpec> variants() {
  std::vector<ExerciseSpec> out;
  for (ExerciseTopic topic : {ExerciseTopic::orientation, ExerciseTopic::mapping, ExerciseTopic::clipping,
                              ExerciseTopic::pipeline})
    for (uint64_t seed : {1, 2, 3, 11})
      out.push_back({seed, topic, seed % 3 == 0 ? Projection::parallel : seed % 3 == 1 ? Projection::perspective
                                                                                       : Projection::oblique});
  return out;
}

/// For each sub-question (in order), the index of the assignment item its value belongs to.
std::vector<size_t> itemOfEachValue(const Built& b) {
  std::vector<size_t> out;
  for (size_t i = 0; i < b.assignment.items.size(); ++i) {
    const Json flat = Json(b.reference.at(Json::json_pointer(b.assignment.items[i].path))).flatten();
    for (const auto& [path, v] : flat.items())
      if (v.is_number()) out.push_back(i);
  }
  return out;
}

TEST(MoodleBank, EachItemWeighsItsPointsAndTheQuestionTheAssignmentsTotal) {
  size_t questions = 0;
  for (const ExerciseSpec& spec : variants())
    for (Language lang : {Language::en, Language::de}) {
      const Built b = build(spec, lang == Language::en ? "dana" : "emil", lang);
      const std::string what = std::string(toString(spec.topic)) + " seed " + std::to_string(spec.seed);
      const std::vector<SubQuestion> subs = subQuestions(cdataText(b.xml, b.xml.find("type=\"cloze\""), b.xml.size()));
      const std::vector<size_t> itemOf = itemOfEachValue(b);
      ASSERT_EQ(subs.size(), itemOf.size()) << what;
      std::vector<long> weight(b.assignment.items.size(), 0), count(b.assignment.items.size(), 0);
      std::vector<int> least(b.assignment.items.size(), INT_MAX), most(b.assignment.items.size(), 0);
      long total = 0;
      double points = 0;
      for (size_t k = 0; k < subs.size(); ++k) {
        EXPECT_GE(subs[k].weight, 1) << what;
        weight[itemOf[k]] += subs[k].weight, ++count[itemOf[k]], total += subs[k].weight;
        least[itemOf[k]] = std::min(least[itemOf[k]], subs[k].weight);
        most[itemOf[k]] = std::max(most[itemOf[k]], subs[k].weight);
      }
      for (const AssignmentItem& item : b.assignment.items) points += item.points;
      // The common factor: the question's total weight over the assignment's total points, an integer.
      const double factor = double(total) / points;
      EXPECT_EQ(factor, std::round(factor)) << what << ": total weight " << total << " for " << points << " points";
      EXPECT_LE(total, 99999) << what;  // Moodle's largest mark
      for (size_t i = 0; i < b.assignment.items.size(); ++i) {
        const AssignmentItem& item = b.assignment.items[i];
        ASSERT_GT(count[i], 0) << what << ": " << item.path;
        // The item's weights over the factor are its points: a 2-point matrix counts 2, a 1-point vector 1.
        EXPECT_DOUBLE_EQ(double(weight[i]) / factor, item.points)
            << what << ": " << item.title << " (" << count[i] << " values) weighs " << weight[i] << " of " << total;
        // Shared out evenly: the values of an item differ by at most 1.
        EXPECT_LE(most[i] - least[i], 1) << what << ": " << item.title;
      }
      ++questions;
    }
  EXPECT_EQ(questions, 32u);
}

TEST(MoodleBank, WeightsAreEqualWithinAnItemWhereASmallFactorAllowsIt) {
  // The pipeline sheet: 16-value matrices at 2 and 1 points, 3- and 4-value vectors, single numbers.
  const Built b = build({5, ExerciseTopic::pipeline, Projection::perspective}, "frank");
  const std::vector<SubQuestion> subs = subQuestions(cdataText(b.xml, b.xml.find("type=\"cloze\""), b.xml.size()));
  const std::vector<size_t> itemOf = itemOfEachValue(b);
  ASSERT_EQ(subs.size(), itemOf.size());
  std::map<size_t, std::set<int>> weights;
  for (size_t k = 0; k < subs.size(); ++k) weights[itemOf[k]].insert(subs[k].weight);
  for (const auto& [item, w] : weights) EXPECT_EQ(w.size(), 1u) << b.assignment.items[item].title;
  // Small: the largest weight, a single number worth 1 point, is the factor itself.
  int largest = 0;
  for (const SubQuestion& q : subs) largest = std::max(largest, q.weight);
  EXPECT_LE(largest, 240);
}

TEST(MoodleBank, TheWeightFactorIsTheLeastThatSharesEveryItemsPoints) {
  // The factor: fractions and items worth nothing.
  EXPECT_EQ(clozeWeightFactor({{2, 16}, {1, 3}, {1, 1}}), 24);  // 16/2 = 8 and 3: each value weighs 3, 8, 24
  EXPECT_EQ(clozeWeightFactor({{0.5, 3}, {0, 7}, {1, 2}}), 6);  // 3/(1/2) = 6 and 2
  EXPECT_EQ(clozeWeightFactor({{0, 3}}), 0);
  // Beyond the cap (polygons of 28, 36, … values): the least factor giving every value a weight of 1.
  EXPECT_EQ(clozeWeightFactor({{1, 28}, {1, 36}, {1, 32}, {1, 20}, {2, 21}}), 36);
  EXPECT_THROW(clozeWeightFactor({{std::sqrt(2.0), 3}}), Error);
}

TEST(MoodleBank, BeyondTheCapEachItemStillWeighsItsPointsSpreadAsEvenlyAsIntegersAllow) {
  Assignment a;
  Json key;
  const std::pair<const char*, std::pair<double, size_t>> items[] = {
      {"a", {1, 28}}, {"b", {1, 36}}, {"c", {2, 21}}, {"d", {0, 5}}, {"e", {0.5, 4}}};
  for (const auto& [name, pc] : items) {
    a.items.push_back({std::string("/") + name, name, pc.first, true, {}});
    for (size_t k = 0; k < pc.second; ++k) key[name].push_back(double(k) + 0.5);
  }
  const std::vector<ClozeValue> values = clozeValues(a, key, {}, Language::en);
  ASSERT_EQ(values.size(), 28u + 36u + 21u + 4u);  // the item worth nothing is not asked
  std::map<std::string, std::vector<int>> weights;
  for (const ClozeValue& v : values) weights[v.item].push_back(v.weight);
  // F = 36: the least that gives each of b's 36 values a weight of 1 (e's 1/2 point: F even).
  EXPECT_EQ(std::accumulate(weights["/a"].begin(), weights["/a"].end(), 0), 36);
  EXPECT_EQ(std::accumulate(weights["/b"].begin(), weights["/b"].end(), 0), 36);
  EXPECT_EQ(std::accumulate(weights["/c"].begin(), weights["/c"].end(), 0), 72);
  EXPECT_EQ(std::accumulate(weights["/e"].begin(), weights["/e"].end(), 0), 18);
  EXPECT_EQ(weights["/a"].front(), 2);  // 36 over 28: eight 2s, then twenty 1s
  EXPECT_EQ(weights["/a"].back(), 1);
  EXPECT_EQ(weights.count("/d"), 0u);
  for (const auto& [item, w] : weights) EXPECT_LE(*std::max_element(w.begin(), w.end()) - *std::min_element(w.begin(), w.end()), 1) << item;
}

/// The polygon Sutherland–Hodgman writes for `input` against `plane`, by the rule the bank states
/// (its words, not the clipper's code): the edges from the closing one, Q_n → Q_1, on; entering: the
/// intersection, then P; both inside: P; leaving: the intersection; a vertex on the plane is inside
/// and not written twice.
Json byTheStatedRule(const Json& input, int plane) {
  auto bc = [&](const Json& q) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double values[] = {x, w - x, y, w - y, z, w - z};
    return values[plane];
  };
  auto cut = [&](const Json& in, const Json& out) {  // from the inside vertex
    const double t = bc(in) / (bc(in) - bc(out));
    Json v = Json::array();
    for (int c = 0; c < 4; ++c) v.push_back(in[c].get<double>() + t * (out[c].get<double>() - in[c].get<double>()));
    return v;
  };
  Json out = Json::array();
  const size_t n = input.size();
  for (size_t k = 0; k < n; ++k) {
    const Json& S = input[(k + n - 1) % n];
    const Json& P = input[k];
    const bool sIn = bc(S) >= 0, pIn = bc(P) >= 0;
    if (!sIn && pIn && bc(P) > 0) out.push_back(cut(P, S));
    if (pIn) out.push_back(P);
    if (sIn && !pIn && bc(S) > 0) out.push_back(cut(S, P));
  }
  return out;
}

bool sameVertices(const Json& a, const Json& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t c = 0; c < a[i].size(); ++c)
      if (std::abs(a[i][c].get<double>() - b[i][c].get<double>()) > 1e-6 * std::max(1.0, std::abs(b[i][c].get<double>())))
        return false;
  return true;
}

TEST(MoodleBank, PolygonItemsStateTheVertexOrderAndTheKeyFollowsIt) {
  size_t polygons = 0;
  for (const ExerciseSpec& spec : variants())
    for (Language lang : {Language::en, Language::de}) {
      const Built b = build(spec, "gina", lang);
      const std::string what = std::string(toString(spec.topic)) + " seed " + std::to_string(spec.seed);
      const size_t cloze = b.xml.find("type=\"cloze\"");
      const std::string text = cdataText(b.xml, cloze, b.xml.size());
      const std::string rule = lang == Language::en ? "Order of a polygon's vertices: the order Sutherland–Hodgman writes them."
                                                    : "Reihenfolge der Eckpunkte eines Polygons: die, in der Sutherland–Hodgman sie ausgibt.";
      const std::string closing = lang == Language::en ? "starting with the closing edge from the last vertex to the first"
                                                       : "beginnend mit der schließenden Kante vom letzten zum ersten Punkt";
      bool anyPolygon = false;
      for (const AssignmentItem& item : b.assignment.items) {
        const bool polygon = item.path.find("/clip_steps/") != std::string::npos || item.path.ends_with("/clipped_dc");
        if (!polygon) continue;
        anyPolygon = true;
        ++polygons;
        // Just above the item's first value: which vertex comes first and which way round.
        const std::string row = "<tr><td>" + asHtml(item.title) + " [1][1]</td>";
        const size_t at = text.find(row);
        ASSERT_NE(at, std::string::npos) << what << ": " << item.title;
        const size_t previous = text.rfind("<tr>", at - 1);
        ASSERT_NE(previous, std::string::npos);
        const std::string note = text.substr(previous, at - previous);
        EXPECT_NE(note.find(lang == Language::en ? "Vertices in the order" : "Eckpunkte in der Reihenfolge"), std::string::npos)
            << what << ": " << item.title << ": " << note;
        EXPECT_NE(note.find(item.path.ends_with("/clipped_dc")
                                ? (lang == Language::en ? "after the front plane (the same first vertex, the same direction)"
                                                        : "nach der vorderen Ebene (derselbe erste Punkt, derselbe Umlaufsinn)")
                                : (lang == Language::en ? "first the vertex it writes first, then on in the direction of"
                                                        : "zuerst der Punkt, den er zuerst schreibt, dann weiter im Umlaufsinn")),
                  std::string::npos)
            << what << ": " << note;
      }
      const size_t ruleAt = text.find(rule);
      EXPECT_EQ(ruleAt != std::string::npos, anyPolygon) << what;
      EXPECT_EQ(text.find(closing) != std::string::npos, anyPolygon) << what;
      if (!anyPolygon) continue;
      // The rule comes before the answers it speaks of.
      EXPECT_LT(ruleAt, text.find(":NUMERICAL:")) << what;
      // And it is the key's order: each plane's polygon is what the stated rule writes from the one before.
      const Json& poly = b.reference.at(Json::json_pointer("/objects/0/polygons/0"));
      Json input = poly.at("npc_h");
      for (int plane = 0; plane < 6; ++plane) {
        const Json& key = poly.at("clip_steps").at(size_t(plane)).at("polygon");
        EXPECT_TRUE(sameVertices(byTheStatedRule(input, plane), key)) << what << " plane " << plane;
        input = key;
      }
      // The clipped polygon in DC: the front plane's, vertex for vertex, divided by w and mapped.
      const Json& dc = poly.at("clipped_dc");
      const Json& m = b.reference.at(Json::json_pointer("/matrices/dc_from_npc"));
      ASSERT_EQ(dc.size(), input.size()) << what;
      Json mapped = Json::array();
      for (const Json& q : input) {
        const double h[] = {q[0].get<double>() / q[3].get<double>(), q[1].get<double>() / q[3].get<double>(),
                            q[2].get<double>() / q[3].get<double>(), 1};
        Json v = Json::array();
        for (int r = 0; r < 3; ++r) {
          double sum = 0;
          for (int c = 0; c < 4; ++c) sum += m[r][c].get<double>() * h[c];
          v.push_back(sum);
        }
        mapped.push_back(v);
      }
      EXPECT_TRUE(sameVertices(mapped, dc)) << what << ": " << dc.dump() << " vs " << mapped.dump();
    }
  EXPECT_EQ(polygons, 4u * 7u * 2u);  // the clipping sheets' six passes and the polygon in DC, both languages
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
