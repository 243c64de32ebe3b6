// ODE must be initialised once for every test in this binary.
#include <gtest/gtest.h>
#include <ode/ode.h>

#include "OdeMessages.h"

namespace {
class OdeEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    odelab::OdeMessages::install();
  }
  void TearDown() override { dCloseODE(); }
};

const auto* const environment = ::testing::AddGlobalTestEnvironment(new OdeEnvironment);
}  // namespace
