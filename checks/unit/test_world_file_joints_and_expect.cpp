// A joint's own ERP and CFM are read only where ODE applies them (ball and
// fixed joints) and refused on a hinge or slider, which ODE would leave
// unchanged by them; a measure's `expect` (the world's analytic answer) reads
// back the same.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "world/WorldJson.h"
#include "world_file_error_of.h"

namespace {

using namespace odelab::world;

std::string worldWith(const std::string& joint, const std::string& measures = "[]") {
  return R"({"format": "odelab-world", "version": 1, "settings": {"step": 0.001, "gravity": [0, -9.81, 0]},
    "bodies": [{"mass": 1, "inertia": [0.01, 0.01, 0.01, 0, 0, 0], "position": [0, 1, 0]}],
    "geoms": [{"shape": "box", "body": 0, "size": [0.1, 0.1, 0.1]}, {"shape": "plane", "body": -1, "plane": [0, 1, 0, 0]}],
    "joints": [)" + joint + R"(], "surfaces": [{"mu": 0.5}], "measures": )" + measures + "}";
}

std::string errorOf(const std::string& text) { return worldFileErrorOf(text); }

TEST(WorldFileJoints, HingeAndSliderOwnErpCfmAreRefused) {
  const std::string hinge = R"({"type": "hinge", "body1": 0, "body2": -1, "anchor": [0, 1, 0], "axis": [0, 0, 1], )";
  EXPECT_NE(errorOf(worldWith(hinge + R"("erp": 0.9})")).find("joints[0].erp: a hinge joint has no erp of its own"),
            std::string::npos);
  EXPECT_NE(errorOf(worldWith(hinge + R"("cfm": 0.01})")).find("joints[0].cfm: a hinge joint has no cfm of its own"),
            std::string::npos);
  const std::string slider = R"({"type": "slider", "body1": 0, "body2": -1, "axis": [1, 0, 0], "cfm": 0.01})";
  EXPECT_NE(errorOf(worldWith(slider)).find("joints[0].cfm: a slider joint has no cfm of its own"), std::string::npos);
}

TEST(WorldFileJoints, BallAndFixedOwnErpCfmReadBack) {
  for (const std::string joint : {R"({"type": "fixed", "body1": 0, "body2": -1, "erp": 0.9, "cfm": 0.01})",
                                  R"({"type": "ball", "body1": 0, "body2": -1, "anchor": [0, 2, 0], "erp": 0.9, "cfm": 0.01})"}) {
    const World w = worldFromJson(worldWith(joint));
    EXPECT_EQ(w.joints[0].erp, 0.9);
    EXPECT_EQ(w.joints[0].cfm, 0.01);
    const World again = worldFromJson(worldToJson(w));
    EXPECT_EQ(again.joints[0].erp, 0.9);
    EXPECT_EQ(again.joints[0].cfm, 0.01);
  }
}

TEST(WorldFileExpect, ReadsBackAndIsRefusedOutOfRange) {
  const std::string fixed = R"({"type": "fixed", "body1": 0, "body2": -1})";
  const World w = worldFromJson(worldWith(fixed, R"([{"kind": "energy", "expect": -0.5},
      {"kind": "tunnelling", "geom": 1, "expect": 1}, {"kind": "rest", "expect": "never"}])"));
  const World again = worldFromJson(worldToJson(w));
  ASSERT_EQ(again.measures.size(), 3u);
  EXPECT_EQ(again.measures[0].expect, -0.5);
  EXPECT_EQ(again.measures[1].expect, 1.0);
  EXPECT_TRUE(again.measures[2].expectNever);
  EXPECT_TRUE(std::isnan(again.measures[2].expect));
  const World timed = worldFromJson(worldWith(fixed, R"([{"kind": "rest", "expect": 1.5}])"));
  EXPECT_EQ(worldFromJson(worldToJson(timed)).measures[0].expect, 1.5);
  EXPECT_NE(errorOf(worldWith(fixed, R"([{"kind": "rest", "expect": "soon"}])")).find("measures[0].expect"),
            std::string::npos);
  EXPECT_NE(errorOf(worldWith(fixed, R"([{"kind": "tunnelling", "geom": 1, "expect": 2}])")).find("measures[0].expect"),
            std::string::npos);  // more bodies than the world has
  EXPECT_NE(errorOf(worldWith(fixed, R"([{"kind": "penetration", "expect": 0}])")).find("measures[0].expect"),
            std::string::npos);  // no analytic answer of that kind is stated this way
}

}  // namespace
