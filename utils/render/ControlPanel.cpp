#include "ControlPanel.h"

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../FormatValue.h"
#include "../SceneKeys.h"
#include "../TypedNumber.h"
#include "CameraControl.h"

namespace odelab {

namespace {
// The panel's width in text heights: room for a label, a slider and a
// field; narrower (down to the least) in a narrow window, to leave the
// scene at least three quarters of it.
constexpr float WIDTH_IN_LINES = 18.0f, LEAST_WIDTH_IN_LINES = 14.0f;
constexpr float MOST_WINDOW_SHARE = 0.25f;
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
#ifdef __EMSCRIPTEN__
  ImGui_ImplOpenGL3_Init("#version 300 es");
#else
  ImGui_ImplOpenGL3_Init("#version 330");
#endif
  textPixels_ = static_cast<float>(textPixels);
  width_ = WIDTH_IN_LINES * textPixels_;
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
  // A key pressed and released within one frame (scripted input, a quick
  // tap) would leave ImGui's key state up before it looks: it is held down
  // for the next frame, as a click is.
  if (event.type == SDL_KEYDOWN && event.key.keysym.scancode < 512) pressedKeys_.push_back(event.key.keysym.scancode);
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

namespace {

// Tab in a typed field commits it (the field takes Tab through this
// callback, so ImGui does not move the focus instead).
int noteTab(ImGuiInputTextCallbackData* data) {
  if (data->EventFlag == ImGuiInputTextFlags_CallbackCompletion) *static_cast<bool*>(data->UserData) = true;
  return 0;
}

std::string shownText(double value, bool integer) {
  char text[64];
  std::snprintf(text, sizeof text, integer ? "%.0f" : "%.6g", value);
  return text;
}

// A button on the same line as the last item where it fits, else on the next.
bool flowButton(const char* label) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float width = ImGui::CalcTextSize(label).x + 2 * style.FramePadding.x;
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= right) ImGui::SameLine();
  return ImGui::Button(label);
}

// The world settings in force as the command line that starts the program
// with them ("test2 --erp 0.4 --cfm 0 ... --solver quick").
std::string commandLineOf(const AbstractWindow& scene) {
  std::string line = scene.programName();
  for (const SettingSpec& spec : settingsTable())
    line += std::string(" ") + spec.option + " " + settingText(spec.id, settingValue(scene.tuning().settings(), spec.id));
  return line;
}

// A drag moves the mouse this far before it counts: a click is not a drag.
constexpr float LEAST_DRAG_PIXELS = 4.0f;

}  // namespace

bool ControlPanel::edit(const std::string& label, double& value, double min, double max, bool logScale,
                        bool integer) {
  auto found = editing_.find(label);
  double shown = found != editing_.end() ? found->second : value;
  ImGui::PushID(label.c_str());
  ImGui::TextWrapped("%s", label.c_str());
  ImGui::SetNextItemWidth(width_ * 0.45f);
  const ImGuiSliderFlags flags = (logScale ? ImGuiSliderFlags_Logarithmic : 0) | ImGuiSliderFlags_AlwaysClamp;
  // No number on the slider: its handle would cover it; the field beside
  // it shows the value, as it changes during a drag too.
  ImGui::SliderScalar("##slider", ImGuiDataType_Double, &shown, &min, &max, "", flags);
  const bool sliderActive = ImGui::IsItemActive();
  // A stray click on the slider would jump the value to the click: only a
  // drag commits.
  if (sliderActive && ImGui::IsMouseDragging(ImGuiMouseButton_Left, LEAST_DRAG_PIXELS)) dragged_ = true;
  bool done = ImGui::IsItemDeactivated() && dragged_;
  if (ImGui::IsItemDeactivated()) {
    if (!dragged_) shown = value;
    dragged_ = false;
  }
  if (sliderActive) {
    editing_[label] = shown;
    typing_.erase(label);
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  // The typed text is the field's own until Enter or Tab commits it (or a
  // click elsewhere), or Esc drops it.
  auto typed = typing_.find(label);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%s",
                typed != typing_.end() ? typed->second.c_str() : shownText(shown, integer).c_str());
  bool tab = false;
  const bool enter = ImGui::InputText("##typed", buffer, sizeof buffer,
                                     ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll |
                                         ImGuiInputTextFlags_CallbackCompletion,
                                     noteTab, &tab);
  const bool escape = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
  if (ImGui::IsItemActive() && !escape) typing_[label] = buffer;
  if (ImGui::IsItemActivated()) refusals_.erase(label);
  const bool commit = (enter || tab || (ImGui::IsItemDeactivated() && !escape)) && typing_.count(label) > 0;
  if (ImGui::IsItemDeactivated() && escape) typing_.erase(label);
  if (commit) {
    double read = 0;
    const std::string why = readTypedNumber(typing_[label], min, max, integer, read);
    typing_.erase(label);
    if (why.empty() && read != value) {
      shown = read;
      done = true;
    } else if (!why.empty()) {
      refusals_[label] = why + "; unchanged";
      std::fprintf(stderr, "panel: %s: %s; unchanged\n", label.c_str(), why.c_str());
    }
  }
  const auto refusal = refusals_.find(label);
  if (refusal != refusals_.end()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.45f, 1.0f));
    ImGui::TextWrapped("%s", refusal->second.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PopID();
  if (!done) return false;
  editing_.erase(label);
  value = shown;
  return true;
}

