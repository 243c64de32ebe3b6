// test0 - Box & Sphere (thesis 5.1): boxes and spheres of random size dropped
// onto a static platform. Shows auto-disable (disabled bodies draw grey) and
// its side effect: a disabled body whose support expires can hang in the air.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "AbstractWindow.h"
#include "Box.h"
#include "CommandLine.h"
#include "Sphere.h"
#include "SceneRegistry.h"
#include "shared/BodyMeasures.h"

namespace {

using namespace odelab;

constexpr double SPAWN_HEIGHT = 10.0;
constexpr double DENSITY = 500.0;          // kg/m^3, about that of wood (proposed)
constexpr double LIFETIME_SECONDS = 30.0;  // (proposed)
constexpr double BOUNDARY_XZ = 50.0;       // (proposed) |x| or |z| beyond this is removed
constexpr double BOUNDARY_Y = -20.0;       // (proposed) below this is removed
constexpr double PLATFORM_HALF = 5.0;
constexpr double REST_SPEED = 0.05;        // m/s: below this a body counts as at rest
constexpr double SUPPORT_GAP = 0.05;       // m: a body with nothing this close below its lowest point hangs
// A window given no --spawn-interval drops a box at once and a sphere this
// long after, so its first seconds show objects falling, settling and going
// grey (auto-disable) before any key is pressed; headless runs are untouched.
constexpr double FIRST_SPHERE_AT = 1.0;    // s

class BoxAndSphere : public AbstractWindow {
 public:
  BoxAndSphere() : AbstractWindow(WorldSettings{}) {
    bindKey(SDLK_b, "B", "spawn a box of random size at [0, 10, 0]", [this](int) { spawn(true); });
    bindKey(SDLK_n, "N", "spawn a sphere of random size at [0, 10, 0]", [this](int) { spawn(false); });
    // Every object appears at one point: faster than 0.01 s they pile into
    // each other there, a crawl of overlapping contacts rather than a scene.
    spawnKnob_ = &declare(Knob::interval("spawn_interval", "spawn interval (0: off)", spawnInterval_, 0.01, 1e6)
                              .withOption("--spawn-interval",
                                          "spawn a box, then a sphere, ... every S simulated seconds; 0: off "
                                          "(default: 1 headless; in the window a box at once, a sphere at 1 s, "
                                          "then B / N)")
                              .zeroIsOff()
                              .logarithmic()
                              .defaultPickedByScene());  // spawnInterval(): 1 s headless unless given
    declare(Knob::integer("spawn_count", "spawn count (0: no limit)", spawnLimit_, 0, 1000000000)
                .withOption("--spawn-count", "stop spawning after N objects (0 = no limit)"));
    declare(Knob::choice(
                "spawn_shapes", "timed spawns", SPAWN_SHAPES, {},
                [this] { return static_cast<int>(std::find(SPAWN_SHAPES.begin(), SPAWN_SHAPES.end(), spawnShapes_) -
                                                 SPAWN_SHAPES.begin()); },
                [this](int choice) { spawnShapes_ = SPAWN_SHAPES.at(static_cast<size_t>(choice)); })
                .withOption("--spawn-shapes",
                            "what timed spawning drops: both (alternately), box or sphere. Spheres have no rolling "
                            "resistance in ODE and may roll off the platform"));
    useContactChoices(dInfinity);  // the thesis names no friction here: never slides
  }

 protected:
  void configureWorld() override { dWorldSetAutoDisableFlag(world(), 1); }

  void initialCamera(Camera& camera) const override { camera.lookAt({0.0f, 7.0f, 12.0f}, {0.0f, 2.5f, 0.0f}); }

  void buildScene() override {
    Box& platform = add<Box>(world(), space(), 2 * PLATFORM_HALF, 0.2, 2 * PLATFORM_HALF, 1.0);
    platform.setAsFixedGeom();
    platform.setPosition(0.0, -0.1, 0.0);
    platform.color = Color{0.45f, 0.5f, 0.55f};
    platform_ = &platform;
    bornAt_.clear();
    spawned_ = removed_ = maxBodies_ = maxHanging_ = hangingWoken_ = 0;
    hanging_.clear();
    nextSpawn_ = 0.0;
    startDrops_ = 0;
  }

  void afterStep() override {
    if (windowStart() && startDrops_ < 2 && simulatedTime() >= startDrops_ * FIRST_SPHERE_AT) {
      spawn(startDrops_ == 0);
      ++startDrops_;
    }
    const double interval = spawnInterval();
    if (interval > 0 && (spawnLimit_ == 0 || spawned_ < spawnLimit_) && simulatedTime() >= nextSpawn_) {
      spawn(spawnShapes_ == "box" || (spawnShapes_ == "both" && spawned_ % 2 == 0));
      nextSpawn_ += interval;
    }
    // Counted before this step's removals: the most that were ever alive.
    maxBodies_ = std::max(maxBodies_, bodyCount());
    const int removedBefore = removed_;
    removeExpired();
    trackHanging(removed_ > removedBefore);
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    std::ostringstream s;
    s << "spawned " << spawned_ << "   removed " << removed_ << " (lifetime " << LIFETIME_SECONDS
      << " s, or outside the boundary)   B box, N sphere";
    lines.push_back(s.str());
  }

  // The live plot (L): the scene's headline measurement.
  bool plotValue(double& value) const override {
    value = double(bodyCount() - disabledBodyCount());
    return true;
  }
  std::string plotLabel() const override { return "active (not disabled) bodies"; }

