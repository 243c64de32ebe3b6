#!/bin/sh
# windows_wine_prefix.sh: makes the private Wine prefix $WINEPREFIX (once;
# wine would make it on first use, but then inside a timed check) and waits
# for its wineserver to finish.
set -e
[ -n "$WINEPREFIX" ] || { echo "error: WINEPREFIX is not set"; exit 2; }
mkdir -p "$WINEPREFIX"
wineboot --init
wineserver -w
echo "ok:   Wine prefix $WINEPREFIX ready ($(wine --version))"
