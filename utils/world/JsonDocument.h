#pragma once

// A JSON text read into one flat table of values, for the world reader.
// Not nlohmann's document: that allocates a node per key and per value and
// frees them one by one, which was most of reading a large world (100,000
// bodies: building and freeing it took longer than lexing the text). Here
// every value is one 16-byte entry of one array, keys and strings share one
// buffer, and an array's or object's items are a run of indices in another:
// a handful of allocations for the whole text, time and memory linear in it.
//
// Who reads the text: nlohmann's SAX parser, whose events fill the table as
// they come, so that what is accepted, each number's value, and each
// refusal's exception and message are nlohmann's (checks/unit/test_json_document.cpp
// holds the table to json::parse's values and messages). Its lexer is most
// of what is left of the time; a lexer of our own would be faster and would
// be a second JSON reader to keep right.
//
// Bounds, each checked as the text is read: arrays and objects nested at most
// MAX_JSON_DEPTH deep (JsonLines.h); a key given twice in one object is found
// (nlohmann would keep the last), in n log n for an object of n keys; a text
// under 4 GiB (32-bit offsets; a world file is at most 64 MiB).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace odelab::world {

class JsonDocument;

// One value of a JsonDocument, or none (a field that is absent). Cheap to copy:
// it points into its document, which must outlive it.
class JsonValue {
 public:
  JsonValue() = default;
  JsonValue(const JsonDocument& doc, std::uint32_t index) : doc_(&doc), index_(index) {}
  explicit operator bool() const { return doc_ != nullptr; }

  bool isNull() const;
  bool isBoolean() const;
  bool isNumber() const;
  bool isInteger() const;   // a whole number as written, signed or not (nlohmann's is_number_integer)
  bool isUnsigned() const;  // a whole number written without a minus sign (is_number_unsigned)
  bool isString() const;
  bool isArray() const;
  bool isObject() const;

  bool boolean() const;
  double real() const;  // any number, as a double
  long long integer() const;
  unsigned long long whole() const;  // an unsigned number
  std::string_view text() const;     // a string, its escapes resolved
  bool textIs(std::string_view word) const { return isString() && text() == word; }

  std::size_t size() const;                   // an array's items or an object's members; 0 otherwise
  JsonValue operator[](std::size_t i) const;  // the i-th item (or member's value), in the text's order
  std::string_view key(std::size_t i) const;  // an object's i-th member's key
  JsonValue find(std::string_view key) const;  // an object's member, or none
  std::string dump() const;                   // a scalar as nlohmann writes it (for messages)

 private:
  const JsonDocument* doc_ = nullptr;
  std::uint32_t index_ = 0;
};

// What reading found, other than text that is not JSON (thrown as nlohmann
// throws it: json::parse_error, json::out_of_range for a number past a
// double's range).
struct JsonDocumentProblems {
  bool tooDeep = false;            // reading stopped at an array or object past MAX_JSON_DEPTH
  bool duplicateKey = false;       // some object gives a key twice (reading went on)
  std::string duplicate;           // the first such key
};

class JsonDocument {
 public:
  // Throws nlohmann's exceptions for text that is not JSON; a problem of
  // JsonDocumentProblems leaves the document empty (tooDeep) or whole.
  explicit JsonDocument(const std::string& text);
  const JsonDocumentProblems& problems() const { return problems_; }
  JsonValue root() const { return nodes_.empty() ? JsonValue() : JsonValue(*this, 0); }

  // The table JsonValue reads.
  enum class Kind : std::uint8_t { Null, Boolean, Integer, Unsigned, Real, String, Array, Object };
  struct Run {
    std::uint32_t first, count;
  };
  // 16 bytes a value: most of a world's values are numbers.
  struct Node {
    union {
      long long integer;
      unsigned long long whole;
      double real;
      Run run;  // a string: its place in chars_; an array or object: its items in items_
    };
    std::uint32_t keyAt = 0;      // as a member of an object: where its key starts in chars_
    std::uint16_t keyLength = 0;  // LONG_KEY: the length is the 4 bytes before keyAt
    Kind kind = Kind::Null;
    bool boolean = false;
  };
  static constexpr std::uint16_t LONG_KEY = 0xffff;
  const Node& node(std::uint32_t index) const { return nodes_[index]; }
  std::uint32_t item(std::uint32_t at) const { return items_[at]; }
  std::string_view key(const Node& member) const;
  std::string_view chars(std::uint32_t at, std::uint32_t length) const { return std::string_view(chars_).substr(at, length); }

 private:
  class Builder;  // SAX events into the table (JsonDocument.cpp)
  void clear();   // a text refused before its end leaves no values
  std::vector<Node> nodes_;           // every value, each before its items (the root first)
  std::vector<std::uint32_t> items_;  // each array's and object's items, a run per container
  std::string chars_;                 // every key and string
  JsonDocumentProblems problems_;
};

}  // namespace odelab::world
