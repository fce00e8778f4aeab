#!/usr/bin/env bash
# omnirange-tuner on bad data and careless use, under Xvfb, driven by xdotool:
#  - inputs that cannot work (no images folder, a wrong image size) are one
#    line and exit 1 before any window opens;
#  - a corrupt frame shows a placeholder with the reason, not another frame;
#  - a value typed but not committed is what Save writes; a refused value is
#    said and not saved, committed with Enter too (not clamped into range);
#  - Train refuses to write over a file that is not a colour model, and asks
#    before it replaces one (and keeps it on "no");
#  - unsaved changes mark the title and closing asks: Cancel keeps the
#    window, Save writes and closes.
#   tuner_care_test.sh SOURCE_DIR APPS_DIR WORK_DIR
set -euo pipefail
src=$1; apps=$2; work=$3
rm -rf "$work" && mkdir -p "$work"
cp -r "$src/rawlogs/factory-sample.rawlog" "$src/rawlogs/factory-sample_Images" "$work/"
cp "$src/ini/factory.ini" "$work/user.ini"
cp "$src/ini/experiment-base.ini" "$work/"  # user.ini's base
log=$work/factory-sample.rawlog
"$apps/omnirange-train" -q -i "$log" -c "$work/user.ini" -o "$work/f.hist"
. "$(dirname "$0")/tuner_window.sh"

# Before any window: one line naming the problem, exit 1.
refused_at_start() {  # refused_at_start EXPECTED_TEXT ARGS...
  local out rc=0
  out=$("$apps/omnirange-tuner" "${@:2}" </dev/null 2>&1) || rc=$?
  [ $rc -eq 1 ] && [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] && [[ "$out" == *"$1"* ]] || { echo "  got ($rc): $out"; return 1; }
}
mv "$work/factory-sample_Images" "$work/hidden"
check "a missing images folder is refused at start" refused_at_start "images folder" -i "$log" -c "$work/user.ini" -H "$work/f.hist"
mv "$work/hidden" "$work/factory-sample_Images"
printf 'base = user.ini\n[rangefinder]\nimage_width = 800\n' >"$work/wrong-size.ini"
check "a wrong image size is refused at start" refused_at_start "but the camera is 800x768" -i "$log" -c "$work/wrong-size.ini" -H "$work/f.hist"

# Frame 3 cut short: the rest of the log still works.
jpg=$work/factory-sample_Images/factory-sample_OMNICAM_000003.jpg
head -c 4000 "$jpg" >"$jpg.cut" && mv "$jpg.cut" "$jpg"
echo "precious" >"$work/user.hist"  # where Train writes (the ini's name, .hist)

start_tuner "$work/tuner.log" -i "$log" -c "$work/user.ini" -H "$work/f.hist"
press() {  # press WINDOW KEY...: without a window manager, a window takes keys once it has the focus
  xdotool windowfocus --sync "$1" 2>/dev/null || true
  xdotool key --window "$1" "${@:2}" 2>/dev/null || true  # a dialog may be gone before the key is released
  sleep 0.7
}
key() { press "$win" "$@"; }
title() { xdotool getwindowname "$win"; }
saved_threshold() { grep "^threshold = " "$work/user.ini" | cut -d' ' -f3; }
dialog() { timeout 10 xdotool search --sync --onlyvisible --name "$1" | head -1 || true; }

key Right; key Right; key Right
xwd -root -silent | /usr/bin/convert xwd:- "$work/shot.png"
placeholder=$(count_colour "$work/shot.png" "rgb(90,40,40)"); green=$(count_colour "$work/shot.png" "rgb(0,255,0)")
echo "frame 3: $placeholder placeholder pixels, $green hit-green pixels"
check "the corrupt frame 3 is named in the title" grep -q "frame 3 / 19" <(title)
check "the corrupt frame shows a placeholder" [ "$placeholder" -gt 100000 ]
check "the corrupt frame shows no other frame's rays" [ "$green" -lt 50 ]
check "the reason is said" grep -q "frame 3: image .*000003.jpg.* truncated" "$work/tuner.log"
key Right
check "the next frame works again" grep -q "frame 4 / 19" <(title)

# Typed, not committed (no Enter), then Ctrl+S.
key ctrl+t; key ctrl+a; xdotool type --window "$win" "0.2"; sleep 0.5; key ctrl+s
check "typed text is what Save writes" [ "$(saved_threshold)" = "0.2" ]
check "saved: no unsaved mark" bash -c "[[ '$(title)' != '*'* ]]"
key ctrl+t; key ctrl+a; xdotool type --window "$win" "5"; sleep 0.5; key ctrl+s
check "a value out of range is refused and said" grep -q "refused: threshold '5': must be within \[0, 1\]" "$work/tuner.log"
check "a refused value is not saved" [ "$(saved_threshold)" = "0.2" ]
# Typed and committed with Enter: GTK would clamp 2 into [0, 1] without a word; the tuner refuses it.
key ctrl+t; key ctrl+a; xdotool type --window "$win" "2"; sleep 0.5; key Return; key ctrl+s
check "a value out of range committed with Enter is refused, not clamped" grep -q "refused: threshold '2': must be within \[0, 1\]" "$work/tuner.log"
check "the clamped value is not saved" [ "$(saved_threshold)" = "0.2" ]

key ctrl+h
check "Train does not offer to replace a file that is not a colour model" [ -z "$(timeout 3 xdotool search --onlyvisible --name "replace the histogram" | head -1 || true)" ]
check "Train refuses it and says why" grep -q "user.hist' exists and is not a colour model" "$work/tuner.log"
check "the file is kept" grep -qx "precious" "$work/user.hist"
cp "$work/f.hist" "$work/user.hist"
key ctrl+h
train_dialog=$(dialog "replace the histogram")
check "Train asks before replacing a histogram" [ -n "$train_dialog" ]
[ -n "$train_dialog" ] && press "$train_dialog" Escape
check "'no' keeps the histogram" cmp -s "$work/f.hist" "$work/user.hist"
check "'no' is said" grep -q "not trained: .*user.hist kept" "$work/tuner.log"

key bracketright  # threshold 0.2 -> 0.4, not saved
check "unsaved changes mark the title" bash -c "[[ '$(title)' == '*'* ]]"
key ctrl+w
close_dialog=$(dialog "unsaved changes")
check "closing with unsaved changes asks" [ -n "$close_dialog" ]
[ -n "$close_dialog" ] && press "$close_dialog" Escape
check "Cancel keeps the window" kill -0 "$tuner"
key ctrl+w
close_dialog=$(dialog "unsaved changes")
[ -n "$close_dialog" ] && press "$close_dialog" Return
rc=0; timeout 10 tail --pid="$tuner" -f /dev/null || rc=$?
check "Save closes the window" bash -c "! kill -0 $tuner 2>/dev/null"
check "Save on close writes the changed value" [ "$(saved_threshold)" = "0.4" ]

echo "--- tuner's log:"; cat "$work/tuner.log"
[ $fail -eq 0 ] && echo "1 passed, 0 failed" || { echo "0 passed, 1 failed"; exit 1; }