void ControlPanel::sceneList(AbstractWindow& scene) {
  SessionTools& session = scene.session();
  const std::vector<SceneChoice>& choices = session.sceneChoices();
  if (choices.empty()) return;
  // Open at first: choosing a scene is what the launcher is for.
  if (!ImGui::CollapsingHeader("Scenes (Page Down / Up)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (int i = 0; i < static_cast<int>(choices.size()); ++i) {
    const bool current = i == session.currentScene();
    const std::string row = choices[i].name + (current ? "   (on screen)" : "");
    if (ImGui::Selectable(row.c_str(), current)) session.requestSceneSwitch(i - session.currentScene());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", choices[i].description.c_str());
  }
  ImGui::Separator();
}

void ControlPanel::timeButtons(AbstractWindow& scene) {
  auto press = [&scene](SDL_Keycode key) { scene.handleKey(key, false); };
  if (ImGui::Button(scene.session().time().paused() ? "Run (P)" : "Pause (P)")) press(SDLK_p);
  if (flowButton("Step (O)")) press(SDLK_o);
  // R resets in most scenes; where the scene gave R an action of its own
  // (test7 throws), Shift+R resets.
  const KeyBinding* r = scene.keys().find(SDLK_r);
  const bool rResets = !r || r->description.rfind("reset", 0) == 0;  // test2, test8: "reset the pendulum"
  if (flowButton(rResets ? "Reset (R)" : "Reset (Shift+R)")) scene.handleKey(SDLK_r, !rResets);
  if (ImGui::Button("Slower (-)")) press(SDLK_MINUS);
  if (flowButton("Faster (=)")) press(SDLK_EQUALS);
  ImGui::SameLine();
  ImGui::Text("x%s", formatValue(scene.session().time().scale()).c_str());
  if (ImGui::Button("Rewind (,)")) press(SDLK_COMMA);
  if (flowButton("Forward (.)")) press(SDLK_PERIOD);
  if (ImGui::Button("Start view (Home)")) scene.camera().goHome();
  if (flowButton("Frame all")) frameScene(scene);
}

void ControlPanel::copyCommandLine(const AbstractWindow& scene) {
  // The settings as typed options, onto the clipboard and standard output,
  // so a run tuned here can be started again from a shell.
  if (ImGui::Button("Copy as command line")) {
    copied_ = commandLineOf(scene);
    SDL_SetClipboardText(copied_.c_str());
    std::printf("command line: %s\n", copied_.c_str());
    std::fflush(stdout);
  }
  if (!copied_.empty()) ImGui::TextWrapped("copied: %s", copied_.c_str());
}

void ControlPanel::timelineSlider(AbstractWindow& scene) {
  // Always there, so that the panel's rows keep their places.
  long long last = std::max(1LL, scene.session().timeline().horizon());
  long long first = 0;
  long long target = scrubbing_ ? scrubStep_ : std::min(scene.run().steps(), last);
  ImGui::SetNextItemWidth(-1);
  ImGui::SliderScalar("##timeline", ImGuiDataType_S64, &target, &first, &last, "timeline: step %lld",
                      ImGuiSliderFlags_AlwaysClamp);
  if (ImGui::IsItemActive()) {
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, LEAST_DRAG_PIXELS)) scrubbing_ = true;
    if (scrubbing_) scrubStep_ = target;
  }
  // Released after a drag: the run as it was at that step, rebuilt by
  // replaying its recorded inputs (as , and . do), and paused there.
  if (ImGui::IsItemDeactivated()) {
    if (scrubbing_ && scrubStep_ != scene.run().steps()) scene.replayTo(scrubStep_);
    scrubbing_ = false;
  }
}

