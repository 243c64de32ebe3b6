#pragma once

// A world file (doc/world-format.md) as a scene: `odelab --world FILE` runs
// it in the window or headless, with the framework's HUD, keys, panel,
// metrics and state hash, as a test program runs its own scene. A file that
// testN --export-world wrote gives testN's run again, to the state hash.

#include <memory>
#include <unordered_map>

#include "AbstractWindow.h"
#include "EngineLink.h"
#include "GhostLaw.h"
#include "WorldDescription.h"
#include "WorldMeasures.h"

namespace odelab::world {

class WorldFileScene : public AbstractWindow {
 public:
  // Takes any world the reader (WorldJson.h) accepted: it throws nothing of its own.
  explicit WorldFileScene(World world);
  ~WorldFileScene() override;
  SceneBounds bounds() const override;
  const GhostMotion* ghost() const override { return ghost_.get(); }
  // The window's title: the file's own, or its exporting program's, or the file name.
  std::string fileTitle(const std::string& path) const;

 protected:
  void configureWorld() override;
  void buildScene() override;
  void setContactSurface(dGeomID o1, dGeomID o2, dSurfaceParameters& surface) override;
  void addHudLines(std::vector<std::string>& lines) const override;
  void beforeStep() override;  // the file's events
  void afterStep() override;   // its measures
  void addMetrics(Metrics& metrics) const override;
  void initialCamera(Camera& camera) const override;  // framing the file's bodies
  bool plotValue(double& value) const override;  // the live plot (L): the total energy when measured
  std::string plotLabel() const override;
  const FileOrigin* fileOrigin() const override { return &origin_; }
  // Headless without --seconds: the file's duration, where it states one.
  double defaultHeadlessSeconds() const override {
    return world_.duration > 0 ? world_.duration : AbstractWindow::defaultHeadlessSeconds();
  }

 private:
  bool droppedLater(int body) const;
  static Color bodyColor(int body);  // a body's own colour, by its index in the file
  // The geoms of the bodies marked in `bodies` (and the static ones when
  // `statics`), their bodies, offsets and collide bits.
  void buildGeoms(const std::vector<bool>& bodies, bool statics);
  void buildBody(int index, AbstractObject& owner);
  void warnOfOverlaps();
  dJointID buildJoint(const Joint& joint);

  World world_;
  double fileMu_;  // the default surface's friction: the mu knob overrides every surface once moved from it
  std::unordered_map<dGeomID, int> geomIndex_;
  std::unordered_map<dJointID, int> jointIndex_;  // the file's index of each joint built
  FileOrigin origin_;
  std::vector<AbstractObject*> bodyOwner_;  // per body: the object whose body it is, null until dropped in
  std::unique_ptr<WorldMeasures> measures_;
  std::unique_ptr<GhostMotion> ghost_;  // null: the file states none
  size_t nextEvent_ = 0;
  bool warned_ = false;  // overlaps are said once, not again on R
};

}  // namespace odelab::world
