#!/usr/bin/env bash
# Runs the apps on a list of bad inputs, as a careless or hostile user would
# give them, and prints a markdown table of what each did (docs/robustness.md
# sums up its kinds). A case passes when the app ends within 60 s with
# exit code 1 or 2, one line on stderr, no output file left and every input
# unchanged, or, for the few inputs that are legal but odd, exit 0 with the
# warning asked for. Exits 1 if any case does not pass.
#
#   scripts/bad-inputs.sh BUILD_DIR [WORK_DIR]
set -uo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: bad-inputs.sh BUILD_DIR [WORK_DIR]}" && pwd)"
work="${2:-$(mktemp -d)}"
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
apps="$build/apps"
sample="$src/rawlogs/factory-sample.rawlog"
ini="$src/ini/factory.ini"

# --- fixtures -----------------------------------------------------------
"$apps/omnirange-train" -q -i "$sample" -c "$ini" -o floor.hist || exit 1
cp "$sample" s.rawlog && cp -r "$src/rawlogs/factory-sample_Images" s_Images
cp "$ini" f.ini && cp "$src/ini/experiment-base.ini" .  # f.ini and its base
head -c 20000 "$sample" > cut.rawlog
: > empty.rawlog
# The same "random" bytes every run, so that the table reads the same.
LC_ALL=C awk 'BEGIN { srand(7); for (i = 0; i < 5000; i++) printf "%c", int(rand() * 256) }' > random.rawlog
mkdir -p cutimg_Images && cp s.rawlog cutimg.rawlog
cp s_Images/* cutimg_Images/ && f=$(ls cutimg_Images | sort | sed -n 5p)
truncate -s 30000 "cutimg_Images/$f"
cp s.rawlog noimages.rawlog
head -c 3000 floor.hist > cut.hist
printf 'not a histogram at all' > text.hist
mkdir -p readonly && chmod 555 readonly
ln -sf s.rawlog link-to-input.rawlog
cp "$src/worlds/factory.world" w.world && cp "$src/worlds/factory.route" w.route
printf 'omnirange-world 1\nname far\nbounds xmin=-5 ymin=-5 xmax=5 ymax=5\nfloor material=concrete\nmaterial name=concrete rgb=150,148,142\nbox x=1000000 y=0 w=1 d=1 z1=1 material=concrete\n' > far.world
printf '0 0\n1e300 0\n' > far.route
printf 'omnirange-world 1\nbox x=1 y=\n' > broken.world
printf '0 0\n1 abc\n' > broken.route

# ini variants: f.ini (whose [rangefinder] comes from its base) with a
# [rangefinder] section of the lines given.
variant() {  # variant NAME LINE...
  local name="$1"; shift
  { cat f.ini; printf '\n[rangefinder]\n'; printf '%s\n' "$@"; } > "$name.ini"
}
variant thr_abc 'threshold = abc'
variant thr_comma 'threshold = 0,075'
variant n_suffix 'N = 20abc'
variant h_unit 'h = 0.931m'
variant scan_frac 'scanlines = 360.7'
variant mirrored_maybe 'mirrored = maybe'
variant dup 'N = 20' 'N = 30'
variant pose_nan 'pose_x = nan'
variant tol_inf 'outlier_abs_tol = inf'
variant n_huge 'N = 2147483647'
variant k_huge 'K = 2147483647'
variant width_huge 'outlier_max_width = 2147483647'
variant scan_huge 'scanlines = 1e9'
variant r_abc 'R = abc'
variant r_neg 'R = -5'
variant unknown 'thresold = 0.1'
variant width_small 'image_width = 640' 'cx = 320'
variant empty_value 'threshold ='
sed 's/^base = .*/base = nowhere.ini/' f.ini > no_base.ini
printf '[laser]\nfov = 180\n' > renamed_robot.ini
printf '[lazer]\nfov_deg = 90\n' > misspelt_robot.ini
printf '[robot]\nspeed = 0.01\nframe_rate = 100\n' > slow_robot.ini

# --- running ------------------------------------------------------------
declare -a inputs_sums
problems=0
n=0
echo "| # | bad input | app | exit | stderr (first line) | lines | output left | inputs kept | verdict |"
echo "|---|---|---|---|---|---|---|---|---|"
# case DESCRIPTION EXPECT(error|error:TEXT|libexit:TEXT|warn:TEXT) OUTPUT -- COMMAND...
run_case() {
  local what="$1" expect="$2" out="$3"; shift 4
  n=$((n + 1))
  rm -rf "$out" "${out%.rawlog}_Images"
  local before after
  before=$(md5sum s.rawlog f.ini floor.hist w.world w.route imp_laser.csv 2>/dev/null | md5sum)
  timeout 60 "$@" >stdout.txt 2>stderr.txt
  local code=$?
  after=$(md5sum s.rawlog f.ini floor.hist w.world w.route imp_laser.csv 2>/dev/null | md5sum)
  local lines first left kept verdict="pass"
  lines=$(grep -c . stderr.txt)
  first=$(grep -m1 . stderr.txt | cut -c1-150 | sed 's/|/\\|/g')
  [[ "$expect" == libexit:* ]] && first="$(tr '\n' ' ' < stderr.txt | cut -c1-200)"
  [[ "$expect" == warn:* ]] && first="(warning) $(grep -h -m1 "${expect#warn:}" stdout.txt stderr.txt | cut -c1-150)"
  left="no"; [ -e "$out" ] && left="yes"
  kept="yes"; [ "$before" == "$after" ] || kept="NO"
  case "$expect" in
    error) { [ $code -eq 1 ] || [ $code -eq 2 ]; } && [ "$lines" -eq 1 ] && [ "$left" == "no" ] || verdict="PROBLEM" ;;
    # The same, and the line says this (the reason, not a later failure).
    error:*) [ $code -eq 1 ] && [ "$lines" -eq 1 ] && [ "$left" == "no" ] && grep -q "${expect#error:}" stderr.txt || verdict="PROBLEM" ;;
    # A library that calls exit() (libjpeg inside MRPT): its own line, then ours naming the file.
    libexit:*) [ $code -eq 1 ] && [ "$lines" -le 2 ] && [ "$left" == "no" ] && tail -1 stderr.txt | grep -q "${expect#libexit:}" || verdict="PROBLEM" ;;
    warn:*) [ $code -eq 0 ] && cat stdout.txt stderr.txt | grep -q "${expect#warn:}" || verdict="PROBLEM" ;;
  esac
  [ "$kept" == "yes" ] || verdict="PROBLEM"
  [ $code -eq 124 ] && verdict="PROBLEM (hang)"
  [ $code -gt 128 ] && verdict="PROBLEM (signal $((code - 128)))"
  [ "$verdict" == "pass" ] || problems=$((problems + 1))
  local app a; for a in "$@"; do case "$a" in */omnirange-*) app=$(basename "$a"); break ;; esac; done
  app=${app:-$(basename "$1")}
  echo "| $n | $what | $app | $code | ${first:-} | $lines | $left | $kept | $verdict |"
}

scan() { run_case "$1" "$2" out.rawlog -- "$apps/omnirange-scan" -q "${@:3}"; }
S=(-i s.rawlog -c f.ini -H floor.hist -o out.rawlog)

