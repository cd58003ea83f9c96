// The viewer's menus, keys, help and export (menus.h).
//
// Index: 1 the menu bar and the keys  2 help and export
#include "app/ui/menus.h"

#include "app/export/svg.h"
#include "app/gl/shader.h"
#include "app/gl/texture_io.h"
#include "app/render/headless.h"
#include "app/ui/keys.h"
#include "app/ui/widgets.h"
#include "app/views/render_request.h"
#include "base/error.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>

#include <array>
#include <optional>
#include <tuple>

namespace vplab {

namespace {

/// The value after `value` in `all` (the enum's table), the first after the last: the keys' cycles.
template <typename Enum, size_t N>
Enum nextOf(const std::array<Enum, N>& all, Enum value) {
  for (size_t i = 0; i < N; ++i)
    if (all[i] == value) return all[(i + 1) % N];
  return all[0];
}

}  // namespace

// ---------------------------------------------------------------- 1 the menu bar and the keys

void Menus::menuBar() {
  if (!ImGui::BeginMainMenuBar()) return;
  std::optional<ui::FingerRows> rows(std::in_place, s_.touch);  // every menu's entries, on touch
  const bool fileMenu = ImGui::BeginMenu(ui::tr(s_, "File"));
  ui::recordRect("menu.file");
  if (fileMenu) {
    // The browser owns Ctrl+N, Ctrl+O, Ctrl+S, Ctrl+W and F11, F12: the page offers these here only.
    auto key = [this](text::Text shortcut) { return session_.files().browser() ? nullptr : ui::tr(s_, shortcut); };
    if (ImGui::MenuItem(ui::tr(s_, "New (default lecture scene)"), key("Ctrl+N"))) session_.newDocument();
    ui::recordRect("menu.new");
    if (session_.files().browser()) {
      if (ImGui::MenuItem(ui::tr(s_, "Open a scene or an OBJ mesh…"))) session_.files().chooseFileToOpen();
      ui::recordRect("menu.open");
      if (ImGui::MenuItem(ui::tr(s_, "Save (download)"))) session_.files().save();
      ui::recordRect("menu.save");
    } else {
      if (ImGui::MenuItem(ui::tr(s_, "Open scene…"), ui::tr(s_, "Ctrl+O"))) session_.files().chooseFileToOpen();
      if (ImGui::MenuItem(ui::tr(s_, "Save"), ui::tr(s_, "Ctrl+S"))) session_.files().save();
      if (ImGui::MenuItem(ui::tr(s_, "Save as…"), ui::tr(s_, "Ctrl+Shift+S"))) session_.files().saveAs();
    }
    if (ImGui::MenuItem(ui::tr(s_, "Open exercise…"))) session_.exercises().chooseFile();
    ui::recordRect("menu.openExercise");
    if (ImGui::BeginMenu(ui::tr(s_, "Presets"), !session_.files().presets().empty())) {
      for (const SceneFileInfo& p : session_.files().presets())
        if (ImGui::MenuItem((p.titleIn(s_.display.language) + "##" + p.file.filename().string()).c_str())) {
          const std::filesystem::path file = p.file;
          session_.unlessUnsaved([this, file] { session_.openScene(file); });
        }
      ImGui::EndMenu();
    }
    lessonsMenu();
    // An exercise's answer, from wherever the Tasks are scrolled.
    if (s_.practice) {
      if (ImGui::MenuItem(ui::tr(s_, "Hand in…"))) session_.exercises().handIn();
      ui::recordRect("menu.handIn");
    }
    ImGui::Separator();
    const bool exportOpen = ImGui::BeginMenu(ui::tr(s_, "Export a view"));
    ui::recordRect("menu.export");
    if (exportOpen) {
      exportMenu();
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem(ui::tr(s_, "Screenshot"), key("F12"))) s_.screenshotRequested = true;
    if (!session_.files().browser()) {  // a page is closed by its tab
      if (ImGui::MenuItem(ui::tr(s_, "Quit"), ui::tr(s_, "Ctrl+Q"))) s_.quitRequested = true;
      ui::recordRect("menu.quit");  // the monkey test clicks anywhere but here
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu(ui::tr(s_, "Edit"))) {
    if (ImGui::MenuItem(ui::tr(s_, "Undo"), ui::tr(s_, "Ctrl+Z"), false, s_.doc.canUndo())) s_.doc.undo();
    if (ImGui::MenuItem(ui::tr(s_, "Redo"), ui::tr(s_, "Ctrl+Y"), false, s_.doc.canRedo())) s_.doc.redo();
    ImGui::EndMenu();
  }
  const bool viewMenu = ImGui::BeginMenu(ui::tr(s_, "View"));
  ui::recordRect("menu.view");
  if (viewMenu) {
    // A preference, kept when another scene is opened: white views for a bright lecture hall and
    // for exported pictures that will be printed.
    bool light = s_.display.theme == Theme::light;
    if (ImGui::MenuItem(ui::tr(s_, "Light theme (bright hall, print)"), nullptr, &light))
      s_.display.theme = light ? Theme::light : Theme::dark;
    // How long a lesson's move from one step into the next takes (0: at once).
    float seconds = float(s_.lessonSeconds);
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("0.00 s").x * 3);
    if (ImGui::SliderFloat(ui::tr(s_, "lesson moves"), &seconds, 0.f, 3.f, "%.1f s")) s_.lessonSeconds = seconds;
    ui::recordRect("menu.lessonSeconds");
    ui::tooltip(ui::Widgets(s_), "How long the camera and every number take to move from one step of a lesson into the next.");
    languageMenu();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu(ui::tr(s_, "Help"))) {
    if (ImGui::MenuItem(ui::tr(s_, "Mouse and keys"), "F1")) s_.showHelp = true;
    ImGui::EndMenu();
  }
  rows.reset();
  ImGui::EndMainMenuBar();
}

// View ▸ Language: the menus', panels' and views' language, remembered for the next start (the
// session writes the choice; --lang overrides it for one run).
void Menus::languageMenu() {
  const bool open = ImGui::BeginMenu(ui::tr(s_, "Language"));
  ui::recordRect("menu.language");
  if (!open) return;
  for (const auto& [lang, name, id] : {std::tuple{Language::en, text::Text("English"), "menu.language.en"},
                                       std::tuple{Language::de, text::Text("German (Deutsch)"), "menu.language.de"}}) {
    if (ImGui::MenuItem(ui::tr(s_, name), nullptr, s_.display.language == lang)) session_.chooseLanguage(lang);
    ui::recordRect(id);
  }
  ui::tooltip(ui::Widgets(s_), "The language of the menus, panels and the views' labels; vplab remembers it (--lang chooses it for one run).");
  ImGui::EndMenu();
}

// The bundled lessons do not change while vplab runs: their titles are read once per language, not in
// every frame the menu bar is drawn.
const std::vector<LessonFileInfo>& Menus::bundledLessons(Language lang) {
  auto found = bundledLessons_.find(lang);
  if (found == bundledLessons_.end()) found = bundledLessons_.emplace(lang, listBundledLessons(lang)).first;
  return found->second;
}

void Menus::lessonsMenu() {
  // The lessons in the labels' language first, then the others (a German course may show an English one).
  const Language first = s_.display.language;
  const Language second = first == Language::de ? Language::en : Language::de;
  const std::vector<LessonFileInfo>& mine = bundledLessons(first);
  const std::vector<LessonFileInfo>& others = bundledLessons(second);
  const bool open = ImGui::BeginMenu(ui::tr(s_, "Lessons"), !mine.empty() || !others.empty());
  ui::recordRect("menu.lessons");
  if (!open) return;
  auto items = [this](const std::vector<LessonFileInfo>& lessons, const char* prefix) {
    for (const LessonFileInfo& l : lessons) {
      const std::string label = prefix + l.title + "##" + l.file.filename().string();
      if (ImGui::MenuItem(label.c_str())) session_.openLesson(l.file);
      ui::recordRect(("menu.lesson." + l.file.stem().string()).c_str());
    }
  };
  items(mine, "");
  if (!others.empty()) {
    ImGui::Separator();
    items(others, second == Language::de ? ui::tr(s_, "(Deutsch) ") : ui::tr(s_, "(English) "));
  }
  if (s_.lesson) {
    ImGui::Separator();
    if (ImGui::MenuItem(ui::tr(s_, "Close the lesson"), "Esc")) {
      s_.lesson.reset();
      s_.lessonMarks.clear();
    }
  }
  ImGui::EndMenu();
}

void Menus::shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput) return;
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.KeyCtrl) {
    if (pressed(keys::kZ) && io.KeyShift) s_.doc.redo();
    else if (pressed(keys::kZ)) s_.doc.undo();
    if (pressed(keys::kY)) s_.doc.redo();
    if (session_.files().browser()) return;  // Ctrl+S, Ctrl+O, Ctrl+N, Ctrl+W, Ctrl+Q are the browser's: the File menu has them
    if (pressed(keys::kS)) {
      if (io.KeyShift) session_.files().saveAs();
      else session_.files().save();
    }
    if (pressed(keys::kN)) session_.newDocument();
    if (pressed(keys::kO)) session_.files().chooseFileToOpen();
    if (pressed(keys::kQ)) s_.quitRequested = true;
    return;
  }
  if (pressed(keys::kF11) && !session_.files().browser()) s_.lectureMode = !s_.lectureMode;
  if (pressed(keys::kEscape) && s_.lectureMode) {
    s_.lectureMode = false;
    return;
  }
  if (pressed(keys::kF1)) s_.showHelp = !s_.showHelp;
  if (pressed(keys::kF12) && !session_.files().browser()) s_.screenshotRequested = true;
  if (pressed(keys::kEscape) && !s_.lesson) s_.probe.reset();  // in a lesson: the lesson's (app/ui/lesson_presenter.h)
  for (size_t i = 0; i < allOf<Style>().size() && !s_.lesson; ++i)  // 1 to 5; in a lesson they type a step's number
    if (pressed(keys::kDigit1 + int(i)))
      s_.display.camera.style = s_.display.world.style = s_.display.npc.style = allOf<Style>()[i];
  if (pressed(keys::kP)) {
    Camera& c = s_.doc.scene().camera;
    c.projection = nextOf(allOf<Projection>(), c.projection);
  }
  if (pressed(keys::kC)) s_.pipeline.strategy = nextOf(allOf<ClipStrategy>(), s_.pipeline.strategy);
  if (pressed(keys::kB)) s_.pipeline.boundingBoxTest = !s_.pipeline.boundingBoxTest;
  if (pressed(keys::kR)) {
    s_.display.world.orbit = defaultWorldOrbit(s_.doc.shown(), s_.worldAspect);
    s_.display.npc.orbit = defaultNpcOrbit();
  }
}

