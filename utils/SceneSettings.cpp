#include "SceneSettings.h"

#include <sstream>

#include "FormatValue.h"

namespace odelab {

std::string SceneSettings::settingsInForce() const {
  std::ostringstream text;
  text << " (step " << formatValue(settings_.step) << ", ERP " << formatValue(settings_.erp) << ", CFM "
       << formatValue(settings_.cfm) << ", solver " << solverName(settings_.solver) << ", " << settings_.iterations
       << " iterations, SOR w " << formatValue(settings_.sor) << ")";
  return text.str();
}

}  // namespace odelab
