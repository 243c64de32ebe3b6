#!/usr/bin/env bash
# One scene of the browser build against the desktop build (checks/web.cmake):
#   1. in a window in headless Chromium for --window-seconds of simulated time:
#      the run ends with status 0 and its canvas shows a picture, i.e. at
#      least 5% of the pixels differ from the commonest colour (the sky) and
#      there are at least 16 colours (a blank or one-colour canvas has 1);
#      with --shadow-check SCREENSHOT_CHECK, that program (checks/
#      screenshot_check.cpp) must also find a shadow cast on a lit surface
#      in the scene's part of the canvas (left of the panel, below the HUD);
#   2. headless in Chromium and natively, --seconds S (or the scene's own
#      length) with the same ARGS: METRIC from both runs' --metrics-json
#      differs by at most TOLERANCE (absolute);
#   3. with --download NAME: the window run's file NAME fetched through the
#      page's download link is the run's file byte for byte and ends with
#      "# complete".
#
#   check-scene.sh --site DIR --native PROGRAM --out DIR --metric NAME
#                  --tolerance X [--seconds S] [--window-seconds S] [--download NAME]
#                  [--shadow-check SCREENSHOT_CHECK] -- ARGS...
#
# Exits 77 (CTest's skip) when DIR holds no browser build.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
say() { printf 'web check: %s\n' "$*" >&2; }
usage() { say "error: $*"; exit 2; }

site='' native='' out='' metric='' tolerance='' seconds='' window_seconds=2 download='' shadow_check=''
while [ $# -gt 0 ]; do
  case $1 in
    --site | --native | --out | --metric | --tolerance | --seconds | --window-seconds | --download | --shadow-check)
      [ $# -ge 2 ] || usage "$1 needs a value"
      name=${1#--}
      printf -v "${name//-/_}" '%s' "$2"
      shift 2
      ;;
    --) shift; break ;;
    *) usage "unknown argument '$1'" ;;
  esac
done
args=("$@")
[ -n "$site" ] && [ -n "$native" ] && [ -n "$out" ] && [ -n "$metric" ] && [ -n "$tolerance" ] ||
  usage "--site, --native, --out, --metric and --tolerance are needed"
native=$(realpath "$native")
scene=$(basename "$native")
length=()
[ -n "$seconds" ] && length=(--seconds "$seconds")
if [ ! -f "$site/$scene.js" ] || [ ! -d "$root/web/node_modules/puppeteer-core" ]; then
  say "skipped: no browser build of $scene in $site, or no web/node_modules (scripts/odelab.sh web makes both)"
  exit 77
fi
rm -rf "$out"
mkdir -p "$out"
failed=0
fail() { say "FAIL $scene: $*"; failed=1; }

# 1 (and 3): the window.
drive=(node "$root/web/drive.mjs" --site "$site" --scene "$scene" --timeout 240)
[ -n "$download" ] && drive+=(--download "$download")
"${drive[@]}" --out "$out/window" -- --seconds "$window_seconds" --width 800 --height 450 "${args[@]}" >/dev/null ||
  fail "the window run did not end (see $out/window)"
python3 - "$out/window/result.json" <<'PY' || failed=1
import json, sys
r = json.load(open(sys.argv[1]))
p = r.get("picture") or {}
print(f"web check: {r['scene']} window: status {r.get('status')}, {r.get('seconds', 0):.1f} s, "
      f"{p.get('colours')} colours, {100 * p.get('other_than_commonest', 0):.1f}% not the commonest", file=sys.stderr)
ok = r.get("status") == 0 and p.get("colours", 0) >= 16 and p.get("other_than_commonest", 0) >= 0.05
sys.exit(0 if ok else 1)
PY
# The panel takes the right quarter of an 800-pixel canvas, the HUD the top.
if [ -n "$shadow_check" ] && [ -f "$out/window/canvas.png" ]; then
  "$shadow_check" "$out/window/canvas.png" --size 800x450 --region 0,0.25,0.75,1 >"$out/window/shadow-check.txt" 2>&1 ||
    fail "no shadow cast on a lit surface in the canvas (see $out/window/shadow-check.txt)"
fi
if [ -n "$download" ]; then
  got=$out/window/downloads/$download
  written=$out/window/files/$download
  if [ ! -f "$got" ]; then
    fail "$download was not downloaded ($(python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get("download"))' "$out/window/result.json"))"
  elif ! cmp -s "$got" "$written"; then
    fail "the downloaded $download differs from the one the run wrote"
  elif ! tail -n 1 "$got" | grep -q '^# complete'; then
    fail "the downloaded $download does not end with '# complete' (last line: $(tail -n 1 "$got"))"
  else
    say "$scene: $download downloaded whole ($(wc -l <"$got") lines, ends '$(tail -n 1 "$got" | cut -c1-40)')"
  fi
fi

# 2: the metric, headless in both.
"${drive[@]}" --out "$out/headless" -- --headless --metrics-json metrics.json "${length[@]}" "${args[@]}" >/dev/null ||
  fail "the headless run in the browser did not end (see $out/headless)"
mkdir -p "$out/native"
(cd "$out/native" && "$native" --headless --metrics-json metrics.json "${length[@]}" "${args[@]}" >log.txt 2>&1) ||
  fail "the native run failed (see $out/native/log.txt)"
python3 - "$out/headless/files/metrics.json" "$out/native/metrics.json" "$metric" "$tolerance" "$scene" "$out/comparison.json" <<'PY' || failed=1
import json, sys
web_path, native_path, metric, tolerance, scene, comparison_path = sys.argv[1:]
try:
    web, native = json.load(open(web_path)), json.load(open(native_path))
except OSError as error:
    sys.exit(f"web check: FAIL {scene}: no metrics ({error})")
if metric not in web or metric not in native:
    sys.exit(f"web check: FAIL {scene}: metric {metric} missing (web: {metric in web}, native: {metric in native})")
difference = abs(float(web[metric]) - float(native[metric]))
# Kept for scripts/web/comparison-table.py.
json.dump({"scene": scene, "metric": metric, "web": web[metric], "native": native[metric],
           "difference": difference, "tolerance": float(tolerance)}, open(comparison_path, "w"))
print(f"web check: {scene} {metric}: web {web[metric]!r}, native {native[metric]!r}, "
      f"difference {difference:.3g} (tolerance {tolerance})", file=sys.stderr)
sys.exit(0 if difference <= float(tolerance) else 1)
PY
exit $failed
