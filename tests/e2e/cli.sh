#!/usr/bin/env bash
# cli.sh: end-to-end tests of the command-line tool on the bundled models: outputs written and
# consistent with the JSON summary, deterministic for a seed, clear exit codes and messages for
# bad input, and no crash on any bundled model (poor ones included).
# usage: cli.sh PATH/TO/coverage-axis PATH/TO/tests/data
set -u
source "$(dirname "$0")/check.bash" "$@"

# 1. a normal run: files written, JSON consistent with the .ma header
"$tool" "$data/fox.obj" -o "$tmp/fox.ma" --obj "$tmp/fox.obj" --ply "$tmp/fox.ply" --json > "$tmp/fox.json" 2> "$tmp/err"
check "fox run exits 0" test $? -eq 0
check "fox .ma/.obj/.ply written" test -s "$tmp/fox.ma" -a -s "$tmp/fox.obj" -a -s "$tmp/fox.ply"
json_field() { grep -o "\"$1\":[^,}]*" "$2" | head -1 | cut -d: -f2; }
selected=$(json_field selected "$tmp/fox.json")
optimal=$(json_field optimal "$tmp/fox.json")
read -r nv ne nf < "$tmp/fox.ma"
check "JSON 'selected' equals the .ma vertex count ($selected vs $nv)" test "$selected" = "$nv"
check "fox cover is proven optimal" test "$optimal" = "true"
check ".ma has nv v lines" test "$(grep -c '^v ' "$tmp/fox.ma")" -eq "$nv"
check ".ma has ne e lines" test "$(grep -c '^e ' "$tmp/fox.ma")" -eq "$ne"
check ".ma has nf f lines" test "$(grep -c '^f ' "$tmp/fox.ma")" -eq "$nf"
check "JSON has per-stage times" grep -q '"time_s":{"read":[0-9.]*,"candidates":[0-9.]*,"select":[0-9.]*,"connect":[0-9.]*' "$tmp/fox.json"
check "stderr is empty when not a terminal" test ! -s "$tmp/err"

# 2. the same seed gives the same skeleton; another seed gives another sampling
"$tool" "$data/fox.obj" -o "$tmp/fox2.ma" --quiet
check "same seed, same skeleton" cmp -s "$tmp/fox.ma" "$tmp/fox2.ma"
"$tool" "$data/fox.obj" -o "$tmp/fox3.ma" --quiet --seed 7
differ() { ! cmp -s "$1" "$2"; }
check "another seed, another skeleton" differ "$tmp/fox.ma" "$tmp/fox3.ma"

# 3. units: a model scaled by 1000 gives the same skeleton scaled by 1000
awk '/^v /{printf "v %.17g %.17g %.17g\n", $2*1000, $3*1000, $4*1000; next} {print}' "$data/fox.obj" > "$tmp/fox_big.obj"
"$tool" "$tmp/fox_big.obj" -o "$tmp/fox_big.ma" --quiet
check "scaled model: same number of balls" test "$(head -1 "$tmp/fox_big.ma")" = "$(head -1 "$tmp/fox.ma")"
r_small=$(awk '/^v /{print $5; exit}' "$tmp/fox.ma")
r_big=$(awk '/^v /{print $5; exit}' "$tmp/fox_big.ma")
check "scaled model: radius scales ($r_small -> $r_big)" awk -v a="$r_small" -v b="$r_big" 'BEGIN{d=b-1000*a; if(d<0)d=-d; exit !(d < 1e-6*b)}'

# 4. options
"$tool" "$data/fox.obj" -o "$tmp/g.ma" --solver greedy --json > "$tmp/g.json"
check "greedy solver runs" test $? -eq 0
"$tool" "$data/fox.obj" -o "$tmp/p.ma" --effort prove --json > "$tmp/p.json"
check "prove effort runs and proves the fox's cover" grep -q '"optimal":true.*"effort":"prove"' "$tmp/p.json"
"$tool" "$data/fox.obj" -o "$tmp/fd.ma" --json > "$tmp/fd.json"
check "the default effort is fast" grep -q '"effort":"fast"' "$tmp/fd.json"
check "greedy uses at least as many balls as the optimum" test "$(json_field selected "$tmp/g.json")" -ge "$selected"
"$tool" "$data/fox.obj" -o "$tmp/r.ma" --candidates random:3000 --skip-uncoverable --export-candidates "$tmp/cand.obj" --export-samples "$tmp/s.obj" --quiet
check "random candidates run" test $? -eq 0
check "exported candidates have radii" awk 'NF!=5{exit 1}' "$tmp/cand.obj"
"$tool" "$data/fox.obj" -o "$tmp/f.ma" --surface-samples "$tmp/s.obj" --candidates "$tmp/cand.obj" --skip-uncoverable --json > "$tmp/f.json"
check "samples and candidates from files" test "$(json_field candidates "$tmp/f.json")" -eq "$(wc -l < "$tmp/cand.obj")"
"$tool" "$data/fox.obj" -o "$tmp/sc.ma" --scale 1.5 --skip-uncoverable --quiet
check "scale dilation runs" test $? -eq 0

