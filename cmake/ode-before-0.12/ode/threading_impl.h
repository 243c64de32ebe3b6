// ODE before 0.12 has no threading_impl.h; a program that includes it gets
// the no-op threading API of ode_before_0_12.h instead (found ahead of any
// newer ODE's header on the include path).
#include "../ode_before_0_12.h"
