#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
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

namespace {
// The bits of a double, so that -0.0 and 0.0 (equal as numbers) tell apart.
std::uint64_t bitsOf(double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}
}  // namespace

TEST(Metrics, JsonReadsBackExactlyWhatItHolds) {
  // Whole numbers below 2^64 (counts, state_hash) and numbers of at most 10
  // significant digits come back bit for bit, -0.0 with its sign.
  const double exact[] = {1e-300,
                          -0.0,
                          0.0075,
                          0.30000001,
                          -123456.7891,
                          1.5e-12,
                          4503599627370495.0,      // 2^52 - 1, the largest state_hash (StateHash.h)
                          9007199254740992.0,      // 2^53
                          9007199254740994.0,      // 2^53 + 2: above 2^53, even numbers only
                          18446744073709549568.0,  // 2^64 - 2048, the largest double below 2^64
                          -9223372036854775808.0,  // -2^63
                          1e300};
  Metrics m;
  for (size_t i = 0; i < sizeof exact / sizeof exact[0]; ++i) m.set("v" + std::to_string(i), exact[i]);
  const Metrics back = odelab::parseMetricsJson(m.toJson());
  ASSERT_EQ(back.entries().size(), m.entries().size());
  for (size_t i = 0; i < m.entries().size(); ++i) {
    EXPECT_EQ(back.entries()[i].first, m.entries()[i].first);
    EXPECT_EQ(bitsOf(back.entries()[i].second), bitsOf(m.entries()[i].second))
        << m.entries()[i].first << " = " << m.entries()[i].second << " read back as " << back.entries()[i].second
        << " from\n" << m.toJson();
  }
}

TEST(Metrics, JsonKeepsTenDigitsAndReadsBackToTheSameText) {
  // 0.1 + 0.2 is written 0.3 and read back as 0.3: the 10 digits the checks
  // compare (expect_metrics sim_seconds==1.5 for a run that ends at
  // 1.499999999999946 s). Written again, the text is the same.
  Metrics m;
  m.set("sum", 0.1 + 0.2);
  m.set("third", 1.0 / 3.0);
  m.set("sim_seconds", 1.499999999999946);
  m.set("max", std::numeric_limits<double>::max());
  m.set("smallest", 5e-324);
  const Metrics back = odelab::parseMetricsJson(m.toJson());
  EXPECT_EQ(back.get("sum"), 0.3);
  EXPECT_EQ(back.get("third"), 0.3333333333);
  EXPECT_EQ(back.get("sim_seconds"), 1.5);
  EXPECT_EQ(back.get("max"), std::numeric_limits<double>::max());  // 1.797693135e308 would be infinite
  EXPECT_EQ(back.get("smallest"), 4.940656458e-324);
  EXPECT_EQ(back.toJson(), m.toJson());
}

TEST(Metrics, JsonTextIsOneNamePerLineWholeNumbersExact) {
  Metrics m;
  m.set("steps", 20000);
  m.set("state_hash", 4503599627370495.0);  // 2^52 - 1, as StateHash.h cuts it
  m.set("big", 18446744073709549568.0);     // 2^64 - 2048: every digit, no exponent
  m.set("huge", 1e20);                      // past 2^64: 10 digits
  m.set("sum", 0.1 + 0.2);
  m.set("small", 1.234567891234e-5);
  m.set("tiny", 1e-300);
  m.set("minus_zero", -0.0);
  m.set("negative", -3);
  m.set("broken", std::numeric_limits<double>::infinity());
  m.set("quote\"back\\slash", 1);
  EXPECT_EQ(m.toJson(),
            "{\n"
            "  \"steps\": 20000,\n"
            "  \"state_hash\": 4503599627370495,\n"
            "  \"big\": 18446744073709549568,\n"
            "  \"huge\": 1e+20,\n"
            "  \"sum\": 0.3,\n"
            "  \"small\": 1.234567891e-05,\n"
            "  \"tiny\": 1e-300,\n"
            "  \"minus_zero\": -0.0,\n"
            "  \"negative\": -3,\n"
            "  \"broken\": \"inf\",\n"
            "  \"quote\\\"back\\\\slash\": 1\n"
            "}\n");
  EXPECT_EQ(odelab::parseMetricsJson(m.toJson()).get("quote\"back\\slash"), 1);
  EXPECT_EQ(Metrics().toJson(), "{\n}\n");
}

TEST(Metrics, PrintedLinesHaveTheJsonDigits) {
  Metrics m;
  m.set("steps", 20000);
  m.set("sum", 0.1 + 0.2);
  m.set("big", 18446744073709549568.0);
  m.set("broken", std::nan(""));
  std::ostringstream out;
  m.print(out);
  EXPECT_EQ(out.str(), "steps = 20000\nsum = 0.3\nbig = 18446744073709549568\nbroken = nan\n");
}

