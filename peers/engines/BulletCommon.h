#pragma once

// What the Bullet adapter's files share: conversions between the world
// description's arrays and Bullet's types, and the list of translation notes.

#include <btBulletDynamicsCommon.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "world/WorldDescription.h"

namespace odelab::engines::bullet {

inline btVector3 toBt(const world::Vec3& v) { return btVector3(v[0], v[1], v[2]); }
// The description's quaternion is [w, x, y, z]; Bullet's constructor takes x, y, z, w.
inline btQuaternion toBt(const world::Quat& q) { return btQuaternion(q[1], q[2], q[3], q[0]); }
inline world::Vec3 fromBt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
inline world::Quat fromBt(const btQuaternion& q) { return {q.w(), q.x(), q.y(), q.z()}; }

// Translation notes: one sentence per fact, each said once, in the order found.
class Notes {
 public:
  void add(const std::string& sentence) {
    if (seen_.insert(sentence).second) list_.push_back(sentence);
  }
  const std::vector<std::string>& list() const { return list_; }

 private:
  std::set<std::string> seen_;
  std::vector<std::string> list_;
};

// A number as a note prints it: six significant digits, no trailing zeros.
inline std::string number(double value) {
  std::ostringstream text;
  text.precision(6);
  text << value;
  return text.str();
}

}  // namespace odelab::engines::bullet
