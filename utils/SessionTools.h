#pragma once

#include <string>
#include <vector>

#include "CopyLine.h"
#include "DebugMarkers.h"
#include "DragEnergy.h"
#include "Metrics.h"
#include "MouseDrag.h"
#include "Rewind.h"
#include "RunLog.h"
#include "RunOptions.h"
#include "SceneView.h"
#include "StripChart.h"
#include "TimeControl.h"

namespace odelab {

// What a person at the window works with beside the physics: the clock
// (pause, scale, budget), rewind, the mouse drag, the run log, the notice
// and error on screen, the view toggles with their contact markers and live
// plot, and the requests the frame loop answers (quit, next scene,
// screenshot). Headless runs carry it too, idle. AbstractWindow, whose
// member it is, feeds it from its step and its keys (a friend); the front
// end reads it through AbstractWindow::session().
// A scene the launcher offers: "test4" and its one-line description.
struct SceneChoice {
  std::string name, description;
};

class SessionTools {
 public:
  TimeControl& time() { return time_; }
  const TimeControl& time() const { return time_; }
  const Timeline& timeline() const { return rewind_.timeline(); }
  const ViewFlags& viewFlags() const { return viewFlags_; }
  // The compare window shows every engine's view with the leading scene's toggles.
  void showAs(const ViewFlags& flags) { viewFlags_ = flags; }
  const std::vector<ContactMarker>& contactMarkers() const { return contactMarkers_; }
  const StripChart& chart() const { return chart_; }
  HudMode hudMode() const { return hudMode_; }
  bool quitRequested() const { return quitRequested_; }
  void requestQuit() { quitRequested_ = true; }
  // The launcher's window: its scenes (none in a program of its own), the
  // one on screen, and a request that ends this scene's frame loop asking
  // for the scene `offset` places on in the list, wrapping (0: none).
  // Requests of one frame add up: two Page Ups are two switches, and Page
  // Down then Page Up come back to this scene, made afresh.
  const std::vector<SceneChoice>& sceneChoices() const { return sceneChoices_; }
  int currentScene() const { return currentScene_; }
  void requestSceneSwitch(int offset) {
    if (offset == 0) return;
    switchRequest_ += offset;
    switchRequested_ = true;
    quitRequested_ = true;
  }
  bool switchRequested() const { return switchRequested_; }
  int switchRequest() const { return switchRequest_; }  // the offsets requested, summed
  bool mouseLook() const { return mouseLook_; }
  void toggleMouseLook() { mouseLook_ = !mouseLook_; }
  bool takeScreenshotRequest();  // true once per F12 press
  // The last blow-up or ODE error, kept on screen until dismissed (Enter).
  const std::string& failure() const { return failure_; }
  void dismissFailure() { failure_.clear(); }
  // Prints a line on stderr and keeps it for the HUD for a few seconds.
  void notify(const std::string& message);
  std::string notice() const;  // the notice of the last few seconds ("" when none)
  bool dragging() const { return drag_.active(); }
  // The scene's own options the command line gave (--ccd, --space sap):
  // nothing on the panel sets them, so the copied command line repeats them.
  const std::vector<LineOption>& givenSceneOptions() const { return givenSceneOptions_; }
  void setGivenSceneOptions(std::vector<LineOption> options) { givenSceneOptions_ = std::move(options); }
  const double* dragTarget() const { return drag_.target(); }

 private:
  friend class AbstractWindow;
  TimeControl time_;
  Rewind rewind_;
  MouseDrag drag_;
  DragEnergy dragEnergy_;  // the drag's work against what the bodies gained
  RunLog runLog_;
  ViewFlags viewFlags_;
  std::vector<ContactMarker> contactMarkers_;
  StripChart chart_;
  double nextChartTime_ = 0.0;
  HudMode hudMode_ = HudMode::Compact;
  bool quitRequested_ = false;
  int switchRequest_ = 0;
  bool switchRequested_ = false;
  std::vector<SceneChoice> sceneChoices_;
  int currentScene_ = -1;
  bool mouseLook_ = false;
  bool screenshotRequested_ = false;
  std::string notice_, failure_;
  long long failures_ = 0;    // blow-ups and ODE errors a window recovered from
  double noticeUntil_ = 0.0;  // in real seconds of window time
  Metrics marks_;             // mark() and the drag's distances
  std::vector<LineOption> givenSceneOptions_;
};

}  // namespace odelab