scan "rawlog missing" error -i nothing.rawlog -c f.ini -H floor.hist -o out.rawlog
scan "rawlog is a folder" error -i s_Images -c f.ini -H floor.hist -o out.rawlog
scan "rawlog cut at 20 kB" error -i cut.rawlog -c f.ini -H floor.hist -o out.rawlog
scan "rawlog empty" error -i empty.rawlog -c f.ini -H floor.hist -o out.rawlog
scan "rawlog of random bytes" error -i random.rawlog -c f.ini -H floor.hist -o out.rawlog
scan "rawlog without its images folder" "error:there is no folder .noimages_Images." -i noimages.rawlog -c f.ini -H floor.hist -o out.rawlog
scan "one JPEG cut short" error -i cutimg.rawlog -c f.ini -H floor.hist -o out.rawlog
run_case "one JPEG cut short, --skip-bad-images" "warn:skipped" out.rawlog -- "$apps/omnirange-scan" -i cutimg.rawlog -c f.ini -H floor.hist -o out.rawlog --skip-bad-images
scan "a corrupt JPEG stored inside the rawlog" "libexit:corrupt-embedded-jpeg.rawlog" -i "$src/tests/data/corrupt-embedded-jpeg.rawlog" -c f.ini -H floor.hist -o out.rawlog
scan "no image under the label" error "${S[@]}" --omni-label NOSUCH
scan "image size other than the ini's" "error:but the camera is 640x768" -i s.rawlog -c width_small.ini -H floor.hist -o out.rawlog
scan "histogram missing" error -i s.rawlog -c f.ini -H none.hist -o out.rawlog
scan "histogram is /dev/zero" error -i s.rawlog -c f.ini -H /dev/zero -o out.rawlog
scan "histogram cut short" error -i s.rawlog -c f.ini -H cut.hist -o out.rawlog
scan "histogram is text" error -i s.rawlog -c f.ini -H text.hist -o out.rawlog
run_case "output is the input rawlog" error s.rawlog.none -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o s.rawlog
run_case "output is the histogram" error floor.hist.none -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o floor.hist
run_case "output is the ini" error f.ini.none -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o f.ini
run_case "output is a link to the input" error link.none -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o link-to-input.rawlog
run_case "output folder does not exist" error nofolder/out.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o nofolder/out.rawlog
run_case "output folder is a file" error f.ini/out.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o f.ini/out.rawlog
# (root writes into read-only folders: that case only means something for other users)
[ "$(id -u)" -ne 0 ] && run_case "output folder read-only" error readonly/out.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o readonly/out.rawlog
run_case "disk full (file size limit 20 kB)" error out.rawlog -- bash -c 'trap "" XFSZ; ulimit -f 20; exec "$@"' _ "$apps/omnirange-scan" -q "${S[@]}"
for v in thr_abc thr_comma n_suffix h_unit scan_frac mirrored_maybe dup pose_nan tol_inf n_huge k_huge width_huge scan_huge r_abc r_neg unknown empty_value; do
  edit=$(diff f.ini "$v.ini" | grep '^>' | grep -v '^> \[rangefinder\]' | sed 's/^> //' | paste -sd ' ' | sed 's/^ *//')
  scan "ini: \`$edit\`" error -i s.rawlog -c "$v.ini" -H floor.hist -o out.rawlog
done
scan "ini missing" error -i s.rawlog -c none.ini -H floor.hist -o out.rawlog
scan "ini whose base is missing" error -i s.rawlog -c no_base.ini -H floor.hist -o out.rawlog
scan "ini section missing" error "${S[@]}" -s nosection
scan "threads -j 0" error "${S[@]}" -j 0
scan "threads -j 70000" error "${S[@]}" -j 70000
scan "unknown option" error "${S[@]}" --frobnicate

train() { run_case "$1" "$2" "$3" -- "$apps/omnirange-train" -q "${@:4}"; }
printf '' > nolaser.txt
train "histogram output is the input rawlog" error s.rawlog.none -i s.rawlog -c f.ini -o s.rawlog
train "histogram output is the ini" error f.ini.none -i s.rawlog -c f.ini -o f.ini
train "no laser under the label" error t.hist -i s.rawlog -c f.ini -o t.hist --laser-label NOSUCH
training() { { cat f.ini; printf '\n[%s]\n%s\n' "$2" "$3"; } > "$1.ini"; }
training bins0 training 'bins = 0' && train "[training] bins = 0" "error:bins = '0'" t.hist -i s.rawlog -c bins0.ini -o t.hist
training bins_huge training 'bins = 100000' && train "[training] bins = 100000" "error:bins = '100000'" t.hist -i s.rawlog -c bins_huge.ini -o t.hist
training space_xyz training 'colour_space = XYZ' && train "[training] colour_space = XYZ" error t.hist -i s.rawlog -c space_xyz.ini -o t.hist
training margin_huge training 'laser_margin = 1e6' && train "[training] laser_margin = 1e6" "error:laser_margin = '1e6'" t.hist -i s.rawlog -c margin_huge.ini -o t.hist
training misspelt training 'binz = 8' && train "[training] an unknown key" "error:binz" t.hist -i s.rawlog -c misspelt.ini -o t.hist
training no_grid learning 'thresholds =' && train "[learning] thresholds empty" "error:thresholds" t.hist -i s.rawlog -c no_grid.ini -o t.hist --learn l.ini
train "--bins is an ini key" error t.hist -i s.rawlog -c f.ini -o t.hist --bins 8
train "--figures-frame past the end" error t.hist -i s.rawlog -c f.ini -o t.hist --figures t --figures-frame 500
train "--every -3" error t.hist -i s.rawlog -c f.ini -o t.hist --every -3

sim() { run_case "$1" "$2" o.rawlog -- "$apps/omnirange-sim" -q -o o.rawlog "${@:3}"; }
run_case "output is the world file" error w.world.none -- "$apps/omnirange-sim" -q -w w.world -r w.route -o w.world -n 2
sim "world: a solid 1000 km away" error -w far.world -r w.route -n 2
sim "route: a waypoint at 1e300" error -w w.world -r far.route -n 2
sim "world: a line cut short" error -w broken.world -r w.route -n 2
sim "route: a word for a number" error -w w.world -r broken.route -n 2
sim "frames -n -1" error -w w.world -r w.route -n -1
sim "route of more frames than any run writes (1 cm/s at 100 Hz)" error -w w.world -r w.route -c slow_robot.ini
sim "threads -j 70000" error -w w.world -r w.route -n 2 -j 70000
sim "robot ini with a renamed key (fov)" error -w w.world -r w.route -n 2 -c renamed_robot.ini
sim "robot ini with a misspelt section" error -w w.world -r w.route -n 2 -c misspelt_robot.ini

