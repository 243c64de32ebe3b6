#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "Metrics.h"

using odelab::Metrics;

TEST(Metrics, JsonRoundTripsAndKeepsOrder) {
  Metrics m;
  m.set("steps", 10000);
  m.set("energy_rel_variation", 0.0075);
  m.set("steps", 20000);  // replaces in place
  const Metrics back = odelab::parseMetricsJson(m.toJson());
  ASSERT_EQ(back.entries().size(), 2u);
  EXPECT_EQ(back.entries()[0].first, "steps");
  EXPECT_EQ(back.get("steps"), 20000);
  EXPECT_DOUBLE_EQ(back.get("energy_rel_variation"), 0.0075);
}

TEST(Metrics, NonFiniteValuesBecomeNull) {
  Metrics m;
  m.set("broken", std::nan(""));
  EXPECT_NE(m.toJson().find("null"), std::string::npos);
  EXPECT_TRUE(std::isnan(odelab::parseMetricsJson(m.toJson()).get("broken")));
}

TEST(Metrics, MalformedJsonIsRefused) {
  EXPECT_THROW(odelab::parseMetricsJson("{\"a\": }"), std::runtime_error);
  EXPECT_THROW(odelab::parseMetricsJson("[1]"), std::runtime_error);
}

TEST(Metrics, WritesAtomicallyAndLeavesNoTemporary) {
  Metrics m;
  m.set("x", 1.5);
  const std::string path = "metrics_test.json";
  m.writeJsonAtomically(path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(odelab::parseMetricsJson(text.str()).get("x"), 1.5);
  // The temporary file is ".metrics_test.json.XXXXXX" (utils/SafeFile.cpp): none is left.
  for (const auto& entry : std::filesystem::directory_iterator("."))
    EXPECT_NE(entry.path().filename().string().rfind("." + path + ".", 0), 0u) << entry.path();
  std::remove(path.c_str());
}

TEST(Metrics, UnwritablePathThrowsNamingIt) {
  Metrics m;
  try {
    m.writeJsonAtomically("/nonexistent-folder/m.json");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/m.json"), std::string::npos);
  }
}