namespace {

// A view as the viewer shows it, as a request (app/views/render_request.h): its size, every view
// setting (styles, observers, overlays, morph) and the frame's marks (probe, handles, step-through),
// the pipeline's options and the UI scale.
RenderRequest shownViewRequest(const ViewerState& s, ViewKind kind, int width, int height, float scale) {
  RenderRequest r;
  r.view = kind;
  r.width = width;
  r.height = height;
  r.pipeline = s.pipeline;
  r.scale = scale;
  r.display = s.display;
  r.highlights = s.highlights;
  return r;
}

}  // namespace

// Each view as it is shown, to PNG, and the wireframe styles also as SVG (vector lines). The PNG is
// the image on screen, read back (drawn by the render thread from the same settings: drawing it
// again here would make the window wait for a large scene); the SVG is made from the view's request.
void Menus::exportMenu() {
  struct Entry {
    ViewKind kind;
    text::Text png, svg, title;
  };
  const Entry entries[] = {
      {ViewKind::camera, "camera view as PNG…", "camera view as SVG…", "Export the camera view"},
      {ViewKind::world, "world view as PNG…", "world view as SVG…", "Export the world view"},
      {ViewKind::npc, "NPC view as PNG…", "NPC view as SVG…", "Export the NPC view"}};
  for (const Entry& e : entries) {
    // The image shown (drawn in this thread or on the views' render thread: textures are shared).
    const GLuint texture = images_.texture(e.kind);
    const ViewKind kind = e.kind;
    const int w = images_.width(kind), h = images_.height(kind);
    const bool pngChosen = ImGui::MenuItem(ui::tr(s_, e.png), nullptr, false, texture != 0);
    ui::recordRect(("export." + std::string(toString(e.kind)) + ".png").c_str());
    if (pngChosen) {
      session_.files().fileDialog().open(ui::tr(s_, e.title), FileChooser::Mode::save, {".png"},
                   "vplab-" + std::string(toString(e.kind)) + ".png", [this, texture, kind, w, h](const std::filesystem::path& f) {
                     try {
                       // OpenGL ES (the browser's WebGL2) cannot read a texture back, and the page has
                       // no render thread to wait for: the view is drawn again, as it is shown.
                       const bool es = gl::dialectOf(ctx_.gl()) == gl::GlslDialect::es300;
                       const bool camera = kind == ViewKind::camera;  // shown at the device's W × H
                       writePng(es ? exportImage(kind, camera ? 0 : w, camera ? 0 : h) : readTexture(ctx_.gl(), texture), f);
                       s_.setStatus(ui::tr(s_, "exported {1}", {f.string()}), false);
                     } catch (const Error& err) {
                       s_.setStatus(err.what(), true);
                     }
                   });
    }
    const std::optional<std::string> why = svgExportError(e.kind, s_.doc.shown(), s_.display);
    const bool svgChosen = ImGui::MenuItem(ui::tr(s_, e.svg), nullptr, false, !why && texture != 0);
    ui::recordRect(("export." + std::string(toString(e.kind)) + ".svg").c_str());
    if (svgChosen) {
      session_.files().fileDialog().open(ui::tr(s_, e.title), FileChooser::Mode::save, {".svg"},
                   "vplab-" + std::string(toString(kind)) + ".svg", [this, kind, w, h](const std::filesystem::path& f) {
                     try {
                       writeSvg(svgOfRequest(s_.doc.shown(), shownViewRequest(s_, kind, w, h, uiScale_)), f);
                       s_.setStatus(ui::tr(s_, "exported {1}", {f.string()}), false);
                     } catch (const Error& err) {
                       s_.setStatus(err.what(), true);
                     }
                   });
    }
    if (why && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why->c_str());
  }
}