run_case "accuracy: rawlog without scans" error acc_table.md -- "$apps/omnirange-accuracy" -q -i s.rawlog -o acc
"$apps/omnirange-scan" -q "${S[@]}" && mv out.rawlog scanned.rawlog
run_case "accuracy: --first past the end" error acc_table.md -- "$apps/omnirange-accuracy" -q -i scanned.rawlog -o acc --first 100000
run_case "calibrate: histogram of another floor" error cal.ini -- "$apps/omnirange-calibrate" -q -i s.rawlog -c f.ini -H text.hist
printf '#direct\n6 -96 0 0.0026\n#inverse\n2 1 1\n#center\n380 515\n#affine\n1 0 0\n#size\n768 1024\n' > wrong_count_calib.txt
printf '#direct\n3 96 0 0.0026\n#inverse\n2 1 1\n#center\n380 515\n#affine\n1 0 0\n#size\n768 1024\n' > upward_calib.txt
run_case "calibrate: OCamCalib file with a wrong count" error cal.ini -- "$apps/omnirange-calibrate" -q --ocamcalib wrong_count_calib.txt --save-to cal.ini
run_case "calibrate: OCamCalib centre looking up (a0 > 0)" error cal.ini -- "$apps/omnirange-calibrate" -q --ocamcalib upward_calib.txt --save-to cal.ini
mkdir -p imp && cp "$(ls s_Images/* | sort | head -1)" imp/100.0.jpg && cp "$(ls s_Images/* | sort | sed -n 2p)" imp/100.4.jpg
printf '100.0, 1.5, 2.5, 3.5\n100.4, 1.5, 2.5, 3.5\n' > imp_laser.csv
printf '100.4, 1, 2, 3\n100.0, 1, 2, 3\n' > imp_unsorted.csv
printf '100.0, 1, 2, 3\n100.4, 1, 2\n' > imp_short.csv
run_case "import: laser rows out of time order" error imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_unsorted.csv -o imp.rawlog
run_case "import: a laser row with a range missing" error imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_short.csv -o imp.rawlog
printf '100.0,2,1,2,2,2,3\n100.4,2,1,2,2,2,3\n' > imp_commas.csv
run_case "import: ranges written with decimal commas (2,1)" "error:decimal commas" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_commas.csv -o imp.rawlog
mkdir -p imp_bad && printf 'not an image' > imp_bad/100.0.jpg
run_case "import: an image that does not decode" error imp.rawlog -- "$apps/omnirange-import" -q --images imp_bad --laser imp_laser.csv -o imp.rawlog
run_case "import: output is the laser log" error imp_laser.csv.none -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv -o imp_laser.csv
printf 'ODOM 0 0 0 0 0 0 100.0 h 0\nFLASER 3 1 2 0 0 0 0 0 0 100.4 h 0\n' > imp_short.carmen
run_case "import: a CARMEN FLASER with a range missing" error imp.rawlog -- "$apps/omnirange-import" -q --images imp --carmen imp_short.carmen -o imp.rawlog
run_case "import: a CARMEN log and a laser CSV both" error imp.rawlog -- "$apps/omnirange-import" -q --images imp --carmen imp_short.carmen --laser imp_laser.csv -o imp.rawlog
mkdir -p exp && cp -r "$src/ini" exp/ini && ln -sf "$src/worlds" exp/worlds
awk '{print} /^\[experiment\]/{print "unknown_key = 1"}' "$ini" > exp/ini/exp_bad.ini
run_case "experiment: unknown key" error report -- "$apps/omnirange-experiment" -q exp/ini/exp_bad.ini -o report
run_case "experiment: ini missing" error report -- "$apps/omnirange-experiment" -q none.ini -o report

# The output rule: an output replaces only what the same program wrote
# before; the user's own files around it must come through whole.
mkdir -p users_folder && echo mine > users_folder/note.txt && echo mine > users_file.txt
kept() {  # kept FILE...: each still holds "mine"
  for f in "$@"; do
    [ "$(cat "$f" 2>/dev/null)" = mine ] || { echo "| | PROBLEM: $f of the user's was changed or removed |"; problems=$((problems + 1)); }
  done
}
run_case "experiment: -o names a folder of the user's" error none.out -- "$apps/omnirange-experiment" -q exp/ini/factory.ini -n 5 -o users_folder
run_case "experiment: -o names a file of the user's" error none.out -- "$apps/omnirange-experiment" -q exp/ini/factory.ini -n 5 -o users_file.txt
run_case "experiment: -o names the worlds folder it reads" error none.out -- "$apps/omnirange-experiment" -q exp/ini/factory.ini -n 5 -o exp/worlds/
run_case "scan: an output whose NAME_Images is the input's" error none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o s
run_case "scan: an output MRPT's programs would read other images of (NAME.rawlog.gz)" "error:not named NAME.rawlog" s2.rawlog.gz -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o s2.rawlog.gz
run_case "scan: an output onto a text file of the user's" error none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o users_file.txt
run_case "calibrate: --save-to the colour model it reads" error none.out -- "$apps/omnirange-calibrate" -q -i s.rawlog -c f.ini -H floor.hist --save-to floor.hist
run_case "import: an output inside its images folder" error none.out -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv -o imp/out.rawlog

# Readers: no FIFO, no time that is not decimal seconds, no image too large to decode.
mkfifo odometry.fifo
run_case "import: the odometry is a FIFO" error imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv --odometry odometry.fifo -o imp.rawlog
mkdir -p imp_fifo && cp imp/100.0.jpg imp_fifo/ && mkfifo imp_fifo/100.4.jpg
run_case "import: a FIFO named like an image" "error:not a regular file" imp.rawlog -- "$apps/omnirange-import" -q --images imp_fifo --laser imp_laser.csv -o imp.rawlog
mkfifo world.fifo
run_case "sim: the world file is a FIFO" error sim.rawlog -- "$apps/omnirange-sim" -q -w world.fifo -r w.route -o sim.rawlog
printf '100.0, 1, 2, 3\n1e300, 1, 2, 3\n' > imp_far.csv
run_case "import: a laser time of 1e300" error imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_far.csv -o imp.rawlog
head -c 3000000 /dev/zero | tr '\0' '7' > imp_endless.csv
run_case "import: a laser log of one 3 MB line" error imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_endless.csv -o imp.rawlog
mkdir -p imp_hex && cp imp/100.0.jpg imp_hex/0x10.jpg
run_case "import: an image named 0x10.jpg" error imp.rawlog -- "$apps/omnirange-import" -q --images imp_hex --laser imp_laser.csv -o imp.rawlog
printf '\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x4e\x20\0\0\x4e\x20\x08\x02\0\0\0\0\0\0\0\0\0\0\0IEND\xae\x42\x60\x82' > huge.png
run_case "calibrate: a checkerboard image of 20000 x 20000 px" error none.out -- "$apps/omnirange-calibrate" -q --checkerboard huge.png --board 8x6
# omnirange-slam's [ICP] section, read as strictly as every ini of ours.
sed 's/^maxIterations *=.*/maxIterations = abc/' "$src/ini/icp-slam-omniscan.ini" > icp_abc.ini
run_case "slam: [ICP] maxIterations = abc" error slam_out -- "$apps/omnirange-slam" -q -i s.rawlog -c icp_abc.ini -o slam_out
sed 's/^thresholdDist *=.*/thresholdDist = 0.2m/' "$src/ini/icp-slam-omniscan.ini" > icp_unit.ini
run_case "slam: [ICP] thresholdDist = 0.2m" error slam_out -- "$apps/omnirange-slam" -q -i s.rawlog -c icp_unit.ini -o slam_out
# The tuner: what would make every frame fail is one line before any window (no display needed).
run_case "tuner: the rawlog's images folder is missing" "error:images folder" none.out -- "$apps/omnirange-tuner" -i noimages.rawlog -c f.ini -H floor.hist
run_case "tuner: images of another size than the ini's camera" "error:but the camera is 640x768" none.out -- "$apps/omnirange-tuner" -i s.rawlog -c width_small.ini -H floor.hist
# Calibration that is not sure says so and saves nothing (real images, made by others).
real="$src/../shared/data/real/mei-paraboloid"
if [ -d "$real" ]; then
  run_case "calibrate: 5 boards that leave the centre 3.1 px loose" "error:may be wrong" cal.ini -- "$apps/omnirange-calibrate" -q \
    --save-to cal.ini $(for i in 1 3 5 7 9; do echo --checkerboard "$real/img_para_00$i.pgm"; done)
