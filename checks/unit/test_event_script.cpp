// The --events script format (utils/EventScript.h): what each line becomes,
// and that every mistake is refused with a message naming file and line.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "CommandLine.h"
#include "EventScript.h"

namespace {

using namespace odelab;

// A stand-in for SDL_GetKeyFromName: a few names, case-insensitive.
int lookup(const std::string& name) {
  static const std::map<std::string, int> keys{{"p", 'p'}, {"o", 'o'}, {",", ','}, {".", '.'},
                                               {"f3", 1000 + 3}, {"left shift", 2000}, {"*", '*'}};
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto found = keys.find(lower);
  return found == keys.end() ? 0 : found->second;
}

std::vector<ScriptEvent> parse(const std::string& text) {
  std::istringstream in(text);
  return parseEventScript(in, "s.events", lookup);
}

// The UsageError's message, or "" if the text parses.
std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

TEST(EventScript, ReadsEveryKindOfEvent) {
  const auto events = parse(
      "# a comment\n"
      "\n"
      "1 key P\n"
      "2 key F3 shift   # trailing comment\n"
      "3 down 10 20\n"
      "3 move 30 40\n"
      "4 up 30 41\n"
      "5 mark after_drag\n"
      "6 quit\n");
  ASSERT_EQ(events.size(), 7u);
  EXPECT_EQ(events[0].kind, ScriptEvent::Kind::Key);
  EXPECT_EQ(events[0].key, 'p');
  EXPECT_FALSE(events[0].shift);
  EXPECT_EQ(events[0].line, 3);
  EXPECT_EQ(events[1].key, 1003);
  EXPECT_TRUE(events[1].shift);
  EXPECT_EQ(events[2].kind, ScriptEvent::Kind::Down);
  EXPECT_EQ(events[2].x, 10);
  EXPECT_EQ(events[2].y, 20);
  EXPECT_EQ(events[3].kind, ScriptEvent::Kind::Move);
  EXPECT_EQ(events[4].kind, ScriptEvent::Kind::Up);
  EXPECT_EQ(events[4].y, 41);
  EXPECT_EQ(events[5].kind, ScriptEvent::Kind::Mark);
  EXPECT_EQ(events[5].label, "after_drag");
  EXPECT_EQ(events[6].kind, ScriptEvent::Kind::Quit);
  EXPECT_EQ(events[6].frame, 6);
}

TEST(EventScript, RepeatsQuotedNamesAndPunctuation) {
  const auto events = parse("2 key O *3\n1 key \"Left Shift\"\n1 key ,\n1 key . shift *2\n1 key *\n");
  // Sorted by frame, file order kept within a frame, repeats expanded.
  ASSERT_EQ(events.size(), 8u);
  EXPECT_EQ(events[0].key, 2000);
  EXPECT_EQ(events[1].key, ',');
  EXPECT_EQ(events[2].key, '.');
  EXPECT_TRUE(events[2].shift);
  EXPECT_EQ(events[3].key, '.');
  EXPECT_EQ(events[4].key, '*');
  for (int i = 5; i < 8; ++i) {
    EXPECT_EQ(events[i].key, 'o');
    EXPECT_EQ(events[i].frame, 2);
    EXPECT_EQ(events[i].line, 1);
  }
}

TEST(EventScript, ReadsModifiersButtonsWheelAndResize) {
  const auto events = parse(
      "1 key P ctrl alt\n"
      "1 key O alt shift *2\n"
      "2 down 5 6 right\n"
      "2 up 5 6 middle\n"
      "2 down 5 6 left\n"
      "3 wheel -2 100\n"
      "4 resize 1 8192\n");
  ASSERT_EQ(events.size(), 8u);
  EXPECT_TRUE(events[0].ctrl && events[0].alt && !events[0].shift);
  EXPECT_TRUE(events[1].alt && events[1].shift && !events[1].ctrl);
  EXPECT_EQ(events[2].key, 'o');
  EXPECT_EQ(events[3].kind, ScriptEvent::Kind::Down);
  EXPECT_EQ(events[3].button, ScriptEvent::Button::Right);
  EXPECT_EQ(events[4].kind, ScriptEvent::Kind::Up);
  EXPECT_EQ(events[4].button, ScriptEvent::Button::Middle);
  EXPECT_EQ(events[5].button, ScriptEvent::Button::Left);
  EXPECT_EQ(events[6].kind, ScriptEvent::Kind::Wheel);
  EXPECT_EQ(events[6].x, -2);
  EXPECT_EQ(events[6].y, 100);
  EXPECT_EQ(events[7].kind, ScriptEvent::Kind::Resize);
  EXPECT_EQ(events[7].x, 1);
  EXPECT_EQ(events[7].y, 8192);
}

TEST(EventScript, EmptyScriptHasNoEvents) { EXPECT_TRUE(parse("# nothing\n\n   \n").empty()); }

TEST(EventScript, AcceptsWindowsLineEnds) { EXPECT_EQ(parse("1 key P\r\n2 quit\r\n").size(), 2u); }

TEST(EventScript, RefusesMistakesNamingFileAndLine) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"1 key P\n2 key NoSuchKey\n", "s.events:2: key: unknown key name 'NoSuchKey'"},
      {"0 key P\n", "s.events:1: frame '0'"},
      {"-3 key P\n", "s.events:1: frame '-3'"},
      {"x key P\n", "s.events:1: frame 'x'"},
      {"1.5 key P\n", "s.events:1: frame '1.5'"},
      {"99999999999999999999 key P\n", "s.events:1: frame"},
      {"1\n", "s.events:1: expected '<frame> <event>"},
      {"1 jump\n", "s.events:1: unknown event 'jump'"},
      {"1 key\n", "s.events:1: key: expected"},
      {"1 key P meta\n", "s.events:1: key: unexpected 'meta'"},
      {"1 key P ctrl alt ctrl\n", "s.events:1: key: unexpected 'ctrl'"},
      {"1 down 1 2 fourth\n", "s.events:1: down: unknown button 'fourth'"},
      {"1 up 1 2 left 3\n", "s.events:1: up: expected"},
      {"1 move 1 2 left\n", "s.events:1: move: expected"},
      {"1 wheel 1\n", "s.events:1: wheel: expected"},
      {"1 wheel 0 101\n", "s.events:1: wheel: dx and dy are notches"},
      {"1 wheel x 1\n", "s.events:1: wheel: dx and dy are notches"},
      {"1 resize 0 100\n", "s.events:1: resize: width and height"},
      {"1 resize 100 8193\n", "s.events:1: resize: width and height"},
      {"1 resize 100\n", "s.events:1: resize: expected"},
      {"1 key P *0\n", "s.events:1: key: unexpected '*0'"},
      {"1 key P shift shift\n", "s.events:1: key: unexpected 'shift'"},
      {"\n\n1 down 10\n", "s.events:3: down: expected"},
      {"1 move 10 20 30\n", "s.events:1: move: expected"},
      {"1 up -1 5\n", "s.events:1: up: x and y"},
      {"1 down 1.5 5\n", "s.events:1: down: x and y"},
      {"1 mark\n", "s.events:1: mark: expected"},
      {"1 mark a-b\n", "s.events:1: mark: expected"},
      {"1 mark a b\n", "s.events:1: mark: expected"},
      {"1 quit now\n", "s.events:1: quit: expected"},
      {"1 key \"Left Shift\n", "s.events:1: unclosed quote"},
  };
  for (const auto& [text, message] : cases) {
    const std::string error = errorOf(text);
    EXPECT_NE(error.find(message), std::string::npos) << "script: " << text << "error: " << error;
    EXPECT_EQ(error.rfind("--events: ", 0), 0u) << error;
  }
}

