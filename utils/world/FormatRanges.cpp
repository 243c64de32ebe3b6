#include "FormatRanges.h"

#include <sstream>
#include <utility>
#include <vector>

#include "WorldSettings.h"

namespace odelab::world::limits {

std::string rangesAsJson() {
  // Names: an object's kind and field as the schema's $defs name them; "[]" for each item of an array.
  const std::vector<std::pair<const char*, std::pair<double, double>>> table = {
      {"settings.step", {ranges::STEP.min, ranges::STEP.max}},
      {"settings.erp", {ranges::ERP.min, ranges::ERP.max}},
      {"settings.cfm", {ranges::CFM.min, ranges::CFM.max}},
      {"settings.iterations", {ranges::ITERATIONS.min, ranges::ITERATIONS.max}},
      {"settings.sor_w", {ranges::SOR.min, ranges::SOR.max}},
      {"settings.gravity[]", {-GRAVITY_COMPONENT, GRAVITY_COMPONENT}},
      {"body.mass", {MASS_MIN, MASS_MAX}},
      {"body.inertia[]", {-INERTIA, INERTIA}},
      {"body.position[]", {-LENGTH, LENGTH}},
      {"body.linear_velocity[]", {-SPEED, SPEED}},
      {"body.angular_velocity[]", {-ANGULAR_SPEED, ANGULAR_SPEED}},
      {"geom.size[]", {SIDE_MIN, SIDE_MAX}},
      {"geom.radius", {SIDE_MIN, SIDE_MAX}},
      {"geom.length", {0.0, SIDE_MAX}},
      {"geom.position[]", {-LENGTH, LENGTH}},
      {"geom.plane[]", {-LENGTH, LENGTH}},
      {"joint.anchor[]", {-LENGTH, LENGTH}},
      {"joint.axis[]", {-LENGTH, LENGTH}},
      {"event.impulse[]", {-IMPULSE, IMPULSE}},
      {"world.duration", {DURATION_MIN, TIME}},
      {"probe.at", {0.0, TIME}},
      {"probe.from", {0.0, TIME}},
      {"probe.until", {0.0, TIME}},
      {"probe.value", {-READING, READING}},
      {"probe.expect", {-READING, READING}},
      {"probe.tolerance", {0.0, READING}},
      {"probe.relative_tolerance", {0.0, RELATIVE_TOLERANCE}},
  };
  std::ostringstream out;
  out.precision(17);
  out << "{";
  for (std::size_t i = 0; i < table.size(); ++i)
    out << (i ? ",\n " : "") << "\"" << table[i].first << "\": [" << table[i].second.first << ", " << table[i].second.second << "]";
  out << ",\n \"gravity_magnitude\": [" << ranges::GRAVITY.min << ", " << ranges::GRAVITY.max << "]";
  out << ",\n \"items\": " << ITEMS << ",\n \"bytes\": " << BYTES << "}\n";
  return out.str();
}

}  // namespace odelab::world::limits