fi
# What an independent hostile run found: each class once.
run_case "tuner: --save-to the histogram it reads" "error:is the input" none.out -- "$apps/omnirange-tuner" -i s.rawlog -c f.ini -H floor.hist --save-to floor.hist
run_case "train: --learn into the base of the -c ini" "error:is the input" none.out -- "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o other.hist --learn experiment-base.ini
run_case "slam: -o the input's images folder" "error:is the input" none.out -- "$apps/omnirange-slam" -q -i s.rawlog -c "$src/ini/icp-slam-omniscan.ini" -o s_Images
cp s.rawlog ro.rawlog && chmod 444 ro.rawlog
run_case "scan: -o a read-only rawlog" "error:read-only" none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o ro.rawlog
ln -f s.rawlog hard.rawlog
run_case "scan: -o a hard link to its input" "error:is the input" none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o hard.rawlog
run_case "train: --learn and --learn-candidates the same file" "error:same place" same.ini -- "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o other.hist --learn same.ini --learn-candidates same.ini
variant no_equals 'threshold 0.05'
run_case "scan: an ini line without '='" "error:is not 'key = value'" out.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c no_equals.ini -H floor.hist -o out.rawlog
variant case_twice 'threshold = 0.05' 'Threshold = 0.2'
run_case "scan: a key repeated in another case" "error:repeats" out.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c case_twice.ini -H floor.hist -o out.rawlog
: > empty_robot.ini
run_case "sim: an empty robot ini" "error:holds no key" o.rawlog -- "$apps/omnirange-sim" -q -w w.world -r w.route -c empty_robot.ini -n 2 -o o.rawlog
{ printf 'P5\n12000 10000\n255\n'; head -c 1000 /dev/zero; } > big.pgm
run_case "calibrate: a PGM of 12000 x 10000 px" "error:more than 100 megapixels" none.out -- "$apps/omnirange-calibrate" -q --rim big.pgm
run_case "accuracy: -o . (a folder, not a prefix)" "error:is a folder" none.out -- "$apps/omnirange-accuracy" -q -i s.rawlog -o .
printf '100.0, 1e300, 0, 0\n100.4, 1, 0, 0\n' > imp_odo_far.csv
run_case "import: odometry at x = 1e300" "error:odometry at time" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv --odometry imp_odo_far.csv -o imp.rawlog
printf '100.0, 0, 0, 0\n100.1, 100, 0, 0\n100.2, 200, 0, 0\n100.4, 400, 0, 0\n' > imp_odo_mm.csv
run_case "import: odometry in millimetres (1000 m/s)" "error:x and y in millimetres" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv --odometry imp_odo_mm.csv -o imp.rawlog
printf '100.0, 0, 0, 0\n100.1, 0, 0, 45\n100.2, 0, 0, 90\n100.4, 0, 0, 180\n' > imp_odo_deg.csv
run_case "import: odometry heading in degrees" "error:the heading in degrees" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv --odometry imp_odo_deg.csv -o imp.rawlog
printf '100.0, 0x10, 2, 3\n100.4, 1, 2, 3\n' > imp_hexrange.csv
run_case "import: a laser range written 0x10" "error:hexadecimal" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_hexrange.csv -o imp.rawlog
{ printf 'P5\n640 480\n255\n'; head -c 5000 /dev/zero; } > cut.pgm
run_case "calibrate: a PGM cut short" "error:fewer pixels than its header says" none.out -- "$apps/omnirange-calibrate" -q --rim cut.pgm
run_case "calibrate: --board 99999x99999" "error:inner corners each way" none.out -- "$apps/omnirange-calibrate" -q --checkerboard cut.pgm --board 99999x99999
run_case "experiment: -n -1" "error:at least 1 frame" none.out -- "$apps/omnirange-experiment" -q "$src/ini/factory.ini" -n -1 -o exp_neg
# What a second hostile run found.
run_case "calibrate: --save-to the base of its -c ini" "error:is the input" none.out -- "$apps/omnirange-calibrate" -q -i s.rawlog -c f.ini -H floor.hist --save-to experiment-base.ini
run_case "import: -o the base of its -c ini, --force" "error:is the input" none.out -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv -c f.ini -o experiment-base.ini --force
printf 'base = %s\n[experiment]\nname = ../../userlog\n' "$src/ini/factory.ini" > escape.ini
run_case "experiment: a name that leads out of the report" "error:plain name" none.out -- "$apps/omnirange-experiment" -q escape.ini -n 5 -o exp_escape
run_case "experiment: -o ''" "error:names no file" none.out -- "$apps/omnirange-experiment" -q "$src/ini/factory.ini" -n 5 -o ''
variant pose_far 'pose_x = 50'
"$apps/omnirange-scan" -q -i s.rawlog -c pose_far.ini -H floor.hist -o pose_far.rawlog
run_case "accuracy: a scan no laser ray can be compared with" "error:could be compared" acc_far_pairs.csv -- "$apps/omnirange-accuracy" -q -i pose_far.rawlog -o acc_far
run_case "train: --learn ''" "error:names no file" none.out -- "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o other.hist --learn ''
run_case "scan: a rawlog that already holds OMNISCAN scans" "error:already holds" out2.rawlog -- "$apps/omnirange-scan" -q -i pose_far.rawlog -c f.ini -H floor.hist -o out2.rawlog
# What a third hostile run found.
mkdir -p deep/inner && ln -sfn deep/inner imgs && cp f.ini deep/f2.ini && cp experiment-base.ini deep/
run_case "train: --learn onto its -c ini through a link and '..'" "error:is the input" none.out -- "$apps/omnirange-train" -q -i s.rawlog -c deep/f2.ini -o other.hist --learn imgs/../f2.ini
mkdir -p photos && echo mine > photos/p.txt && ln -sfn photos usr_Images
run_case "sim: a user's link named like the output's images" "error:did not write" none.out -- "$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -o usr.rawlog
if [ -d "$real" ]; then
  run_case "calibrate: one image given twice" "error:given twice" none.out -- "$apps/omnirange-calibrate" -q \
    --checkerboard "$real/img_para_001.pgm" --checkerboard "$real/img_para_002.pgm" --checkerboard "$real/img_para_001.pgm"
