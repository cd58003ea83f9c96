#include "course/exercise_file.h"

#include "base/error.h"
#include "io/json_read.h"
#include "io/limits.h"


namespace vplab {

std::optional<uint64_t> exerciseSeedFrom(std::string_view text) {
  if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  return std::stoull(std::string(text));
}

using Json = nlohmann::ordered_json;

Json exerciseFileObject(const ExerciseRef& ref) {
  return {{"vplab_exercise", 1},
          {"topic", toString(ref.spec.topic)},
          {"seed", ref.spec.seed},
          {"projection", toString(ref.spec.projection)},
          {"student_id", ref.studentId},
          {"language", ref.language == Language::de ? "de" : "en"}};
}

std::string exerciseFileJson(const ExerciseRef& ref) { return exerciseFileObject(ref).dump(2) + "\n"; }

ExerciseRef parseExerciseFile(std::string_view text, std::string_view source) {
  return parseExerciseObject(parseCheckedJson(text, source, kDefaultLimits.jsonDepth), source);
}

ExerciseRef parseExerciseObject(const Json& j, std::string_view source, std::string_view at) {
  const JsonReader r{std::string(source)};
  const std::string base(at);
  if (!j.is_object()) r.fail(base.empty() ? "/" : base, "an object expected (an exercise: topic, seed, projection, student_id)");
  r.object(j, base, {"vplab_exercise", "topic", "seed", "projection", "student_id", "language"});
  if (!j.contains("vplab_exercise") || j["vplab_exercise"] != 1)
    r.fail(base + "/vplab_exercise", "missing or not 1 (the format's version: this file is not a vplab exercise)");
  auto name = [&](const char* key) -> std::string {
    const Json& v = r.required(j, base, key);
    if (!v.is_string()) r.fail(base + "/" + key, "a string expected");
    return v.get<std::string>();
  };
  ExerciseRef ref;
  const std::string topic = name("topic");
  const auto t = fromString<ExerciseTopic>(topic);
  if (!t) r.fail(base + "/topic", "\"" + topic + "\" where orientation, mapping, clipping or pipeline is expected");
  ref.spec.topic = *t;
  const Json& seed = r.required(j, base, "seed");
  if (!seed.is_number_unsigned() || seed.get<uint64_t>() > kMaxExerciseSeed)
    r.fail(base + "/seed", seed.dump() + " where a whole number from 0 to 999999999999999999 is expected");
  ref.spec.seed = seed.get<uint64_t>();
  if (j.contains("projection")) {
    const std::string projection = name("projection");
    const auto p = fromString<Projection>(projection);
    if (!p) r.fail(base + "/projection", "\"" + projection + "\" where perspective, parallel or oblique is expected");
    ref.spec.projection = *p;
  }
  if (j.contains("student_id")) {
    ref.studentId = name("student_id");
    if (!ref.studentId.empty() && !validStudentId(ref.studentId))
      r.fail(base + "/student_id", "\"" + ref.studentId + "\": at most 64 letters, digits, '.', '-' or '@' expected");
  }
  if (j.contains("language")) {
    const std::string lang = name("language");
    if (lang != "en" && lang != "de") r.fail(base + "/language", "\"" + lang + "\" where en or de is expected");
    ref.language = lang == "de" ? Language::de : Language::en;
  }
  return ref;
}

Json answerNamingExercise(const Json& answer, const ExerciseRef& ref) {
  Json named = {{"exercise", exerciseFileObject(ref)}};
  for (const auto& [key, value] : answer.items())
    if (key != "exercise") named[key] = value;
  return named;
}

std::optional<ExerciseRef> exerciseOfAnswer(const Json& answer, std::string_view source) {
  if (!answer.is_object() || !answer.contains("exercise")) return std::nullopt;
  return parseExerciseObject(answer["exercise"], source, "/exercise");
}

std::string exerciseKey(const ExerciseRef& ref) {
  std::string key = std::string(toString(ref.spec.topic)) + "-" + std::to_string(ref.spec.seed) + "-" +
                    std::string(toString(ref.spec.projection));
  if (!ref.studentId.empty()) key += "-" + ref.studentId;
  return key;
}

}  // namespace vplab
