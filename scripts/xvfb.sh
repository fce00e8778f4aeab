# Sourced by every script that needs a screen:
#   start_xvfb SIZE   starts Xvfb with a screen of SIZE (e.g. 1600x1000x24) on
#                     a display it picks itself (-displayfd: two at once never
#                     meet), exports DISPLAY and sets $xvfb (its PID); says why
#                     and returns 1 when it does not start within 20 s.
start_xvfb() {
  local number; number=$(mktemp)
  Xvfb -displayfd 3 -screen 0 "$1" 3>"$number" >/dev/null 2>&1 & xvfb=$!
  local tries=0
  until [ -s "$number" ]; do
    if ! kill -0 "$xvfb" 2>/dev/null || [ $tries -ge 200 ]; then
      rm -f "$number"; kill "$xvfb" 2>/dev/null || true
      echo "Xvfb did not start (is Debian's xvfb installed?)" >&2; return 1
    fi
    sleep 0.1; tries=$((tries + 1))
  done
  export DISPLAY=:$(tr -dc 0-9 <"$number"); rm -f "$number"
}
