#pragma once

#include <ode/ode.h>
#include <ode/threading_impl.h>

#include <stdexcept>
#include <string>

namespace odelab {

// ODE's built-in thread pool serving its multi-threaded implementation, for
// threaded island stepping. Created once and kept across resets (the world is
// rebuilt on every R); attach() hooks it to each new world.
class IslandThreads {
 public:
  explicit IslandThreads(int threads) : threads_(threads) {
    impl_ = dThreadingAllocateMultiThreadedImplementation();
    if (!impl_) throw std::runtime_error("ODE has no built-in multi-threaded implementation");
    pool_ = dThreadingAllocateThreadPool(static_cast<unsigned>(threads), 0, dAllocateFlagBasicData, nullptr);
    if (!pool_) {
      dThreadingFreeImplementation(impl_);
      throw std::runtime_error("ODE could not start a pool of " + std::to_string(threads) + " threads");
    }
    dThreadingThreadPoolServeMultiThreadedImplementation(pool_, impl_);
  }
  ~IslandThreads() {
    dThreadingImplementationShutdownProcessing(impl_);
    dThreadingFreeThreadPool(pool_);
    dThreadingFreeImplementation(impl_);
  }
  IslandThreads(const IslandThreads&) = delete;
  IslandThreads& operator=(const IslandThreads&) = delete;

  void attach(dWorldID world) const {
    dWorldSetStepIslandsProcessingMaxThreadCount(world, static_cast<unsigned>(threads_));
    dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(impl_), impl_);
  }

 private:
  int threads_;
  dThreadingImplementationID impl_ = nullptr;
  dThreadingThreadPoolID pool_ = nullptr;
};

}  // namespace odelab