fi
printf 'a\n<!-- table: truth -->\nold\n<!-- table: maps -->\nx\n<!-- end table -->\n' > nested.md
run_case "summary: a table block left open before the next" "error:nested.md: a table block" none.out -- "$apps/omnirange-summary" -q --csv "$src/docs/results/suite.csv" --fill nested.md
run_case "summary: -o with --fill (it would be ignored)" "error:with --fill: --fill makes" none.out -- "$apps/omnirange-summary" -q --csv "$src/docs/results/suite.csv" --fill nested.md -o sumout
run_case "import: --images and --image-list both" "error:not both" imp.rawlog -- "$apps/omnirange-import" -q --images imp --image-list imp_list.csv --laser imp_laser.csv -o imp.rawlog
mkdir -p gmap && cp "$src/rawlogs/factory-sample_truemap.gridmap.gz" gmap/gm_truemap.gridmap.gz
printf 'omnirange-world 1\nname g\ngridmap file=gm_truemap.gridmap.gz z1=2 material=brick\n' > gmap/g.world
run_case "sim: the world's grid map as the output's true map" "error:is the input" none.out -- "$apps/omnirange-sim" -q -w gmap/g.world -r "$src/worlds/campus.route" -n 2 -o gmap/gm.rawlog
# After a fourth independent hostile run.
run_case "accuracy: --max-difference 1e20" "error:max_difference must be within" acc4_pairs.csv -- "$apps/omnirange-accuracy" -q -i s.rawlog -o acc4 --max-difference 1e20
variant pose_far 'pose_x = 1e308'
run_case "scan: [rangefinder] pose_x = 1e308" "error:not within" far.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c pose_far.ini -H floor.hist -o far.rawlog
sed 's/^sigma_dist *=.*/sigma_dist = 1e308/' "$src/ini/robot-omnip2dx.ini" > robot_sigma.ini
run_case "sim: robot [odometry] sigma_dist = 1e308" "error:sigma_dist" r4.rawlog -- "$apps/omnirange-sim" -q -w w.world -r w.route -c robot_sigma.ini -n 2 -o r4.rawlog
sed 's/^speed *=.*/speed = 1e-300/' "$src/ini/robot-omnip2dx.ini" > robot_slow.ini
run_case "sim: robot [robot] speed = 1e-300" "error:speed must be within" r4.rawlog -- "$apps/omnirange-sim" -q -w w.world -r w.route -c robot_slow.ini -n 2 -o r4.rawlog
sed -e 's/^image_width *=.*/image_width = 11000/' -e 's/^image_height *=.*/image_height = 10000/' "$src/ini/robot-omnip2dx.ini" > robot_big.ini
run_case "sim: a camera of 110 megapixels" "error:100 megapixels" r4.rawlog -- "$apps/omnirange-sim" -q -w w.world -r w.route -c robot_big.ini -n 2 -o r4.rawlog
{ printf '0 0\n# '; head -c 2000000 /dev/zero | tr '\0' x; printf '\n1 0\n'; } > long.route
run_case "sim: a route line of 2 MB" "error:a line of more than 1 MB" r4.rawlog -- "$apps/omnirange-sim" -q -w w.world -r long.route -n 2 -o r4.rawlog
sed 's/^thresholdDist *=.*/thresholdDist = 1e200/' "$src/ini/icp-slam-omniscan.ini" > icp_huge.ini
run_case "slam: [ICP] thresholdDist = 1e200" "error:icp_huge.ini" slam_out -- "$apps/omnirange-slam" -q -i s.rawlog -c icp_huge.ini -o slam_out
sed 's/^maxIterations *=.*/maxIterations = 1.9/' "$src/ini/icp-slam-omniscan.ini" > icp_frac.ini
run_case "slam: [ICP] maxIterations = 1.9" "error:not a whole number" slam_out -- "$apps/omnirange-slam" -q -i s.rawlog -c icp_frac.ini -o slam_out
{ printf 'threshold = 0.01\n'; cat f.ini; } > above.ini
run_case "scan: a key above every section" "error:above every" above.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c above.ini -H floor.hist -o above.rawlog
run_case "scan: a rawlog given as the ini" "error:is it an ini file" bin.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c s.rawlog -H floor.hist -o bin.rawlog
run_case "train: -n with --learn (learning would read every pair)" "error:is not read by --learn" t4.hist -- "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o t4.hist -n 8 --learn t4.ini
printf 'not a CARMEN log\n' > notcarmen.log
run_case "import: --carmen with no CARMEN message" "error:no CARMEN" imp4.rawlog -- "$apps/omnirange-import" -q --images imp --carmen notcarmen.log -o imp4.rawlog
mkfifo fill.fifo
run_case "summary: --fill a FIFO" "error:not a regular file" none.out -- "$apps/omnirange-summary" -q --csv "$src/docs/results/suite.csv" --fill fill.fifo
long_name=$(printf 'c%.0s' $(seq 249)).rawlog
run_case "scan: an output name of 256 characters" "error:(File name too long)" none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o "$long_name"
run_case "scan: a line break in the output's name (a marker would list another file)" "error:has a control character" none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o $'nl\nfile f.ini.rawlog'
run_case "accuracy: a prefix of 250 characters (names each output it would make)" "error:_pairs.csv' (File name too long)" none.out -- "$apps/omnirange-accuracy" -q -i scanned.rawlog -o "$(printf 'c%.0s' $(seq 250))"
# Sparse files: large to a reader, nothing on the disk.
cp floor.hist big.hist && truncate -s 1G big.hist
run_case "scan: -H a 1 GB file that begins as a histogram" "error:more than the" none.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H big.hist -o none.rawlog
truncate -s 1G big.md
run_case "summary: --fill a 1 GB file" "error:more than a page of tables" none.out -- "$apps/omnirange-summary" -q --csv "$src/docs/results/suite.csv" --fill big.md
printf '# my notes\n' > notable.md
run_case "summary: --fill a file with no table block" "error:no table block" none.out -- "$apps/omnirange-summary" -q --csv "$src/docs/results/suite.csv" --fill notable.md
mkdir -p figs
run_case "summary: -o a folder (hidden files)" "error:is a folder" none.out -- "$apps/omnirange-summary" -q --csv "$src/docs/results/suite.csv" -s "$src/ini/suite.txt" -o figs/
run_case "train: --figures a folder (hidden files)" "error:is a folder" t4.hist -- "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o t4.hist --figures figs/
run_case "calibrate: -i with --rim (it would be ignored)" "error:read by the calibration against a laser only" none.out -- "$apps/omnirange-calibrate" -q --rim "s_Images/$(ls s_Images | head -1)" -i s.rawlog
run_case "calibrate: -o with --rim (it would be ignored)" "error:checkerboard calibration only" rim.yaml -- "$apps/omnirange-calibrate" -q --rim "s_Images/$(ls s_Images | head -1)" -o rim.yaml
echo mine > users_pairs.csv && echo mine > notes.md && printf '; mine\n[rangefinder]\nN = 10\n' > hand.ini && cp hand.ini hand.ini.orig
run_case "accuracy: -o onto a user's CSV of that name" "error:not what omnirange-accuracy writes" none.out -- "$apps/omnirange-accuracy" -q -i s.rawlog -o users
run_case "summary: -o onto a user's notes.md" "error:not what omnirange-summary writes" none.out -- "$apps/omnirange-summary" -q --csv "$src/docs/results/suite.csv" -s "$src/ini/suite.txt" -o notes
run_case "train: --learn onto a hand-written ini" "error:not what omnirange-train writes" t4.hist -- "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o t4.hist --learn hand.ini
kept users_pairs.csv notes.md
cmp -s hand.ini hand.ini.orig || { echo "| | PROBLEM: the user's hand.ini was changed |"; problems=$((problems + 1)); }
ln -sfn nodir/x.rawlog dangling.rawlog
run_case "scan: -o a link to nothing" "error:which does not exist" none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o dangling.rawlog
[ -L dangling.rawlog ] || { echo "| | PROBLEM: the user's link dangling.rawlog was replaced |"; problems=$((problems + 1)); }
# After a fifth: one program's rawlog images are not another's to replace.
"$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -o simd.rawlog
run_case "scan: -o over a simulated dataset (its images)" "error:is what omnirange-sim wrote, not omnirange-scan" none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o simd.rawlog
[ "$(ls simd_Images | grep -c OMNICAM)" = 2 ] || { echo "| | PROBLEM: the simulated dataset's images were replaced |"; problems=$((problems + 1)); }
sed 's/^\[ICP\]/[IPC]/' "$src/ini/icp-slam-omniscan.ini" > icp_ipc.ini
run_case "slam: a misspelt section [IPC]" "error:unknown section \[IPC\]" slam_out -- "$apps/omnirange-slam" -q -i s.rawlog -c icp_ipc.ini -o slam_out
sed 's/^ALFA *=.*/ALFA = 1/' "$src/ini/icp-slam-omniscan.ini" > icp_alfa.ini
run_case "slam: [ICP] ALFA = 1 (MRPT asserts below 1)" "error:ALFA" slam_out -- "$apps/omnirange-slam" -q -i s.rawlog -c icp_alfa.ini -o slam_out
head -1 "$src/docs/results/suite.csv" > header_only.csv && cp notable.md tables.md && printf '<!-- table: truth -->\nx\n<!-- end table -->\n' >> tables.md
run_case "summary: --fill from a CSV with no experiment" "error:no experiment in it" none.out -- "$apps/omnirange-summary" -q --csv header_only.csv --fill tables.md
{ cat f.ini; printf '\n[other]\n'; for i in $(seq 1 120000); do echo "k$i = 1"; done; } > big.ini
run_case "scan: an ini of more than 1 MB" "error:larger than 1 MB" big.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c big.ini -H floor.hist -o big.rawlog
if [ -d "$real" ]; then
  mkdir -p boards && cp "$real/img_para_001.pgm" "$real/img_para_003.pgm" "$real/img_para_004.pgm" boards/
  run_case "calibrate: -o inside its --checkerboard-dir" "error:inside the input" boards/intr.yaml -- "$apps/omnirange-calibrate" -q --checkerboard-dir boards --board 8x6 --square 0.042 -o boards/intr.yaml --accept
