#!/usr/bin/env bash
# Issue #17 item 2, the judged path: gaitmap walk (first header cell "sensor", as pandas writes it)
# → gait-parameters per foot → CSV; every motion-capture stride (IC to IC) must contain the midpoint
# of exactly one estimated stride, and the matched stride lengths must be plausible (no length
# reference in the shared data). A still recording is refused and leaves the project unchanged.
source "$(dirname "$0")/lib/common.bash" "$@"
need_shared gaitmap/imu_sample_ic_stride.csv gaitmap/stride_borders_sample_ic_stride.csv gaitmap/imu_sample_healthy_stair_up.csv
G="$SHARED_DATA/gaitmap"
P="$WORK/p.athlos"
sed '1s/^/sensor/; 2s/^/axis/' "$G/imu_sample_ic_stride.csv" > "$WORK/walk.csv"
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import" "$ATHLOS" import "$P" "$WORK/walk.csv" --as walk --format gaitmap
# The default (the judged command line) and the Kalman smoother (method=rts) must both pass the rule.
for method in default rts; do
extra=(); out=strides
[ "$method" = rts ] && { extra=(--param method=rts); out=rts-strides; }
for foot in left right; do
  expect_ok "run $foot $method" "$ATHLOS" run "$P" gait-parameters --input "walk/$foot-foot" \
    --output "walk/$foot-$out" "${extra[@]}"
  expect_ok "export $foot $method" "$ATHLOS" export "$P" "walk/$foot-$out" --to "$WORK/$foot.csv"
  head -1 "$WORK/$foot.csv" | grep -q '^start,end,stride_length,' || fail "$foot header: $(head -1 "$WORK/$foot.csv")"
  # Reference strides of this foot in seconds (sample index / 102.4 Hz), then the matching rule.
  awk -F, -v foot="$foot" 'NR > 1 && $2 == foot { printf "%.6f %.6f\n", $3 / 102.4, $4 / 102.4 }' \
    "$G/stride_borders_sample_ic_stride.csv" > "$WORK/ref-$foot"
  [ "$(wc -l < "$WORK/ref-$foot")" -ge 7 ] || fail "$foot: reference strides not read"
  result=$(awk -F, 'NR == FNR { s[++n] = $1; e[n] = $2; next }
    FNR > 1 { mid = ($1 + $2) / 2; for (i = 1; i <= n; ++i) if (mid >= s[i] && mid <= e[i]) { hits[i]++; len[i] = $3 } }
    END { bad = 0; for (i = 1; i <= n; ++i) {
            if (hits[i] != 1) { printf "stride %d (%.2f-%.2f s) matched %d times; ", i, s[i], e[i], hits[i]; bad++ }
            else if (len[i] < 1.0 || len[i] > 1.8) { printf "stride %d length %.3f m implausible; ", i, len[i]; bad++ } }
          print bad ? "" : "ok" }' <(tr ' ' , < "$WORK/ref-$foot") "$WORK/$foot.csv")
  [ "$result" = "ok" ] || fail "$foot $method: $result"
done
done
expect_ok "info" "$ATHLOS" info "$P" --json
grep -q '"path": "walk/left-strides-trajectory"' "$WORK/out" || fail "no trajectory stream"
grep -q '"path": "walk/left-rts-strides-trajectory"' "$WORK/out" || fail "no rts trajectory stream"

# gait-summary on both feet: its steady-state mean stride length per foot must equal the mean recomputed
# here from the exported strides (|turning_angle| <= 0.3 rad, first and last stride of every run of
# adjacent straight strides left out), and the symmetry index in the row "both" must follow from them.
expect_ok "gait-summary" "$ATHLOS" run "$P" gait-summary --input walk/left-strides,walk/right-strides \
  --output walk/summary
expect_ok "export summary" "$ATHLOS" export "$P" walk/summary --to "$WORK/summary.csv"
head -1 "$WORK/summary.csv" | grep -q '^foot,strides \[1\],used \[1\],stride_length_mean \[m\],stride_length_sd \[m\],stride_length_cv \[%\],stride_length_si \[%\]' \
  || fail "summary header: $(head -1 "$WORK/summary.csv")"
[ "$(cut -d, -f1 "$WORK/summary.csv" | tail -n +2 | tr '\n' ' ')" = "left right both " ] \
  || fail "summary rows: $(cut -d, -f1 "$WORK/summary.csv" | tr '\n' ' ')"
steady_mean() {  # the mean stride_length of the steady strides of an exported gait-parameters CSV
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { n++; s[n] = $c["start"]; e[n] = $c["end"]; l[n] = $c["stride_length"]; a = $c["turning_angle"];
      ok[n] = (a <= 0.3 && a >= -0.3) }
    END { i = 1; while (i <= n) { if (!ok[i]) { i++; continue }
            j = i; while (j < n && ok[j + 1] && (s[j + 1] - e[j])^2 <= 1e-6) j++
            for (k = i + 1; k < j; ++k) { sum += l[k]; m++ }
            i = j + 1 }
          printf "%.9f %d\n", sum / m, m }' "$1"
}
for foot in left right; do
  expect_ok "export $foot strides" "$ATHLOS" export "$P" "walk/$foot-strides" --to "$WORK/$foot-default.csv"
  read -r mean used < <(steady_mean "$WORK/$foot-default.csv")
  row=$(grep "^$foot," "$WORK/summary.csv")
  [ "$(echo "$row" | cut -d, -f3)" = "$used" ] || fail "$foot: used $(echo "$row" | cut -d, -f3), expected $used"
  awk -v a="$(echo "$row" | cut -d, -f4)" -v b="$mean" 'BEGIN { exit !((a - b)^2 < 1e-12) }' \
    || fail "$foot: summary mean $(echo "$row" | cut -d, -f4), recomputed $mean"
done
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { h = $i; sub(/ \[.*\]$/, "", h); c[h] = i }; next } { m[$1] = $c["stride_length_mean"]; si[$1] = $c["stride_length_si"] }
  END { want = 200 * (m["left"] - m["right"]) / (m["left"] + m["right"]); if (want < 0) want = -want
        exit !((si["both"] - want)^2 < 1e-12 && m["left"] > 1.0 && m["left"] < 1.8) }' "$WORK/summary.csv" \
  || fail "summary symmetry index: $(cat "$WORK/summary.csv")"
