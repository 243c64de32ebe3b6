#!/usr/bin/env bash
# Checks of the web page itself, apart from any one scene's physics
# (checks/web.cmake, label web):
#   clock       a window run of test3 under a coarse clock (performance.now()
#               in steps of 250 ms, so that several frames in a row read the
#               same time, as a browser's blurred timer or headless
#               Chromium's virtual time gives) keeps running: it ends its
#               --seconds with status 0 and reports that much simulated time;
#   bad-option  an address parameter the program refuses (an unknown one,
#               a value of the wrong kind) gives status 2 and a message that
#               names the parameter and gives no command-line advice
#               (--help cannot be typed into a page);
#   files       every page names an icon the site serves, refers to no
#               missing file, and has no request refused (web/check-pages.mjs).
#
#   check-page.sh --site DIR --out DIR clock|bad-option|files
#
# Exits 77 (CTest's skip) when DIR holds no browser build.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
say() { printf 'web page check: %s\n' "$*" >&2; }

site='' out=''
while [ $# -gt 1 ]; do
  case $1 in
    --site) site=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) break ;;
  esac
done
[ $# -eq 1 ] && [ -n "$site" ] && [ -n "$out" ] || { say "usage: $0 --site DIR --out DIR clock|bad-option|files"; exit 2; }
what=$1
if [ ! -f "$site/test3.js" ] || [ ! -d "$root/web/node_modules/puppeteer-core" ]; then
  say "skipped: no browser build in $site, or no web/node_modules (scripts/odelab.sh web makes both)"
  exit 77
fi
rm -rf "$out"
mkdir -p "$out"
drive=(node "$root/web/drive.mjs" --site "$site" --timeout 240)

case $what in
  clock)
    "${drive[@]}" --scene test3 --clock-step 250 --out "$out/run" -- --seconds 1 --width 400 --height 300 \
      --metrics-json metrics.json >/dev/null ||
      { say "FAIL: the run under a coarse clock did not end (see $out/run)"; exit 1; }
    python3 - "$out/run" <<'PY'
import json, os, sys
run = sys.argv[1]
result, log = json.load(open(os.path.join(run, "result.json"))), open(os.path.join(run, "log.txt")).read()
try:
    metrics = json.load(open(os.path.join(run, "files", "metrics.json")))
except OSError:
    metrics = {}
print(f"web page check: coarse clock: status {result.get('status')}, {metrics.get('sim_seconds')} simulated seconds, "
      f"{metrics.get('steps')} steps", file=sys.stderr)
if result.get("status") != 0:
    sys.exit(f"web page check: FAIL: the run under a coarse clock ended with status {result.get('status')}:\n{log[-2000:]}")
# The window run ends on the step a headless run of --seconds 1 ends on.
if not metrics.get("sim_seconds", 0) >= 1.0 - 1e-9 or not metrics.get("steps", 0) > 0:
    sys.exit(f"web page check: FAIL: the run's metrics do not show 1 simulated second: {metrics}")
PY
    ;;
  bad-option)
    failed=0
    # NAME, then the run's options: an unknown parameter, a value that is
    # not a number, and a value outside an option's range.
    for refused in "bogus:--bogus 1" "erp:--erp high" "seconds:--seconds -3"; do
      name=${refused%%:*}
      read -r -a args <<<"${refused#*:}"
      "${drive[@]}" --scene test3 --out "$out/$name" -- "${args[@]}" >/dev/null ||
        { say "FAIL: the run with ${args[*]} did not end (see $out/$name)"; failed=1; continue; }
      python3 - "$out/$name/result.json" "$out/$name/log.txt" "$name" <<'PY' || failed=1
import json, sys
result, log, name = json.load(open(sys.argv[1])), open(sys.argv[2]).read(), sys.argv[3]
print(f"web page check: parameter {name}: status {result.get('status')}: {' / '.join(log.split(chr(10))[:3])}", file=sys.stderr)
problems = []
if result.get("status") != 2:
    problems.append(f"status {result.get('status')}, not 2")
if "--help" in log:
    problems.append("the message advises --help, which a page cannot take")
if f"parameter '{name}'" not in log:
    problems.append(f"the message does not name the address parameter '{name}'")
if problems:
    sys.exit(f"web page check: FAIL parameter {name}: {'; '.join(problems)}:\n{log}")
PY
    done
    exit $failed
    ;;
  files)
    node "$root/web/check-pages.mjs" --site "$site" --scene test3 >"$out/pages.txt" 2>&1 ||
      { cat "$out/pages.txt" >&2; say "FAIL: see $out/pages.txt"; exit 1; }
    cat "$out/pages.txt" >&2
    ;;
  *) say "unknown check '$what'"; exit 2 ;;
esac
