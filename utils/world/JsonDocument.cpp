#include "JsonDocument.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

#include "JsonLines.h"

namespace odelab::world {

using nlohmann::json;

// nlohmann's SAX events, written into the document's table as they come. The
// items of the open arrays and objects wait on one stack shared by all of
// them and move to the table's item list when their container closes, so
// each value is placed once: linear time, no allocation per value.
class JsonDocument::Builder {
 public:
  explicit Builder(JsonDocument& doc) : doc_(doc) {}

  bool null() {
    add(Kind::Null);
    return true;
  }
  bool boolean(bool value) {
    doc_.nodes_[add(Kind::Boolean)].boolean = value;
    return true;
  }
  bool number_integer(json::number_integer_t value) {
    doc_.nodes_[add(Kind::Integer)].integer = value;
    return true;
  }
  bool number_unsigned(json::number_unsigned_t value) {
    doc_.nodes_[add(Kind::Unsigned)].whole = value;
    return true;
  }
  bool number_float(json::number_float_t value, const json::string_t& /*as written*/) {
    doc_.nodes_[add(Kind::Real)].real = value;
    return true;
  }
  bool string(json::string_t& value) { return string(std::string_view(value)); }
  bool string(std::string_view value) {
    const std::uint32_t index = add(Kind::String);
    const std::uint32_t at = store(value);
    doc_.nodes_[index].run = {at, static_cast<std::uint32_t>(value.size())};
    return true;
  }
  bool binary(json::binary_t& /*not in JSON text*/) {
    add(Kind::Null);
    return true;
  }
  bool start_object(std::size_t /*unknown*/) { return open(Kind::Object); }
  bool start_array(std::size_t /*unknown*/) { return open(Kind::Array); }
  bool key(json::string_t& key) { return this->key(std::string_view(key)); }
  bool key(std::string_view key) {
    if (key.size() >= LONG_KEY) {
      const auto length = static_cast<std::uint32_t>(key.size());
      doc_.chars_.append(reinterpret_cast<const char*>(&length), sizeof length);
      keyLength_ = LONG_KEY;
    } else {
      keyLength_ = static_cast<std::uint16_t>(key.size());
    }
    keyAt_ = store(key);
    return true;
  }
  bool end_object() {
    const Run run = doc_.nodes_[close()].run;
    duplicates(run.first, run.count);
    return true;
  }
  bool end_array() {
    close();
    return true;
  }
  // As nlohmann's own document builder does: its exception, thrown as its own type.
  template <class Exception>
  bool parse_error(std::size_t /*byte*/, const std::string& /*token*/, const Exception& error) {
    throw error;
  }

 private:
  using Kind = JsonDocument::Kind;
  using Node = JsonDocument::Node;
  using Run = JsonDocument::Run;

  // A new value, as an item of the innermost open container (with the key
  // just read, in an object); returns its index.
  std::uint32_t add(Kind kind) {
    const auto index = static_cast<std::uint32_t>(doc_.nodes_.size());
    Node node{};
    node.kind = kind;
    if (!open_.empty()) {
      if (inObject_) {
        node.keyAt = keyAt_;
        node.keyLength = keyLength_;
      }
      waiting_.push_back(index);
    }
    doc_.nodes_.push_back(node);
    return index;
  }

  bool open(Kind kind) {
    if (open_.size() >= static_cast<std::size_t>(MAX_JSON_DEPTH)) {
      doc_.problems_.tooDeep = true;
      return false;  // nlohmann stops reading; the caller says where (JsonLines' scan)
    }
    const std::uint32_t index = add(kind);
    open_.push_back(index);
    firstWaiting_.push_back(waiting_.size());
    inObject_ = kind == Kind::Object;
    return true;
  }

