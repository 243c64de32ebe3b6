#include "StateHash.h"

namespace odelab {

namespace {

class Fnv1a {
 public:
  template <typename T>
  void mix(const T* values, int count) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values);
    for (size_t i = 0; i < count * sizeof(T); ++i) hash_ = (hash_ ^ bytes[i]) * 1099511628211ull;
  }
  template <typename T>
  void mix(T value) {
    mix(&value, 1);
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 1469598103934665603ull;
};

}  // namespace

std::uint64_t stateHash(dWorldID world, long long steps, double simulatedTime, const std::vector<dBodyID>& bodies) {
  Fnv1a hash;
  hash.mix(steps);
  hash.mix(simulatedTime);
  dVector3 gravity;
  dWorldGetGravity(world, gravity);
  hash.mix(gravity, 3);
  hash.mix(dWorldGetERP(world));
  hash.mix(dWorldGetCFM(world));
  hash.mix(dWorldGetQuickStepNumIterations(world));
  hash.mix(dWorldGetQuickStepW(world));
  hash.mix(dWorldGetContactMaxCorrectingVel(world));
  hash.mix(dWorldGetContactSurfaceLayer(world));
  for (const dBodyID body : bodies) {
    hash.mix(dBodyGetPosition(body), 3);
    hash.mix(dBodyGetQuaternion(body), 4);
    hash.mix(dBodyGetLinearVel(body), 3);
    hash.mix(dBodyGetAngularVel(body), 3);
  }
  return hash.value() & ((1ull << 52) - 1);
}

}  // namespace odelab
