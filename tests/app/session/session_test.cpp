// The session without a window (issue 39 item 1): opening, saving, the questions before unsaved
// changes are lost or the program quits, autosave and recovery, links, lessons and the language,
// each driven through the answers a dialog would give. No GL, no ImGui: the file chooser is a fake
// that records what it was asked and answers as the user would.
#include "app/session/session.h"

#include "app/document/autosave.h"
#include "base/error.h"
#include "io/scene_io.h"
#include "tests/support/crash.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace vplab {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using test::readFile;
using test::TempDir;

fs::path preset(const char* name) { return fs::path(VPLAB_ASSETS) / "scenes" / name; }

/// A file chooser that remembers the last question and answers it when the test says so.
struct FakeChooser : FileChooser {
  struct Asked {
    std::string title;
    Mode mode = Mode::open;
    fs::path start;
    std::function<void(const fs::path&)> onChosen;
  };
  std::optional<Asked>* asked;
  explicit FakeChooser(std::optional<Asked>* out) : asked(out) {}
  void open(std::string title, Mode mode, std::vector<std::string>, fs::path start,
            std::function<void(const fs::path&)> onChosen) override {
    *asked = Asked{std::move(title), mode, std::move(start), std::move(onChosen)};
  }
  bool isOpen() const override { return asked->has_value(); }
};

/// A session over its own model, counting what it tells the viewer.
struct Lab {
  ViewerModel model;
  std::optional<FakeChooser::Asked> asked;
  int changed = 0;
  std::vector<size_t> steps;
  Session session;

  explicit Lab(Scene scene = defaultScene())
      : model(std::move(scene)),
        session(model, std::make_unique<FakeChooser>(&asked),
                {.changed = [this] { ++changed; }, .goToStep = [this](size_t s) { steps.push_back(s); }}) {}