  // The innermost container's items move from the stack to the item list.
  std::uint32_t close() {
    const std::uint32_t index = open_.back();
    const std::size_t first = firstWaiting_.back();
    doc_.nodes_[index].run = {static_cast<std::uint32_t>(doc_.items_.size()), static_cast<std::uint32_t>(waiting_.size() - first)};
    doc_.items_.insert(doc_.items_.end(), waiting_.begin() + static_cast<std::ptrdiff_t>(first), waiting_.end());
    waiting_.resize(first);
    open_.pop_back();
    firstWaiting_.pop_back();
    inObject_ = !open_.empty() && doc_.nodes_[open_.back()].kind == Kind::Object;
    return index;
  }

  std::uint32_t store(std::string_view text) {
    const auto at = static_cast<std::uint32_t>(doc_.chars_.size());
    doc_.chars_ += text;
    return at;
  }

  // A key given twice among an object's members: compared pairwise for the
  // few members of an object of this format, sorted for a larger one, so
  // that no object costs more than n log n.
  void duplicates(std::uint32_t first, std::uint32_t count) {
    if (doc_.problems_.duplicateKey || count < 2) return;
    auto keyOf = [&](std::uint32_t k) { return doc_.key(doc_.nodes_[doc_.items_[first + k]]); };
    std::string_view twice;
    bool found = false;
    if (count <= 16) {
      for (std::uint32_t a = 1; a < count && !found; ++a)
        for (std::uint32_t b = 0; b < a && !found; ++b)
          if (keyOf(a) == keyOf(b)) {
            twice = keyOf(a);
            found = true;
          }
    } else {
      keys_.clear();
      for (std::uint32_t k = 0; k < count; ++k) keys_.push_back(keyOf(k));
      std::sort(keys_.begin(), keys_.end());
      for (std::size_t k = 1; k < keys_.size() && !found; ++k)
        if (keys_[k] == keys_[k - 1]) {
          twice = keys_[k];
          found = true;
        }
    }
    if (found) {
      doc_.problems_.duplicateKey = true;
      doc_.problems_.duplicate = std::string(twice);
    }
  }