TEST(EventScript, UnreadableFileIsAUsageError) {
  EXPECT_THROW(loadEventScript("/nonexistent/x.events", lookup), UsageError);
}

// Issue 15: 880 bytes of *N repeats grew to 622 MB; /dev/zero never ended;
// 40,000 presses in one frame failed only once the window was open.
TEST(EventScript, BoundsEventsLinesAndFrames) {
  std::string many;
  for (int frame = 1; frame <= 3; ++frame) many += std::to_string(frame) + " key P *100000\n";
  EXPECT_NE(errorOf(many).find("more than 200000 events"), std::string::npos) << errorOf(many);
  EXPECT_NE(errorOf("1 key P *40000\n").find("frame 1 has 40000 events"), std::string::npos)
      << errorOf("1 key P *40000\n");
  EXPECT_EQ(errorOf("1 key P *16384\n2 key P *16384\n"), "");
  EXPECT_NE(errorOf("1 mark " + std::string(5000, 'a') + "\n").find("line longer than 1024"), std::string::npos);
}

TEST(EventScript, OnlyRegularFilesAreRead) {
  for (const auto& [path, why] : {std::pair{"/dev/zero", "is a device"}, {"/dev/null", "is a device"}, {"/tmp", "is a folder"}}) {
    try {
      loadEventScript(path, lookup);
      ADD_FAILURE() << path << " was read";
    } catch (const UsageError& error) {
      EXPECT_NE(std::string(error.what()).find(std::string("--events: cannot read the script '") + path + "': " + why),
                std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