expect_fail "summary of nothing" "no steady-state stride" "$ATHLOS" run "$P" gait-summary --input walk/left-strides \
  --output walk/x --param edge_strides=100
expect_fail "summary of one foot twice" "is also the left foot" "$ATHLOS" run "$P" gait-summary \
  --input walk/left-strides,walk/left-rts-strides --output walk/x
expect_fail "unknown method" "method" "$ATHLOS" run "$P" gait-parameters --input walk/left-foot --output walk/x \
  --param method=kalman
# An IMU stream without the gyroscope is refused with the columns it has (the events family's shared check).
awk 'BEGIN { print "t,acc_x,acc_y,acc_z"; for (i = 0; i < 50; ++i) printf "%.3f,0,0,9.81\n", i / 100 }' > "$WORK/acc.csv"
expect_ok "import accelerometer only" "$ATHLOS" import "$P" "$WORK/acc.csv" --as acc --kind imu
expect_fail "gait-parameters without gyroscope" "needs adjacent columns gyr_x, gyr_y, gyr_z \(it has: acc_x, acc_y, acc_z\)" \
  "$ATHLOS" run "$P" gait-parameters --input acc/imu --output acc/x
expect_fail "gait-events without gyroscope" "needs adjacent columns gyr_x, gyr_y, gyr_z \(it has: acc_x, acc_y, acc_z\)" \
  "$ATHLOS" run "$P" gait-events --input acc/imu --output acc/x

# Empty cells (NaN on import) in a few samples are bridged: the strides stay within 5 mm of the complete
# walk's; a gap of 0.5 s is refused with its times and max_gap.
awk -F, 'BEGIN { OFS = "," } NR == 1000 || NR == 1500 || NR == 2500 { $2 = ""; $8 = "" } { print }' "$WORK/walk.csv" \
  > "$WORK/holes.csv"
