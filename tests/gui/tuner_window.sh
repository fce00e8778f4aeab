# Sourced by the tuner's Xvfb tests: a virtual display, the tuner on it, and
# a pixel count of a screenshot.
#   start_tuner LOG ARGS...  starts Xvfb (a screen of $SCREEN, 1600x1000x24 unless set) and
#                            omnirange-tuner ARGS (from $apps),
#                            its output into LOG; sets $win (its window), $tuner, $xvfb
#   count_colour SHOT COLOUR pixels of exactly COLOUR in the image SHOT
#   factory_work             an empty $work with f.hist trained on the factory sample and
#                            user.ini, a copy of ini/factory.ini beside its base
#   check DESCRIPTION CMD... runs CMD and says ok or FAIL (FAIL sets $fail to 1)

. "$(dirname "${BASH_SOURCE[0]}")/../../scripts/xvfb.sh"

start_tuner() {
  local log=$1; shift
  tuner=""
  start_xvfb "${SCREEN:-1600x1000x24}"
  trap 'kill $tuner $xvfb 2>/dev/null || true' EXIT
  "$apps/omnirange-tuner" "$@" </dev/null >"$log" 2>&1 & tuner=$!
  win=$(timeout 30 xdotool search --sync --onlyvisible --name "omnirange-tuner" | head -1)
  sleep 2
  xdotool windowactivate --sync "$win" 2>/dev/null || xdotool windowfocus --sync "$win"
}

count_colour() {
  /usr/bin/convert "$1" -fill black +opaque "$2" -fill white -opaque "$2" -format "%[fx:round(mean*w*h)]" info:
}

factory_work() {
  rm -rf "$work" && mkdir -p "$work"
  "$apps/omnirange-train" -q -i "$src/rawlogs/factory-sample.rawlog" -c "$src/ini/factory.ini" -o "$work/f.hist"
  cp "$src/ini/factory.ini" "$work/user.ini"
  cp "$src/ini/experiment-base.ini" "$work/"  # user.ini's base
}

fail=0
check() {
  if "${@:2}"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi
}
