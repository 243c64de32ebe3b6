#pragma once

// The thesis's measurements, written once for every peer engine: each runs
// one scene on an Engine's model and puts the same metrics the ODE program
// of that scene writes (same names, same definitions) into `metrics`.

#include "Metrics.h"
#include "PeerScene.h"

namespace odelab::peers {

struct Tally {
  long steps = 0;
  double simSeconds = 0.0;
  bool finite = true;  // false: the state became non-finite (the run stopped there)
};

// Default run length of each scene: the ODE program's.
double defaultSeconds(const std::string& scene);

Tally measureEnergy(Engine& engine, const RunOptions& options, Metrics& metrics);      // test2
Tally measureElongation(Engine& engine, const RunOptions& options, Metrics& metrics);  // test8
Tally measureBounces(Engine& engine, const RunOptions& options, Metrics& metrics);     // test9
Tally measureHold(Engine& engine, const RunOptions& options, Metrics& metrics);        // test4
Tally measureWall(Engine& engine, const RunOptions& options, Metrics& metrics);        // test10
Tally measureJoints(Engine& engine, const RunOptions& options, Metrics& metrics);      // test7
Tally measureRebounds(Engine& engine, const RunOptions& options, Metrics& metrics);    // test1
Tally measureUpright(Engine& engine, const RunOptions& options, Metrics& metrics);     // test6
Tally measureChain(Engine& engine, const RunOptions& options, Metrics& metrics);       // test3
Tally measurePlates(Engine& engine, const RunOptions& options, Metrics& metrics);      // test5

// test1's layout: where ball i starts (its restitution is i / (BALL_COUNT - 1)).
Vec3 ballStart(int ball);
double ballBounce(int ball);

}  // namespace odelab::peers