expect_ok "import with holes" "$ATHLOS" import "$P" "$WORK/holes.csv" --as holes --format gaitmap
expect_ok "strides with holes" "$ATHLOS" run "$P" gait-parameters --input holes/left-foot --output holes/left-strides
expect_ok "export with holes" "$ATHLOS" export "$P" holes/left-strides --to "$WORK/holes-left.csv"
expect_ok "export without holes" "$ATHLOS" export "$P" walk/left-strides --to "$WORK/whole-left.csv"
result=$(awk -F, 'NR == FNR { l[FNR] = $3; n = FNR; next }
  FNR > 1 { d = $3 - l[FNR]; if (d < 0) d = -d; if (d > 0.005) bad = bad sprintf("row %d: %s against %s; ", FNR, $3, l[FNR]) }
  END { if (FNR != n) bad = bad sprintf("%d rows against %d", FNR, n); print bad ? bad : "ok" }' \
  "$WORK/whole-left.csv" "$WORK/holes-left.csv")
[ "$result" = "ok" ] || fail "strides with holes: $result"
awk -F, 'BEGIN { OFS = "," } NR >= 1000 && NR < 1051 { $2 = "" } { print }' "$WORK/walk.csv" > "$WORK/gap.csv"
expect_ok "import with a gap" "$ATHLOS" import "$P" "$WORK/gap.csv" --as gap --format gaitmap
expect_fail "a gap too long" "no complete IMU sample from t = .* longer than max_gap = 0.05 s" \
  "$ATHLOS" run "$P" gait-parameters --input gap/left-foot --output gap/left-strides

# Another mounting (the held-out walk may come from other devices): the same walk in the raw frames of
# gaitmap's lateral NilsPods (its extract_example_data.py: raw = Rz(±90°) Rx(±90°) aligned, so x points
# up and the medio-lateral axis is z). The default ml_axis=auto must give the same strides and lengths.
awk -F, 'NR <= 2 { print; next }
  { printf "%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
      $1, $6, $7, $2, -$3, $4, -$5, $12, $13, $8, -$9, $10, -$11 }' "$WORK/walk.csv" > "$WORK/raw.csv"
expect_ok "import raw mounting" "$ATHLOS" import "$P" "$WORK/raw.csv" --as raw --format gaitmap
for foot in left right; do
  expect_ok "run raw $foot" "$ATHLOS" run "$P" gait-parameters --input "raw/$foot-foot" --output "raw/$foot-strides"
  expect_ok "export raw $foot" "$ATHLOS" export "$P" "raw/$foot-strides" --to "$WORK/raw-$foot.csv"
  expect_ok "export aligned $foot" "$ATHLOS" export "$P" "walk/$foot-strides" --to "$WORK/aligned-$foot.csv"
  result=$(awk -F, 'NR == FNR { a[FNR] = $0; n = FNR; next }
    { split(a[FNR], x, ","); for (c = 1; c <= 11; ++c) { d = x[c] - $c; if (d < 0) d = -d;
        if (d > 1e-6) { printf "row %d column %d: %s against %s; ", FNR, c, $c, x[c]; bad = 1 } } }
    END { if (FNR != n) printf "%d rows against %d; ", FNR, n; print (bad || FNR != n) ? "" : "ok" }' \
    "$WORK/aligned-$foot.csv" "$WORK/raw-$foot.csv")
  [ "$result" = "ok" ] || fail "raw mounting, $foot: $result"
done

# A sample-index file at 204.8 Hz (the stair file rewritten the way pandas writes gaitmap's imu_sample.csv):
# the import tells the rate from the motion and says so, --rate overrides it, a bad --rate is a usage error.
awk -F, 'BEGIN { OFS = "," } NR == 1 { print "sensor" $0; next } NR == 2 { print; next } { $1 = NR - 3; print }' \
  "$G/imu_sample_healthy_stair_up.csv" > "$WORK/stairs.csv"
expect_ok "import index 204.8 Hz" "$ATHLOS" import "$P" "$WORK/stairs.csv" --as stairs --format gaitmap
grep -q "sampling rate 204.8 Hz from the motion" "$WORK/err" || fail "rate not found from the motion: $(cat "$WORK/err")"
expect_ok "info stairs" "$ATHLOS" info "$P" --json
grep -q '"sampling_rate_source": "motion"' "$WORK/out" || fail "rate source not recorded"
expect_ok "stairs strides" "$ATHLOS" run "$P" gait-parameters --input stairs/left-foot --output stairs/left-strides
expect_ok "export stairs" "$ATHLOS" export "$P" stairs/left-strides --to "$WORK/stairs-left.csv"
median=$(awk -F, 'NR > 1 { print $5 }' "$WORK/stairs-left.csv" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
awk -v m="$median" 'BEGIN { exit !(m > 0.9 && m < 1.6) }' || fail "stair stride time $median s: the time axis is off"
# gait-summary of the strides on the stairs (terrain=up: stride_height at least 0.2 m, two steps): the
# mean stride height is two risers (0.12-0.19 m each), the steady stride length varies little, and
# terrain=level finds no steady stride on this flight.
expect_ok "stairs summary" "$ATHLOS" run "$P" gait-summary --input stairs/left-strides --output stairs/summary \
  --param terrain=up
expect_ok "export stairs summary" "$ATHLOS" export "$P" stairs/summary --to "$WORK/stairs-summary.csv"
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { h = $i; sub(/ \[.*\]$/, "", h); c[h] = i }; next }
  { exit !($c["used"] >= 5 && $c["stride_height_mean"] > 0.24 && $c["stride_height_mean"] < 0.38 &&
           $c["stride_length_cv"] < 5) }' "$WORK/stairs-summary.csv" \
  || fail "stairs summary: $(cat "$WORK/stairs-summary.csv")"
expect_fail "stairs summary, level" "on other terrain" "$ATHLOS" run "$P" gait-summary --input stairs/left-strides \
  --output stairs/x --param terrain=level
expect_ok "import --rate" "$ATHLOS" import "$P" "$WORK/stairs.csv" --as stairs2 --format gaitmap --rate 204.8
grep -q "from the motion" "$WORK/err" && fail "--rate given, yet estimated: $(cat "$WORK/err")"
expect_fail "bad --rate" "--rate '0'" "$ATHLOS" import "$P" "$WORK/stairs.csv" --as stairs3 --format gaitmap --rate 0

# Nothing to find: refused with the reason, the project byte-identical.
awk 'BEGIN { print ",left_sensor,left_sensor,left_sensor,left_sensor,left_sensor,left_sensor";
  print ",acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z"; for (i = 0; i < 1000; ++i) printf "%d,0,0,9.81,0.1,0,0\n", i }' \
  > "$WORK/still.csv"
expect_ok "import still" "$ATHLOS" import "$P" "$WORK/still.csv" --as still --format gaitmap
before=$(cd "$WORK" && find p.athlos -type f -exec md5sum {} + | sort)
expect_fail "still foot" "no stride found" "$ATHLOS" run "$P" gait-parameters --input still/left-foot --output still/strides
after=$(cd "$WORK" && find p.athlos -type f -exec md5sum {} + | sort)
[ "$before" = "$after" ] || fail "a refused run changed the project"

# The gait report (athlos report --gait): a PDF of a recording's stride tables, summary computed in
# memory, the project byte-identical; ambiguous or missing tables are refused with their names.
cp "$P" "$WORK/before-report.athlos"
expect_fail "gait report, two tables per foot" "'walk' has 2 gait-parameters tables of the left foot \(left-rts-strides, left-strides\)" \
  "$ATHLOS" report "$P" --gait walk --to "$WORK/gait.pdf"
expect_ok "gait report" "$ATHLOS" report "$P" --gait walk --strides walk/left-strides,walk/right-strides --to "$WORK/gait.pdf"
[ "$(head -c 5 "$WORK/gait.pdf")" = "%PDF-" ] || fail "gait report is not a PDF"
pages=$(grep -a -o '/Type /Page\b' "$WORK/gait.pdf" | wc -l)
[ "$pages" -ge 2 ] || fail "gait report has $pages pages (summary and strides expected)"
expect_ok "gait report, one foot, stairs" "$ATHLOS" report "$P" --gait stairs --param terrain=up --to "$WORK/stairs.pdf"
grep -q "stairs/left-strides" "$WORK/out" || fail "stairs report: $(cat "$WORK/out")"
expect_fail "gait report, one foot twice" "both of the left foot" "$ATHLOS" report "$P" --gait walk \
  --strides walk/left-strides,walk/left-rts-strides --to "$WORK/x.pdf"
expect_fail "gait report, no stride table" "'acc' has no gait-parameters table" "$ATHLOS" report "$P" --gait acc --to "$WORK/x.pdf"
expect_fail "gait report, no steady stride" "no steady-state stride" "$ATHLOS" report "$P" --gait stairs \
  --param terrain=level --to "$WORK/x.pdf"
expect_fail "coach report of a gait project" "no athlete position streams.*for the gait report of its stride tables: --gait (holes|raw|stairs|walk)" \
  "$ATHLOS" report "$P" --to "$WORK/x.pdf"
expect_fail "--strides without --gait" "--strides needs --gait" "$ATHLOS" report "$P" --strides walk/left-strides --to "$WORK/x.pdf"
[ -e "$WORK/x.pdf" ] && fail "a refused gait report wrote a PDF"
cmp -s "$P" "$WORK/before-report.athlos" || fail "the gait report changed the project"
finish
