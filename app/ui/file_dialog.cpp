#include "app/ui/file_dialog.h"

#include "app/text/catalogue.h"
#include "app/ui/widgets.h"

#define IMGUI_DEFINE_MATH_OPERATORS
#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace vplab {

void FileDialog::open(std::string title, Mode mode, std::vector<std::string> extensions, std::filesystem::path start,
                      std::function<void(const std::filesystem::path&)> onChosen) {
  title_ = std::move(title);
  mode_ = mode;
  extensions_ = std::move(extensions);
  std::error_code ec;
  if (start.empty()) start = std::filesystem::current_path(ec);
  if (std::filesystem::is_directory(start, ec)) {
    directory_ = start;
    name_.clear();
  } else {
    directory_ = start.parent_path().empty() ? std::filesystem::current_path(ec) : start.parent_path();
    name_ = start.filename().string();
  }
  onChosen_ = std::move(onChosen);
  error_.clear();
  pending_ = true;
  list();
}

void FileDialog::list() {
  entries_.clear();
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(directory_, ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    const bool dir = e.is_directory(ec);
    const std::string ext = e.path().extension().string();
    if (dir || std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end()) entries_.push_back(e);
  }
  if (ec) error_ = directory_.string() + ": " + ec.message();
  std::sort(entries_.begin(), entries_.end(), [&](const auto& a, const auto& b) {
    std::error_code e1;
    const bool da = a.is_directory(e1), db = b.is_directory(e1);
    return da != db ? da : a.path().filename() < b.path().filename();
  });
}

void FileDialog::draw(Language lang) {
  if (pending_) {
    ImGui::OpenPopup(title_.c_str());
    pending_ = false;
    open_ = true;
  }
  if (!open_) return;
  ImGui::SetNextWindowSize(ImVec2(560, 420) * ImGui::GetIO().FontGlobalScale, ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(title_.c_str(), &open_)) return;
  ImGui::TextUnformatted(directory_.string().c_str());
  if (ImGui::Button(text::Text("Up").in(lang)) && directory_.has_parent_path()) {
    directory_ = directory_.parent_path();
    list();
  }
  const float footer = ImGui::GetFrameHeightWithSpacing() * 2.5f;
  ImGui::BeginChild("files", ImVec2(0, -footer), true);
  std::filesystem::path chosen;
  for (const auto& e : entries_) {
    std::error_code ec;
    const bool dir = e.is_directory(ec);
    const std::string label = dir ? text::fill(lang, "[dir] {1}", {e.path().filename().string()}) : e.path().filename().string();
    if (ImGui::Selectable(label.c_str(), !dir && e.path().filename().string() == name_,
                          ImGuiSelectableFlags_AllowDoubleClick)) {
      if (dir) {
        directory_ = e.path();
        list();
        break;
      }
      name_ = e.path().filename().string();
      if (ImGui::IsMouseDoubleClicked(0)) chosen = e.path();
    }
  }
  ImGui::EndChild();
  ImGui::SetNextItemWidth(-1);
  // The name takes the keys as the dialog opens: Enter accepts what is suggested, as in every file dialog.
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  if (ImGui::InputText("##name", &name_, ImGuiInputTextFlags_EnterReturnsTrue) && !name_.empty())
    chosen = directory_ / name_;
  ui::recordRect("dialog.fileName");
  if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error_.c_str());
  if (ImGui::Button((mode_ == Mode::open ? text::Text("Open") : text::Text("Save")).in(lang)) && !name_.empty()) chosen = directory_ / name_;
  ImGui::SameLine();
  if (ImGui::Button(text::Text("Cancel").in(lang))) {
    open_ = false;
    ImGui::CloseCurrentPopup();
  }
  if (!chosen.empty()) {
    if (mode_ == Mode::save && chosen.extension().empty() && !extensions_.empty()) chosen += extensions_.front();
    open_ = false;
    ImGui::CloseCurrentPopup();
    onChosen_(chosen);
  }
  ImGui::EndPopup();
}

}  // namespace vplab
