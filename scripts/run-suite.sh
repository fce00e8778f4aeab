#!/usr/bin/env bash
# Runs the experiments of ini/suite.txt in the groups given (every group when
# none is), then tables their figures with omnirange-summary.
#   run-suite.sh [-j JOBS] [-o PREFIX] [GROUP...]
# -j 1 (the default for one or two experiments) shows each experiment's stages
# and progress; with more jobs each experiment's output goes to
# results/logs/NAME.log and one line reports each that ends, with the time left.
# Needs a build (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=""; prefix=""
while getopts "j:o:" opt; do
  case $opt in
    j) jobs=$OPTARG ;;
    o) prefix=$OPTARG ;;
    *) echo "usage: run-suite.sh [-j JOBS] [-o PREFIX] [GROUP...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
groups=("$@")

names=(); ran_groups=()
while read -r name group _; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  # The held-out worlds run only when their group is named: a run spends them.
  if { [ ${#groups[@]} -eq 0 ] && [ "$group" != heldout ]; } || [[ " ${groups[*]} " == *" $group "* ]]; then
    names+=("$name")
    [[ " ${ran_groups[*]:-} " == *" $group "* ]] || ran_groups+=("$group")
  fi
done < ini/suite.txt
n=${#names[@]}
[ "$n" -gt 0 ] || { echo "run-suite.sh: no experiment in ini/suite.txt of the groups: ${groups[*]}" >&2; exit 2; }
[ -n "$jobs" ] || { [ "$n" -le 2 ] && jobs=1 || jobs=$(nproc); }
[ -n "$prefix" ] || prefix=results/$( [ ${#groups[@]} -eq 0 ] && echo suite || (IFS=-; echo "${groups[*]}") )-summary
# The summary tables the groups that ran (not the held-out worlds, when no group is named).
group_args=(); for g in "${ran_groups[@]}"; do group_args+=(-g "$g"); done

t0=$(date +%s)
if [ "$jobs" -eq 1 ]; then
  k=0
  for name in "${names[@]}"; do
    k=$((k + 1))
    echo "== experiment $k of $n: $name"
    build/apps/omnirange-experiment "ini/$name.ini" </dev/null
  done
else
  mkdir -p results/logs
  echo "== $n experiments, $jobs at a time; each one's output in results/logs/NAME.log"
  declare -A running=()
  next=0; done_count=0; failed=()
  while [ $next -lt "$n" ] || [ ${#running[@]} -gt 0 ]; do
    while [ $next -lt "$n" ] && [ ${#running[@]} -lt "$jobs" ]; do
      name=${names[$next]}; next=$((next + 1))
      build/apps/omnirange-experiment "ini/$name.ini" </dev/null >"results/logs/$name.log" 2>&1 &
      running[$!]=$name
    done
    status=0; wait -n -p pid || status=$?
    name=${running[$pid]}; unset "running[$pid]"
    done_count=$((done_count + 1))
    elapsed=$(( $(date +%s) - t0 ))
    left=$(( elapsed * (n - done_count) / done_count ))
    if [ $status -ne 0 ]; then failed+=("$name"); result="FAILED: $(tail -1 "results/logs/$name.log")"; else result="done"; fi
    printf '[%d/%d] %s %s (%d s so far, about %d min %02d s left)\n' \
      "$done_count" "$n" "$name" "$result" "$elapsed" $((left / 60)) $((left % 60))
  done
  [ ${#failed[@]} -eq 0 ] || { echo "run-suite.sh: failed: ${failed[*]}" >&2; exit 1; }
fi
echo "== $n experiments in $(( $(date +%s) - t0 )) s"
build/apps/omnirange-summary "${group_args[@]}" -o "$prefix"
