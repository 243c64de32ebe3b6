// The metrics' one rule for values that are not finite numbers (utils/Metrics.h,
// doc/manual.md "Outputs"): a metric not measured is
// JSON null and nothing else is; a measured NaN or infinity is the string
// "nan", "inf" or "-inf", so no reader mistakes a blow-up for a figure not
// measured yet, or either for a number.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "Metrics.h"
#include "SceneVisits.h"

using odelab::Metrics;

namespace {
constexpr double INF = std::numeric_limits<double>::infinity();

std::string printed(const Metrics& m) {
  std::ostringstream out;
  m.print(out);
  return out.str();
}
}  // namespace

TEST(MetricsNotMeasured, NotMeasuredIsNullAndMeasuredNonFiniteIsNamed) {
  Metrics m;
  m.setNotMeasured("period_seconds");
  m.set("energy_drift", std::nan(""));
  m.set("energy_max_J", INF);
  m.set("energy_min_J", -INF);
  const std::string json = m.toJson();
  EXPECT_NE(json.find("\"period_seconds\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"energy_drift\": \"nan\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"energy_max_J\": \"inf\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"energy_min_J\": \"-inf\""), std::string::npos) << json;
  // null only where nothing was measured.
  EXPECT_EQ(json.find("null"), json.rfind("null")) << json;
  const std::string lines = printed(m);
  EXPECT_NE(lines.find("period_seconds = not measured\n"), std::string::npos) << lines;
  EXPECT_NE(lines.find("energy_drift = nan\n"), std::string::npos) << lines;
  EXPECT_NE(lines.find("energy_min_J = -inf\n"), std::string::npos) << lines;
}

TEST(MetricsNotMeasured, ReadBackKeepsTheDifference) {
  Metrics m;
  m.setNotMeasured("time_to_rest_s");
  m.set("energy_drift", std::nan(""));
  m.set("energy_max_J", INF);
  m.set("energy_min_J", -INF);
  m.set("steps", 10);
  const Metrics back = odelab::parseMetricsJson(m.toJson());
  EXPECT_TRUE(back.has("time_to_rest_s"));
  EXPECT_FALSE(back.measured("time_to_rest_s"));
  EXPECT_TRUE(std::isnan(back.get("time_to_rest_s")));
  EXPECT_TRUE(back.measured("energy_drift"));
  EXPECT_TRUE(std::isnan(back.get("energy_drift")));
  EXPECT_EQ(back.get("energy_max_J"), INF);
  EXPECT_EQ(back.get("energy_min_J"), -INF);
  EXPECT_TRUE(back.measured("steps"));
  EXPECT_FALSE(back.measured("absent"));
  EXPECT_EQ(back.toJson(), m.toJson());
}

TEST(MetricsNotMeasured, MeasuringLaterReplacesNotMeasured) {
  Metrics m;
  m.setNotMeasured("period_seconds");
  m.set("period_seconds", 2.0);
  EXPECT_TRUE(m.measured("period_seconds"));
  m.set("period_seconds", 0.0, false);
  EXPECT_FALSE(m.measured("period_seconds"));
  m.set("period_seconds", 2.0, true);
  EXPECT_EQ(m.get("period_seconds"), 2.0);
}

TEST(MetricsNotMeasured, CopiesUnderAPrefixKeepIt) {
  // A compare run's and a launcher session's metrics copy each run's under a prefix.
  Metrics run;
  run.setNotMeasured("period_seconds");
  run.set("energy_drift", std::nan(""));
  Metrics all;
  odelab::addPrefixed(all, "jolt.", run);
  EXPECT_FALSE(all.measured("jolt.period_seconds"));
  EXPECT_TRUE(all.measured("jolt.energy_drift"));
  EXPECT_NE(all.toJson().find("\"jolt.period_seconds\": null"), std::string::npos);
  EXPECT_NE(all.toJson().find("\"jolt.energy_drift\": \"nan\""), std::string::npos);
}

TEST(MetricsNotMeasured, OtherStringsAreRefusedNamingTheMetric) {
  try {
    odelab::parseMetricsJson("{\"energy_drift\": \"NaN\"}");
    FAIL() << "a string that is not one of the writer's was read";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("\"energy_drift\" is a string"), std::string::npos) << error.what();
  }
  EXPECT_THROW(odelab::parseMetricsJson("{\"notes\": [null]}"), std::runtime_error);
}