# connection routes and the target size
for route in medial power; do
  "$tool" "$data/torus.obj" -o "$tmp/t_$route.ma" --connect $route --json > "$tmp/t.json"
  check "torus, $route route: one loop (b1 = 1)" test "$(json_field betti1 "$tmp/t.json")" -eq 1
  check "torus, $route route: connected" test "$(json_field components "$tmp/t.json")" -eq 1
  check "torus, $route route reported" grep -q "\"connect\":\"$route\"" "$tmp/t.json"
done
"$tool" "$data/fox.obj" -o "$tmp/k.ma" --target-count 30 --json > "$tmp/k.json"
check "target count: at most 30 balls" test "$(json_field selected "$tmp/k.json")" -le 30
check "target count: a larger delta than the default" awk -v d="$(json_field delta "$tmp/k.json")" -v d0="$(json_field delta "$tmp/fox.json")" 'BEGIN{exit !(d > d0)}'
check "target count: the HD reached is reported (the evaluation's)" test "$(json_field hd_reached "$tmp/k.json")" = "$(json_field hd_two_sided "$tmp/k.json")"
check "no target: hd_reached is null" test "$(json_field hd_reached "$tmp/fox.json")" = "null"

# the target error: the HD the library measured is what --evaluate measures, and within E
"$tool" "$data/fox.obj" -o "$tmp/te.ma" --samples 800 --voronoi-samples 2000 --target-error 2.6 --evaluate --json > "$tmp/te.json"
check "target error runs" test $? -eq 0
hd_te=$(json_field hd_reached "$tmp/te.json")
check "target error: HD reached $hd_te <= 2.6" awk -v h="$hd_te" 'BEGIN{exit !(h >= 0 && h <= 2.6)}'
check "target error: --evaluate measures the same HD" awk -v h="$hd_te" -v e="$(json_field hd_two_sided "$tmp/te.json")" 'BEGIN{d=h-e; if(d<0)d=-d; exit !(d < 1e-9)}'
check "target error: several probes" test "$(json_field probes "$tmp/te.json")" -ge 2
# searching further: a target the unfitted probes miss on the fox is reached by fitted ones, and
# the skeleton written is fitted as judged (its evaluation is the HD reached)
"$tool" "$data/fox.obj" -o "$tmp/tf.ma" --samples 800 --voronoi-samples 2000 --target-error 2.2 --evaluate --json > "$tmp/tf.json"
check "target error 2.2 on the fox: reached (exit 0)" test $? -eq 0
check "target error 2.2: target_reached true" grep -q '"target_reached":true' "$tmp/tf.json"
check "target error 2.2: the written skeleton is fitted" grep -q '"fit":{' "$tmp/tf.json"
check "target error 2.2: more than one search's probes" test "$(json_field probes "$tmp/tf.json")" -gt 14
check "target error 2.2: --evaluate measures the HD reached" awk -v h="$(json_field hd_reached "$tmp/tf.json")" -v e="$(json_field hd_two_sided "$tmp/tf.json")" 'BEGIN{d=h-e; if(d<0)d=-d; exit !(h <= 2.2 && d < 1e-9)}'
# a target no probe reaches: exit 4, the best skeleton written, the JSON says what was reached
"$tool" "$data/fox.obj" -o "$tmp/tn.ma" --samples 800 --voronoi-samples 2000 --target-error 0.01 --json > "$tmp/tn.json"
check "unreachable target error: exit 4" test $? -eq 4
check "unreachable target error: the best skeleton is written" test -s "$tmp/tn.ma"
check "unreachable target error: target_reached false" grep -q '"target_reached":false' "$tmp/tn.json"
check "unreachable target error: the status in the report" grep -q '"status":"CA_ERROR_TARGET_NOT_REACHED"' "$tmp/tn.json"
check "unreachable target error: the HD reached is above the target" awk -v h="$(json_field hd_reached "$tmp/tn.json")" 'BEGIN{exit !(h > 0.01)}'
check "unreachable target error: the message says what was reached" grep -q 'not reached: the lowest two-sided HD found is' "$tmp/tn.json"
check "target error reached: target_reached true" grep -q '"target_reached":true' "$tmp/te.json"
"$tool" "$data/fox.obj" -o "$tmp/te2.ma" --target-error 2 --target-count 30 --json > "$tmp/te2.json"
check "target error with target count: refused by the library (exit 1)" test $? -eq 1
check "target error with target count: INVALID_ARGUMENT naming both" grep -q 'CA_ERROR_INVALID_ARGUMENT.*target_error and target_count' "$tmp/te2.json"
"$tool" "$data/fox.obj" -o "$tmp/te3.ma" --target-error -1 --quiet 2> "$tmp/err"
check "negative target error: usage error (exit 2)" test $? -eq 2
"$tool" "$data/fox.obj" -o "$tmp/te4.ma" --target-error 2 --connect power --quiet 2> "$tmp/err"
check "target error with --connect power: usage error (exit 2)" test $? -eq 2
check "target error with --connect power: says why" grep -q 'default connection' "$tmp/err"
# with --fit the search measures fitted skeletons: the HD reached is that of the fitted .ma written
"$tool" "$data/fox.obj" -o "$tmp/tf.ma" --samples 800 --voronoi-samples 2000 --target-error 2.6 --fit --evaluate --json > "$tmp/tf.json"
check "target error with --fit runs" test $? -eq 0
hd_tf=$(json_field hd_reached "$tmp/tf.json")
check "target error with --fit: HD reached $hd_tf <= 2.6" awk -v h="$hd_tf" 'BEGIN{exit !(h >= 0 && h <= 2.6)}'
check "target error with --fit: --evaluate measures the same HD" awk -v h="$hd_tf" -v e="$(json_field hd_two_sided "$tmp/tf.json")" 'BEGIN{d=h-e; if(d<0)d=-d; exit !(d < 1e-9)}'
check "target error with --fit: the skeleton was fitted" grep -q '"error_after"' "$tmp/tf.json"

