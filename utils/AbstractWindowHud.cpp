// AbstractWindow, HUD: the text lines the window front end draws.
#include <cmath>
#include <iomanip>
#include <sstream>

#include "AbstractWindow.h"
#include "FormatValue.h"
#include "OdeMessages.h"
#include "SpringDamper.h"

namespace odelab {

// ERP and CFM as the spring and damper they mean at this step, and the ERP
// and CFM that would keep that spring at the next step size (F8).
std::string AbstractWindow::springLine() const {
  const SpringDamper spring = springDamperOf(settings_.erp, settings_.cfm, settings_.step);
  if (spring.rigid) return "constraints rigid (CFM 0): no spring; ERP corrects " + formatValue(settings_.erp) +
                           " of the error per step";
  WorldSettings next = settings_;
  ParameterStepper::stepStepSize(next, +1);
  const ErpCfm keep = erpCfmFor(spring, next.step);
  std::ostringstream s;
  s << "spring kp " << formatValue(spring.kp) << " N/m, damper kd " << formatValue(spring.kd)
    << " N s/m; at step " << formatValue(next.step) << " keep them with ERP " << formatValue(keep.erp) << ", CFM "
    << formatValue(keep.cfm);
  return s.str();
}

std::vector<std::string> AbstractWindow::hudLines() const {
  std::vector<std::string> lines;
  std::ostringstream s;
  s << title_;
  lines.push_back(s.str());
  s.str("");
  s << "ERP " << formatValue(settings_.erp) << "   CFM " << formatValue(settings_.cfm) << "   step "
    << formatValue(settings_.step) << " s   F2 increment " << formatValue(stepper_.increment());
  lines.push_back(s.str());
  s.str("");
  s << "solver " << (settings_.solver == Solver::QuickStep ? "dWorldQuickStep" : "dWorldStep") << "   iterations "
    << settings_.iterations << "   SOR w " << formatValue(settings_.sor) << "   space " << spaceKindName(spaceKind_);
  lines.push_back(s.str());
  s.str("");
  s << std::fixed << std::setprecision(0) << "FPS " << framesPerSecond_ << std::setprecision(2) << "   sim "
    << simulatedTime_ << " s   real-time x" << realTimeFactor_;
  lines.push_back(s.str());
  s.str("");
  s << "bodies " << bodyCount() << " (" << disabledBodyCount() << " disabled)   contacts " << contactsLastStep_;
  lines.push_back(s.str());
  s.str("");
  s << (paused_ ? "PAUSED (P runs, O steps)" : "running") << "   time scale x" << formatValue(timeScale_)
    << "   rewind , .  (" << timeline_.snapshotCount() << " snapshots)   H help";
  lines.push_back(s.str());
  lines.push_back(springLine());
  if (const AbstractObject* object = draggedObject()) {
    const dReal* v = dBodyGetLinearVel(object->getBody());
    s.str("");
    s << "dragging object #" << dragIndex_ << " (" << (object->shape() == Shape::Box ? "box" : "sphere") << ", "
      << formatValue(object->mass()) << " kg), speed "
      << formatValue(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])) << " m/s";
    lines.push_back(s.str());
  }
  addHudLines(lines);
  if (!notice_.empty() && wallSeconds_ < noticeUntil_) lines.push_back(notice_);
  for (const auto& message : OdeMessages::recent()) lines.push_back(message);
  return lines;
}

}  // namespace odelab
