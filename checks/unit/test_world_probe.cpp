// A probe measure (a body's state read as one figure, held to an expect):
// read back as written, and every field out of its range or of place
// refused with its path; a world's description and duration likewise.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "world/WorldJson.h"
#include "world_file_error_of.h"

namespace {

using namespace odelab::world;

std::string worldWith(const std::string& measures, const std::string& top = "") {
  return R"({"format": "odelab-world", "version": 1, )" + top +
         R"("settings": {"step": 0.001, "gravity": [0, -9.81, 0]},
    "bodies": [{"mass": 1, "inertia": [0.01, 0.01, 0.01, 0, 0, 0], "position": [0, 1, 0]}],
    "geoms": [{"shape": "sphere", "body": 0, "radius": 0.1}, {"shape": "plane", "body": -1, "plane": [0, 1, 0, 0]}],
    "surfaces": [{"mu": 0.5}], "measures": )" +
         measures + "}";
}

std::string errorOf(const std::string& text) { return worldFileErrorOf(text); }

TEST(WorldProbe, ReadsBackAsWritten) {
  const World w = worldFromJson(worldWith(
      R"([{"kind": "probe", "name": "apex", "body": 0, "of": "position", "axis": "y", "take": "max", "from": 0.5,
           "until": 2, "expect": 1.25, "relative_tolerance": 0.01},
          {"kind": "probe", "name": "landing", "body": 0, "of": "position", "axis": "y", "take": "first_crossing",
           "value": 0.1, "expect": 0.4, "tolerance": 0.005},
          {"kind": "probe", "name": "spin", "body": 0, "of": "angular_momentum", "axis": "magnitude", "at": 1.5},
          {"kind": "probe", "name": "last_speed", "body": 0, "of": "velocity", "axis": "x"}])",
      R"("description": "a ball", "duration": 2.5, )"));
  const World again = worldFromJson(worldToJson(w));
  EXPECT_EQ(again.description, "a ball");
  EXPECT_EQ(again.duration, 2.5);
  ASSERT_EQ(again.measures.size(), 4u);
  const Measure& apex = again.measures[0];
  EXPECT_EQ(apex.kind, MeasureKind::Probe);
  EXPECT_EQ(apex.name, "apex");
  EXPECT_EQ(apex.of, ProbeOf::Position);
  EXPECT_EQ(apex.axis, 1);
  EXPECT_EQ(apex.take, ProbeTake::Max);
  EXPECT_EQ(apex.from, 0.5);
  EXPECT_EQ(apex.until, 2.0);
  EXPECT_EQ(apex.expect, 1.25);
  EXPECT_EQ(apex.relativeTolerance, 0.01);
  EXPECT_TRUE(std::isnan(apex.tolerance));
  EXPECT_EQ(again.measures[1].take, ProbeTake::FirstCrossing);
  EXPECT_EQ(again.measures[1].value, 0.1);
  EXPECT_EQ(again.measures[1].tolerance, 0.005);
  EXPECT_EQ(again.measures[2].axis, MAGNITUDE);
  EXPECT_EQ(again.measures[2].at, 1.5);
  EXPECT_TRUE(std::isnan(again.measures[3].at));  // the run's last state
  EXPECT_TRUE(std::isnan(again.measures[3].expect));
}

TEST(WorldProbe, RefusesWhatIsWrongNamingTheField) {
  const std::string probe = R"({"kind": "probe", "name": "p", "body": 0, "of": "position", "axis": "y", )";
  const auto refused = [&](const std::string& rest, const std::string& said) {
    const std::string error = errorOf(worldWith("[" + probe + rest + "]"));
    EXPECT_NE(error.find(said), std::string::npos) << rest << " gave: " << error;
  };
  refused(R"("at": -1})", "measures[0].at: must be in [0, 1e+06]");
  refused(R"("at": 2e6})", "measures[0].at: must be in [0, 1e+06]");
  refused(R"("take": "max", "from": -0.5})", "measures[0].from: must be in [0, 1e+06]");
  refused(R"("take": "max", "from": 2, "until": 1})", "measures[0].until: must be after from");
  refused(R"("take": "max", "at": 1})", "measures[0].at: is not used by take \"max\"");
  refused(R"("value": 1})", "measures[0].value: is not used by take \"at\"");
  refused(R"("take": "first_crossing"})", "measures[0].value: is missing");
  refused(R"("take": "first_crossing", "value": 1e40})", "measures[0].value: must be in [-1e+33, 1e+33]");
  refused(R"("take": "highest"})", "measures[0].take: \"highest\" is not one of");
  refused(R"("expect": 1})", "measures[0].expect: needs a tolerance");
  refused(R"("expect": 1e34, "tolerance": 1})", "measures[0].expect: must be in [-1e+33, 1e+33]");
  refused(R"("expect": 1, "tolerance": -1})", "measures[0].tolerance: must be in [0, 1e+33]");
  refused(R"("expect": 1, "relative_tolerance": 2})", "measures[0].relative_tolerance: must be in [0, 1]");
  refused(R"("expect": 1, "tolerance": 0.1, "relative_tolerance": 0.1})", "measures[0].relative_tolerance: is given with tolerance");
  refused(R"("tolerance": 0.1})", "measures[0].tolerance: is given without expect");
  refused(R"("expect": 0, "relative_tolerance": 0.1})", "measures[0].relative_tolerance: is relative to expect, which is 0");
  refused(R"("expect": 1, "tolerance": "infinity"})", "measures[0].tolerance: must be a finite number");
  EXPECT_NE(errorOf(worldWith(R"([{"kind": "probe", "body": 0, "of": "position", "axis": "magnitude"}])"))
                .find("measures[0].axis: a position has no magnitude"),
            std::string::npos);
  EXPECT_NE(errorOf(worldWith(R"([{"kind": "probe", "body": 0, "of": "spin", "axis": "y"}])")).find("measures[0].of"),
            std::string::npos);
  EXPECT_NE(errorOf(worldWith(R"([{"kind": "probe", "body": 3, "of": "velocity", "axis": "y"}])")).find("measures[0].body"),
            std::string::npos);
  EXPECT_NE(errorOf(worldWith("[]", R"("duration": 0, )")).find("duration: must be in [1e-06, 1e+06]"), std::string::npos);
  EXPECT_NE(errorOf(worldWith("[]", R"("description": 3, )")).find("description: must be a string"), std::string::npos);
}

}  // namespace