# divide and conquer on request: spatial parts, still a full cover
"$tool" "$data/fox.obj" -o "$tmp/dc.ma" --samples 3000 --divide 1000 --json > "$tmp/dc.json"
check "--divide 1000 on 3000 samples: split into parts" test "$(json_field parts "$tmp/dc.json")" -ge 2
check "--divide: every sample covered" test "$(json_field uncovered "$tmp/dc.json")" -eq 0
check "default: no parts at 1500 samples" test "$(json_field parts "$tmp/fox.json")" -eq 0

# user control: forced-in / forced-out balls and ignorable samples are honoured
"$tool" "$data/fox.obj" -o "$tmp/u0.ma" --export-candidates "$tmp/fc.obj" --quiet
echo "0 1 2" > "$tmp/in.txt"
"$tool" "$data/fox.obj" -o "$tmp/u1.ma" --force-in "$tmp/in.txt" --quiet
for i in 0 1 2; do
  ball=$(sed -n "$((i + 1))p" "$tmp/fc.obj" | cut -d' ' -f2-5)
  check "forced-in ball $i is in the skeleton" grep -qF "v $ball" "$tmp/u1.ma"
done
grep '^v ' "$tmp/u0.ma" | head -3 | while read -r _ x y z r; do grep -nF "v $x $y $z $r" "$tmp/fc.obj" | head -1 | cut -d: -f1; done | awk '{print $1-1}' > "$tmp/out.txt"
"$tool" "$data/fox.obj" -o "$tmp/u2.ma" --force-out "$tmp/out.txt" --skip-uncoverable --quiet
check "forced-out run succeeds" test $? -eq 0 -a -s "$tmp/u2.ma" -a "$(wc -l < "$tmp/out.txt")" -eq 3
while read -r i; do
  ball=$(sed -n "$((i + 1))p" "$tmp/fc.obj" | cut -d' ' -f2-5)
  check "forced-out ball $i is not in the skeleton" test -z "$(grep -F "v $ball" "$tmp/u2.ma")"
done < "$tmp/out.txt"
seq 0 1499 > "$tmp/all.txt"
"$tool" "$data/fox.obj" -o "$tmp/u3.ma" --ignore-samples "$tmp/all.txt" --json > "$tmp/u3.json"
check "every sample ignorable: nothing to cover" test "$(json_field selected "$tmp/u3.json")" -eq 0
echo 99999 > "$tmp/bad.txt"
"$tool" "$data/fox.obj" -o "$tmp/u4.ma" --force-in "$tmp/bad.txt" --quiet 2> "$tmp/err"
check "out-of-range ball index is a clear failure" test $? -eq 3 -a -s "$tmp/err"

