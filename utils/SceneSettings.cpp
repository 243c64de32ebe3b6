#include "SceneSettings.h"

#include "SettingsTable.h"

namespace odelab {

std::string SceneSettings::settingsInForce() const { return settingsInForceText(settings_); }

}  // namespace odelab
