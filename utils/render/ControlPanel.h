#pragma once

#include <SDL2/SDL.h>

#include <deque>
#include <map>
#include <string>
#include <vector>

#include "../AbstractWindow.h"
#include "CompareViews.h"

namespace odelab {

// The on-screen control panel (Dear ImGui, Tab shows and hides it): the
// world settings of the settings table, the scene's own parameters, and
// buttons for pause, step, time scale, rewind and reset. Every change goes
// through the scene's changeKnob / handleKey, the same
// path as the F-keys: clamped, recorded for rewind, logged, and written to
// the output files.
class ControlPanel {
 public:
  // Needs the window's GL context current. `textPixels` sizes the font.
  ControlPanel(SDL_Window* window, void* glContext, const std::string& fontPath, int textPixels, bool visible);
  ~ControlPanel();
  ControlPanel(const ControlPanel&) = delete;
  ControlPanel& operator=(const ControlPanel&) = delete;

  // Feeds an event to the panel. True when the panel takes it (the pointer
  // is over the panel, or a field is being typed in): the scene must not.
  bool handleEvent(const SDL_Event& event);
  void toggle() { visible_ = !visible_; }
  bool visible() const { return visible_; }
  // Width the panel's column takes at the window's right edge (0 when hidden).
  int coveredWidth() const { return visible_ ? static_cast<int>(width_) + 2 * MARGIN : 0; }
  // Builds and draws this frame's panel over the scene.
  void draw(AbstractWindow& scene, int windowWidth, int windowHeight);
  // A compare window's engines, each ticked to show its view or not, and
  // the merged view (M), at the top of the panel.
  void showEngines(CompareViews& views, const CompareLanes& lanes) {
    compareViews_ = &views;
    compareLanes_ = &lanes;
  }

 private:
  static constexpr int MARGIN = 10;
  bool contains(int x, int y) const;
  // The launcher's scenes, one row each, the one on screen marked; a click
  // switches as Page Down does. Absent in a program of its own.
  void sceneList(AbstractWindow& scene);
  void timeButtons(AbstractWindow& scene);
  // A slider over the steps this run has reached: a drag goes back (or
  // forth again) to any of them.
  void timelineSlider(AbstractWindow& scene);
  void copyCommandLine(const AbstractWindow& scene);
  void engineTicks();                       // showEngines' ticks
  void sceneKeys(AbstractWindow& scene);    // the scene's own keys as buttons
  void viewToggles(AbstractWindow& scene);  // C, J, X, V, L, H and the F2 increment
  void knobs(AbstractWindow& scene);
  void knobRow(AbstractWindow& scene, int index, const Knob& knob);
  void knobRowControls(AbstractWindow& scene, int index, const Knob& knob);  // the row without its reach
  // A value edited by slider or typing, committed when the edit ends, so a
  // drag is one change on the timeline, not one per frame: a slider when a
  // drag (not a click) is released, a field on Enter, Tab or a click
  // elsewhere, its text read as the command line reads the option (a
  // refusal is shown under the field; Esc drops the text). A logarithmic
  // slider cannot reach 0, so it may start above `min`, which the field
  // still accepts.
  bool edit(const std::string& label, double& value, double sliderMin, double min, double max, bool logScale,
            bool integer);
  // Hands the keys and text queued since the last frame to ImGui, at most
  // one change of each key a frame (see queuedKeys_).
  void feedKeys();

  bool visible_;
  float textPixels_ = 16, width_ = 0, x_ = 0, y_ = 0, height_ = 0;
  int mouseX_ = -1, mouseY_ = -1;
  bool leftDown_ = false, leftPressed_ = false;
  // Key presses, releases and typed text not yet given to ImGui, in order.
  // ImGui 1.86 reads a key's state once a frame: a tap whose press and
  // release come in one frame would be missed (or, held down by force,
  // repeated), so the release waits for the next frame.
  struct QueuedKey {
    int scancode = 0;
    SDL_Keycode key = 0;
    bool down = false;
    Uint16 mod = 0;
    std::string text;  // typed text (no key) when not empty
  };
  std::deque<QueuedKey> queuedKeys_;
  std::map<std::string, double> editing_;        // a slider's value during its drag
  std::map<std::string, std::string> typing_;    // a field's text while it is typed in
  std::map<std::string, std::string> refusals_;  // why a typed value was refused, shown under it
  std::string copied_;                           // the last "copy as command line"
  bool scrubbing_ = false;                       // the timeline slider is being dragged
  long long scrubStep_ = 0;
  bool dragged_ = false;                         // the active slider has been dragged
  CompareViews* compareViews_ = nullptr;
  const CompareLanes* compareLanes_ = nullptr;
};

}  // namespace odelab