# oriented point cloud input
"$tool" "$data/fish_points.xyz" -o "$tmp/pc.ma" --json --time-limit 120 > "$tmp/pc.json"
check "point cloud run exits 0" test $? -eq 0
check "point cloud skeleton has balls" test "$(json_field selected "$tmp/pc.json")" -ge 5
check "point cloud skeleton is connected" test "$(json_field components "$tmp/pc.json")" -eq 1
check "point cloud: JSON names the normals used (given)" test "$(json_field normals "$tmp/pc.json")" = '"given"'
# the readers' point-cloud forms, and which normals each run used
for f in fish500.xyz:given fish500.ply:given fish500.obj:given fish500_nonormals.xyz:estimated \
         fish500_nonormals.ply:estimated fish500_nonormals.obj:estimated fish500.pts:estimated fish500_plain.pts:estimated; do
  "$tool" "$data/formats/${f%%:*}" -o "$tmp/pcf.ma" --json --time-limit 120 > "$tmp/pcf.json"
  check "${f%%:*}: a point cloud with normals ${f##*:}" test "$(json_field input_triangles "$tmp/pcf.json") $(json_field normals "$tmp/pcf.json")" = "0 \"${f##*:}\""
done
"$tool" "$data/formats/fish500_nonormals.xyz" -o "$tmp/pcf.ma" --time-limit 120 > "$tmp/pcf.txt"
check "the summary says the normals were estimated" grep -q '^normals     estimated by PCA and oriented (the file has none)' "$tmp/pcf.txt"
"$tool" "$data/fish_points.xyz" -o "$tmp/pce.ma" --json --normals estimate --time-limit 120 > "$tmp/pce.json"
check "--normals estimate: the report says estimated" grep -q '"normals":"estimated"' "$tmp/pce.json"
"$tool" "$data/fox.obj" -o "$tmp/m.ma" --json --samples 300 > "$tmp/m.json"
check "a mesh has no point normals" grep -q '"normals":"none"' "$tmp/m.json"

# 5. evaluation: of our own skeleton and as a separate command on the written .ma
"$tool" "$data/fox.obj" -o "$tmp/e.ma" --evaluate --json > "$tmp/e.json"
check "--evaluate runs" test $? -eq 0
check "--evaluate adds the Hausdorff distances" grep -q '"hd_two_sided":[0-9.]*' "$tmp/e.json"
"$tool" evaluate "$data/fox.obj" "$tmp/e.ma" --json > "$tmp/e2.json"
check "evaluate command runs" test $? -eq 0
# the .ma holds 9 significant digits, so the two agree to about that
check "evaluate command gives the same two-sided distance" awk -v a="$(json_field hd_two_sided "$tmp/e.json")" -v b="$(json_field hd_two_sided "$tmp/e2.json")" 'BEGIN{d=a-b; if(d<0)d=-d; exit !(a > 0 && d < 1e-6*a)}'
printf '2 0 0\nv 0 0 0 1\n' > "$tmp/bad.ma"
"$tool" "$data/fox.obj" -o "$tmp/f.ma" --fit --evaluate --json > "$tmp/f.json"
check "--fit runs" test $? -eq 0
check "--fit keeps the balls and edges" test "$(json_field selected "$tmp/f.json") $(json_field edges "$tmp/f.json")" = "$(json_field selected "$tmp/e.json") $(json_field edges "$tmp/e.json")"
check "--fit moves the balls" bash -c "! cmp -s '$tmp/e.ma' '$tmp/f.ma'"
# the thorough fit keeps the better of two fits by the evaluator at its defaults (what --evaluate runs)
"$tool" "$data/fox.obj" -o "$tmp/ft.ma" --fit-thorough --evaluate --json > "$tmp/ft.json"
check "--fit-thorough runs" test $? -eq 0
check "--fit-thorough is no farther than --fit" awk -v t="$(json_field hd_two_sided "$tmp/ft.json")" -v f="$(json_field hd_two_sided "$tmp/f.json")" 'BEGIN{exit !(t > 0 && t <= f + 1e-9)}'
check "--fit-thorough keeps the balls and edges" test "$(json_field selected "$tmp/ft.json") $(json_field edges "$tmp/ft.json")" = "$(json_field selected "$tmp/e.json") $(json_field edges "$tmp/e.json")"
# the covered fit keeps the cover (the fit's own count of uncovered samples is 0) with added balls
"$tool" "$data/fox.obj" -o "$tmp/fc.ma" --fit-covered --evaluate --json > "$tmp/fc.json"
check "--fit-covered runs" test $? -eq 0
check "--fit-covered leaves no sample uncovered" test "$(grep -o '"fit":{[^}]*}' "$tmp/fc.json" | grep -o '"uncovered":[0-9]*' | cut -d: -f2)" = 0
check "--fit-covered adds balls on the fox" test "$(json_field selected "$tmp/fc.json")" -gt "$(json_field selected "$tmp/e.json")"
"$tool" evaluate "$data/fox.obj" "$tmp/bad.ma" > /dev/null 2> "$tmp/err"
check "evaluate: a malformed .ma is a clear failure" test $? -eq 3 -a -s "$tmp/err"

