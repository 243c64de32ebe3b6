#pragma once

// --bounce-velocity for the scenes that bounce (test1, test9): ODE's
// surface.bounce_vel, the slowest impact that still bounces. The thesis
// states it for test1 only, so each scene says where its default comes from.

#include <CLI/CLI.hpp>

#include <string>

#include "CommandLine.h"

namespace odelab {

inline void addBounceVelocityOption(CLI::App& app, double& bounceVelocity, const std::string& source) {
  app.add_option("--bounce-velocity", bounceVelocity, "slowest impact that bounces, m/s (" + source + ")")
      ->check(cli::finiteRange(0.0, 1000.0))
      ->capture_default_str();
}

}  // namespace odelab
