// The page's services, the browser's side of what the desktop does with files and its window title
// (docs/students.md "In the browser"): the file picker and drag and drop (the files land in the in-memory
// file system under /uploads), downloads (saved scenes and exported views are written under /downloads,
// handed to the browser and removed), the address's fragment (the link to what is shown), the
// autosave and the chosen language kept in localStorage, and the warning before a page with unsaved
// changes is left. The DOM side is in index.html (vplabPage).
#pragma once

#include "app/session/exercises.h"
#include "app/session/file_chooser.h"
#include "base/language.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace vplab::page {

/// The browser's FileChooser: open mode clicks the page's hidden file input and calls back when the
/// picked file has been copied into /uploads; save mode writes the file under /downloads, then the
/// browser downloads it under the suggested name.
class BrowserFiles final : public FileChooser {
 public:
  void open(std::string title, Mode mode, std::vector<std::string> extensions, std::filesystem::path start,
            std::function<void(const std::filesystem::path&)> onChosen) override;
  bool isOpen() const override { return false; }  // the browser's picker is the browser's
  bool downloads() const override { return true; }
  /// The page copied the picked file to `file`: the pending open goes on. Returns false when no
  /// open was asked for (the file is then opened as a dropped one).
  bool chosen(const std::filesystem::path& file);

 private:
  std::function<void(const std::filesystem::path&)> pending_;
};

/// Hands `file` (in the in-memory file system) to the browser as a download named `name`, then removes it.
void download(const std::filesystem::path& file, const std::string& name);
/// location.hash without '#'.
std::string locationHash();
/// Replaces the fragment without a new history entry (the back button does not step through drags).
void replaceLocationHash(const std::string& fragment);
/// The page asks before it is left (closed, reloaded, navigated away) while `unsaved`.
void setUnsavedChanges(bool unsaved);
/// Hands a scene's text to the page's loader worker (loader-worker.js), which builds its meshes off
/// this thread and answers through vplab_loader_mesh and vplab_loader_done (SceneLoader::useRemote).
void buildInWorker(uint64_t id, const std::string& text, const std::string& source, const std::filesystem::path& baseDir);
/// The first frame is on the canvas: resolves window.vplab.ready and notes the time.
void firstFrameDrawn();
/// A frame's own work from `start` to `end` (emscripten_get_now(), ms): a performance measure "vplab frame".
void frameWorked(double start, double end);
/// A part of the frame (app/render/frame_parts.h) that took `seconds` and ended now: a measure
/// "vplab part: <part>".
void partWorked(const char* part, double seconds);
/// Whether a field has the keys: when none has, the page's hidden input lets go of the focus, which
/// closes a phone's on-screen keyboard (index.html opens it, in the tap's handler).
void setKeysWanted(bool wanted);
/// Lecture mode takes the browser's full screen (`on`) or leaves it; a browser that refuses (no
/// recent gesture, an iframe without allowfullscreen) leaves the page as it is, lecture mode still on.
void setFullScreen(bool on);
/// The page's document.title.
void setPageTitle(const std::string& title);
/// Says on the page, over the canvas, that the lab stopped (an unexpected error); also console.error.
void showFatalError(const std::string& message);
/// The autosave in the browser's localStorage, the page's counterpart of the desktop's state
/// directory: unsaved changes survive a closed tab, a crash or a reload. Each tab keeps its own
/// (under "vplab.recovery.TAB", TAB kept in the tab's sessionStorage), so two tabs never overwrite
/// each other's; index.html finds, before the lab starts, which kept scenes belong to no open tab
/// (each open tab holds a Web Lock named for it).
struct KeptScene {
  std::string key;   // its localStorage key
  std::string text;  // the autosave file's content
};
/// The scenes left by tabs that are no longer open (and by this tab before a reload).
std::vector<KeptScene> keptScenes();
/// Removes a kept scene (recovered or discarded).
void dropKeptScene(const std::string& key);
/// Keeps `text` (this tab's autosave file) in localStorage; an empty text removes it. Returns
/// false when the browser refused (storage full or disabled).
bool storeRecovery(const std::string& text);
/// Where an exercise's answers are kept: localStorage ("vplab.answer.KEY", exerciseKey), shared by
/// the page's tabs (the latest typed wins), surviving a reload (issue 40).
AnswerShelf answerShelf();
/// The page's language (index.html decides it before the lab starts): View ▸ Language's choice kept in
/// localStorage ("vplab.language"), else the browser's (navigator.languages: German for "de…", else English).
Language language();
/// View ▸ Language chose `lang`: the page's own texts follow it, and localStorage keeps it for the
/// next visit. Returns false when the browser refused to keep it (storage full or disabled).
bool rememberLanguage(Language lang);
/// Whether the canvas's WebGL context is lost now (its webglcontextlost event may not have come yet).
bool graphicsContextLost();
/// Forgets every GL name of a lost context in emscripten's tables (the context was restored without
/// them): deleting one then is a no-op, not a call that WebGL warns about in the console.
void forgetLostGlObjects();
/// The canvas's size in CSS pixels (width, height).
std::pair<double, double> canvasCssSize();
/// window.devicePixelRatio (1 on a plain screen, 2 on most laptops' and tablets' screens).
double devicePixelRatio();

}  // namespace vplab::page