  void addMetrics(Metrics& m) const override {
    m.set("spawned", spawned_);
    m.set("removed_bodies", removed_);
    m.set("max_bodies", maxBodies_);
    int resting = 0;
    double maxSpeed = 0.0;
    for (const auto& object : objects()) {
      if (object->isFixed()) continue;
      const dReal* v = dBodyGetLinearVel(object->getBody());
      const double speed = vectorLength(v);
      maxSpeed = std::max(maxSpeed, speed);
      const dReal* p = object->getPosition();
      const bool abovePlatform = std::fabs(p[0]) < PLATFORM_HALF && std::fabs(p[2]) < PLATFORM_HALF && p[1] > 0.0;
      if (abovePlatform && speed < REST_SPEED) ++resting;
    }
    m.set("bodies_resting_on_platform", resting);
    m.set("max_speed", maxSpeed);
    m.set("hanging_disabled_bodies", int(hangingDisabledBodies().size()));
    m.set("max_hanging_disabled_bodies", maxHanging_);
    m.set("hanging_bodies_woken", hangingWoken_);
  }

 private:
  double spawnInterval() const {
    // Headless, a run without --spawn-interval spawns every second.
    if (options().headless && spawnKnob_->parsed && spawnKnob_->parsed->count() == 0) return 1.0;
    return spawnInterval_;
  }

  // A window whose spawning was not chosen on the command line (the
  // launcher's scenes too): its first box and sphere drop by themselves.
  bool windowStart() const {
    return !options().headless && !(spawnKnob_->parsed && spawnKnob_->parsed->count() > 0);
  }

  double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(random()); }

  void spawn(bool box) {
    AbstractObject* object;
    if (box) {
      const double w = uniform(0.2, 1.0), h = uniform(0.2, 1.0), d = uniform(0.2, 1.0);
      object = &add<Box>(world(), space(), w, h, d, DENSITY * w * h * d);
    } else {
      const double r = uniform(0.1, 0.5);
      object = &add<Sphere>(world(), space(), r, DENSITY * 4.0 / 3.0 * M_PI * r * r * r);
    }
    object->setPosition(0.0, SPAWN_HEIGHT, 0.0);
    dMatrix3 rotation;
    dRFromAxisAndAngle(rotation, uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(0, M_PI));
    dBodySetRotation(object->getBody(), rotation);
    object->color = Color{static_cast<float>(uniform(0.3, 1.0)), static_cast<float>(uniform(0.3, 1.0)),
                          static_cast<float>(uniform(0.3, 1.0))};
    bornAt_[object] = simulatedTime();
    ++spawned_;
  }

  // Disabled bodies left in the air: nothing (platform or body) within
  // SUPPORT_GAP below their lowest point. "Below" is by bounding boxes: any
  // other geom whose box overlaps the slab under this one's counts as support,
  // so a body is called hanging only when nothing at all is under it.
  std::vector<const AbstractObject*> hangingDisabledBodies() const {
    std::vector<const AbstractObject*> hanging;
    for (const auto& object : objects()) {
      if (object->isFixed() || dBodyIsEnabled(object->getBody())) continue;
      dReal box[6];
      dGeomGetAABB(object->getGeom(), box);
      bool supported = false;
      for (const auto& other : objects()) {
        if (other.get() == object.get()) continue;
        dReal o[6];
        dGeomGetAABB(other->getGeom(), o);
        supported = o[0] < box[1] && o[1] > box[0] && o[4] < box[5] && o[5] > box[4] &&
                    o[3] > box[2] - SUPPORT_GAP && o[2] < box[2] + SUPPORT_GAP;
        if (supported) break;
      }
      if (!supported) hanging.push_back(object.get());
    }
    return hanging;
  }

  // A body starts hanging only when its support goes, i.e. after a removal;
  // one that hangs stays disabled until something touches it and ODE wakes
  // it: those are counted as woken.
  void trackHanging(bool removedSome) {
    for (auto it = hanging_.begin(); it != hanging_.end();) {
      if (dBodyIsEnabled((*it)->getBody())) {
        ++hangingWoken_;
        it = hanging_.erase(it);
      } else {
        ++it;
      }
    }
    if (!removedSome) return;
    for (const AbstractObject* object : hangingDisabledBodies()) hanging_.insert(object);
    maxHanging_ = std::max(maxHanging_, int(hanging_.size()));
  }

  void removeExpired() {
    const double now = simulatedTime();
    removeIf([&](const AbstractObject& object) {
      auto born = bornAt_.find(&object);
      if (born == bornAt_.end()) return false;  // the platform
      const dReal* p = object.getPosition();
      const bool outside = std::fabs(p[0]) > BOUNDARY_XZ || std::fabs(p[2]) > BOUNDARY_XZ || p[1] < BOUNDARY_Y;
      if (!outside && now - born->second < LIFETIME_SECONDS) return false;
      bornAt_.erase(born);
      hanging_.erase(&object);
      ++removed_;
      return true;
    });
  }

  Box* platform_ = nullptr;
  std::map<const AbstractObject*, double> bornAt_;
  int spawned_ = 0;
  int removed_ = 0;
  int maxBodies_ = 0;  // the most bodies alive at once (after a step's spawn)
  std::set<const AbstractObject*> hanging_;  // disabled bodies left in the air, until woken or removed
  int maxHanging_ = 0;
  int hangingWoken_ = 0;
  double nextSpawn_ = 0.0;
  int startDrops_ = 0;  // of the window's first box and sphere, dropped so far
  double spawnInterval_ = 0.0;
  const Knob* spawnKnob_ = nullptr;
  int spawnLimit_ = 0;
  inline static const std::vector<std::string> SPAWN_SHAPES{"both", "box", "sphere"};
  std::string spawnShapes_ = "both";
};

}  // namespace

ODELAB_SCENE(BoxAndSphere,
             "Boxes and spheres of random size fall onto a platform; auto-disable on.")
