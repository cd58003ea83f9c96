#include "app/web/page_services.h"

#include <emscripten.h>
#include <emscripten/html5.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <optional>
#include <memory>
#include <system_error>

namespace vplab::page {

namespace {

// The JavaScript halves (index.html defines window.vplabPage). Strings cross as UTF-8 pointers.
// clang-format off
EM_JS(void, jsPickFile, (const char* accept), { vplabPage.pickFile(UTF8ToString(accept)); });
EM_JS(void, jsDownload, (const char* file, const char* name), { vplabPage.download(UTF8ToString(file), UTF8ToString(name)); });
EM_JS(char*, jsLocationHash, (), {
  var s = location.hash.replace(/^#/, ""); var n = lengthBytesUTF8(s) + 1; var p = _malloc(n);
  stringToUTF8(s, p, n); return p;
});
EM_JS(char*, jsKeptScenes, (), {
  var s = JSON.stringify(vplabPage.keptScenes());
  var n = lengthBytesUTF8(s) + 1; var p = _malloc(n); stringToUTF8(s, p, n); return p;
});
EM_JS(void, jsDropKeptScene, (const char* key), { vplabPage.dropKeptScene(UTF8ToString(key)); });
EM_JS(int, jsStoreRecovery, (const char* text), { return vplabPage.storeRecovery(UTF8ToString(text)) ? 1 : 0; });
// An exercise's answer as the student types it (issue 40), one per exercise and shared by the tabs.
EM_JS(char*, jsKeptAnswer, (const char* key), {
  var s = null;
  try { s = localStorage.getItem("vplab.answer." + UTF8ToString(key)); } catch (e) {}
  if (s === null) return 0;
  var n = lengthBytesUTF8(s) + 1; var p = _malloc(n); stringToUTF8(s, p, n); return p;
});
EM_JS(int, jsStoreAnswer, (const char* key, const char* text), {
  try { localStorage.setItem("vplab.answer." + UTF8ToString(key), UTF8ToString(text)); return 1; } catch (e) { return 0; }
});
EM_JS(int, jsLanguageIsGerman, (), { return vplabPage.language() === "de" ? 1 : 0; });
EM_JS(int, jsRememberLanguage, (const char* code), { return vplabPage.rememberLanguage(UTF8ToString(code)) ? 1 : 0; });
EM_JS(void, jsReplaceLocationHash, (const char* fragment), { vplabPage.replaceHash(UTF8ToString(fragment)); });
EM_JS(void, jsSetUnsaved, (int unsaved), { vplabPage.unsaved = !!unsaved; });
EM_JS(void, jsFirstFrame, (), { vplabPage.firstFrame(); });
EM_JS(void, jsFrameWorked, (double start, double end), { vplabPage.frameWorked(start, end); });
EM_JS(void, jsPartWorked, (const char* part, double start, double end), { vplabPage.partWorked(UTF8ToString(part), start, end); });
EM_JS(void, jsKeysWanted, (int wanted), { vplabPage.keysWanted(!!wanted); });
EM_JS(void, jsFullScreen, (int on), { vplabPage.fullScreen(!!on); });
EM_JS(void, jsBuildInWorker, (double id, const char* text, size_t length, const char* source, const char* baseDir), {
  vplabPage.buildInWorker(id, text, length, UTF8ToString(source), UTF8ToString(baseDir));
});
EM_JS(void, jsSetTitle, (const char* title), { document.title = UTF8ToString(title); });
EM_JS(int, jsContextLost, (), {
  var gl = Module.canvas && Module.canvas.getContext("webgl2");
  return gl && gl.isContextLost() ? 1 : 0;
});
EM_JS(void, jsForgetLostGlObjects, (), {
  [GL.buffers, GL.programs, GL.framebuffers, GL.renderbuffers, GL.textures, GL.shaders, GL.vaos, GL.queries,
   GL.samplers, GL.transformFeedbacks, GL.syncs].forEach(function(table) {
    if (table) for (var i = 0; i < table.length; ++i) table[i] = null;
  });
});
EM_JS(void, jsFatal, (const char* message), { vplabPage.fatal(UTF8ToString(message)); });
// clang-format on

/// A file name the in-memory file system and the browser both take: the last path part, without
/// control characters or slashes.
std::string safeName(const std::filesystem::path& suggested, const char* fallback) {
  std::string name = suggested.filename().string();
  std::string out;
  for (char c : name)
    if (static_cast<unsigned char>(c) >= 0x20 && c != '/' && c != '\\' && c != 0x7f) out += c;
  if (out.empty() || out == "." || out == "..") out = fallback;
  return out.substr(0, 200);
}

}  // namespace

void BrowserFiles::open(std::string /*title*/, Mode mode, std::vector<std::string> extensions,
                        std::filesystem::path start, std::function<void(const std::filesystem::path&)> onChosen) {
  if (mode == Mode::open) {
    std::string accept;
    for (const std::string& e : extensions) accept += (accept.empty() ? "" : ",") + e;
    pending_ = std::move(onChosen);
    jsPickFile(accept.c_str());
    return;
  }
  const std::string name = safeName(start, extensions.empty() ? "vplab-file" : ("vplab" + extensions.front()).c_str());
  const std::filesystem::path dir = "/downloads";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::filesystem::path file = dir / name;
  onChosen(file);  // writes it (and says so in the status line, or the error)
  if (std::filesystem::exists(file, ec)) download(file, name);
}

bool BrowserFiles::chosen(const std::filesystem::path& file) {
  if (!pending_) return false;
  auto callback = std::move(pending_);
  pending_ = nullptr;
  callback(file);
  return true;
}

void download(const std::filesystem::path& file, const std::string& name) { jsDownload(file.c_str(), name.c_str()); }

std::string locationHash() {
  std::unique_ptr<char, decltype(&std::free)> text(jsLocationHash(), &std::free);
  return text ? std::string(text.get()) : std::string();
}

std::vector<KeptScene> keptScenes() {
  std::unique_ptr<char, decltype(&std::free)> text(jsKeptScenes(), &std::free);
  std::vector<KeptScene> kept;
  try {
    for (const auto& k : nlohmann::json::parse(text ? text.get() : "[]"))
      kept.push_back({k.at("key").get<std::string>(), k.at("text").get<std::string>()});
  } catch (const std::exception&) {
    // index.html writes this list itself; a broken one offers nothing rather than stopping the page
  }
  return kept;
}

void dropKeptScene(const std::string& key) { jsDropKeptScene(key.c_str()); }

bool storeRecovery(const std::string& text) { return jsStoreRecovery(text.c_str()) != 0; }

AnswerShelf answerShelf() {
  AnswerShelf shelf;
  shelf.load = [](const std::string& key) -> std::optional<std::string> {
    char* text = jsKeptAnswer(key.c_str());
    if (!text) return std::nullopt;
    std::string kept(text);
    std::free(text);
    return kept;
  };
  shelf.store = [](const std::string& key, const std::string& text) { return jsStoreAnswer(key.c_str(), text.c_str()) != 0; };
  return shelf;
}

Language language() { return jsLanguageIsGerman() ? Language::de : Language::en; }
bool rememberLanguage(Language lang) { return jsRememberLanguage(lang == Language::de ? "de" : "en") != 0; }

void replaceLocationHash(const std::string& fragment) { jsReplaceLocationHash(fragment.c_str()); }
void setUnsavedChanges(bool unsaved) { jsSetUnsaved(unsaved ? 1 : 0); }
void buildInWorker(uint64_t id, const std::string& text, const std::string& source, const std::filesystem::path& baseDir) {
  jsBuildInWorker(double(id), text.data(), text.size(), source.c_str(), baseDir.string().c_str());
}

void firstFrameDrawn() { jsFirstFrame(); }
void frameWorked(double start, double end) { jsFrameWorked(start, end); }
void partWorked(const char* part, double seconds) {
  const double end = emscripten_get_now();
  jsPartWorked(part, end - 1000 * seconds, end);
}
void setKeysWanted(bool wanted) { jsKeysWanted(wanted ? 1 : 0); }
void setFullScreen(bool on) { jsFullScreen(on ? 1 : 0); }
void setPageTitle(const std::string& title) { jsSetTitle(title.c_str()); }
void showFatalError(const std::string& message) { jsFatal(message.c_str()); }
void forgetLostGlObjects() { jsForgetLostGlObjects(); }
std::pair<double, double> canvasCssSize() {
  double w = 0, h = 0;
  if (emscripten_get_element_css_size("#canvas", &w, &h) != EMSCRIPTEN_RESULT_SUCCESS) return {0, 0};
  return {w, h};
}

bool graphicsContextLost() { return jsContextLost() != 0; }
double devicePixelRatio() { return emscripten_get_device_pixel_ratio(); }

}  // namespace vplab::page
