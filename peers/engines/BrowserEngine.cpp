// Havok, Jolt and Rapier in the browser build: the page loads their npm
// WebAssembly builds beside the scene (web/engines/, bundled into the site)
// and keeps them as globalThis.odelabEngines; this adapter speaks
// doc/engine-protocol.md to them directly, one synchronous call a message,
// where the desktop speaks it to a Node.js child (NodeEngine.cpp).
#include <emscripten.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

#include "Adapters.h"
#include "ProtocolEngine.h"
#include "WasmEngines.h"

namespace odelab::engines {

namespace {

// The page's answers pass as strings: a call leaves its answer in
// odelabEngineAnswer and returns its length in bytes; takeAnswer copies it.
// An answer that begins with "error: " is a refusal.
EM_JS(int, askPage, (const char* what, const char* name, const char* setting, int session, const char* line), {
  var engines = globalThis.odelabEngines;
  var answer;
  try {
    var op = UTF8ToString(what);
    if (!engines) {
      answer = op === "info" ? JSON.stringify({missing: "this site was built without its engines (web/engines/: "
                                                          + "npm ci in web and peers/wasm, then build the site again)"})
                             : "error: this site was built without its engines";
    } else if (op === "info") {
      answer = engines.info(UTF8ToString(name));
    } else if (op === "open") {
      answer = String(engines.open(UTF8ToString(name), UTF8ToString(setting)));
    } else {
      answer = engines.request(session, UTF8ToString(line));
    }
  } catch (error) {
    answer = "error: " + (error && error.message ? error.message : String(error));
  }
  globalThis.odelabEngineAnswer = answer;
  return lengthBytesUTF8(answer);
});

EM_JS(void, takeAnswer, (char* buffer, int size), {
  stringToUTF8(globalThis.odelabEngineAnswer, buffer, size);
  globalThis.odelabEngineAnswer = "";
});

std::string ask(const char* what, const std::string& name, const std::string& setting, int session,
                const std::string& line) {
  const int size = askPage(what, name.c_str(), setting.c_str(), session, line.c_str());
  std::string answer(static_cast<size_t>(size) + 1, '\0');
  takeAnswer(answer.data(), size + 1);
  answer.resize(static_cast<size_t>(size));
  return answer;
}

bool refused(const std::string& answer) { return answer.rfind("error: ", 0) == 0; }

// One engine session of the page as the protocol's link: a message that
// takes a reply leaves it for readLine.
class PageLink : public ProtocolLink {
 public:
  explicit PageLink(int session) : session_(session) {}
  bool writeLine(const std::string& line) override {
    const std::string answer = ask("request", "", "", session_, line);
    if (refused(answer)) {
      failure_ = answer.substr(7);
      return false;
    }
    if (!answer.empty()) replies_.push_back(answer);
    return true;
  }
  bool readLine(std::string& line) override {
    if (replies_.empty()) return false;
    line = replies_.front();
    replies_.erase(replies_.begin());
    return true;
  }
  std::string endedHow() override {
    return failure_.empty() ? "no reply; the page's console may say why" : failure_;
  }

 private:
  int session_;
  std::vector<std::string> replies_;
  std::string failure_;
};

}  // namespace

world::EngineInfo browserEngineInfo(const std::string& name) {
  world::EngineInfo info = wasmEngineInfo(name);
  if (!info.missing.empty()) return info;
  // The page answers {"version": "...", "missing": "..."} ("missing" empty
  // when it has the engine loaded).
  const std::string answer = ask("info", name, "", 0, "");
  if (refused(answer)) {
    info.missing = answer.substr(7);
    return info;
  }
  const nlohmann::json fields = nlohmann::json::parse(answer, nullptr, false);
  if (!fields.is_object()) {
    info.missing = "the page's answer about it is not JSON: " + answer.substr(0, 200);
    return info;
  }
  info.version = fields.value("version", "");
  info.missing = fields.value("missing", "");
  info.available = info.missing.empty();
  return info;
}

std::unique_ptr<world::Engine> makeBrowserEngine(const std::string& name, world::EngineSetting setting) {
  const WasmEngineKind* kind = wasmEngineKind(name);
  if (!kind) throw world::EngineError("'" + name + "' is not one of " + wasmEngineList());
  const std::string answer =
      ask("open", name, setting == world::EngineSetting::Best ? "best" : "default", 0, "");
  if (refused(answer)) throw world::EngineError(std::string(kind->title) + ": " + answer.substr(7));
  return makeProtocolEngine(kind->title, "engine in the page", std::make_unique<PageLink>(std::stoi(answer)));
}

}  // namespace odelab::engines
