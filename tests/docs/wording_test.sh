#!/usr/bin/env bash
# The project speaks of itself, never of how it was made: no rounds of work
# named by their ordinal or as "this" or "that" one, in its docs, comments,
# inis or output. Where history matters, a date or a commit.
# The tuner's own sense of "session" (TunerSession, a session over a rawlog)
# is a thing of the program and stays.
#   wording_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"
ordinal='(first|second|third|fourth|fifth|sixth|seventh|eighth|ninth|tenth|eleventh|twelfth|thirteenth|fourteenth|fifteenth|sixteenth|seventeenth|eighteenth|nineteenth|twentieth|[0-9]+(st|nd|rd|th))'
rounds="\\b${ordinal}[ -](session|round|sitting)s?\\b|\\b(since|until) the ${ordinal}\\b|\\bthe day's ${ordinal}\\b|\\b(this|that|same|last|next|previous|earlier|later) session\\b|\\bsessions\\b"
hits=$(grep -rniE "$rounds" README.md docs plugin apps eval sim tuner tests scripts ini worlds fuzz examples rawlogs/README.md \
         --include='*.md' --include='*.h' --include='*.cpp' --include='*.sh' --include='*.ini' --include='*.txt' \
         --include='*.world' --include='*.route' --include='*.py' --include='CMakeLists.txt' \
       | grep -v '^tests/docs/wording_test.sh:' || true)
if [ -n "$hits" ]; then
  echo "words about how the project was made, not about the project:"
  echo "$hits"
  exit 1
fi
echo "no rounds of work named"
