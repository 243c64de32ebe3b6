#pragma once

#include <SDL2/SDL.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "../AbstractWindow.h"
#include "../EventScript.h"

namespace odelab {

// Plays a --events script: before a frame's event polling, that frame's
// events go into SDL's queue with SDL_PushEvent, so they take the same path
// as real input (key down and up; button down, motion, up; wheel; SDL_QUIT).
// Presses carry a click count as SDL's do (two quick presses at one pixel:
// a double click).
// A resize asks the window system for the new size (SDL_SetWindowSize), as
// a user dragging the window's border does; the size-changed event comes
// back from it.
// A mark travels as a user event in the same queue, so it is taken in order
// with the input around it, and calls scene.mark() when polled.
class EventPlayer {
 public:
  // `events`: a parsed script (loadEventScript), possibly empty. Call after
  // SDL's video subsystem is up.
  EventPlayer(std::vector<ScriptEvent> events, SDL_Window* window);

  // Pushes the events of `frame` (frames count from 1).
  void pushDue(long long frame);
  // Whether the script has events still to push: while it has, frames are
  // counted as the script expects and the window never idles.
  bool playing() const { return next_ < events_.size(); }
  // If `event` is a mark of this script: records it, calls `onMark` with its
  // label, and returns true.
  bool handle(const SDL_Event& event, AbstractWindow& scene, const std::function<void(const std::string&)>& onMark);

 private:
  void push(SDL_Event& event);
  void pushMotion(int x, int y);

  std::vector<ScriptEvent> events_;
  std::size_t next_ = 0;
  SDL_Window* window_ = nullptr;
  Uint32 windowId_ = 0;
  Uint32 markType_ = static_cast<Uint32>(-1);
  int mouseX_ = 0, mouseY_ = 0;
  Uint32 buttonsHeld_ = 0;  // SDL_BUTTON_LMASK ... as a motion event's state
  // The last press, for counting clicks as SDL does for real input: a
  // press of the same button at the same pixel within DOUBLE_CLICK_FRAMES
  // frames of the last one is its second click.
  static constexpr long long DOUBLE_CLICK_FRAMES = 10;
  Uint8 lastButton_ = 0;
  long long lastPressFrame_ = -DOUBLE_CLICK_FRAMES - 1;
  int lastPressX_ = -1, lastPressY_ = -1;
  Uint8 lastClicks_ = 0;
};

}  // namespace odelab
