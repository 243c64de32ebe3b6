// Lets the programs build against an ODE older than 0.12 (0.11.1 is the
// thesis's version), force-included by cmake/OdeRoot.cmake when ode.h has no
// threading API. Two kinds of difference: the vector and matrix helpers had
// upper-case macro names then, and the threading API did not exist, so its
// calls become no-ops here and every world steps on the calling thread (a
// program's --threads then changes nothing).
#ifndef ODELAB_ODE_BEFORE_0_12_H
#define ODELAB_ODE_BEFORE_0_12_H

#include <cstddef>
#include <ode/ode.h>

#ifndef dODE_VERSION
#define dODE_VERSION ODELAB_ODE_VERSION  // ode.h had no version macro; CMake passes ode.pc's
#endif

#define dMultiply0_331(A, B, C) dMULTIPLY0_331(A, B, C)
#define dMultiply1_331(A, B, C) dMULTIPLY1_331(A, B, C)
#define dMultiply1_333(A, B, C) dMULTIPLY1_333(A, B, C)
#define dCalcVectorCross3(a, b, c) dCROSS(a, =, b, c)

struct dxThreadingImplementation;
struct dxThreadingThreadPool;
struct dThreadingFunctionsInfo;
typedef dxThreadingImplementation* dThreadingImplementationID;
typedef dxThreadingThreadPool* dThreadingThreadPoolID;

inline dThreadingImplementationID dThreadingAllocateMultiThreadedImplementation() { return nullptr; }
inline dThreadingImplementationID dThreadingAllocateSelfThreadedImplementation() { return nullptr; }
inline dThreadingThreadPoolID dThreadingAllocateThreadPool(unsigned, std::size_t, unsigned, void*) { return nullptr; }
inline void dThreadingThreadPoolServeMultiThreadedImplementation(dThreadingThreadPoolID, dThreadingImplementationID) {}
inline void dThreadingImplementationShutdownProcessing(dThreadingImplementationID) {}
inline void dThreadingFreeThreadPool(dThreadingThreadPoolID) {}
inline void dThreadingFreeImplementation(dThreadingImplementationID) {}
inline const dThreadingFunctionsInfo* dThreadingImplementationGetFunctions(dThreadingImplementationID) {
  return nullptr;
}
inline void dWorldSetStepThreadingImplementation(dWorldID, const dThreadingFunctionsInfo*,
                                                 dThreadingImplementationID) {}
inline void dWorldSetStepIslandsProcessingMaxThreadCount(dWorldID, unsigned) {}

#endif
