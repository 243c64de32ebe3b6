// ODE before 0.12 has no version.h; the version is the one ode.pc gave CMake
// (a newer ODE's header on the system path would name the wrong one).
#include "../ode_before_0_12.h"
