// test1 - Jumping Balls (thesis 5.2): fifty balls in a row fall onto the
// ground, ball i with restitution (bounce) i/49, from 0 to 1. Each ball's
// bounce is stored as its geom's data and read when its contact is made.
// Does ODE reproduce every coefficient? With restitution e the rebound speed
// is e times the impact speed, so each rebound apex, measured from the
// contact height (the centre's height minus the radius), is e^2 times the
// previous one. Per ball the first two rebound apexes are compared with that
// exact ratio. The thesis (ODE 0.11.1, ERP 0, CFM 0): every coefficient is
// reproduced accurately; CFM ~0.001 damps every ball to rest whatever its
// bounce; ERP above 0 spoils the low-bounce balls.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <vector>

#include "Plane.h"
#include "Sphere.h"
#include "SceneRegistry.h"
#include "shared/ApexTracker.h"
#include "shared/BodyMeasures.h"
#include "shared/BounceVelocityOption.h"
#include "shared/SceneConstants.h"

namespace {

using namespace odelab;

// The scene's constants: SceneConstants.h (shared with the peers in peers/).
using namespace scene::test1;
constexpr double THESIS_ERP = 0.0;         // the thesis: ERP > 0 spoils low-bounce balls
constexpr double THESIS_CFM = 0.0;         // the thesis: CFM ~0.001 damps every ball
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

WorldSettings settingsForThisScene() {
  WorldSettings settings;
  settings.erp = THESIS_ERP;
  settings.cfm = THESIS_CFM;
  settings.gravity = GRAVITY_FACTOR * SURFACE_GRAVITY;
  return settings;
}

// The surface data each ball carries on its geom.
struct BallSurface {
  double bounce;
};

// One ball's measurement: its first two rebound apexes above the contact height.
struct BallRecord {
  dBodyID body = nullptr;
  double bounce = 0.0;
  ApexTracker tracker;
  double apex[2] = {NaN, NaN};

  bool measured() const { return std::isfinite(apex[1]); }
  double ratio() const { return apex[1] / apex[0]; }
  double error() const { return std::fabs(ratio() - bounce * bounce); }
};

class JumpingBalls : public AbstractWindow {
 public:
  JumpingBalls() : AbstractWindow(settingsForThisScene()) {
    declare(bounceVelocityKnob(bounceVelocity_, "the thesis"));
    useContactChoices(dInfinity);  // the thesis names no friction here: never slides
  }

  SceneBounds bounds() const override { return {{0.0, 3.5, 0.0}, 11.0}; }

 protected:
  void buildScene() override {
    add<Plane>(space());
    balls_.assign(BALL_COUNT, BallRecord{});
    for (int i = 0; i < BALL_COUNT; ++i) {
      const double bounce = static_cast<double>(i) / (BALL_COUNT - 1);
      Sphere& ball = add<Sphere>(world(), space(), BALL_RADIUS, BALL_MASS);
      ball.setPosition((i - 0.5 * (BALL_COUNT - 1)) * SPACING, DROP_HEIGHT, 0.0);
      const BallSurface surface{bounce};
      ball.setData(&surface, sizeof surface);
      // Blue for dead balls through red for the perfectly elastic one.
      ball.color = Color{static_cast<float>(0.2 + 0.75 * bounce), 0.3f, static_cast<float>(0.95 - 0.75 * bounce)};
      balls_[i].body = ball.getBody();
      balls_[i].bounce = bounce;
      balls_[i].tracker.restart(0.0, dBodyGetPosition(ball.getBody()));
    }
  }

  // The ball's own bounce, read from its geom; the ground carries none.
  void setContactSurface(dGeomID o1, dGeomID o2, dSurfaceParameters& surface) override {
    const BallSurface* ball = AbstractObject::dataOf<BallSurface>(o1);
    if (!ball) ball = AbstractObject::dataOf<BallSurface>(o2);
    surface.mode = dContactBounce;
    surface.mu = contactMu();
    surface.bounce = ball ? ball->bounce : 0.0;
    surface.bounce_vel = bounceVelocity_;
  }

  void afterStep() override {
    for (auto& ball : balls_) {
      Apex apex;
      if (!ball.tracker.update(simulatedTime(), dBodyGetPosition(ball.body), apex)) continue;
      const int index = ball.tracker.count() - 1;
      if (index < 2) ball.apex[index] = apex.position[1] - BALL_RADIUS;  // above the contact height
    }
  }

