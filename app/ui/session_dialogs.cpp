// Index: 1 the frame  2 loading  3 questions
#include "app/ui/session_dialogs.h"

#include "app/ui/widgets.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>  // GetTopMostPopupModal

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vplab {

// ---------------------------------------------------------------- 1 the frame

void SessionDialogs::draw(float scale) {
  shownQuestion_ = false;
  loadingWindow(scale);
  recoveryDialog();
  quitDialog();
  discardDialog();
  session_.files().fileDialog().draw(s_.display.language);
}

bool SessionDialogs::open() const { return session_.asking() || ImGui::GetTopMostPopupModal() != nullptr; }

std::optional<double> SessionDialogs::wakeIn() const {
  if (session_.asking() && !shownQuestion_) return 0.0;
  return std::nullopt;
}

// ---------------------------------------------------------------- 2 loading

void SessionDialogs::loadingWindow(float scale) {
  if (!session_.loader().busy()) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(420 * scale, 0), ImGuiCond_Always);
  ImGui::Begin(ui::tr(s_, "Loading###Loading"), nullptr,
               ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("%s", ui::tr(s_, "Reading and tessellating {1}", {session_.loader().file().filename().string()}).c_str());
  // The reader reports no fraction: the bar sweeps to show the work goes on, the time counts.
  const double t = session_.loader().elapsed();
  char label[32];
  std::snprintf(label, sizeof label, "%.1f s", t);
  ImGui::ProgressBar(float(std::fmod(t, 1.5) / 1.5), ImVec2(-1, 0), label);
  if (ImGui::Button(ui::tr(s_, "Cancel"))) session_.cancelLoading();
  ui::recordRect("load.cancel");
  ImGui::End();
}

// ---------------------------------------------------------------- 3 questions

void SessionDialogs::recoveryDialog() {
  const char* title = ui::tr(s_, "Recover unsaved changes?###Recover unsaved changes?");
  const std::vector<Recovery>& recoveries = session_.recovery().recoveries();
  if (!recoveries.empty() && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  shownQuestion_ = true;
  const bool browser = session_.files().browser();
  auto line = [](const std::string& text) { ImGui::TextUnformatted(text.c_str()); };
  if (recoveries.size() == 1) {
    const Recovery& r = recoveries.front();
    const std::string name = session_.recovery().sceneName(r);
    if (browser) {
      line(ui::tr(s_, "A visit to vplab was left with unsaved changes of {1};", {name}));
      line(ui::tr(s_, "they were kept at {1}.", {r.savedAt}));
    } else {
      line(ui::tr(s_, "vplab did not end normally with unsaved changes of {1};", {name}));
      line(ui::tr(s_, "they were kept at {1} ({2}).", {r.savedAt, r.file.string()}));
    }
  } else {
    const std::string count = std::to_string(recoveries.size());
    if (browser) {
      line(ui::tr(s_, "{1} tabs or visits were left with unsaved changes. Recover one here;", {count}));
      ImGui::TextUnformatted(ui::tr(s_, "the others stay kept and are offered in the next tab or visit."));
    } else {
      line(ui::tr(s_, "{1} sessions were left with unsaved changes. Recover one here;", {count}));
      ImGui::TextUnformatted(ui::tr(s_, "the others stay kept and are offered at the next start."));
    }
  }
  std::optional<size_t> recovered, discarded;
  bool later = false;
  // The newest few, so that the dialog fits a screen after many crashes; the others come up as
  // these are discarded.
  constexpr size_t kListed = 6;
  const size_t listed = std::min(recoveries.size(), kListed);
  for (size_t i = 0; i < listed; ++i) {
    ImGui::PushID(int(i));
    if (recoveries.size() > 1) {
      ImGui::Separator();
      line(ui::tr(s_, "{1}, kept at {2}", {session_.recovery().sceneName(recoveries[i]), recoveries[i].savedAt}));
    }
    if (ImGui::Button(ui::tr(s_, "Recover them"))) recovered = i;
    const std::string suffix = i == 0 ? std::string() : "." + std::to_string(i);
    ui::recordRect(("recovery.recover" + suffix).c_str());
    ImGui::SameLine();
    if (ImGui::Button(ui::tr(s_, "Discard them"))) discarded = i;
    ui::recordRect(("recovery.discard" + suffix).c_str());
    ImGui::PopID();
  }
  if (recoveries.size() > listed) {
    ImGui::Separator();
    line(ui::tr(s_, "and {1} older ones, listed as these are discarded", {std::to_string(recoveries.size() - listed)}));
  }
  if (recoveries.size() > 1) {
    ImGui::Separator();
    if (ImGui::Button(ui::tr(s_, "Later"))) later = true;
    ui::recordRect("recovery.later");
  }
  // The answer last: it changes the list drawn above.
  if (recovered) session_.recovery().recover(*recovered);
  else if (discarded) session_.recovery().discardRecovery(*discarded);
  else if (later) session_.recovery().recoverLater();
  if (session_.recovery().recoveries().empty()) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

void SessionDialogs::quitDialog() {
  const char* title = ui::tr(s_, "Unsaved changes###Unsaved changes");  // the popup's id in either language
  if (session_.quitAsked() && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  shownQuestion_ = true;
  ImGui::TextUnformatted(ui::tr(s_, "The scene has unsaved changes. Save them before quitting?"));
  if (ImGui::Button(ui::tr(s_, "Save"))) {
    ImGui::CloseCurrentPopup();
    session_.saveAndQuit();
  }
  ImGui::SameLine();
  if (ImGui::Button(ui::tr(s_, "Discard them and quit"))) {
    ImGui::CloseCurrentPopup();
    session_.discardAndQuit();
  }
  ImGui::SameLine();
  if (ImGui::Button(ui::tr(s_, "Cancel"))) {
    ImGui::CloseCurrentPopup();
    session_.cancelQuit();
  }
  if (!session_.quitAsked()) ImGui::CloseCurrentPopup();  // answered elsewhere
  ImGui::EndPopup();
}

void SessionDialogs::discardDialog() {
  const char* title = ui::tr(s_, "Discard unsaved changes?###Discard unsaved changes?");
  if (session_.discardAsked() && !ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  shownQuestion_ = true;
  ImGui::TextUnformatted(ui::tr(s_, "The scene has unsaved changes. They are lost if another scene is opened."));
  if (ImGui::Button(ui::tr(s_, "Discard them"))) {
    ImGui::CloseCurrentPopup();
    session_.discardChanges();
  }
  ui::recordRect("discard.confirm");
  ImGui::SameLine();
  if (ImGui::Button(ui::tr(s_, "Keep editing"))) {
    ImGui::CloseCurrentPopup();
    session_.keepEditing();
  }
  if (!session_.discardAsked()) ImGui::CloseCurrentPopup();  // answered elsewhere (a link, a test)
  ImGui::EndPopup();
}

}  // namespace vplab
