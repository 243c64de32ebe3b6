#!/bin/sh
# ghost_changes_nothing.sh ODELAB WORLD WORK
#
# A world's "ghost" is drawn, never stepped or measured: WORLD run headless
# as it is and with its "ghost" field taken out gives the same state_hash
# (every body's exact state at the end) and the same figure for every probe.
set -eu
odelab=$1 world=$2 work=$3
rm -rf "$work"
mkdir -p "$work/with" "$work/without"
/usr/bin/python3 - "$world" "$work/without/world.json" <<'PY'
import json, sys
world = json.load(open(sys.argv[1]))
assert "ghost" in world, sys.argv[1] + " states no ghost: nothing to compare"
del world["ghost"]
json.dump(world, open(sys.argv[2], "w"))
PY
(cd "$work/with" && "$odelab" --world "$world" --headless --metrics-json m.json >log 2>&1)
(cd "$work/without" && "$odelab" --world world.json --headless --metrics-json m.json >log 2>&1)
/usr/bin/python3 - "$work/with/m.json" "$work/without/m.json" <<'PY'
import json, sys
with_ghost, without = (json.load(open(p)) for p in sys.argv[1:3])
def flat(m):
    return m.get("metrics", m)
a, b = flat(with_ghost), flat(without)
keys = [k for k in a if k == "state_hash" or k.endswith("_value")]
assert "state_hash" in keys, "no state_hash in the metrics"
differ = [k for k in keys if a.get(k) != b.get(k)]
if differ:
    sys.exit("ghost_changes_nothing: the ghost changed " + ", ".join(f"{k} ({a.get(k)} vs {b.get(k)})" for k in differ))
print("ghost_changes_nothing: same " + ", ".join(f"{k} = {a[k]}" for k in keys))
PY
