#!/bin/sh
# engine_failure_not_physics.sh SOURCE_DIR TESTS_DIR [node]
#
# An engine that fails is not a blow-up, and every relative measure has a
# defined denominator (doc/hardening.md, "Fourth round"):
#   - with "node": test2 --engine jolt whose Node.js child is killed
#     (SIGKILL) mid-run ends with status 7, not 3; its metrics say
#     engine_failed 1 and non_finite 0; Test2_output.txt's last line is
#     "# incomplete: ...; engine jolt failed: ...";
#   - a world at rest without gravity, and the same world moved below
#     y = 0 with gravity, measured for energy: energy_rel_variation is a
#     number (not null) and not negative.
source_dir=$(cd "$1" && pwd) tests=$(cd "$2" && pwd) node=${3:-}
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_engine_failure.XXXXXX") || exit 2
pids=
trap 'for p in $pids; do kill -KILL "$p" 2>/dev/null; done; rm -rf "$root"' EXIT
cd "$root" || exit 2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok:   $*"; }
metric() { python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get(sys.argv[2]))" "$1" "$2"; }

if [ "$node" = node ]; then
  "$tests/test2" --headless --seconds 100000 --engine jolt --metrics-json m.json >/dev/null 2>err.txt &
  pid=$!
  pids=$pid
  n=0
  while [ "$(cat Test2_output.txt 2>/dev/null | wc -l)" -lt 50 ] && [ $n -lt 1200 ]; do sleep 0.1; n=$((n + 1)); done
  child=$(pgrep -P "$pid" | head -n 1)
  [ -n "$child" ] || fail "no engine child found"
  kill -KILL "$child"
  wait "$pid"
  status=$?
  pids=
  [ "$status" = 7 ] && ok "engine killed: status 7" || fail "engine killed: status $status, expected 7 (3 is a blow-up)"
  [ "$(metric m.json engine_failed)" = 1 ] && ok "engine killed: engine_failed 1" ||
    fail "engine killed: engine_failed is $(metric m.json engine_failed)"
  [ "$(metric m.json non_finite)" = 0 ] && ok "engine killed: non_finite 0" ||
    fail "engine killed: non_finite is $(metric m.json non_finite), counted as a blow-up"
  case $(tail -n 1 Test2_output.txt) in
    "# incomplete: "*"engine jolt failed"*) ok "engine killed: the last line names the engine's failure" ;;
    *) fail "engine killed: last line '$(tail -n 1 Test2_output.txt)'" ;;
  esac
fi

# Worlds whose energy is 0 throughout, or below 0: the format's own
# example of a thrown ball (doc/worlds/projectile.json), at rest without
# gravity, and thrown 100 m below y = 0 over a floor there.
python3 - "$source_dir/doc/worlds/projectile.json" <<'PY' || fail "could not write the worlds"
import json, sys
world = json.load(open(sys.argv[1]))
world["measures"] = [{"kind": "energy"}]
at_rest = json.loads(json.dumps(world))
at_rest["settings"]["gravity"] = [0, 0, 0]
at_rest["bodies"][0]["linear_velocity"] = [0, 0, 0]
json.dump(at_rest, open("at_rest.json", "w"))
world["bodies"][0]["position"][1] -= 100
for geom in world["geoms"]:
    if geom["shape"] == "plane":
        geom["plane"][3] -= 100
json.dump(world, open("below.json", "w"))
PY
for world in at_rest below; do
  "$tests/odelab" --world $world.json --headless --seconds 1 --metrics-json $world-m.json >/dev/null 2>err.txt ||
    fail "$world: odelab --world failed: $(cat err.txt)"
  value=$(metric $world-m.json energy_rel_variation)
  if python3 -c "import sys; v = float(sys.argv[1]); sys.exit(0 if v == v and v >= 0 else 1)" "$value" 2>/dev/null; then
    ok "$world: energy_rel_variation $value"
  else
    fail "$world: energy_rel_variation is $value, expected a number at least 0"
  fi
done
[ "$failures" = 0 ]
