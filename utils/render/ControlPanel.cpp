#include "ControlPanel.h"

#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../CopyLine.h"
#include "../FormatValue.h"
#include "../SceneKeys.h"
#include "../TypedNumber.h"
#include "CameraControl.h"
#include "WindowLayout.h"

namespace odelab {

namespace {
// The panel's width in text heights: room for a label, a slider and a
// field; narrower (down to the least) in a narrow window, to leave the
// scene at least three quarters of it.
constexpr float WIDTH_IN_LINES = 18.0f;  // before the first frame (WindowLayout has the rule)
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
  const bool keyEvent = event.type == SDL_KEYDOWN || event.type == SDL_KEYUP;
  // A release is queued while the panel is hidden too, so that a key held
  // as Tab hid it is not left down in ImGui.
  if (keyEvent && event.key.keysym.scancode < 512 && (visible_ || event.type == SDL_KEYUP))
    queuedKeys_.push_back({event.key.keysym.scancode, event.key.keysym.sym, event.type == SDL_KEYDOWN,
                           event.key.keysym.mod, ""});
  if (!visible_) return false;
  if (event.type == SDL_TEXTINPUT) queuedKeys_.push_back({0, 0, false, 0, event.text.text});
  else if (!keyEvent) ImGui_ImplSDL2_ProcessEvent(&event);
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

// A drag moves the mouse this far before it counts: a click is not a drag.
constexpr float LEAST_DRAG_PIXELS = 4.0f;

}  // namespace

bool ControlPanel::edit(const std::string& label, double& value, double sliderMin, double min, double max,
                        bool logScale, bool integer) {
  auto found = editing_.find(label);
  double shown = found != editing_.end() ? found->second : value;
  ImGui::PushID(label.c_str());
  ImGui::TextWrapped("%s", label.c_str());
  ImGui::SetNextItemWidth(width_ * 0.45f);
  const ImGuiSliderFlags flags = (logScale ? ImGuiSliderFlags_Logarithmic : 0) | ImGuiSliderFlags_AlwaysClamp;
  // No number on the slider: its handle would cover it; the field beside
  // it shows the value, as it changes during a drag too.
  ImGui::SliderScalar("##slider", ImGuiDataType_Double, &shown, &sliderMin, &max, "", flags);
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
  // Text left as shown (a field clicked and left) changes nothing, not even
  // the digits the field rounded away.
  if (commit && typing_[label] == shownText(shown, integer)) {
    typing_.erase(label);
  } else if (commit) {
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
  // One row that opens into the list: eleven rows open would push the
  // timeline and the scene's own buttons below a 720-row window's edge.
  const int current = session.currentScene();
  const bool known = current >= 0 && current < static_cast<int>(choices.size());
  ImGui::TextUnformatted("Scene (Page Down / Up)");
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::BeginCombo("##scene", known ? choices[static_cast<size_t>(current)].name.c_str() : "",
                        ImGuiComboFlags_HeightLargest)) {
    for (int i = 0; i < static_cast<int>(choices.size()); ++i) {
      if (ImGui::Selectable(choices[i].name.c_str(), i == current)) session.requestSceneSwitch(i - current);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", choices[i].description.c_str());
    }
    ImGui::EndCombo();
  }
  if (known && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", choices[static_cast<size_t>(current)].description.c_str());
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
  // Every value the run is tuned by as typed options (utils/CopyLine.h),
  // onto the clipboard and standard output, so a run tuned here can be
  // started again from a shell.
  if (ImGui::Button("Copy as command line")) {
    copied_ = copyLine(scene);
    SDL_SetClipboardText(copied_.c_str());
    std::printf("command line: %s\n", copied_.c_str());
    std::fflush(stdout);
  }
  // What was copied shows beside the pointer, not as a line in the column
  // that would push the rows below it down.
  if (!copied_.empty() && ImGui::IsItemHovered()) {
    // Opaque: it lies over the rows below, whose text would show through.
    ImGui::PushStyleVar(ImGuiStyleVar_Alpha, 1.0f);
    ImVec4 background = ImGui::GetStyleColorVec4(ImGuiCol_PopupBg);
    background.w = 1.0f;
    ImGui::PushStyleColor(ImGuiCol_PopupBg, background);
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(width_ - 2 * ImGui::GetStyle().WindowPadding.x);
    ImGui::Text("copied: %s", copied_.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
    ImGui::PopStyleColor();
    ImGui::PopStyleVar();
  }
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
  // During a drag and where it is released: the run as it was at that
  // step, rebuilt by replaying its recorded inputs (as , and . do), and
  // paused there; the scene follows the handle.
  if (scrubbing_ && scrubStep_ != scene.run().steps()) scene.replayTo(scrubStep_);
  if (ImGui::IsItemDeactivated()) scrubbing_ = false;
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

void ControlPanel::engineTicks() {
  if (!compareViews_ || !compareLanes_) return;
  if (!ImGui::CollapsingHeader("Engines (views)", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const std::vector<CompareLanes::Lane>& lanes = compareLanes_->lanes();
  const ImGuiStyle& style = ImGui::GetStyle();
  const float room = ImGui::GetContentRegionAvail().x;
  float rowWidth = 0;
  for (size_t lane = 0; lane < lanes.size(); ++lane) {
    // As many to a row as fit.
    const float width = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(lanes[lane].engine.c_str()).x;
    if (lane > 0 && rowWidth + style.ItemSpacing.x + width <= room) {
      ImGui::SameLine();
      rowWidth += style.ItemSpacing.x + width;
    } else {
      rowWidth = width;
    }
    // ODE's view leads: the camera, the drag and the merged view are its.
    bool shown = compareViews_->shown(lane);
    ImGui::BeginDisabled(lane == 0 || compareViews_->merged());
    if (ImGui::Checkbox(lanes[lane].engine.c_str(), &shown)) compareViews_->setShown(lane, shown);
    ImGui::EndDisabled();
  }
  bool merged = compareViews_->merged();
  if (ImGui::Checkbox("merged (M)", &merged)) compareViews_->toggleMerged();
}

void ControlPanel::knobs(AbstractWindow& scene) {
  // Every knob, under its group's header: World open, the contact choices
  // and the scene's values closed (open, a scene's dozen values would push
  // the timeline and the scene's keys below the window's edge). A closed
  // header counts its values, so it still says what it holds.
  const std::deque<Knob>& all = scene.tuning().knobs();
  const struct {
    KnobGroup group;
    const char* name;
    bool open;
  } groups[] = {{KnobGroup::World, "World", true}, {KnobGroup::Contacts, "Contacts", false}, {KnobGroup::Scene, "Scene", false}};
  for (const auto& group : groups) {
    std::vector<int> rows;
    for (int i = 0; i < static_cast<int>(all.size()); ++i)
      if (all[i].group == group.group) rows.push_back(i);
    if (rows.empty()) continue;
    const std::string header = group.open ? std::string(group.name)
                                          : std::string(group.name) + " (" + std::to_string(rows.size()) +
                                                (rows.size() == 1 ? " value)" : " values)") + "###" + group.name;
    if (!ImGui::CollapsingHeader(header.c_str(), group.open ? ImGuiTreeNodeFlags_DefaultOpen : 0)) continue;
    for (const int i : rows) knobRow(scene, i, all[i]);
  }
}

void ControlPanel::knobRow(AbstractWindow& scene, int index, const Knob& knob) {
  // A setting the engine shown does not take: greyed, marked, and the
  // engine's note as its tooltip (it stays editable: ODE's lane takes it).
  const std::string notReached = scene.knobNotReached(knob);
  if (!notReached.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextUnformatted(("not in " + scene.engine().engineName() + ":").c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", notReached.c_str());
  }
  knobRowControls(scene, index, knob);
  if (!notReached.empty()) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", notReached.c_str());
    ImGui::PopStyleColor();
  }
}

void ControlPanel::knobRowControls(AbstractWindow& scene, int index, const Knob& knob) {
  if (knob.kind == KnobKind::Switch) {
    const std::string effect = knob.effectText();
    bool on = knob.get() > 0;
    const std::string label = knob.label + (knob.keyName.empty() ? "" : "   " + knob.keyName) +
                              (effect.empty() ? "" : "; " + effect);
    // The box, then its label wrapped beside it: a checkbox's own label does
    // not wrap, and a long one would run past the panel's edge.
    if (ImGui::Checkbox(("##" + knob.name).c_str(), &on)) scene.changeKnob(index, on ? 1 : 0);
    const bool hovered = ImGui::IsItemHovered();
    ImGui::SameLine();
    ImGui::TextWrapped("%s", label.c_str());
    if ((hovered || ImGui::IsItemHovered()) && !knob.help.empty())
      ImGui::SetTooltip("%s\n%s", knob.option.c_str(), knob.help.c_str());
    return;
  }
  if (knob.kind == KnobKind::Choice) {
    ImGui::TextUnformatted((knob.label + (knob.keyName.empty() ? "" : "   " + knob.keyName)).c_str());
    int choice = static_cast<int>(knob.get());
    const int before = choice;
    // The option's words, as the HUD and the command line say them; what
    // each calls in ODE in its tooltip.
    for (int c = 0; c < static_cast<int>(knob.choices.size()); ++c) {
      if (c > 0) ImGui::SameLine();
      ImGui::RadioButton(knob.choices[c].c_str(), &choice, c);
      if (ImGui::IsItemHovered() && c < static_cast<int>(knob.choiceNames.size()))
        ImGui::SetTooltip("%s %s: %s", knob.option.c_str(), knob.choices[c].c_str(), knob.choiceNames[c].c_str());
    }
    if (choice != before) scene.changeKnob(index, choice);
    return;
  }
  double value = knob.get();
  const std::string effect = knob.effectText();
  const std::string label = knob.label + (knob.unit.empty() ? "" : " (" + knob.unit + ")") +
                            (knob.key != SDLK_UNKNOWN ? "   " + knob.keyName : "") +
                            (knob.lowerKey != SDLK_UNKNOWN ? " / " + knob.lowerKeyName : "") +
                            (effect.empty() ? "" : "; " + effect);
  // A logarithmic slider cannot reach 0; CFM 0 is typed (or F4 down), and
  // the field takes the range the command line takes.
  const double sliderMin = knob.logScale && knob.panelMin() <= 0 ? 1e-10 : knob.panelMin();
  if (edit(label, value, sliderMin, knob.panelMin(), knob.panelMax(), knob.logScale, knob.kind == KnobKind::Integer))
    scene.changeKnob(index, value);
  if (ImGui::IsItemHovered() && !knob.help.empty())
    ImGui::SetTooltip("%s %s\n%s", knob.option.c_str(), knob.rangeText().c_str(), knob.help.c_str());
}

void ControlPanel::feedKeys() {
  ImGuiIO& io = ImGui::GetIO();
  std::vector<int> changed;    // keys pressed or released this frame
  bool editingKeyDown = false;  // BackSpace, Enter, an arrow ... pressed this frame
  while (!queuedKeys_.empty()) {
    const QueuedKey& next = queuedKeys_.front();
    if (next.text.empty()) {
      // A key's second change waits for the next frame, and everything
      // after it too, to keep the order.
      if (std::find(changed.begin(), changed.end(), next.scancode) != changed.end()) break;
      changed.push_back(next.scancode);
      io.KeysDown[next.scancode] = next.down;
      io.KeyShift = (next.mod & KMOD_SHIFT) != 0;
      io.KeyCtrl = (next.mod & KMOD_CTRL) != 0;
      io.KeyAlt = (next.mod & KMOD_ALT) != 0;
      io.KeySuper = (next.mod & KMOD_GUI) != 0;
      if (next.down && (next.key < 32 || next.key > 126)) editingKeyDown = true;
    } else {
      // ImGui takes a frame's text before its keys: text typed after a
      // BackSpace (say) waits a frame, so the BackSpace does not eat it.
      if (editingKeyDown) break;
      io.AddInputCharactersUTF8(next.text.c_str());
    }
    queuedKeys_.pop_front();
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
  feedKeys();
  ImGui::NewFrame();
  if (visible_) {
    width_ = static_cast<float>(panelCoveredWidth(windowWidth, static_cast<int>(textPixels_)) - 2 * MARGIN);
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
    // same place (after the launcher's scene list), then the contact
    // choices and the scene's knobs, so every value the copied command
    // line names is tuned in one place; then the scene's keys and the drawing.
    sceneList(scene);
    timeButtons(scene);
    engineTicks();
    ImGui::Separator();
    knobs(scene);
    copyCommandLine(scene);
    ImGui::Separator();
    timelineSlider(scene);
    sceneKeys(scene);
    viewToggles(scene);
    height_ = ImGui::GetWindowHeight();
    ImGui::End();
  }
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace odelab