// ---------------------------------------------------------------- 2 help and export

void Menus::helpWindow() {
  if (!s_.showHelp) return;
  // Fits the display at any UI scale; the text wraps inside.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(ImMin(ImVec2(560, 520) * uiScale_, display * 0.9f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImGui::GetIO().DisplaySize * 0.5f, ImGuiCond_FirstUseEver, ImVec2(0.5f, 0.5f));
  if (ImGui::Begin(ui::tr(s_, "Help (F1)###help"), &s_.showHelp)) {
    ImGui::TextUnformatted(ui::tr(s_, "Mouse"));
    for (const text::Text line : {text::Text("world and NPC views: left-drag orbits, right- or middle-drag pans, the wheel zooms"),
                                  text::Text("world view: drag the handles (VRP, PRP, the window's edges, front and back planes)"),
                                  text::Text("any view: click a vertex to probe it through the pipeline")}) {
      ImGui::Bullet();
      ImGui::TextWrapped("%s", ui::tr(s_, line));
    }
    ImGui::Spacing();
    ImGui::TextUnformatted(ui::tr(s_, "Keys"));
    const text::Text keys[][2] = {{"Ctrl+Z", "undo"},
                                  {"Ctrl+Y, Ctrl+Shift+Z", "redo"},
                                  {"Ctrl+N", "new: the default lecture scene"},
                                  {"Ctrl+O", "open a scene"},
                                  {"Ctrl+S / Ctrl+Shift+S", "save (a bundled scene: as a copy) / save as"},
                                  {"Ctrl+Q", "quit (asks when the scene has unsaved changes)"},
                                  {"1 to 5", "style of every view: flat, shaded, wire, hidden-line, hidden removed"},
                                  {"P", "next projection: perspective, parallel, oblique"},
                                  {"C", "next clipping strategy: NPC, WC, divide first (wrong)"},
                                  {"B", "bounding-box test on or off"},
                                  {"R", "reset the observers of the world and NPC views"},
                                  {"Esc", "clear the vertex probe"},
                                  {"F1", "this help"},
                                  {"F11", "lecture mode: one view fills the window (Esc returns)"},
                                  {"Shift+click", "in the camera view: step through the clipping of that polygon"},
                                  {"F12", "screenshot of the whole window (PNG in the working directory)"},
                                  {"→ Space Page Down", "in a lesson (File > Lessons): the next step"},
                                  {"← Page Up", "in a lesson: the step before"},
                                  {"Home / End", "in a lesson: the first / the last step"},
                                  {"a number, Enter", "in a lesson: that step (the digits then choose no style)"},
                                  {"Esc", "in a lesson: forget the typed number, else close the lesson"}};
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
      for (const auto& k : keys) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(ui::tr(s_, k[0]));
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", ui::tr(s_, k[1]));
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

Image Menus::exportImage(ViewKind kind, int width, int height) {
  const GLint previous = [&] {
    GLint fb = 0;
    ctx_.gl().GetIntegerv(GL_FRAMEBUFFER_BINDING, &fb);
    return fb;
  }();
  Image image = renderImage(renderer_, *s_.ranScene, shownViewRequest(s_, kind, width, height, uiScale_));
  ctx_.gl().BindFramebuffer(GL_FRAMEBUFFER, GLuint(previous));
  return image;
}

}  // namespace vplab
