#!/usr/bin/env bash
# omnirange-tuner on a 1280x720 screen, a small laptop's, under Xvfb:
#  - the window fits the screen, and GTK prints no warning at start;
#  - the image with its legend, the buttons under it and every control are in view;
#  - Page Down steps frames even from a number field;
#  - Save changes only the line of the key changed (and adds its comment);
#  - Shift+click places the centre, a drag moves it, Ctrl+Z undoes the drag;
#  - the wheel zooms in and out.
#   tuner_layout_test.sh SOURCE_DIR APPS_DIR WORK_DIR
set -euo pipefail
src=$1; apps=$2; work=$3
. "$(dirname "$0")/tuner_window.sh"
factory_work
SCREEN=1280x720x24 start_tuner "$work/tuner.log" -i "$src/rawlogs/factory-sample.rawlog" -c "$work/user.ini" -H "$work/f.hist"
eval "$(xdotool getwindowgeometry --shell "$win")"  # X, Y, WIDTH, HEIGHT
echo "window: ${WIDTH}x${HEIGHT} at $X,$Y"
check "the window fits a 1280x720 screen" [ $((X + WIDTH)) -le 1280 -a $((Y + HEIGHT)) -le 720 ]
check "no GTK warning at start" bash -c "! grep -q 'Gtk-' '$work/tuner.log'"
xwd -root -silent | /usr/bin/convert xwd:- "$work/shot.png"
green=$(count_colour "$work/shot.png" "rgb(0,255,0)"); legend=$(count_colour "$work/shot.png" "rgb(20,20,20)")
echo "screenshot: $green hit-green pixels, $legend legend-background pixels"
check "the image's rays are in view" [ "$green" -gt 200 ]
check "the legend is in view" [ "$legend" -gt 3000 ]
# Every control in view without scrolling: the last three keys are switches, all on in this ini,
# and a checked box is GTK's blue (#3584E4); all three show in the screen's lower right.
ticks=$(/usr/bin/convert "$work/shot.png" -crop 420x240+860+480 +repage -fill black +opaque "rgb(53,132,228)" \
  -fill white -opaque "rgb(53,132,228)" -format "%[fx:round(mean*w*h)]" info:)
echo "checked-box pixels in the controls' last rows: $ticks"
check "every control is in view, the last ones too" [ "$ticks" -gt 180 ]

key() { xdotool key --window "$win" "$@"; sleep 0.7; }
key ctrl+t  # the threshold's field has the focus
xdotool type --window "$win" "0.1"; sleep 0.3
key Next  # Page Down, from inside the number field
check "Page Down steps a frame from a number field" grep -q "frame 1 / 19" <(xdotool getwindowname "$win")
key ctrl+s
sleep 1
added=$(diff "$src/ini/factory.ini" "$work/user.ini" | grep '^>' | sed 's/^> //' || true)
removed=$(diff "$src/ini/factory.ini" "$work/user.ini" | grep -c '^<' || true)
echo "saved lines added:"; printf '%s\n' "$added"
check "Save wrote the threshold" grep -qx "threshold = 0.1" "$work/user.ini"
# The user's ini had no [rangefinder] (its base has): the section comes with the key.
check "Save changed no other line" [ "$removed" -eq 0 -a "$(printf '%s\n' "$added" | grep -vc '^;\|^threshold = 0.1$\|^\[rangefinder\]$\|^$')" -eq 0 ]
# The centre: Shift+click places it, a drag from it moves it (40 px right, 30 px up on screen).
xdotool mousemove --window "$win" 300 200 keydown shift click 1 keyup shift; sleep 0.8
xdotool mousemove --window "$win" 300 200 mousedown 1; sleep 0.3
xdotool mousemove --window "$win" 320 185; sleep 0.3
xdotool mousemove --window "$win" 340 170 mouseup 1; sleep 0.8
key ctrl+s
cx=$(grep "^cx = " "$work/user.ini" | cut -d' ' -f3); cy=$(grep "^cy = " "$work/user.ini" | cut -d' ' -f3)
echo "centre saved at ($cx, $cy); the ini's was (512, 384)"
# Placed at display (296, 196) (the image sits 4 px in), 1.4 to 2 image px per display px at this size.
check "Shift+click then a drag put the centre right of and above where the ini had it" \
  awk -v x="$cx" -v y="$cy" 'BEGIN { exit !(x > 296 * 1.4 + 40 * 1.4 && x < 336 * 2 && y < 196 * 2 - 30 * 1.4 && y > 166 * 1.4) }'
check "Ctrl+Z undoes the drag" bash -c "xdotool key --window $win ctrl+z; sleep 0.8; xdotool key --window $win ctrl+s; sleep 0.8; \
  awk -v x=\$(grep '^cx = ' '$work/user.ini' | cut -d' ' -f3) -v c=$cx 'BEGIN { exit !(x < c - 20) }'"
# The wheel zooms about the pixel under the mouse: the legend in the corner leaves the view, and comes back.
xdotool mousemove --window "$win" 330 250 click 4 click 4 click 4 click 4; sleep 1
xwd -root -silent | /usr/bin/convert xwd:- "$work/zoomed.png"
zoomed=$(count_colour "$work/zoomed.png" "rgb(20,20,20)")
xdotool mousemove --window "$win" 330 250 click 5 click 5 click 5 click 5 click 5; sleep 1
xwd -root -silent | /usr/bin/convert xwd:- "$work/unzoomed.png"
unzoomed=$(count_colour "$work/unzoomed.png" "rgb(20,20,20)")
echo "legend-background pixels: $zoomed zoomed in, $unzoomed zoomed out"
check "zooming in at the centre takes the corner's legend out of view" [ "$zoomed" -lt 500 ]
check "zooming out brings it back" [ "$unzoomed" -gt 3000 ]
[ $fail -eq 0 ] && echo "1 passed, 0 failed" || { echo "0 passed, 1 failed"; cat "$work/tuner.log"; exit 1; }