TEST(Metrics, ReadsWhatOtherWritersWrite) {
  // Python's json.dump and
  // older files of this writer (10 digits): exponents either case, escaped names.
  const Metrics m = odelab::parseMetricsJson(
      "{\"a\": 1.5, \"b\": -2, \"c\": 1e+20, \"d\": 1E-5, \"e\": null, \"f\\\"g\": 3, \"\\u00e9\": 4}");
  ASSERT_EQ(m.entries().size(), 7u);
  EXPECT_EQ(m.get("a"), 1.5);
  EXPECT_EQ(m.get("b"), -2);
  EXPECT_EQ(m.get("c"), 1e20);
  EXPECT_EQ(m.get("d"), 1e-5);
  EXPECT_TRUE(std::isnan(m.get("e")));
  EXPECT_EQ(m.get("f\"g"), 3);
  EXPECT_EQ(m.get("\xc3\xa9"), 4);
  EXPECT_TRUE(odelab::parseMetricsJson("{}").entries().empty());
  EXPECT_TRUE(odelab::parseMetricsJson(Metrics().toJson()).entries().empty());
  // A name given twice keeps its first place and its last value, as set() does.
  const Metrics twice = odelab::parseMetricsJson("{\"x\": 1, \"y\": 2, \"x\": 3}");
  ASSERT_EQ(twice.entries().size(), 2u);
  EXPECT_EQ(twice.entries()[0].first, "x");
  EXPECT_EQ(twice.get("x"), 3);
}

namespace {
// The message parseMetricsJson refuses `text` with ("" when it reads it).
std::string refusal(const std::string& text) {
  try {
    odelab::parseMetricsJson(text);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Metrics, MalformedFilesAreRefusedSayingWhereAndWhy) {
  // A file cut short, as a crash mid-write would leave it (writeFileAtomically
  // never does): the line and column just past its end.
  EXPECT_EQ(refusal("{\n  \"steps\": 20000,\n  \"sim_"),
            "metrics JSON: parse error at line 3, column 8: syntax error while parsing object key - invalid string: "
            "missing closing quote; last read: '\"sim_'; expected string literal");
  const std::string missing = refusal("{\"a\": }");
  EXPECT_EQ(missing.rfind("metrics JSON: parse error at line 1, column 7", 0), 0u) << missing;
  EXPECT_EQ(refusal("[1]"), "metrics JSON: expected an object, found an array");
  EXPECT_EQ(refusal("3"), "metrics JSON: expected an object, found a number");
  EXPECT_EQ(refusal("null"), "metrics JSON: expected an object, found null");
  const std::string allowed = ", not a number, null, \"nan\", \"inf\", \"-inf\" or list of strings";
  EXPECT_EQ(refusal("{\"a\": \"1\"}"), "metrics JSON: \"a\" is a string" + allowed);
  EXPECT_EQ(refusal("{\"a\": true}"), "metrics JSON: \"a\" is a boolean" + allowed);
  EXPECT_EQ(refusal("{\"a\": {\"b\": 1}}"), "metrics JSON: \"a\" is an object" + allowed);
  EXPECT_EQ(refusal("{\"a\": [1]}"), "metrics JSON: \"a\" is an array with a number" + allowed);
  // What strtod took and JSON does not: NaN and infinity spelled out, hex,
  // a leading '+'; and anything after the object.
  for (const char* text : {"{\"a\": nan}", "{\"a\": inf}", "{\"a\": 0x10}", "{\"a\": +1}", "{\"a\": 1} x", "{\"a\": 1}{}", ""})
    EXPECT_EQ(refusal(text).rfind("metrics JSON: parse error at line 1, column ", 0), 0u) << text << ": " << refusal(text);
}

TEST(Metrics, ManyNamesStayFast) {
  // A session's 100,000 marks: written and read in linear time (a list
  // searched per name would take minutes here).
  Metrics m;
  for (int i = 0; i < 100000; ++i) m.set("visit" + std::to_string(i) + ".test2.energy", i + 0.5);
  const Metrics back = odelab::parseMetricsJson(m.toJson());
  ASSERT_EQ(back.entries().size(), 100000u);
  EXPECT_EQ(back.entries()[99999].first, "visit99999.test2.energy");
  EXPECT_EQ(back.get("visit99999.test2.energy"), 99999.5);
}

TEST(Metrics, ListsOfSentencesRoundTrip) {
  // An engine's translation notes: sentences with quotes and non-ASCII
  // text, written after the numbers and read back in order.
  odelab::Metrics m;
  m.set("steps", 3);
  m.setTexts("translation_notes", {"mu \"infinity\" became 1e6", "float32: ~7 digits", "α"});
  m.setTexts("engine", {"jolt", "best"});
  const odelab::Metrics back = odelab::parseMetricsJson(m.toJson());
  EXPECT_EQ(back.get("steps"), 3);
  ASSERT_EQ(back.texts().size(), 2u);
  EXPECT_EQ(back.texts()[0].second, m.texts()[0].second);
  EXPECT_EQ(back.texts()[1].second, (std::vector<std::string>{"jolt", "best"}));
  EXPECT_THROW(odelab::parseMetricsJson("{\"a\": [1, 2]}"), std::runtime_error);
  EXPECT_THROW(odelab::parseMetricsJson("{\"a\": [[\"x\"]]}"), std::runtime_error);
}
