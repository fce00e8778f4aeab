#!/usr/bin/env bash
# Runs the experiments of ini/suite.txt in the groups given (every group but
# heldout when none is) through GNU parallel, a job per experiment, then
# tables their figures with omnirange-summary.
#   run-suite.sh [-j JOBS] [-o PREFIX] [-r RESULTS_DIR] [-n FRAMES] [-S SSHLOGINFILE] [GROUP...]
# -j 1 (the default for one or two experiments) shows each experiment's stages
# and progress; with more jobs each experiment's output goes to
# RESULTS_DIR/logs/NAME.log and one line reports each that ends, with the
# time left. -S spreads the jobs over the hosts of an ssh login file
# (GNU parallel's --sshloginfile; each host sees this folder at the same path:
# docs/results.md, "Running the suite on several machines"). -n caps every
# experiment's frames (a quick check, not the suite's figures).
# Needs a build (scripts/setup.sh) and GNU parallel (Debian's parallel).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=""; prefix=""; results=results; frames=""; logins=""
while getopts "j:o:r:n:S:" opt; do
  case $opt in
    j) jobs=$OPTARG ;;
    o) prefix=$OPTARG ;;
    r) results=$OPTARG ;;
    n) frames=$OPTARG ;;
    S) logins=$OPTARG ;;
    *) echo "usage: run-suite.sh [-j JOBS] [-o PREFIX] [-r RESULTS_DIR] [-n FRAMES] [-S SSHLOGINFILE] [GROUP...]" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
groups=("$@")
command -v parallel >/dev/null || { echo "run-suite.sh: GNU parallel is missing: run scripts/setup.sh" >&2; exit 2; }

names=(); ran_groups=()
while read -r name group _; do
  [[ -z "$name" || "$name" == \#* ]] && continue
  [[ "$name" =~ ^[A-Za-z0-9_-]+$ ]] || { echo "run-suite.sh: ini/suite.txt: '$name' is not a plain name" >&2; exit 2; }
  # The held-out worlds run only when their group is named: a run spends them.
  if { [ ${#groups[@]} -eq 0 ] && [ "$group" != heldout ]; } || [[ " ${groups[*]} " == *" $group "* ]]; then
    names+=("$name")
    [[ " ${ran_groups[*]:-} " == *" $group "* ]] || ran_groups+=("$group")
  fi
done < ini/suite.txt
n=${#names[@]}
[ "$n" -gt 0 ] || { echo "run-suite.sh: no experiment in ini/suite.txt of the groups: ${groups[*]}" >&2; exit 2; }
[ -n "$jobs" ] || { [ "$n" -le 2 ] && jobs=1 || jobs=$(nproc); }
[ -n "$prefix" ] || prefix=$results/$( [ ${#groups[@]} -eq 0 ] && echo suite || (IFS=-; echo "${groups[*]}") )-summary
# The summary tables the groups that ran (not the held-out worlds, when no group is named).
group_args=(); for g in "${ran_groups[@]}"; do group_args+=(-g "$g"); done

mkdir -p "$results/logs"
options=(--jobs "$jobs" --joblog "$results/logs/joblog.tsv")
[ -n "$logins" ] && options+=(--sshloginfile "$logins" --workdir "$PWD" --env SHOW)
t0=$(date +%s)
status=0
if [ "$jobs" -eq 1 ] && [ -z "$logins" ]; then
  SHOW=1 parallel "${options[@]}" --ungroup scripts/run-experiment.sh {} "$results" "$frames" ::: "${names[@]}" || status=$?
else
  echo "== $n experiments, $jobs at a time; each one's output in $results/logs/NAME.log"
  # Each job says how it ended in one line, given when it ends: counted here, with the time left at the pace so far.
  report_each() {
    local line done_count=0 elapsed left
    while IFS= read -r line; do
      done_count=$((done_count + 1))
      elapsed=$(( $(date +%s) - t0 ))
      left=$(( elapsed * (n - done_count) / done_count ))
      printf '[%d/%d] %s (%d s so far, about %d min %02d s left)\n' "$done_count" "$n" "$line" "$elapsed" $((left / 60)) $((left % 60))
    done
  }
  set +e
  parallel "${options[@]}" scripts/run-experiment.sh {} "$results" "$frames" ::: "${names[@]}" | report_each
  status=${PIPESTATUS[0]}
  set -e
fi
if [ "$status" -ne 0 ]; then
  failed=$(awk -F'\t' 'NR > 1 && $7 != 0 { n = split($9, w, " "); print w[2] }' "$results/logs/joblog.tsv" | xargs)
  echo "run-suite.sh: failed: ${failed:-$status experiments}" >&2
  exit 1
fi
echo "== $n experiments in $(( $(date +%s) - t0 )) s"
build/apps/omnirange-summary "${group_args[@]}" -r "$results" -o "$prefix"
