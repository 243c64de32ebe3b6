#pragma once

#include <ode/ode.h>

#include <cstdint>
#include <vector>

namespace odelab {

// The state_hash of a run (metrics, marks, the determinism checks): FNV-1a
// over the exact bytes of the step count, the simulated time, the world's
// settings (gravity, ERP, CFM, QuickStep iterations and SOR w, contact
// max correcting velocity and surface layer) and every body's position,
// orientation and velocities in the order given; cut to 52 bits so JSON's
// doubles hold it. The count, time and settings make two states differ even
// where there are no bodies yet (test10 before its first launch).
std::uint64_t stateHash(dWorldID world, long long steps, double simulatedTime, const std::vector<dBodyID>& bodies);

}  // namespace odelab
