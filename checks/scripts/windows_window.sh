#!/bin/sh
# windows_window.sh XVFB_RUN EXE SCREENSHOT_CHECK FOLDER
#
# Starts test0.exe (EXE) in a window under Xvfb and Wine, as the Linux
# check test0_window_renders_lit_and_shadowed_scene does: 30 frames with an
# object every 0.05 s, then --screenshot. The program must end with status 0
# and its PNG must pass SCREENSHOT_CHECK (not blank, a lit surface with a
# shadow on it). $WINEPREFIX is this check's own: its wineserver is stopped
# first, so the one that serves the run is started under the X server (a
# wineserver started without DISPLAY is reused and gives "no display").
xvfb_run=$1 exe=$2 check=$3 folder=$4
rm -rf "$folder"
mkdir -p "$folder" || exit 2
cd "$folder" || exit 2
wineserver -k 2>/dev/null
wineserver -w 2>/dev/null
"$xvfb_run" -a -s '-screen 0 1280x800x24' sh -c '
  wine "$0" --screenshot test0_window.png --frames 30 --spawn-interval 0.05 >out.txt 2>err.txt
  echo $? >status
  wineserver -k 2>/dev/null
  wineserver -w 2>/dev/null' "$exe"
status=$(cat status 2>/dev/null)
if [ "$status" != 0 ]; then
  echo "FAIL: test0.exe in a window ended with status ${status:-unknown}"
  tail -n 20 err.txt
  exit 1
fi
echo "ok:   test0.exe ran 30 frames in a window under Wine: $(grep -i 'renderer\|OpenGL' err.txt out.txt | head -1)"
"$check" test0_window.png
