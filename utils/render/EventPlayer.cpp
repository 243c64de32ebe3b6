#include "EventPlayer.h"

#include <algorithm>

#include "RenderError.h"

namespace odelab {

namespace {

Uint8 sdlButton(ScriptEvent::Button button) {
  switch (button) {
    case ScriptEvent::Button::Middle:
      return SDL_BUTTON_MIDDLE;
    case ScriptEvent::Button::Right:
      return SDL_BUTTON_RIGHT;
    case ScriptEvent::Button::Left:
      break;
  }
  return SDL_BUTTON_LEFT;
}

Uint16 modifiers(const ScriptEvent& e) {
  return static_cast<Uint16>((e.shift ? KMOD_LSHIFT : 0) | (e.ctrl ? KMOD_LCTRL : 0) | (e.alt ? KMOD_LALT : 0));
}

}  // namespace

EventPlayer::EventPlayer(std::vector<ScriptEvent> events, SDL_Window* window)
    : events_(std::move(events)), window_(window) {
  if (events_.empty()) return;
  windowId_ = window ? SDL_GetWindowID(window) : 0;
  markType_ = SDL_RegisterEvents(1);
  if (markType_ == static_cast<Uint32>(-1)) throw RenderError("--events: SDL has no user event type left for marks");
}

void EventPlayer::push(SDL_Event& event) {
  if (SDL_PushEvent(&event) < 0) throw RenderError(std::string("--events: cannot queue an event: ") + SDL_GetError());
}

// Moves the cursor to (x, y), with the buttons' state as it stands.
void EventPlayer::pushMotion(int x, int y) {
  SDL_Event motion;
  SDL_zero(motion);
  motion.type = SDL_MOUSEMOTION;
  motion.motion.windowID = windowId_;
  motion.motion.state = buttonsHeld_;
  motion.motion.x = x;
  motion.motion.y = y;
  motion.motion.xrel = x - mouseX_;
  motion.motion.yrel = y - mouseY_;
  push(motion);
  mouseX_ = x;
  mouseY_ = y;
}

void EventPlayer::pushDue(long long frame) {
  for (; next_ < events_.size() && events_[next_].frame <= frame; ++next_) {
    const ScriptEvent& e = events_[next_];
    SDL_Event event;
    SDL_zero(event);
    switch (e.kind) {
      case ScriptEvent::Kind::Key: {
        event.key.windowID = windowId_;
        event.key.keysym.sym = e.key;
        event.key.keysym.scancode = SDL_GetScancodeFromKey(e.key);
        event.key.keysym.mod = modifiers(e);
        event.key.repeat = 0;
        event.type = SDL_KEYDOWN;
        event.key.state = SDL_PRESSED;
        push(event);
        event.type = SDL_KEYUP;
        event.key.state = SDL_RELEASED;
        push(event);
        break;
      }
      case ScriptEvent::Kind::Down:
      case ScriptEvent::Kind::Up: {
        const bool down = e.kind == ScriptEvent::Kind::Down;
        if (e.x != mouseX_ || e.y != mouseY_) pushMotion(e.x, e.y);  // the cursor gets there first
        event.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
        event.button.windowID = windowId_;
        event.button.button = sdlButton(e.button);
        event.button.state = down ? SDL_PRESSED : SDL_RELEASED;
        if (down) {
          const bool again = event.button.button == lastButton_ && e.x == lastPressX_ && e.y == lastPressY_ &&
                             e.frame - lastPressFrame_ <= DOUBLE_CLICK_FRAMES;
          lastClicks_ = again ? static_cast<Uint8>(std::min(lastClicks_ + 1, 255)) : 1;
          lastButton_ = event.button.button;
          lastPressFrame_ = e.frame;
          lastPressX_ = e.x;
          lastPressY_ = e.y;
        }
        event.button.clicks = std::max<Uint8>(lastClicks_, 1);  // a release has its press's count
        event.button.x = e.x;
        event.button.y = e.y;
        push(event);
        if (down)
          buttonsHeld_ |= SDL_BUTTON(event.button.button);
        else
          buttonsHeld_ &= ~SDL_BUTTON(event.button.button);
        break;
      }
      case ScriptEvent::Kind::Wheel:
        event.type = SDL_MOUSEWHEEL;
        event.wheel.windowID = windowId_;
        event.wheel.x = e.x;
        event.wheel.y = e.y;
        event.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
        push(event);
        break;
      case ScriptEvent::Kind::Resize:
        if (window_) SDL_SetWindowSize(window_, e.x, e.y);
        break;
      case ScriptEvent::Kind::Move:
        pushMotion(e.x, e.y);
        break;
      case ScriptEvent::Kind::Mark:
        event.type = markType_;
        event.user.windowID = windowId_;
        event.user.code = static_cast<Sint32>(next_);
        push(event);
        break;
      case ScriptEvent::Kind::Quit:
        event.type = SDL_QUIT;
        push(event);
        break;
      case ScriptEvent::Kind::Text:
        event.type = SDL_TEXTINPUT;
        event.text.windowID = windowId_;
        SDL_strlcpy(event.text.text, e.label.c_str(), sizeof event.text.text);
        push(event);
        break;
    }
  }
}

bool EventPlayer::handle(const SDL_Event& event, AbstractWindow& scene,
                         const std::function<void(const std::string&)>& onMark) {
  if (events_.empty() || event.type != markType_) return false;
  const auto index = static_cast<std::size_t>(event.user.code);
  if (index >= events_.size()) return true;
  scene.mark(events_[index].label);
  onMark(events_[index].label);
  return true;
}

}  // namespace odelab
