#include "ControlPanel.h"

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>

#include <algorithm>
#include <cmath>

#include "../FormatValue.h"
#include "CameraControl.h"

namespace odelab {

namespace {
// The panel's width in text heights: room for a label, a slider and a field.
constexpr float WIDTH_IN_LINES = 18.0f;
}  // namespace

ControlPanel::ControlPanel(SDL_Window* window, void* glContext, const std::string& fontPath, int textPixels,
                           bool visible)
    : visible_(visible) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini written into the working folder
  io.Fonts->AddFontFromFileTTF(fontPath.c_str(), static_cast<float>(textPixels));
  ImGui::StyleColorsDark();
  ImGui::GetStyle().Alpha = 0.92f;
  ImGui_ImplSDL2_InitForOpenGL(window, glContext);
  ImGui_ImplOpenGL3_Init("#version 330");
  width_ = WIDTH_IN_LINES * static_cast<float>(textPixels);
}

ControlPanel::~ControlPanel() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplSDL2_Shutdown();
  ImGui::DestroyContext();
}

bool ControlPanel::contains(int x, int y) const {
  return visible_ && x >= x_ && x < x_ + width_ && y >= y_ && y < y_ + height_;
}

bool ControlPanel::handleEvent(const SDL_Event& event) {
  // The pointer is tracked here rather than read back from SDL, so that
  // scripted events (pushed, never seen by the OS) drive the panel too.
  switch (event.type) {
    case SDL_MOUSEMOTION:
      mouseX_ = event.motion.x;
      mouseY_ = event.motion.y;
      break;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
      mouseX_ = event.button.x;
      mouseY_ = event.button.y;
      if (event.button.button == SDL_BUTTON_LEFT) {
        leftDown_ = event.type == SDL_MOUSEBUTTONDOWN;
        leftPressed_ = leftPressed_ || leftDown_;
      }
      break;
    default:
      break;
  }
  if (!visible_) return false;
  ImGui_ImplSDL2_ProcessEvent(&event);
  const ImGuiIO& io = ImGui::GetIO();
  switch (event.type) {
    case SDL_MOUSEMOTION:
      return contains(event.motion.x, event.motion.y) && leftDown_;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
      return contains(event.button.x, event.button.y);
    case SDL_MOUSEWHEEL:
      return contains(mouseX_, mouseY_);
    case SDL_KEYDOWN:
    case SDL_KEYUP:
    case SDL_TEXTINPUT:
      return io.WantTextInput;
    default:
      return false;
  }
}

bool ControlPanel::edit(const std::string& label, double& value, double min, double max, bool logScale,
                        bool integer) {
  auto found = editing_.find(label);
  double shown = found != editing_.end() ? found->second : value;
  ImGui::PushID(label.c_str());
  ImGui::TextUnformatted(label.c_str());
  ImGui::SetNextItemWidth(width_ * 0.45f);
  const ImGuiSliderFlags flags = (logScale ? ImGuiSliderFlags_Logarithmic : 0) | ImGuiSliderFlags_AlwaysClamp;
  ImGui::SliderScalar("##slider", ImGuiDataType_Double, &shown, &min, &max, integer ? "%.0f" : "%.4g", flags);
  bool done = ImGui::IsItemDeactivatedAfterEdit();
  bool active = ImGui::IsItemActive();
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputDouble("##typed", &shown, 0.0, 0.0, integer ? "%.0f" : "%.6g", ImGuiInputTextFlags_AutoSelectAll);
  done = done || ImGui::IsItemDeactivatedAfterEdit();
  active = active || ImGui::IsItemActive();
  ImGui::PopID();
  if (active) editing_[label] = shown;
  if (!done) return false;
  editing_.erase(label);
  value = shown;
  return true;
}

void ControlPanel::timeButtons(AbstractWindow& scene) {
  auto press = [&scene](SDL_Keycode key) { scene.handleKey(key, false); };
  if (ImGui::Button(scene.time().paused() ? "Run (P)" : "Pause (P)")) press(SDLK_p);
  ImGui::SameLine();
  if (ImGui::Button("Step (O)")) press(SDLK_o);
  ImGui::SameLine();
  if (ImGui::Button("Reset (R)")) press(SDLK_r);
  if (ImGui::Button("Slower (-)")) press(SDLK_MINUS);
  ImGui::SameLine();
  if (ImGui::Button("Faster (=)")) press(SDLK_EQUALS);
  ImGui::SameLine();
  ImGui::Text("x%s", formatValue(scene.time().scale()).c_str());
  if (ImGui::Button("Rewind (,)")) press(SDLK_COMMA);
  ImGui::SameLine();
  if (ImGui::Button("Forward (.)")) press(SDLK_PERIOD);
  if (ImGui::Button("Start view (Home)")) scene.camera().goHome();
  ImGui::SameLine();
  if (ImGui::Button("Frame all")) frameScene(scene);
}

void ControlPanel::settings(AbstractWindow& scene) {
  for (const SettingSpec& spec : settingsTable()) {
    double value = settingValue(scene.settings(), spec.id);
    if (spec.id == SettingId::Solver) {
      ImGui::TextUnformatted("solver");
      int choice = value < 0.5 ? 0 : 1;
      const int before = choice;
      ImGui::RadioButton("QuickStep", &choice, 0);
      ImGui::SameLine();
      ImGui::RadioButton("dWorldStep", &choice, 1);
      if (choice != before) scene.changeSetting(spec.id, choice);
      continue;
    }
    // A logarithmic slider cannot reach 0; CFM 0 is typed (or F4 down).
    const double min = spec.logScale && spec.range->min <= 0 ? 1e-10 : spec.range->min;
    std::string label = std::string(spec.label) + (*spec.unit ? std::string(" (") + spec.unit + ")" : "") + "   " +
                        spec.keyName;
    if (edit(label, value, min, spec.range->max, spec.logScale, spec.integer)) scene.changeSetting(spec.id, value);
  }
}

void ControlPanel::parameters(AbstractWindow& scene) {
  const auto& all = scene.parameters().all();
  for (int i = 0; i < static_cast<int>(all.size()); ++i) {
    const SceneParameter& p = all[i];
    double value = *p.value;
    const std::string label = p.label + (p.unit.empty() ? "" : " (" + p.unit + ")");
    if (edit(label, value, p.min, p.max, p.logScale, false)) scene.changeParameter(i, value);
  }
}

void ControlPanel::draw(AbstractWindow& scene, int windowWidth, int windowHeight) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplSDL2_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(static_cast<float>(mouseX_), static_cast<float>(mouseY_));
  io.MouseDown[0] = leftDown_ || leftPressed_;  // a click within one frame still counts
  leftPressed_ = false;
  ImGui::NewFrame();
  if (visible_) {
    x_ = static_cast<float>(windowWidth) - width_ - MARGIN;
    y_ = MARGIN;
    ImGui::SetNextWindowPos(ImVec2(x_, y_), ImGuiCond_Always);
    // The whole column, so the scene's view ends where the panel begins;
    // what does not fit scrolls.
    ImGui::SetNextWindowSize(ImVec2(width_, static_cast<float>(std::max(1, windowHeight - 2 * MARGIN))),
                             ImGuiCond_Always);
    ImGui::Begin("Controls (Tab hides)", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                      ImGuiWindowFlags_NoCollapse);
    timeButtons(scene);
    ImGui::Separator();
    settings(scene);
    if (!scene.parameters().all().empty()) {
      ImGui::Separator();
      parameters(scene);
    }
    height_ = ImGui::GetWindowHeight();
    ImGui::End();
  }
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace odelab
