#pragma once

#include <string>
#include <vector>

#include "FixedStepClock.h"

namespace odelab {

// How much of the HUD shows; F1 cycles them.
enum class HudMode { Compact, Full, Off };

// Options shared by every test program, filled from the command line.
struct RunOptions {
  bool headless = false;
  double seconds = 0.0;  // headless: run length (0 = the scene's default); window: quit after (0 = never)
  unsigned seed = 1;
  std::string outDir = ".";
  std::string metricsJson;
  std::string screenshot;  // window: save a PNG after `frames` frames and exit
  int frames = 60;
  // --screenshot with --seconds and no --frames: the PNG is the run's last
  // frame, at its --seconds, whatever the frame rate.
  bool screenshotAtEnd = false;
  std::string shaderDir;
  std::string fontPath;
  int width = 1280;
  int height = 720;
  std::string recordDir;   // window: save every frame as a numbered PNG here
  std::string eventsFile;  // window: scripted input (see doc/manual.md, "Scripted input")
  // Window pacing (doc/manual.md, "Real time and frame rate").
  double maxFrameTime = FixedStepClock::DEFAULT_MAXIMUM_ELAPSED_TIME;  // the clock's clamp, s
  double maxFps = 60.0;  // frame cap; 0: none
  bool vsync = true;     // ask the driver to wait for the display's refresh
  int textSize = 0;      // HUD text height in pixels; 0: follows the window height
  HudMode hud = HudMode::Compact;
  bool panel = true;  // the on-screen control panel (Tab)
  // The engine that steps the scene (doc/peers.md): "ode", or one of
  // utils/world/EngineCatalog's, at its defaults or its best settings.
  std::string engine = "ode";
  bool engineBest = false;
  // --compare: the engines run beside ODE in the same run, in lockstep
  // (utils/CompareRun.h); empty for a run of one engine.
  std::vector<std::string> compare;
};

}  // namespace odelab
