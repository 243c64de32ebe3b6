// A world's "ghost" (doc/world-format.md): read back as written, and a ghost
// whose law cannot follow the world refused with status 2 naming the field
// (WorldFileError, as every field of the format), before anything runs.
#include <gtest/gtest.h>

#include <string>

#include "world/WorldJson.h"
#include "world_file_error_of.h"

namespace {

using namespace odelab::world;

// A ball on a ground y = 0; `extra` adds top-level fields.
std::string worldWith(const std::string& ghost, const std::string& extra = "",
                      const std::string& gravity = "[0, -9.81, 0]", const std::string& velocity = "[0, 0, 0]",
                      const std::string& shape = R"("shape": "sphere", "radius": 0.1)") {
  return R"({"format": "odelab-world", "version": 1, )" + extra + R"("settings": {"step": 0.001, "gravity": )" + gravity +
         R"(}, "bodies": [{"mass": 1, "inertia": [0.01, 0.01, 0.01, 0, 0, 0], "position": [0, 1, 0], "linear_velocity": )" +
         velocity + R"(}], "geoms": [{)" + shape +
         R"(, "body": 0}, {"shape": "plane", "body": -1, "plane": [0, 1, 0, 0]}],
    "surfaces": [{"mu": 0, "restitution": 0.5}], "ghost": )" + ghost + "}";
}

std::string errorOf(const std::string& text) { return worldFileErrorOf(text); }

TEST(WorldGhost, ReadsBackAsWritten) {
  const World w = worldFromJson(worldWith(R"({"body": 0, "law": "bounce"})"));
  ASSERT_TRUE(w.ghost.on);
  const World again = worldFromJson(worldToJson(w));
  EXPECT_TRUE(again.ghost.on);
  EXPECT_EQ(again.ghost.body, 0);
  EXPECT_EQ(again.ghost.law, GhostLaw::Bounce);
  const World ballistic = worldFromJson(worldWith(R"({"body": 0, "law": "ballistic"})"));
  EXPECT_EQ(worldFromJson(worldToJson(ballistic)).ghost.law, GhostLaw::Ballistic);
}

TEST(WorldGhost, RefusesWhatIsWrongNamingTheField) {
  const auto refused = [&](const std::string& text, const std::string& said) {
    const std::string error = errorOf(text);
    EXPECT_NE(error.find(said), std::string::npos) << said << " expected; got: " << error;
  };
  refused(worldWith(R"("bounce")"), "ghost: must be an object");
  refused(worldWith(R"({"law": "bounce"})"), "ghost.body: is missing");
  refused(worldWith(R"({"body": 1, "law": "bounce"})"), "ghost.body: must be in [0, 0]");
  refused(worldWith(R"({"body": 0})"), "ghost.law: is missing");
  refused(worldWith(R"({"body": 0, "law": "orbit"})"), "ghost.law: \"orbit\" is not one of");
  refused(worldWith(R"({"body": 0, "law": "bounce", "colour": "grey"})"), "ghost.colour: is not a field of this format");
  // The law's own conditions, each named with the figure at fault.
  refused(worldWith(R"({"body": 0, "law": "bounce"})", "", "[0, -9.81, 0]", "[1, 0, 0]"),
          "ghost.law: \"bounce\" is vertical motion: bodies[0].linear_velocity");
  refused(worldWith(R"({"body": 0, "law": "bounce"})", "", "[1, -9.81, 0]"),
          "ghost.law: \"bounce\" needs gravity along the plane's normal");
  refused(worldWith(R"({"body": 0, "law": "bounce"})", "", "[0, 0, 0]"), "ghost.law: \"bounce\" needs the body under gravity");
  refused(worldWith(R"({"body": 0, "law": "bounce"})", "", "[0, -9.81, 0]", "[0, 0, 0]",
                    R"("shape": "box", "size": [0.2, 0.2, 0.2])"),
          "ghost.law: \"bounce\" needs a body whose one geom is a sphere");
  refused(worldWith(R"({"body": 0, "law": "ballistic"})", R"("events": [{"at": 0.5, "push": 0, "impulse": [1, 0, 0]}], )"),
          "ghost.body: body 0 is pushed by events[0]");
  refused(worldWith(R"({"body": 0, "law": "ballistic"})",
                    R"("joints": [{"type": "ball", "body1": 0, "body2": -1, "anchor": [0, 2, 0]}], )"),
          "ghost.law: \"ballistic\" is a free body's: body 0 has a joint (joints[0])");
  refused(worldWith(R"({"body": 0, "law": "pendulum"})"), "ghost.law: \"pendulum\" needs body 0 held by one joint");
  refused(worldWith(R"({"body": 0, "law": "pendulum"})",
                    R"("joints": [{"type": "slider", "body1": 0, "body2": -1, "axis": [0, 1, 0]}], )"),
          "ghost.law: \"pendulum\" needs a hinge or a ball joint");
}

TEST(WorldGhost, RefusesABounceWithoutOneGround) {
  const std::string noPlane = R"({"format": "odelab-world", "version": 1, "settings": {"step": 0.001, "gravity": [0, -9.81, 0]},
    "bodies": [{"mass": 1, "inertia": [0.01, 0.01, 0.01, 0, 0, 0], "position": [0, 1, 0]}],
    "geoms": [{"shape": "sphere", "body": 0, "radius": 0.1}], "surfaces": [{"mu": 0}],
    "ghost": {"body": 0, "law": "bounce"}})";
  EXPECT_NE(errorOf(noPlane).find("ghost.law: \"bounce\": the world has no plane"), std::string::npos) << errorOf(noPlane);
  const std::string below = worldWith(R"({"body": 0, "law": "bounce"})");
  std::string inside = below;
  inside.replace(inside.find("\"position\": [0, 1, 0]"), 21, "\"position\": [0, 0.05, 0]");
  EXPECT_NE(errorOf(inside).find("ghost.law: \"bounce\": body 0 starts inside the plane"), std::string::npos)
      << errorOf(inside);
}

}  // namespace
