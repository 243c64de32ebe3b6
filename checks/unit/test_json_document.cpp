// The world reader's JSON table (utils/world/JsonDocument.h), filled from
// nlohmann's SAX events: what it holds must be exactly what
// nlohmann::json::parse makes of it (the
// same kinds of number, the same doubles, the same keys in the same places),
// and a text nlohmann refuses must be refused with nlohmann's own exception
// and message. Also its bounds: nesting past MAX_JSON_DEPTH stops the
// reading, and a key given twice is found (nlohmann keeps the last).

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "world/JsonDocument.h"
#include "world/JsonLines.h"

namespace {

using nlohmann::json;
using odelab::world::JsonDocument;
using odelab::world::JsonValue;

// The table's value as nlohmann's, kind for kind.
json asNlohmann(const JsonValue& value) {
  if (value.isObject()) {
    json object = json::object();
    for (std::size_t i = 0; i < value.size(); ++i) object[std::string(value.key(i))] = asNlohmann(value[i]);
    return object;
  }
  if (value.isArray()) {
    json array = json::array();
    for (std::size_t i = 0; i < value.size(); ++i) array.push_back(asNlohmann(value[i]));
    return array;
  }
  if (value.isString()) return std::string(value.text());
  if (value.isBoolean()) return value.boolean();
  if (value.isUnsigned()) return value.whole();
  if (value.isInteger()) return value.integer();
  if (value.isNumber()) return value.real();
  return nullptr;
}

// Kind for kind and bit for bit (nlohmann's == takes 1 and 1.0 as equal).
void expectSame(const json& expected, const json& got, const std::string& where) {
  ASSERT_EQ(expected.type(), got.type()) << where;
  if (expected.is_object()) {
    ASSERT_EQ(expected.size(), got.size()) << where;
    for (const auto& item : expected.items()) {
      ASSERT_TRUE(got.contains(item.key())) << where << "." << item.key();
      expectSame(item.value(), got.at(item.key()), where + "." + item.key());
    }
  } else if (expected.is_array()) {
    ASSERT_EQ(expected.size(), got.size()) << where;
    for (std::size_t i = 0; i < expected.size(); ++i) expectSame(expected[i], got[i], where + "[" + std::to_string(i) + "]");
  } else if (expected.is_number_float()) {
    const double a = expected.get<double>(), b = got.get<double>();
    EXPECT_EQ(0, std::memcmp(&a, &b, sizeof a)) << where << ": " << expected.dump() << " read as " << got.dump();
  } else {
    EXPECT_EQ(expected, got) << where;
  }
}

// Plain texts and texts with escapes, letters past ASCII, a byte-order mark:
// nlohmann's values, each.
const std::vector<std::string> VALID = {
    R"({"format": "odelab-world", "version": 1, "settings": {"step": 0.001, "gravity": [0, -9.81, 0]},
        "bodies": [{"mass": 1, "inertia": [0.1667, 0.1667, 0.1667, 0, 0, 0], "position": [0, 1e-3, -2.5E+2]}],
        "flags": [true, false, null], "empty": {}, "none": []})",
    "0", "-0", "1", "-1", "0.0", "-0.0", "12345678901234567", "123456789012345678", "-123456789012345678",
    "1234567890123456789", "18446744073709551615", "18446744073709551616", "-9223372036854775808",
    "-9223372036854775809", "99999999999999999999999", "0.1", "1e5", "1E+5", "1e-5", "-1.5e-3", "1e-400",
    "4.9e-324", "2.2250738585072014e-308", "1.7976931348623157e308", "0.30000000000000004", "123.456e7",
    "\"\"", "\"plain text\"", R"("a\"b")", R"("tab\there")", R"("\u0041\u00e9")", "\"caf\xc3\xa9\"", "\xEF\xBB\xBF{\"a\": 1}",
    " \r\n\t[ 1 ,\r\n 2 ] \n", "[[[[[]]]]]", R"({"a": {"b": {"c": [1, {"d": "e"}]}}})", "true", "false", "null",
    R"({"key with spaces": 1, "": 2, "k\u0065y": 3})", "[1,2,3,4,5,6,7,8,9,10]",
};