  JsonDocument& doc_;
  std::vector<std::uint32_t> open_;            // the open arrays and objects, outermost first
  std::vector<std::size_t> firstWaiting_;      // where each one's items start on waiting_
  std::vector<std::uint32_t> waiting_;         // the open containers' items so far
  std::vector<std::string_view> keys_;         // a large object's keys, sorted
  std::uint32_t keyAt_ = 0;     // the key just read
  std::uint16_t keyLength_ = 0;
  bool inObject_ = false;  // the innermost open container is an object
};

JsonDocument::JsonDocument(const std::string& text) {
  if (text.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("a JSON text of 4 GiB or more");  // past the table's 32-bit offsets
  // A value takes at least a byte of text (and a key, its quotes): a guess
  // that keeps the table from being copied over as it grows.
  nodes_.reserve(text.size() / 6);
  items_.reserve(text.size() / 6);
  chars_.reserve(text.size() / 2);
  Builder builder(*this);
  if (!json::sax_parse(text.data(), text.data() + text.size(), &builder)) clear();
}

void JsonDocument::clear() {
  nodes_.clear();
  items_.clear();
  chars_.clear();
}

namespace {
bool numeric(JsonDocument::Kind kind) {
  return kind == JsonDocument::Kind::Integer || kind == JsonDocument::Kind::Unsigned || kind == JsonDocument::Kind::Real;
}
}  // namespace

bool JsonValue::isNull() const { return doc_->node(index_).kind == JsonDocument::Kind::Null; }
bool JsonValue::isBoolean() const { return doc_->node(index_).kind == JsonDocument::Kind::Boolean; }
bool JsonValue::isNumber() const { return numeric(doc_->node(index_).kind); }
bool JsonValue::isInteger() const {
  const auto kind = doc_->node(index_).kind;
  return kind == JsonDocument::Kind::Integer || kind == JsonDocument::Kind::Unsigned;
}
bool JsonValue::isUnsigned() const { return doc_->node(index_).kind == JsonDocument::Kind::Unsigned; }
bool JsonValue::isString() const { return doc_->node(index_).kind == JsonDocument::Kind::String; }
bool JsonValue::isArray() const { return doc_->node(index_).kind == JsonDocument::Kind::Array; }
bool JsonValue::isObject() const { return doc_->node(index_).kind == JsonDocument::Kind::Object; }

bool JsonValue::boolean() const { return doc_->node(index_).boolean; }

// As nlohmann's get<double>, get<long long> and get<unsigned long long>: a cast from the number's own type.
double JsonValue::real() const {
  const auto& node = doc_->node(index_);
  switch (node.kind) {
    case JsonDocument::Kind::Integer: return static_cast<double>(node.integer);
    case JsonDocument::Kind::Unsigned: return static_cast<double>(node.whole);
    case JsonDocument::Kind::Real: return node.real;
    default: return 0;
  }
}
long long JsonValue::integer() const {
  const auto& node = doc_->node(index_);
  switch (node.kind) {
    case JsonDocument::Kind::Integer: return node.integer;
    case JsonDocument::Kind::Unsigned: return static_cast<long long>(node.whole);
    case JsonDocument::Kind::Real: return static_cast<long long>(node.real);
    default: return 0;
  }
}
unsigned long long JsonValue::whole() const {
  const auto& node = doc_->node(index_);
  switch (node.kind) {
    case JsonDocument::Kind::Integer: return static_cast<unsigned long long>(node.integer);
    case JsonDocument::Kind::Unsigned: return node.whole;
    case JsonDocument::Kind::Real: return static_cast<unsigned long long>(node.real);
    default: return 0;
  }
}
std::string_view JsonValue::text() const {
  const auto& node = doc_->node(index_);
  return node.kind == JsonDocument::Kind::String ? doc_->chars(node.run.first, node.run.count) : std::string_view();
}

std::size_t JsonValue::size() const {
  const auto& node = doc_->node(index_);
  return node.kind == JsonDocument::Kind::Array || node.kind == JsonDocument::Kind::Object ? node.run.count : 0;
}
JsonValue JsonValue::operator[](std::size_t i) const {
  return JsonValue(*doc_, doc_->item(doc_->node(index_).run.first + static_cast<std::uint32_t>(i)));
}
std::string_view JsonValue::key(std::size_t i) const { return doc_->key(doc_->node((*this)[i].index_)); }
JsonValue JsonValue::find(std::string_view key) const {
  const auto& node = doc_->node(index_);
  if (node.kind != JsonDocument::Kind::Object) return {};
  for (std::uint32_t i = 0; i < node.run.count; ++i) {
    const std::uint32_t member = doc_->item(node.run.first + i);
    if (doc_->key(doc_->node(member)) == key) return JsonValue(*doc_, member);
  }
  return {};
}

std::string_view JsonDocument::key(const Node& member) const {
  std::uint32_t length = member.keyLength;
  if (length == LONG_KEY) std::memcpy(&length, chars_.data() + member.keyAt - sizeof length, sizeof length);
  return std::string_view(chars_.data() + member.keyAt, length);
}

std::string JsonValue::dump() const {
  const auto& node = doc_->node(index_);
  switch (node.kind) {
    case JsonDocument::Kind::Null: return "null";
    case JsonDocument::Kind::Boolean: return node.boolean ? "true" : "false";
    case JsonDocument::Kind::Integer: return json(node.integer).dump();
    case JsonDocument::Kind::Unsigned: return json(node.whole).dump();
    case JsonDocument::Kind::Real: return json(node.real).dump();
    case JsonDocument::Kind::String: return json(std::string(text())).dump();
    case JsonDocument::Kind::Array: return "[...]";
    case JsonDocument::Kind::Object: return "{...}";
  }
  return "";
}

}  // namespace odelab::world