  /// The user picks `file` in the chooser.
  void choose(const fs::path& file) {
    ASSERT_TRUE(asked.has_value()) << "no file was asked for";
    auto onChosen = std::move(asked->onChosen);
    asked.reset();
    onChosen(file);
  }
  /// Frames until the loader has delivered (a scene is read on a worker thread).
  void waitForLoad() {
    for (int i = 0; i < 2000 && session.loader().busy(); ++i) {
      session.beginFrame();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    session.beginFrame();
  }
  void edit() {
    model.doc.scene().camera.front += 0.25;
    model.doc.endFrame(false);
  }
};

// ---------------------------------------------------------------- opening and saving

TEST(Session, OpeningASceneReadsItOnTheWorkerAndStartsACleanDocumentWithFreshViews) {
  Lab lab;
  lab.model.display.world.style = Style::hiddenLine;
  lab.model.selectedObject = 3;
  lab.session.openScene(preset("parallel.json"));
  EXPECT_TRUE(lab.session.loader().busy());
  EXPECT_EQ(lab.session.wakeIn(0), 0.0) << "frames go on while it loads";
  lab.waitForLoad();
  EXPECT_EQ(lab.model.doc.path(), preset("parallel.json"));
  EXPECT_EQ(lab.model.doc.scene().camera, loadScene(preset("parallel.json")).camera);
  EXPECT_FALSE(lab.model.doc.dirty());
  EXPECT_NE(lab.model.display.world.style, Style::hiddenLine) << "a fresh document's views";
  EXPECT_EQ(lab.model.selectedObject, 0);
  EXPECT_THAT(lab.model.status, HasSubstr("parallel.json"));
  EXPECT_FALSE(lab.model.statusIsError);
  EXPECT_GE(lab.changed, 2) << "the start of the load and its arrival";
}

TEST(Session, AnUnreadableSceneIsAnErrorAndTheOpenSceneStays) {
  TempDir dir;
  Lab lab;
  const Scene before = lab.model.doc.scene();
  lab.session.openScene(dir.write("broken.json", "{ \"camera\": "));
  lab.waitForLoad();
  EXPECT_EQ(lab.model.doc.scene(), before);
  EXPECT_TRUE(lab.model.statusIsError);
  EXPECT_THAT(lab.model.status, HasSubstr("broken.json"));
}

TEST(Session, SaveNeverWritesOverABundledSceneItAsksForACopyAndRefusesTheBundledFolder) {
  TempDir dir;
  const fs::path bundled = preset("perspective.json");
  const std::string original = readFile(bundled);
  Lab lab(loadScene(bundled));
  lab.edit();
  lab.session.files().save();
  ASSERT_TRUE(lab.asked.has_value());
  EXPECT_EQ(lab.asked->mode, FileChooser::Mode::save);
  EXPECT_EQ(lab.asked->start.filename(), "perspective.json") << "the copy is named after the scene";
  EXPECT_NE(lab.asked->start.parent_path(), bundled.parent_path());
  lab.choose(bundled);  // the user picks the bundled file itself
  EXPECT_EQ(readFile(bundled), original);
  EXPECT_TRUE(lab.model.statusIsError);
  EXPECT_TRUE(lab.model.doc.dirty());
  lab.session.files().save();
  lab.choose(dir.path / "mine.json");
  EXPECT_FALSE(lab.model.doc.dirty());
  EXPECT_EQ(lab.model.doc.path(), dir.path / "mine.json");
  EXPECT_EQ(loadScene(dir.path / "mine.json").camera, lab.model.doc.scene().camera);
  EXPECT_EQ(readFile(bundled), original);
}

// ---------------------------------------------------------------- the questions

TEST(Session, ReplacingAnEditedSceneAsksFirstAndOnlyDiscardRunsTheReplacement) {
  Lab lab;
  int replaced = 0;
  lab.session.unlessUnsaved([&] { ++replaced; });
  EXPECT_EQ(replaced, 1) << "nothing unsaved: at once";
  EXPECT_FALSE(lab.session.asking());

  lab.edit();
  lab.session.unlessUnsaved([&] { ++replaced; });
  EXPECT_EQ(replaced, 1);
  EXPECT_TRUE(lab.session.discardAsked());
  EXPECT_TRUE(lab.session.asking()) << "nothing behind the question may move";
  lab.session.keepEditing();
  EXPECT_FALSE(lab.session.asking());
  lab.session.discardChanges();  // a stray answer after the question is gone does nothing
  EXPECT_EQ(replaced, 1);

  lab.session.newDocument();
  EXPECT_TRUE(lab.session.discardAsked());
  lab.session.discardChanges();
  EXPECT_FALSE(lab.session.asking());
  EXPECT_FALSE(lab.model.doc.dirty()) << "New replaced the edited scene";
  EXPECT_EQ(lab.model.doc.scene().camera, defaultScene().camera);
}

TEST(Session, QuittingWithUnsavedChangesAsksSaveDiscardOrCancel) {
  TempDir dir;
  Scene scene = loadScene(preset("perspective.json"));
  scene.path = dir.path / "mine.json";
  saveScene(scene, scene.path);
  Lab lab(loadScene(scene.path));

  lab.model.quitRequested = true;
  lab.session.endFrame(0);
  EXPECT_TRUE(lab.model.quitConfirmed) << "nothing unsaved: quits at once";

  lab.model.quitRequested = lab.model.quitConfirmed = false;
  lab.edit();
  lab.model.quitRequested = true;
  lab.session.endFrame(0);
  EXPECT_TRUE(lab.session.quitAsked());
  EXPECT_FALSE(lab.model.quitConfirmed);
  lab.session.cancelQuit();
  EXPECT_FALSE(lab.session.quitAsked());
  EXPECT_FALSE(lab.model.quitConfirmed);

  lab.model.quitRequested = true;
  lab.session.saveAndQuit();
  EXPECT_TRUE(lab.model.quitConfirmed);
  EXPECT_FALSE(lab.model.doc.dirty());
  EXPECT_EQ(loadScene(scene.path).camera.front, lab.model.doc.scene().camera.front) << "saved before quitting";
}

TEST(Session, QuittingAnEditedBundledSceneSavesACopyFirst) {
  TempDir dir;
  Lab lab(loadScene(preset("perspective.json")));
  lab.edit();
  lab.model.quitRequested = true;
  lab.session.saveAndQuit();
  EXPECT_FALSE(lab.model.quitConfirmed) << "not before the copy is saved";
  lab.choose(dir.path / "copy.json");
  EXPECT_TRUE(lab.model.quitConfirmed);
  EXPECT_TRUE(fs::exists(dir.path / "copy.json"));

  Lab other(loadScene(preset("perspective.json")));
  other.edit();
  other.model.quitRequested = true;
  other.session.discardAndQuit();
  EXPECT_TRUE(other.model.quitConfirmed);
  EXPECT_FALSE(other.asked.has_value());
}

// ---------------------------------------------------------------- autosave and recovery

/// Unsaved changes left behind by a process that ended without cleaning up (a crash), in `state`.
void crashWithUnsavedChanges(const fs::path& state, double front) {
  ASSERT_FALSE(test::crashWithUnsavedFront(state, preset("perspective.json"), front).empty());
}

TEST(Session, AutosaveWritesAnEditedSceneAfterTheDelayAndANormalEndLeavesNothing) {
  TempDir dir;
  Lab lab;
  lab.session.recovery().enableAutosave(dir.path / "state", 1.0);
  const fs::path file = lab.session.recovery().autosave()->file();
  lab.session.endFrame(0);
  EXPECT_FALSE(fs::exists(file)) << "nothing changed, nothing to keep";
  lab.edit();
  lab.session.endFrame(10);
  EXPECT_FALSE(fs::exists(file)) << "not before the delay";
  ASSERT_TRUE(lab.session.wakeIn(10).has_value());
  EXPECT_NEAR(*lab.session.wakeIn(10), 1.0, 1e-9);
  lab.session.endFrame(11.5);
  ASSERT_TRUE(fs::exists(file));
  EXPECT_EQ(Autosave::load(*Autosave::read(file)).camera, lab.model.doc.scene().camera);
  lab.session.recovery().endSession();
  EXPECT_FALSE(fs::exists(file));
}

/// Two sessions that ended with unsaved changes (front planes 0.5 and 0.75), offered to a new one.
struct TwoKept {
  TempDir dir;
  fs::path state = dir.path / "state";
  Lab lab;
  TwoKept() {
    crashWithUnsavedChanges(state, 0.5);
    crashWithUnsavedChanges(state, 0.75);
    lab.session.recovery().offerRecoveries(Autosave::findAll(state));
  }
};

TEST(Session, RecoveringAKeptSceneMakesItTheDocumentAndTheOthersStayKept) {
  TwoKept kept;
  Lab& lab = kept.lab;
  const fs::path& state = kept.state;
  ASSERT_EQ(lab.session.recovery().recoveries().size(), 2u);
  EXPECT_TRUE(lab.session.asking());
  const Recovery second = lab.session.recovery().recoveries()[1];
  const double front = Autosave::load(second).camera.front;
  lab.session.recovery().recover(1);
  EXPECT_FALSE(lab.session.asking());
  EXPECT_TRUE(lab.model.doc.dirty()) << "recovered changes are still unsaved";
  EXPECT_EQ(lab.model.doc.scene().camera.front, front);
  EXPECT_THAT(lab.model.status, HasSubstr("1 other kept scene"));
  EXPECT_FALSE(fs::exists(second.file)) << "the recovered one is this session's now";
  EXPECT_EQ(Autosave::findAll(state).size(), 1u) << "the other stays kept for the next start";
}

TEST(Session, DiscardingAndLaterAnswerTheRecoveryQuestion) {
  TwoKept kept;
  Lab& lab = kept.lab;
  const fs::path& state = kept.state;
  lab.session.recovery().discardRecovery(0);
  EXPECT_EQ(lab.session.recovery().recoveries().size(), 1u);
  EXPECT_EQ(Autosave::findAll(state).size(), 1u);
  lab.session.recovery().discardRecovery(7);  // no such entry: nothing happens
  EXPECT_EQ(lab.session.recovery().recoveries().size(), 1u);
  lab.session.recovery().recoverLater();
  EXPECT_FALSE(lab.session.asking());
  EXPECT_EQ(Autosave::findAll(state).size(), 1u) << "kept for the next start";
  EXPECT_EQ(lab.model.doc.scene().camera, defaultScene().camera) << "nothing was recovered";
}

// ---------------------------------------------------------------- links and lessons

TEST(Session, ALinkNamesTheSceneAndCameraAndShowsThemAgain) {
  Lab lab(loadScene(preset("parallel.json")));
  UrlState link = lab.session.links().urlState();
  EXPECT_EQ(link.scene, "parallel");
  Lab other;
  other.session.links().showUrlState(link, /*atStart=*/true);
  EXPECT_EQ(other.model.doc.scene().camera, lab.model.doc.scene().camera);
  EXPECT_EQ(other.model.doc.path(), preset("parallel.json"));

  UrlState bad;
  bad.scene = "nope";
  other.session.links().showUrlState(bad, false);
  ASSERT_EQ(other.model.linkProblems.size(), 1u) << "a scene that is not bundled is named";
  EXPECT_EQ(other.model.linkProblems[0].key, "scene");
  EXPECT_THAT(other.model.status, HasSubstr("scene=\"nope\""));
  EXPECT_TRUE(other.model.statusIsError);
  EXPECT_EQ(other.model.doc.path(), preset("parallel.json")) << "a bad scene opens nothing";
}

// Issue 41: a link explains itself. `#lesson=05-clipping&step=abc` opens the lesson and says the
// step was left out; a step the lesson does not have opens its first and says how many it has; three
// bad keys are named together; an invalid camera is left out and named with its reason.
TEST(Session, ALinkKeepsItsValidPartsAndNamesEveryPartLeftOut) {
  {
    Lab lab;
    lab.session.links().showUrlState(decodeUrlState("lesson=05-clipping.en&step=abc"), true);
    ASSERT_TRUE(lab.model.lesson.has_value()) << "the valid lesson is opened";
    EXPECT_EQ(lab.model.lesson->step(), 0u);
    ASSERT_EQ(lab.model.linkProblems.size(), 1u);
    EXPECT_EQ(lab.model.linkProblems[0].key, "step");
  }
  {
    Lab lab;
    lab.session.links().showUrlState(decodeUrlState("lesson=05-clipping.en&step=99"), true);
    ASSERT_TRUE(lab.model.lesson.has_value());
    EXPECT_EQ(lab.model.lesson->step(), 0u) << "a step the lesson does not have: its first, not its last";
    ASSERT_EQ(lab.model.linkProblems.size(), 1u);
    EXPECT_THAT(lab.model.status, HasSubstr("step=\"99\": the lesson has " + std::to_string(lab.model.lesson->stepCount()) + " steps"));
  }
  {
    Lab lab;
    lab.model.display.language = Language::de;
    lab.session.links().showUrlState(decodeUrlState("scene=nope&vrp=1,2&zoom=3&prp=0,2,7"), true);
    std::vector<std::string> keys;
    for (const LinkProblem& p : lab.model.linkProblems) keys.push_back(p.key);
    EXPECT_EQ(keys, (std::vector<std::string>{"vrp", "zoom", "scene"})) << "every bad key, all at once";
    EXPECT_THAT(lab.model.status, HasSubstr("Im Link nicht verstanden und weggelassen"));
    EXPECT_THAT(lab.model.status, HasSubstr("keine der mitgelieferten Szenen"));
    EXPECT_EQ(lab.model.doc.scene().camera.prp, Vec3(0, 2, 7)) << "the valid camera part is shown";
  }
  {
    Lab lab;
    const Camera before = lab.model.doc.scene().camera;
    lab.session.links().showUrlState(decodeUrlState("prp=" + std::to_string(before.vrp.x) + "," + std::to_string(before.vrp.y) +
                                                    "," + std::to_string(before.vrp.z)),
                                     false);
    EXPECT_EQ(lab.model.doc.scene().camera, before) << "PRP on VRP: the camera is left out";
    ASSERT_EQ(lab.model.linkProblems.size(), 1u);
    EXPECT_THAT(lab.model.status, HasSubstr("the camera is not valid"));
  }
}

TEST(Session, ALessonOpensAtItsStepAndALinkToAnotherStepMovesIt) {
  Lab lab;
  const fs::path lesson = bundledLessonFile("05-clipping.en", Language::en);
  ASSERT_FALSE(lesson.empty());
  lab.session.openLesson(lesson, 2);
  ASSERT_TRUE(lab.model.lesson.has_value());
  EXPECT_EQ(lab.model.lesson->step(), 2u);
  UrlState link = lab.session.links().urlState();
  EXPECT_EQ(link.lesson, "05-clipping.en");
  EXPECT_EQ(link.step, 3u) << "a link counts steps from 1";
  link.step = 5;
  lab.session.links().showUrlState(link, false);
  EXPECT_EQ(lab.steps, std::vector<size_t>{4}) << "the viewer is asked to move the lesson to step 5";
}

TEST(Session, ALessonThatCannotBeReadChangesNothingAndSaysWhy) {
  TempDir dir;
  Lab lab;
  lab.edit();
  const Scene before = lab.model.doc.scene();
  lab.session.openLesson(dir.write("broken.lesson.json", "{ \"steps\": 3 }"));
  EXPECT_FALSE(lab.model.lesson.has_value());
  EXPECT_FALSE(lab.session.asking()) << "nothing to ask about: the lesson was never opened";
  EXPECT_EQ(lab.model.doc.scene(), before);
  EXPECT_TRUE(lab.model.statusIsError);
}

// ---------------------------------------------------------------- preferences and edits

TEST(Session, AChosenLanguageAppliesEvenWhenItCannotBeRemembered) {
  Lab lab;
  lab.session.start({.rememberLanguage = [](Language) { throw Error("the preferences file is read-only"); }});
  lab.session.chooseLanguage(Language::de);
  EXPECT_EQ(lab.model.display.language, Language::de);
  EXPECT_TRUE(lab.model.statusIsError);
  EXPECT_THAT(lab.model.status, HasSubstr("read-only"));
  // The session's own texts follow the language.
  lab.session.openScene(preset("parallel.json"));
  EXPECT_THAT(lab.model.status, HasSubstr("wird geöffnet"));
  lab.waitForLoad();
}

TEST(Session, StartingTakesThePlatformsLanguageOffersTheKeptScenesAndAutosaves) {
  TempDir dir;
  const fs::path state = dir.path / "state";
  crashWithUnsavedChanges(state, 0.5);
  Lab lab;
  std::vector<Language> kept;
  lab.session.start({.language = Language::de,
                     .rememberLanguage = [&](Language lang) { kept.push_back(lang); },
                     .recoveries = Autosave::findAll(state),
                     .autosaveDirectory = state});
  EXPECT_EQ(lab.model.display.language, Language::de);
  EXPECT_TRUE(kept.empty()) << "the start's language is not a choice to remember";
  ASSERT_EQ(lab.session.recovery().recoveries().size(), 1u);
  EXPECT_TRUE(lab.session.asking());
  ASSERT_NE(lab.session.recovery().autosave(), nullptr);
  EXPECT_EQ(lab.session.recovery().autosave()->file().parent_path(), state);
  lab.session.chooseLanguage(Language::en);
  EXPECT_EQ(kept, std::vector<Language>{Language::en});
}

TEST(Session, AnObjectIsAddedWhereTheCameraLooksAndAMeshIsReadOnTheWorker) {
  Lab lab;
  const size_t before = lab.model.doc.scene().objects.size();
  addObject(lab.model, lab.model, lab.model, Shape::cube);
  ASSERT_EQ(lab.model.doc.scene().objects.size(), before + 1);
  EXPECT_EQ(lab.model.doc.scene().objects.back().transform.translate, lab.model.doc.scene().camera.vrp);
  EXPECT_EQ(lab.model.selectedObject, int(before));

  lab.session.files().openFile(fs::path(VPLAB_ASSETS) / "meshes" / "house.obj");
  EXPECT_TRUE(lab.model.objectToLoad.has_value()) << "an OBJ joins the scene, read on the worker";
  lab.session.beginFrame();
  lab.waitForLoad();
  EXPECT_EQ(lab.model.doc.scene().objects.size(), before + 2);
  EXPECT_EQ(lab.model.doc.scene().objects.back().shape, Shape::mesh);
}

// ---------------------------------------------------------------- exercises (issue 40)

ExerciseRef pipelineSheet() { return {ExerciseSpec{4, ExerciseTopic::pipeline, Projection::perspective}, "100", Language::en}; }

TEST(SessionExercises, AnExerciseBecomesTheDocumentAndEndsWithTheNextOne) {
  Lab lab;
  ASSERT_TRUE(lab.session.exercises().open(pipelineSheet(), Reveal::stages));
  ASSERT_TRUE(lab.model.practice);
  EXPECT_EQ(lab.model.doc.scene(), lab.model.practice->exercise.scene);
  EXPECT_TRUE(lab.model.display.overlays.vertexNames) << "the sheet names P1 … Pn, so do the views";
  EXPECT_TRUE(lab.model.showTasks);
  EXPECT_FALSE(lab.model.doc.dirty());
  lab.session.newDocument();
  EXPECT_FALSE(lab.model.practice) << "a new document ends the exercise";
}

TEST(SessionExercises, AClippingSheetStepsThroughItsPolygon) {
  Lab lab;
  ASSERT_TRUE(lab.session.exercises().open({ExerciseSpec{7, ExerciseTopic::clipping, Projection::perspective}, "", Language::en},
                                           Reveal::stages));
  EXPECT_TRUE(lab.model.stepThrough.active);
  EXPECT_EQ(lab.model.stepThrough.object, 0);
}

TEST(SessionExercises, WhatWasTypedIsKeptPerExerciseAndComesBackInTheNextSession) {
  TempDir dir;
  const fs::path shelf = dir.path / "answers";
  {
    Lab lab;
    lab.session.start({.answers = AnswerShelf::inDirectory(shelf)});
    ASSERT_TRUE(lab.session.exercises().open(pipelineSheet(), Reveal::stages));
    lab.model.practice->fields[0].texts[3] = "5/2";
    ++lab.model.practice->edits;
    lab.session.endFrame(0);
    EXPECT_TRUE(fs::exists(shelf / "pipeline-4-perspective-100.json"));
  }
  Lab next;
  next.session.start({.answers = AnswerShelf::inDirectory(shelf)});
  ASSERT_TRUE(next.session.exercises().open(pipelineSheet(), Reveal::stages));
  EXPECT_EQ(next.model.practice->fields[0].texts[3], "5/2");
  // Another exercise keeps its own.
  ASSERT_TRUE(next.session.exercises().open({ExerciseSpec{5, ExerciseTopic::pipeline, Projection::perspective}, "100", Language::en},
                                            Reveal::stages));
  EXPECT_EQ(next.model.practice->fields[0].texts[3], "");
}

TEST(SessionExercises, AShelfThatCannotKeepTheAnswerSaysSoOnceAndTheFieldsStay) {
  Lab lab;
  int stored = 0;
  lab.session.start({.answers = AnswerShelf{[](const std::string&) { return std::nullopt; },
                                            [&](const std::string&, const std::string&) { return ++stored, false; }}});
  ASSERT_TRUE(lab.session.exercises().open(pipelineSheet(), Reveal::stages));
  lab.model.practice->fields[0].texts[0] = "1";
  ++lab.model.practice->edits;
  lab.session.endFrame(0);
  EXPECT_TRUE(lab.model.statusIsError);
  EXPECT_THAT(lab.model.status, HasSubstr("could not be kept"));
  lab.model.setStatus("", false);
  ++lab.model.practice->edits;
  lab.session.endFrame(0);
  EXPECT_EQ(stored, 2);
  EXPECT_TRUE(lab.model.status.empty()) << "said once";
  EXPECT_EQ(lab.model.practice->fields[0].texts[0], "1");
}

TEST(SessionExercises, HandInAsksWhereAndWritesTheAnswerFile) {
  TempDir dir;
  Lab lab;
  ASSERT_TRUE(lab.session.exercises().open(pipelineSheet(), Reveal::stages));
  lab.model.practice->fields[0].texts[0] = "1";
  lab.session.exercises().handIn();
  ASSERT_TRUE(lab.asked);
  EXPECT_EQ(lab.asked->mode, FileChooser::Mode::save);
  EXPECT_EQ(lab.asked->start.filename(), "answer.json");
  lab.choose(dir.path / "answer.json");
  EXPECT_THAT(readFile(dir.path / "answer.json"), HasSubstr("\"1\""));
  EXPECT_THAT(lab.model.status, HasSubstr("answer.json"));
}

TEST(SessionExercises, AFolderThatIsNoExerciseIsNamedAndTheSceneStays) {
  TempDir dir;
  Lab lab;
  const Scene before = lab.model.doc.scene();
  EXPECT_FALSE(lab.session.exercises().openFolder(dir.path, Reveal::stages));
  EXPECT_TRUE(lab.model.statusIsError);
  EXPECT_THAT(lab.model.status, HasSubstr("exercise.json"));
  EXPECT_EQ(lab.model.doc.scene(), before);
  EXPECT_FALSE(lab.model.practice);
}

TEST(SessionExercises, AnExerciseLinkOpensItAndTheShownStateIsItsLink) {
  Lab lab;
  lab.session.links().showUrlState(decodeUrlState("#exercise=clipping&seed=7&id=100&reveal=values"), true);
  ASSERT_TRUE(lab.model.practice);
  EXPECT_EQ(lab.model.practice->ref.spec.seed, 7u);
  EXPECT_EQ(lab.model.practice->reveal, Reveal::values);
  EXPECT_EQ(encodeUrlState(lab.session.links().urlState()), "exercise=clipping&seed=7&id=100&reveal=values");
  // The same link again (the page hears its own address) keeps what was typed.
  lab.model.practice->fields[0].setRows(1);
  lab.session.links().showUrlState(decodeUrlState("exercise=clipping&seed=7&id=100&reveal=values"), false);
  EXPECT_EQ(lab.model.practice->fields[0].rows, 1);
}

}  // namespace
}  // namespace vplab
