#pragma once

// What the accuracy atlas measured of each engine (doc/atlas.md): at one
// step, per setting, how many of its cases of analytic answer the engine
// gets right and how it ends the others. Compiled in from
// doc/atlas-report/atlas-notes.csv (cmake/AtlasNotes.cmake), which
// lab/odelab-report --atlas writes and lab/check_atlas_report.py holds to
// atlas.csv; --list-engines prints it beside each engine's settings.

#include <string>
#include <vector>

namespace odelab::world {

struct AtlasNote {
  const char* engine;    // "bullet"
  const char* setting;   // "default" or "best"
  const char* step;      // "1/240" (seconds)
  int right;             // cases within every probe's tolerance
  int cases;             // cases run
  const char* notRight;  // "bounce-v1-e0p25 off 3 tol; ..." ("" when none)
};

const std::vector<AtlasNote>& atlasNotes();
// "date ...; commit ..." of the atlas run the table comes from ("" when
// this tree had no atlas-notes.csv when it was built).
const char* atlasNotesMade();

// --list-engines' lines for one engine ("  measured ...\n" each), or a line
// saying the atlas has no row for it.
std::string atlasNoteLines(const std::string& engine);

}  // namespace odelab::world