fi
# After a sixth: damaged data that decodes, values without a bound, copies of one view.
mkdir -p midcut && cp s.rawlog midcut.rawlog && cp s_Images/* midcut/ && f=$(ls midcut | sort | sed -n 3p)
size=$(stat -c %s "midcut/$f") && { head -c $((size / 3)) "midcut/$f"; tail -c $((size / 3)) "midcut/$f"; } > midcut.jpg
mkdir -p midcut_Images && cp s_Images/* midcut_Images/ && cp midcut.jpg "midcut_Images/$f"
run_case "scan: a JPEG cut in the middle (its end marker kept)" "error:is damaged" mc.rawlog -- "$apps/omnirange-scan" -q -i midcut.rawlog -c f.ini -H floor.hist -o mc.rawlog
variant azimuth_huge 'forward_azimuth_deg = 1e308'
run_case "scan: forward_azimuth_deg = 1e308" "error:forward_azimuth_deg = '1e308'" az.rawlog -- "$apps/omnirange-scan" -q -i s.rawlog -c azimuth_huge.ini -H floor.hist -o az.rawlog
run_case "import: --laser-max-range 1e308" "error:max range" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv --laser-max-range 1e308 -o imp.rawlog
printf '1000.0, 1.5, 2.5, 3.5\n1000.4, 1.5, 2.5, 3.5\n' > imp_far.csv
run_case "import: a laser log with no time in common with the images" "error:no time in common" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_far.csv -o imp.rawlog
printf '[rangefinder]\nthresold = 0.1\n' > typo_save.ini && cp typo_save.ini typo_save.ini.orig
printf '#direct\n3 -96 0 0.0026\n#inverse\n2 1 1\n#center\n380 515\n#affine\n1 0 0\n#size\n768 1024\n' > good_calib.txt
run_case "calibrate: --save-to an ini with a misspelt key" "error:unknown key 'thresold'" none.out -- "$apps/omnirange-calibrate" -q --ocamcalib good_calib.txt --save-to typo_save.ini
cmp -s typo_save.ini typo_save.ini.orig || { echo "| | PROBLEM: keys were added to an ini every program refuses |"; problems=$((problems + 1)); }
if [ -d "$real" ]; then
  mkdir -p same_view && for i in 1 2 3 4 5; do cp "$real/img_para_001.pgm" "same_view/copy$i.pgm"; done
  run_case "calibrate: five copies of one board image" "error:found in 1 of 5" same.yaml -- "$apps/omnirange-calibrate" -q --checkerboard-dir same_view --board 8x6 --square 0.042 -o same.yaml
fi
# After a seventh: outputs checked before the work, limits that end a run with a line, things given twice.
cp floor.hist kept.hist
run_case "train: --learn-candidates into a missing folder" "error:nodir/c.csv" new_learn.ini -- "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o kept.hist --learn new_learn.ini --learn-candidates nodir/c.csv
cmp -s kept.hist floor.hist || { echo "| | PROBLEM: the histogram was replaced by a run that failed |"; problems=$((problems + 1)); }
run_case "train: a file-size limit (ulimit -f) reached as it writes" "error:" fs.hist -- bash -c 'ulimit -f 20; exec "$@"' _ "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o fs.hist
{ cat w.world; printf "bounds xmin=-1 ymin=-1 xmax=1 ymax=1\n"; } > twobounds.world
run_case "sim: a world with its bounds given twice" "error:given a second time" tb.rawlog -- "$apps/omnirange-sim" -q -w twobounds.world -r w.route -n 2 -o tb.rawlog
mkdir -p imp_dir && cp imp/100.0.jpg imp_dir/ && mkdir -p imp_dir/100.4.jpg
run_case "import: a folder named like an image" "error:is not a regular file" imp.rawlog -- "$apps/omnirange-import" -q --images imp_dir --laser imp_laser.csv -o imp.rawlog
run_case "calibrate: --square 1e-300" "error:within \[0.001, 10\] m" none.out -- "$apps/omnirange-calibrate" -q --checkerboard tiny.pgm --board 8x6 --square 1e-300
"$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o scanned_by_scan.rawlog
run_case "sim: -o over a scan's output (its images)" "error:" none.out -- "$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -o scanned_by_scan.rawlog
[ "$(head -1 scanned_by_scan_Images/.omnirange-output)" = omnirange-scan ] || { echo "| | PROBLEM: the scan's images were replaced |"; problems=$((problems + 1)); }
cat s.rawlog s.rawlog > joined.rawlog && ln -sfn s_Images joined_Images
run_case "scan: two rawlogs joined (time runs back)" "error:before one read earlier" jn.rawlog -- "$apps/omnirange-scan" -q -i joined.rawlog -c f.ini -H floor.hist -o jn.rawlog
# After an eighth: a gzip file that is not a rawlog is not a rawlog's to replace; a laser that never returns.
mkdir -p tarsrc && echo mine > tarsrc/a.txt && tar czf backup.tar.gz tarsrc && cp backup.tar.gz backup.tar.gz.orig
run_case "scan: -o a user's .tar.gz (gzip, not a rawlog)" "error:exists and is not a rawlog" none.out -- "$apps/omnirange-scan" -q -i s.rawlog -c f.ini -H floor.hist -o backup.tar.gz
cmp -s backup.tar.gz backup.tar.gz.orig || { echo "| | PROBLEM: the user's backup.tar.gz was replaced |"; problems=$((problems + 1)); }
printf '100.0, 1000, 2000, 3000\n100.4, 1000, 2000, 3000\n' > imp_mm.csv
run_case "import: laser ranges in millimetres (no range within max range)" "error:ranges in millimetres" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_mm.csv --laser-max-range 10 -o imp.rawlog
mkdir -p .omnirange-K1lled && : > .omnirange-K1lled/.omnirange-commit && printf 'OMNIHIST' > .omnirange-K1lled/left.hist
"$apps/omnirange-train" -q -i s.rawlog -c f.ini -o left.hist
[ ! -e .omnirange-K1lled ] || { echo "| | PROBLEM: a killed run's staging folder was not cleaned |"; problems=$((problems + 1)); }
cp s.rawlog users_log.rawlog && ln -sfn users_log.rawlog gz_truemap.gridmap.gz
run_case "sim: its true map through a link onto a user's rawlog" "error:is not a grid map" gz.rawlog -- "$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -o gz.rawlog
cmp -s users_log.rawlog s.rawlog || { echo "| | PROBLEM: the user's rawlog behind gz_truemap.gridmap.gz was changed |"; problems=$((problems + 1)); }
{ head -10 w.world; printf "box x=0 y=0 w=1 d=1 z1=1 material=concrete x=5\n"; } > dupkey.world
run_case "sim: a key twice on one world line" "error:given twice" dk.rawlog -- "$apps/omnirange-sim" -q -w dupkey.world -r w.route -n 2 -o dk.rawlog
sed 's/^yaw_drift_deg *=.*/yaw_drift_deg = 1e300/' "$src/ini/robot-omnip2dx.ini" > robot_drift.ini
run_case "sim: robot [odometry] yaw_drift_deg = 1e300" "error:yaw_drift_deg" r4.rawlog -- "$apps/omnirange-sim" -q -w w.world -r w.route -c robot_drift.ini -n 2 -o r4.rawlog
{ head -10 w.world; printf "gridmap file=none.gz z1=2 material=concrete\n"; } > nomap.world
run_case "sim: a world's grid map that is missing" "error:grid map 'none.gz' is missing" nm.rawlog -- "$apps/omnirange-sim" -q -w nomap.world -r w.route -n 2 -o nm.rawlog
cp s.rawlog selflink.rawlog && ln -sfn selflink_Images selflink_Images
run_case "scan: an input's images folder that links to itself" "error:leads back to itself" sl.rawlog -- "$apps/omnirange-scan" -q -i selflink.rawlog -c f.ini -H floor.hist -o sl.rawlog
run_case "sim: -f bmp" "error:must be png or jpg, not" fb.rawlog -- "$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -f bmp -o fb.rawlog
printf 'P5\n3 2\n255\n\x01\x02\x03\x04\x05\x06' > tiny.pgm
run_case "calibrate: a 3 x 2 px checkerboard image" "error:too small to show a board" none.out -- "$apps/omnirange-calibrate" -q --checkerboard tiny.pgm --board 8x6
"$apps/omnirange-slam" -q -i s.rawlog -c "$src/ini/icp-slam-omniscan.ini" --label LASER -o slam_notes && echo mine > slam_notes/notes.txt
run_case "slam: -o its own earlier output, with a file the user added" "error:is not something omnirange-slam wrote" none.out -- "$apps/omnirange-slam" -q -i s.rawlog -c "$src/ini/icp-slam-omniscan.ini" --label LASER -o slam_notes
kept slam_notes/notes.txt
mkdir -p negpgm && printf 'P5\n-5 10\n255\n' > negpgm/100.0.pgm
run_case "import: a PGM whose header gives a negative width" "error:does not give a width and a height" negp.rawlog -- "$apps/omnirange-import" -q --images negpgm --laser imp_laser.csv -o negp.rawlog
# Damage libpng would print about, times past any pairing, one file given twice.
"$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -f png -o pngd.rawlog
f=$(ls pngd_Images | grep OMNICAM | sort | head -1) && size=$(stat -c %s "pngd_Images/$f")
printf '%*s' 64 '' | dd of="pngd_Images/$f" bs=1 seek=$((size / 2)) conv=notrunc status=none
run_case "scan: a PNG damaged inside (its end chunk kept)" "error:is damaged" pd.rawlog -- "$apps/omnirange-scan" -q -i pngd.rawlog -c f.ini -H floor.hist -o pd.rawlog
run_case "train: --max-dt 1e300" "error:max_dt must be within" md.hist -- "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o md.hist --max-dt 1e300
cp tables.md twice.md
run_case "summary: --fill one file twice" "error:is given twice" none.out -- "$apps/omnirange-summary" -q --csv "$src/docs/results/suite.csv" --fill twice.md --fill ./twice.md
mkfifo rawlog.fifo
scan "rawlog is a FIFO" "error:is not a regular file" -i rawlog.fifo -c f.ini -H floor.hist -o out.rawlog
# After a ninth: an MRPT program's log folder outside the report, a true map linked onto the rawlog, a failed run's folder with a user's file.
mkdir -p victim && echo mine > victim/note.txt
sed 's|^logOutput_dir = .*|logOutput_dir = '"$PWD"'/victim|' exp/ini/icp-slam-omniscan.ini > exp/ini/icp_victim.ini
printf 'base = factory.ini\n[experiment]\nname = v\nicp_omni_ini = icp_victim.ini\n' > exp/ini/exp_victim.ini
run_case "experiment: icp-slam's logOutput_dir a folder outside the report" "error:plain folder name" none.out -- "$apps/omnirange-experiment" -q exp/ini/exp_victim.ini -n 5 -o exp_victim
kept victim/note.txt
"$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -o lt.rawlog && rm lt_truemap.png && ln -s lt.rawlog lt_truemap.png && cp lt.rawlog lt.rawlog.orig
run_case "sim --force: its true map PNG a link to its rawlog" "error:in the same place" none.out -- "$apps/omnirange-sim" -q --force -w w.world -r w.route -n 3 -o lt.rawlog
cmp -s lt.rawlog lt.rawlog.orig || { echo "| | PROBLEM: the rawlog behind lt_truemap.png was changed |"; problems=$((problems + 1)); }
# A late failure (observations2map told to build no grid: a valid ini, so nothing refuses it before the work).
printf '[MappingApplication]\noccupancyGrid_count = 0\n' > exp/ini/nogrid.ini
printf 'base = factory.ini\n[experiment]\nname = f\nlearn = false\nmap_omni_ini = nogrid.ini\n' > exp/ini/few.ini
"$apps/omnirange-experiment" -q exp/ini/few.ini -n 10 -o few_report 2>/dev/null
run_case "experiment: fails again where a failed run kept its partial output" "error:maps with ground-truth poses" none.out -- "$apps/omnirange-experiment" -q exp/ini/few.ini -n 10 -o few_report
[ "$(ls -d .omnirange-* 2>/dev/null | wc -l)" -le 1 ] || { echo "| | PROBLEM: failed runs' partial outputs pile up |"; problems=$((problems + 1)); }
run_case "experiment: -n 5 with learn = true (one training pair)" "error:too few for learn = true" none.out -- "$apps/omnirange-experiment" -q exp/ini/factory.ini -n 5 -o early_report
! ls -d early_report* 2>/dev/null || { echo "| | PROBLEM: a run refused for too few frames left a folder |"; problems=$((problems + 1)); }
# After a tenth: a table filled from a CSV missing some of its rows.
head -3 "$src/docs/results/suite.csv" > two_rows.csv && cp "$src/README.md" readme_copy.md && cp readme_copy.md readme_copy.orig
run_case "summary: --fill from a CSV that lacks rows the table shows" "error:would lose its rows" none.out -- "$apps/omnirange-summary" -q --csv two_rows.csv --fill readme_copy.md
cmp -s readme_copy.md readme_copy.orig || { echo "| | PROBLEM: readme_copy.md was changed by a refused fill |"; problems=$((problems + 1)); }
# After a fourteenth: another user's output in a sticky folder (as /tmp), an old output that cannot be
# removed whole. Both need a user other than root: root runs them as nobody, if nobody can read here.
nobody=(setpriv --reuid=65534 --regid=65534 --clear-groups)
if [ "$(id -u)" -eq 0 ] && "${nobody[@]}" test -r f.ini -a -r s_Images 2>/dev/null; then
  mkdir -m 1777 sticky && cp floor.hist sticky/f.hist && chmod 666 sticky/f.hist
  run_case "train: another user's histogram in a sticky folder" "error:belongs to another user" none.out -- "${nobody[@]}" "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o sticky/f.hist
  cmp -s sticky/f.hist floor.hist || { echo "| | PROBLEM: another user's sticky/f.hist was changed |"; problems=$((problems + 1)); }
  mkdir -m 777 ro_old && "${nobody[@]}" "$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -o ro_old/d.rawlog && chmod a-w ro_old/d_Images
  run_case "sim: its old images folder read-only" "error:is read-only" none.out -- "${nobody[@]}" "$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -o ro_old/d.rawlog
  "$apps/omnirange-scan" -q -i ro_old/d.rawlog -c f.ini -H floor.hist -o ro_old_scan.rawlog || { echo "| | PROBLEM: the old rawlog and images refused a replacement are not read |"; problems=$((problems + 1)); }
  mkdir -m 666 no_search
  run_case "train: -o in a folder this user may not look in" "error:cannot reach the output" none.out -- "${nobody[@]}" "$apps/omnirange-train" -q -i s.rawlog -c f.ini -o no_search/t.hist
  chmod 755 no_search