# 6. bad input: clear message, documented exit code, no partial output
expect_fail() {  # expect_fail CODE PATTERN args...
  local code=$1 pattern=$2; shift 2
  "$tool" "$@" > "$tmp/out" 2> "$tmp/err"
  local got=$?
  check "exit $code for: $*" test "$got" -eq "$code"
  check "message matches '$pattern' for: $*" grep -qi -- "$pattern" "$tmp/err"
  check "one-line message for: $*" test "$(wc -l < "$tmp/err")" -eq 1
}
expect_fail 3 "no such file\|cannot open" "$tmp/missing.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > "$tmp/badindex.obj"
expect_fail 3 "out of range" "$tmp/badindex.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 nan\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n' > "$tmp/nan.obj"
expect_fail 1 "nan" "$tmp/nan.obj" -o "$tmp/nan.ma"
check "no output after a failure" test ! -e "$tmp/nan.ma"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n' > "$tmp/flat.obj"
# a flat square is a sheet: its skeleton is made of surface balls on it (radius 0 in the .ma)
"$tool" "$tmp/flat.obj" -o "$tmp/flat.ma" --json > "$tmp/flat.json"
check "a flat mesh gives a skeleton of surface balls" python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
assert j['surface_balls'] == j['selected'] > 0 and j['medial_balls'] == 0 and j['open_parts'] == 1 and j['faces'] > 0
v = [l.split() for l in open(sys.argv[2]) if l.startswith('v ')]
assert len(v) == j['selected'] and all(float(x[4]) == 0 and float(x[3]) == 0 for x in v)
" "$tmp/flat.json" "$tmp/flat.ma"
"$tool" "$tmp/flat.obj" -o "$tmp/flat.ma" > "$tmp/flat.txt"
check "the summary counts the surface balls and open parts" grep -q "0 medial and [0-9]* surface balls.*1 open part" "$tmp/flat.txt"
expect_fail 1 "volumetric-only" "$tmp/flat.obj" --volumetric-only
: > "$tmp/empty.obj"
expect_fail 3 "no vertices" "$tmp/empty.obj"
expect_fail 2 "unknown option" "$data/fox.obj" --frobnicate 1
expect_fail 2 "delta" "$data/fox.obj" --delta -1
expect_fail 2 "solver" "$data/fox.obj" --solver magic
expect_fail 2 "effort" "$data/fox.obj" --effort harder
expect_fail 2 "divide" "$data/fox.obj" --divide -1
# --time-limit bounds the whole run: a budget spent before the first step ends it with the
# library's time-limit status, naming the step
expect_fail 1 "CA_ERROR_TIME_LIMIT.*candidates\|candidates.*CA_ERROR_TIME_LIMIT\|time limit reached" "$data/fox.obj" -o "$tmp/tl.ma" --time-limit 1e-9
check "no .ma after a spent budget" test ! -e "$tmp/tl.ma"

# 7. every bundled model, poor ones included: a skeleton (exit 0) or a clean failure (exit 1),
# never a crash or a hang
for m in "$data"/*.obj; do
  timeout 120 "$tool" "$m" -o "$tmp/m.ma" --quiet --time-limit 2 2> "$tmp/err"
  code=$?
  check "$(basename "$m"): exit 0 or 1 (got $code)" test "$code" -eq 0 -o "$code" -eq 1
  if [ "$code" -eq 1 ]; then check "$(basename "$m"): one-line message" test "$(wc -l < "$tmp/err")" -eq 1; fi
done

finish cli
