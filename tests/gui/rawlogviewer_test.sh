#!/usr/bin/env bash
# RawLogViewer (the real program, under Xvfb) opens a rawlog with OMNISCAN
# scans, shows one, and the screenshot is not blank.
#   rawlogviewer_test.sh SOURCE_DIR APPS_DIR WORK_DIR
set -euo pipefail
src=$1; apps=$2; work=$3
rm -rf "$work" && mkdir -p "$work"
"$apps/omnirange-train" -q -i "$src/rawlogs/factory-sample.rawlog" -c "$src/ini/factory.ini" -o "$work/f.hist"
"$apps/omnirange-scan" -q -i "$src/rawlogs/factory-sample.rawlog" -c "$src/ini/factory.ini" -H "$work/f.hist" -o "$work/scanned.rawlog"
"$src/scripts/rawlogviewer-screenshot.sh" "$work/scanned.rawlog" "$work/shot.png"
colours=$(/usr/bin/identify -format %k "$work/shot.png")
dark=$(/usr/bin/convert "$work/shot.png" -colorspace gray -format "%[fx:mean<0.1]" info:)
echo "screenshot: $colours colours, mostly dark: $dark"
[ "$colours" -gt 100 ] && [ "$dark" = 0 ] && echo "1 passed, 0 failed" || { echo "0 passed, 1 failed"; exit 1; }