fi
# After a fifteenth: an image that links to itself, a frame rate of almost nothing, a damaged class name.
cp s.rawlog selfimg.rawlog && mkdir -p selfimg_Images && cp s_Images/* selfimg_Images/
f=$(ls selfimg_Images | grep -v '^\.' | sort | sed -n 3p) && rm "selfimg_Images/$f" && ln -s "$f" "selfimg_Images/$f"
scan "an image that is a link to itself" "error:is a link that leads back to itself" -i selfimg.rawlog -c f.ini -H floor.hist -o out.rawlog
sed 's/^frame_rate *=.*/frame_rate = 1e-300/' "$src/ini/robot-omnip2dx.ini" > robot_slow.ini
run_case "sim: robot frame_rate = 1e-300" "error:frame_rate must be within" r5.rawlog -- "$apps/omnirange-sim" -q -w w.world -r w.route -c robot_slow.ini -n 2 -o r5.rawlog
gzip -dc s.rawlog | sed 's/CObservation2DRangeScan/CObservation2DRa\xffgeScan/' | gzip -c > badclass.rawlog && ln -sfn s_Images badclass_Images
scan "a rawlog with a byte of a class name damaged" "error:truncated or corrupt after" -i badclass.rawlog -c f.ini -H floor.hist -o out.rawlog
printf '100.0, 0, 0, 0\n100.2, 0.1, 0, 0\n100.2, 0.1, 0, 0\n100.4, 0.2, 0, 0\n' > odo_twice.csv
run_case "import: an odometry row logged twice" "error:the same row as the one before it" imp.rawlog -- "$apps/omnirange-import" -q --images imp --laser imp_laser.csv --odometry odo_twice.csv -o imp.rawlog
cp imp/100.0.jpg rim1.jpg && ln -sf rim1.jpg rim_again.jpg
run_case "calibrate: the same --rim image twice (once through a link)" "error:is given twice" cal.ini -- "$apps/omnirange-calibrate" -q --rim rim1.jpg --rim rim_again.jpg --save-to cal.ini
printf 'base = factory.ini\n[experiment]\nmap_omni_ini = icp-slam-omniscan.ini\n' > exp/ini/wrong_map.ini
run_case "experiment: map_omni_ini names an icp-slam ini" "error:it is an icp-slam ini" none.out -- "$apps/omnirange-experiment" -q exp/ini/wrong_map.ini -n 10 -o wrong_map
printf 'base = /proc/kmsg\n[rangefinder]\nN = 10\n' > kmsg.ini
scan "ini: a base that is a kernel file (/proc/kmsg blocks)" "error:is a file of the kernel's" -i s.rawlog -c kmsg.ini -H floor.hist -o out.rawlog
scan "ini: /proc/kmsg itself" "error:is a file of the kernel's" -i s.rawlog -c /proc/kmsg -H floor.hist -o out.rawlog
scan "rawlog: /proc/kmsg" "error:is a file of the kernel's" -i /proc/kmsg -c f.ini -H floor.hist -o out.rawlog
run_case "calibrate: --rim a kernel file (it reads as empty)" "error:is a file of the kernel's" cal.ini -- "$apps/omnirange-calibrate" -q --rim /proc/self/environ --save-to cal.ini
mkdir -p res_named/factory && printf '[metrics]\nframes = 10\n\n[report]\nexperiment = maze\n' > res_named/factory/metrics.ini
printf 'factory tuned the factory\n' > named_suite.txt
run_case "summary: a report of maze put where factory's belongs (-o res/factory)" "error:is a report of 'maze'" sum_named.md -- "$apps/omnirange-summary" -q -s named_suite.txt -r res_named -o sum_named
# A scan whose input is simulated again keeps the images it was made from (hard links, not the input's names).
"$apps/omnirange-sim" -q -w w.world -r w.route -n 2 -o resim.rawlog && "$apps/omnirange-scan" -q -i resim.rawlog -c f.ini -H floor.hist -o resim_scan.rawlog
scan_images() { (cd resim_scan_Images && md5sum -- *); }
scan_images_then=$(scan_images)
"$apps/omnirange-sim" -q -w w.world -r w.route -n 3 -o resim.rawlog
one=$(cd resim_scan_Images && ls | head -1)
{ [ "$(scan_images)" = "$scan_images_then" ] && [ "$(stat -c %i "resim_Images/$one")" != "$(stat -c %i "resim_scan_Images/$one")" ] &&
  "$apps/omnirange-train" -q -i resim_scan.rawlog -c f.ini -o rs.hist; } ||
  { echo "| | PROBLEM: a scan whose input was simulated again lost the images it was made from |"; problems=$((problems + 1)); }