  void addHudLines(std::vector<std::string>& lines) const override {
    std::ostringstream s;
    const BallRecord* worst = worstBall();
    s << "rebound apex ratio against e^2, balls with e >= " << MEASURED_FROM_BOUNCE << ": " << measuredCount()
      << " of " << eligibleCount() << " measured";
    lines.push_back(s.str());
    s.str("");
    if (worst) {
      s << std::setprecision(4) << "worst: ball " << (worst - balls_.data()) << " (e = " << worst->bounce
        << "): apex2 / apex1 = " << worst->ratio() << " against e^2 = " << worst->bounce * worst->bounce
        << ", error " << std::scientific << std::setprecision(2) << worst->error();
    } else {
      s << "worst: waiting for the second rebound apexes";
    }
    lines.push_back(s.str());
    s.str("");
    const double lowest = lowestBall();
    s << "balls at rest " << ballsAtRest() << " of " << BALL_COUNT << "   lowest ball " << std::fixed
      << std::setprecision(4) << std::abs(lowest) << (lowest < 0 ? " m into the ground" : " m above the ground");
    lines.push_back(s.str());
  }

  // The live plot (L): the scene's headline measurement.
  bool plotValue(double& value) const override {
    value = worstBall() ? worstBall()->error() : 0.0;
    return true;
  }
  std::string plotLabel() const override { return "largest |rebound ratio - e^2| so far"; }

  void addMetrics(Metrics& m) const override {
    m.set("bounce_velocity", bounceVelocity_);
    const BallRecord* worst = worstBall();
    // Not measured until a ball has rebounded.
    m.set("max_rebound_error", worst ? worst->error() : NaN, worst != nullptr);
    m.set("worst_ball", worst ? static_cast<double>(worst - balls_.data()) : NaN, worst != nullptr);
    m.set("balls_measured", measuredCount());
    m.set("balls_bounced", static_cast<double>(std::count_if(
                               balls_.begin(), balls_.end(), [](const BallRecord& b) { return b.tracker.count() > 0; })));
    m.set("balls_at_rest", ballsAtRest());
    m.set("lowest_ball_m", lowestBall());
  }

  double defaultHeadlessSeconds() const override { return RUN_SECONDS; }

  void initialCamera(Camera& camera) const override { camera.lookAt({0.0, 5.0, 21.0}, {0.0, 3.2, 0.0}); }

 private:
  static bool eligible(const BallRecord& ball) { return ball.bounce >= MEASURED_FROM_BOUNCE; }

  int eligibleCount() const {
    return static_cast<int>(std::count_if(balls_.begin(), balls_.end(), eligible));
  }

  int measuredCount() const {
    return static_cast<int>(
        std::count_if(balls_.begin(), balls_.end(), [](const BallRecord& b) { return eligible(b) && b.measured(); }));
  }

  // The measured ball with the largest |apex2 / apex1 - e^2|; null while none has both apexes.
  const BallRecord* worstBall() const {
    const BallRecord* worst = nullptr;
    for (const auto& ball : balls_)
      if (eligible(ball) && ball.measured() && (!worst || ball.error() > worst->error())) worst = &ball;
    return worst;
  }

  int ballsAtRest() const {
    int resting = 0;
    for (const auto& ball : balls_) {
      const dReal* v = dBodyGetLinearVel(ball.body);
      const double speed = vectorLength(v);
      if (speed < REST_SPEED && dBodyGetPosition(ball.body)[1] - BALL_RADIUS < REST_CLEARANCE) ++resting;
    }
    return resting;
  }

  // The lowest ball's lowest point above the ground now (negative: sunk into it).
  double lowestBall() const {
    double lowest = std::numeric_limits<double>::infinity();
    for (const auto& ball : balls_) lowest = std::min(lowest, dBodyGetPosition(ball.body)[1] - BALL_RADIUS);
    return lowest;
  }

  std::vector<BallRecord> balls_;
  double bounceVelocity_ = BOUNCE_VELOCITY;
};

}  // namespace

ODELAB_SCENE(JumpingBalls,
             "Fifty balls with restitution 0 to 1 bounce on the ground; each rebound "
             "apex ratio is compared with e^2.")
