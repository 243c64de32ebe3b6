#pragma once

// Surface choices the ODE scenes make that each peer engine has to map onto
// its own. peers/wasm/src/constants.js reads this file too.

namespace odelab::peers {

// test6 and test7 never let a contact slide (ODE's mu = dInfinity). No
// peer's friction coefficient takes infinity: every shape gets this one, a
// friction cone of 89.4 degrees (sliding only once the tangential force is
// 100 times the normal).
constexpr double NO_SLIP_FRICTION = 100.0;

}  // namespace odelab::peers