# What MRPT reads otherwise than a check would, an ini whose base is gone, a link that leads back to itself.
sed 's/^maxIterations *=.*/maxIterations = 8e1/' "$src/ini/icp-slam-omniscan.ini" > icp_exp.ini
run_case "slam: [ICP] maxIterations = 8e1 (MRPT's atoi reads 8)" "error:written in digits" slam_out -- "$apps/omnirange-slam" -q -i s.rawlog -c icp_exp.ini -o slam_out
sed 's/^ALFA *=.*/ALFA = 0.999999/' "$src/ini/icp-slam-omniscan.ini" > icp_slow.ini
run_case "slam: [ICP] ALFA = 0.999999 (a match would take minutes)" "error:ALFA" slam_out -- "$apps/omnirange-slam" -q -i s.rawlog -c icp_slow.ini -o slam_out
mkdir -p nobase && printf 'base = experiment-base.ini\n[rangefinder]\nthreshold = 0.1\n' > nobase/cam.ini && cp nobase/cam.ini nobase/cam.orig
run_case "calibrate: --save-to an ini whose base is missing" "error:experiment-base.ini" none.out -- "$apps/omnirange-calibrate" -q --rim "s_Images/$(ls s_Images | head -1)" --save-to nobase/cam.ini
cmp -s nobase/cam.ini nobase/cam.orig || { echo "| | PROBLEM: an ini whose base is missing was written |"; problems=$((problems + 1)); }
mkdir -p imp_loop && cp imp/100.0.jpg imp_loop/ && ln -sfn 100.4.jpg imp_loop/100.4.jpg
run_case "import: an image that is a link to itself" "error:leads back to itself" il.rawlog -- "$apps/omnirange-import" -q --images imp_loop --laser imp_laser.csv -o il.rawlog
[ -L usr_Images ] && [ "$(cat usr_Images/p.txt)" = mine ] || { echo "| | PROBLEM: the user's link usr_Images was replaced |"; problems=$((problems + 1)); }
kept users_folder/note.txt users_file.txt
[ -n "$(ls s_Images)" ] || { echo "| | PROBLEM: the input's images were removed |"; problems=$((problems + 1)); }

chmod 755 readonly
echo
echo "$n cases, $problems problems"
[ $problems -eq 0 ]