void ControlPanel::sceneKeys(AbstractWindow& scene) {
  for (const KeyBinding* binding : odelab::sceneKeys(scene.keys())) {
    ImGui::PushID(binding->keyName.c_str());
    if (ImGui::Button(binding->keyName.c_str())) scene.handleKey(binding->key, false);
    if (binding->description.find("Shift") != std::string::npos &&
        flowButton(("Shift+" + binding->keyName).c_str()))
      scene.handleKey(binding->key, true);
    // Below its buttons, so it has the panel's width to wrap in.
    ImGui::Indent();
    ImGui::TextWrapped("%s", binding->description.c_str());
    ImGui::Unindent();
    ImGui::PopID();
  }
}

void ControlPanel::viewToggles(AbstractWindow& scene) {
  const ViewFlags& flags = scene.session().viewFlags();
  const struct {
    const char* label;
    bool on;
    SDL_Keycode key;
  } toggles[] = {{"contacts (C)", flags.contacts, SDLK_c}, {"joints (J)", flags.joints, SDLK_j},
                 {"boxes (X)", flags.boxes, SDLK_x},       {"wireframe (V)", flags.wireframe, SDLK_v},
                 {"plot (L)", flags.plot, SDLK_l},         {"help (H)", flags.help, SDLK_h}};
  // Two columns where both fit, else one.
  const ImGuiStyle& style = ImGui::GetStyle();
  float widest = 0;
  for (const auto& toggle : toggles) widest = std::max(widest, ImGui::CalcTextSize(toggle.label).x);
  const float columnWidth = widest + ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + style.ItemSpacing.x;
  const bool twoColumns = 2 * columnWidth <= ImGui::GetContentRegionAvail().x;
  int column = 0;
  for (const auto& toggle : toggles) {
    bool on = toggle.on;
    if (twoColumns && column++ % 2 == 1) ImGui::SameLine(style.WindowPadding.x + columnWidth);
    if (ImGui::Checkbox(toggle.label, &on)) scene.handleKey(toggle.key, false);
  }
  const std::string increment = "F2 increment " + formatValue(scene.tuning().f2Increment());
  if (ImGui::Button(increment.c_str())) scene.handleKey(SDLK_F2, false);
  if (flowButton("smaller")) scene.handleKey(SDLK_F2, true);
}

void ControlPanel::settings(AbstractWindow& scene) {
  for (const SettingSpec& spec : settingsTable()) {
    double value = settingValue(scene.tuning().settings(), spec.id);
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
  const auto& all = scene.tuning().parameters().all();
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
  // The back end's DeltaTime is the clock's difference since the last
  // frame, and a coarse clock reads the same for two frames: a browser's
  // rounded performance.now(), headless Chromium's virtual time. ImGui
  // asserts (aborts) on a step that is not positive; its animations only
  // need some small one.
  if (!(io.DeltaTime > 0.0f)) io.DeltaTime = 1e-4f;
  io.MousePos = ImVec2(static_cast<float>(mouseX_), static_cast<float>(mouseY_));
  io.MouseDown[0] = leftDown_ || leftPressed_;  // a click within one frame still counts
  leftPressed_ = false;
  for (const int key : pressedKeys_) io.KeysDown[key] = true;
  pressedKeys_.clear();
  ImGui::NewFrame();
  if (visible_) {
    width_ = std::clamp(MOST_WINDOW_SHARE * static_cast<float>(windowWidth), LEAST_WIDTH_IN_LINES * textPixels_,
                        WIDTH_IN_LINES * textPixels_);
    x_ = static_cast<float>(windowWidth) - width_ - MARGIN;
    y_ = MARGIN;
    ImGui::SetNextWindowPos(ImVec2(x_, y_), ImGuiCond_Always);
    // The whole column, so the scene's view ends where the panel begins;
    // what does not fit scrolls.
    ImGui::SetNextWindowSize(ImVec2(width_, static_cast<float>(std::max(1, windowHeight - 2 * MARGIN))),
                             ImGuiCond_Always);
    ImGui::Begin("Controls (Tab hides)", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                      ImGuiWindowFlags_NoCollapse);
    // The world settings come first, where every scene has them at the
    // same place (after the launcher's scene list); then the scene's own
    // keys, the drawing and its values.
    sceneList(scene);
    timeButtons(scene);
    ImGui::Separator();
    settings(scene);
    copyCommandLine(scene);
    ImGui::Separator();
    timelineSlider(scene);
    sceneKeys(scene);
    viewToggles(scene);
    if (!scene.tuning().parameters().all().empty()) {
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
