#pragma once

#include <ode/ode.h>

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "AbstractObject.h"
#include "BodyStateWatch.h"
#include "DebugMarkers.h"
#include "DragSpring.h"
#include "SceneView.h"
#include "SpaceKind.h"

namespace odelab {

// One run of the ODE world: the world, its collision space, contact group
// and step threading, the scene's objects, the step counters and the test
// for a state that blew up. It creates and destroys the world (create(),
// destroy()); AbstractWindow, whose member it is, steps it (the step loop
// lives with the scene hooks it calls, so it writes the counters: a
// friend); the front end and checks read it through AbstractWindow::run().
class WorldRun {
 public:
  WorldRun() = default;
  ~WorldRun() = default;  // AbstractWindow's destructor has torn the world down
  WorldRun(const WorldRun&) = delete;
  WorldRun& operator=(const WorldRun&) = delete;

  dWorldID world() const { return world_; }
  dSpaceID space() const { return space_; }
  dJointGroupID contactGroup() const { return contactGroup_; }
  SpaceKind spaceKind() const { return spaceKind_; }
  const std::vector<std::unique_ptr<AbstractObject>>& objects() const { return objects_; }
  double simulatedTime() const { return simulatedTime_; }
  long long steps() const { return steps_; }
  int contactsLastStep() const { return contactsLastStep_; }
  // Real seconds spent in dSpaceCollide since the program started (the window's frame profile).
  double collideWallSeconds() const { return collideWallSeconds_; }
  double lastStepWallSeconds() const { return lastStepWallSeconds_; }  // 0 unless the scene called timeSteps()
  // Why the run stopped before its end, or "": a blow-up (a state not
  // finite) or, with engineFailed(), the engine that stepped it failing.
  const std::string& blowUpReason() const { return blowUpReason_; }
  // The engine --engine named failed while stepping (its process died,
  // answered what is not the protocol, or missed its deadline): the run
  // ended, but not for its physics (exit_code::ENGINE_FAILED).
  bool engineFailed() const { return engineFailed_; }
  int bodyCount() const;
  int disabledBodyCount() const;
  // A hash of the step count, the simulated time, the world's settings and
  // every body's exact state (the determinism check; StateHash.h).
  std::uint64_t stateHash() const;
  std::vector<JointMarker> jointMarkers() const { return collectJointMarkers(objects_); }
  PickHit pickAt(const double origin[3], const double direction[3]) const;

  // A new world seeded from `seed` (every random choice of a run derives
  // from --seed), with its own step threading, an empty contact group and
  // no space yet (setSpaceKind), the counters at zero.
  void create(unsigned seed);
  void destroy();          // objects first, then contact group, space and world
  void freeThreading();    // after destroy(), before dCloseODE()
  // Moves every geom into a new space of that kind (a quadtree covers `bounds`).
  void setSpaceKind(SpaceKind kind, const SceneBounds& bounds);
  // ODE copies the world's ERP and CFM into a ball or fixed joint when it is
  // made (dParamERP, dParamCFM); a later dWorldSetERP / dWorldSetCFM does not
  // reach it. After a live change, every such joint still at the old world
  // values takes the new ones, so that F3 / F4 act as the same values given
  // at the start do; one a scene set on purpose keeps its own.
  void carryWorldErpCfmToJoints(double oldErp, double oldCfm, double erp, double cfm) const;
  // The cheap test behind stateProblem(), inline: it runs after every step.
  bool stateSuspicious() const { return watch_.suspicious(objects_); }
  std::string stateProblem() const;
  std::mt19937& random() { return random_; }
  // Measure every step's wall time (lastStepWallSeconds()); off by default.
  void timeSteps() { timeSteps_ = true; }

 private:
  friend class AbstractWindow;

  std::vector<std::unique_ptr<AbstractObject>> objects_;
  BodyStateWatch watch_;  // stateSuspicious()'s view of the bodies
  std::mt19937 random_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contactGroup_ = nullptr;
  SpaceKind spaceKind_ = SpaceKind::Simple;
  dThreadingImplementationID stepThreading_ = nullptr;  // the world's; see AbstractWindow::createWorld()

  double simulatedTime_ = 0.0;
  long long steps_ = 0;
  int contactsLastStep_ = 0;
  int contactsThisStep_ = 0;
  double lastStepWallSeconds_ = 0.0;
  double collideWallSeconds_ = 0.0;
  double engineStepWallSeconds_ = 0.0;  // --engine: the engine's own calls in the last step
  double engineWallSeconds_ = 0.0;      // ODE's own collision and step calls, this run
  bool profileCollision_ = false;
  bool timeSteps_ = false;
  bool unattended_ = false;  // inside runFor(): no input, rewind or plot, so stepOnce() skips them
  double wallSeconds_ = 0.0;  // real time spent in this run (headless) or its frames (window)
  std::string blowUpReason_;
  bool engineFailed_ = false;
};

}  // namespace odelab
