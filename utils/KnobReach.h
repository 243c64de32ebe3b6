#pragma once

#include <string>
#include <vector>

namespace odelab {

// Whether a world setting of ODE's (a knob: "erp", "cfm", "iterations",
// "sor", "solver") reaches the engine that steps the scene (--engine): ""
// where it does, else why not, for the HUD and the panel to grey the row
// and say so. ERP, CFM and the iteration count reach an engine unless one
// of its own translation notes says they do not (that note is the answer).
// ODE's solver choice and its SOR over-relaxation belong to ODE's solvers,
// which no other engine has: they never reach one (its note where it has
// one). Every other knob reaches every engine (the scene measures or
// builds with it).
std::string knobNotReached(const std::string& knobName, const std::string& engine,
                           const std::vector<std::string>& translationNotes);

}  // namespace odelab