// Numbers at the very end of the text are left to nlohmann (the C library
// needs a character after the number to stop at): each also in an array and
// before a line break, which the table reads itself.
std::vector<std::string> validTexts() {
  std::vector<std::string> texts = VALID;
  for (const std::string& text : VALID)
    if (!text.empty() && (text[0] == '-' || (text[0] >= '0' && text[0] <= '9'))) {
      texts.push_back("[" + text + "]");
      texts.push_back(text + "\n");
      texts.push_back("{\"n\": " + text + "}");
    }
  return texts;
}

TEST(JsonDocument, HoldsWhatNlohmannReads) {
  for (const std::string& text : validTexts()) {
    const JsonDocument document(text);
    ASSERT_FALSE(document.problems().tooDeep) << text;
    ASSERT_TRUE(document.root()) << text;
    expectSame(json::parse(text), asNlohmann(document.root()), "[" + text + "]");
  }
}

// Each refused as nlohmann refuses it: the same exception, the same message.
const std::vector<std::string> INVALID = {
    "", " ", "{", "[", "[1,]", "[01]", "[1 2]", R"({"a" 1})", R"({"a": 1,})", "{\"a\": 1} x", "[1]]", "tru",
    "nul", "[-]", "[1.]", "[1.e5]", "[.5]", "[+1]", "[1e]", "[0x10]", "[Infinity]", "[NaN]", "1e400", "-1e400",
    "[\"\x01\"]", "[\"unterminated]", "{\"a\":}", "{1: 2}", "['a']", "[1,,2]", "\"\xff\"", "[1]\n\n]",
};

TEST(JsonDocument, RefusesWhatNlohmannRefusesWithItsMessage) {
  for (const std::string& text : INVALID) {
    std::string expected, got;
    int expectedId = 0, gotId = 0;
    try {
      const json read = json::parse(text);
      static_cast<void>(read);
    } catch (const json::exception& error) {
      expected = error.what();
      expectedId = error.id;
    }
    try {
      JsonDocument document(text);
    } catch (const json::exception& error) {
      got = error.what();
      gotId = error.id;
    }
    ASSERT_FALSE(expected.empty()) << "nlohmann reads [" << text << "]";
    EXPECT_EQ(expected, got) << "[" << text << "]";
    EXPECT_EQ(expectedId, gotId) << "[" << text << "]";
  }
}

std::string nested(int depth) { return std::string(static_cast<std::size_t>(depth), '[') + std::string(static_cast<std::size_t>(depth), ']'); }

TEST(JsonDocument, StopsPastTheNestingBound) {
  const JsonDocument atBound(nested(odelab::world::MAX_JSON_DEPTH));
  EXPECT_FALSE(atBound.problems().tooDeep);
  EXPECT_TRUE(atBound.root());
  for (const std::string& text : {nested(odelab::world::MAX_JSON_DEPTH + 1), nested(100000),
                                  "{\"a\": \"\\u0041\", \"b\": " + nested(100000) + "}"}) {
    const JsonDocument past(text);
    EXPECT_TRUE(past.problems().tooDeep);
    EXPECT_FALSE(past.root());
  }
}

TEST(JsonDocument, FindsAKeyGivenTwice) {
  std::string many = "{";
  for (int k = 0; k < 40; ++k) many += "\"k" + std::to_string(k) + "\": " + std::to_string(k) + ", ";
  many += "\"k17\": 0}";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"mass": -5, "mass": 1})", "mass"},
      {R"({"a": {"x": 1, "y": 2, "x": 3}})", "x"},
      {many, "k17"},
      {R"({"a": 1, "\u0061": 2})", "a"},  // the same key, once escaped: nlohmann's keys are compared
  };
  for (const auto& [text, key] : cases) {
    const JsonDocument document(text);
    EXPECT_TRUE(document.problems().duplicateKey) << text;
    EXPECT_EQ(key, document.problems().duplicate) << text;
  }
  EXPECT_FALSE(JsonDocument(R"({"a": {"x": 1}, "b": {"x": 1}})").problems().duplicateKey);
}

TEST(JsonDocument, FindsMembersAndLongKeys) {
  const std::string longKey(70000, 'k');
  const JsonDocument document("{\"" + longKey + "\": 7, \"short\": [1, 2]}");
  const JsonValue root = document.root();
  ASSERT_EQ(2u, root.size());
  EXPECT_EQ(longKey, root.key(0));
  EXPECT_EQ(7u, root.find(longKey).whole());
  EXPECT_EQ(2u, root.find("short").size());
  EXPECT_FALSE(root.find("absent"));
}

}  // namespace
