#!/usr/bin/env bash
# Issue #11: damaged input files of every importer (CSV IMU, TDoA, beacons, NMEA, gaitmap, ROS
# ranging, BROAD) never crash or hang `athlos import`; a refused import prints its reason and leaves
# the project byte-identical; an accepted one leaves a readable project.
source "$(dirname "$0")/lib/common.bash" "$@"
need_shared gaitmap/imu_sample_ic_stride.csv uwb-outdoor/LOS_Trajectory_A_Case_1/A3.csv nmea/haicom-305N.log broad/33_disturbed_attached_magnet_2cm.hdf5
P="$WORK/p.athlos"
make_imu_csv "$WORK/imu.csv" 400
expect_ok "new" "$ATHLOS" new "$P"
expect_ok "seed" "$ATHLOS" import "$P" "$WORK/imu.csv" --as seed --kind imu

head -n 300 "$SHARED_DATA/gaitmap/imu_sample_ic_stride.csv" > "$WORK/gaitmap.csv"
head -n 200 "$SHARED_DATA/uwb-outdoor/LOS_Trajectory_A_Case_1/A3.csv" > "$WORK/A3.csv"
cp "$SHARED_DATA/nmea/haicom-305N.log" "$WORK/gps.log"
cp "$SHARED_DATA/broad/33_disturbed_attached_magnet_2cm.hdf5" "$WORK/broad.hdf5"
cp "$TEST_DATA/tdoa_small.csv" "$WORK/tdoa.csv"
cp "$TEST_DATA/beacons.csv" "$WORK/beacons.csv"

# mutate <source> <target> <trial>: four kinds of damage, chosen by the trial number.
mutate() {
  local src="$1" dst="$2" trial="$3" size n off chars=',;.-e9 0\n"x'
  cp "$src" "$dst"; chmod u+w "$dst"; size=$(stat -c %s "$dst")
  case $((trial % 4)) in
    0) n=$((RANDOM % 16 + 1))   # random bytes anywhere
       for _ in $(seq 1 "$n"); do
         off=$(( (RANDOM * 32768 + RANDOM) % size ))
         printf "\\x$(printf %02x $((RANDOM % 256)))" | dd of="$dst" bs=1 seek="$off" conv=notrunc status=none
       done ;;
    1) truncate -s $(( (RANDOM * 32768 + RANDOM) % size )) "$dst" ;;   # cut short
    2) n=$((RANDOM % 8 + 1))    # structural characters of the formats: separators, signs, quotes
       for _ in $(seq 1 "$n"); do
         off=$(( (RANDOM * 32768 + RANDOM) % size ))
         printf "${chars:$((RANDOM % ${#chars})):1}" | dd of="$dst" bs=1 seek="$off" conv=notrunc status=none
       done ;;
    3) off=$(( (RANDOM * 32768 + RANDOM) % size ))   # a block repeated over itself further on
       dd if="$src" of="$dst" bs=1 skip="$off" seek=$(( (off + RANDOM % 200 + 1) % size )) count=$((RANDOM % 300 + 1)) \
          conv=notrunc status=none ;;
  esac
}

RANDOM=${ATHLOS_MUTANT_SEED:-2611}
crashes=0; refused=0; accepted=0; trial=0
for input in imu tdoa beacons nmea gaitmap ros broad; do
  for k in $(seq 1 "${ATHLOS_MUTANTS:-8}"); do
    trial=$((trial + 1))
    case $input in
      imu) src="$WORK/imu.csv"; ext=csv; args=(--kind imu) ;;
      tdoa) src="$WORK/tdoa.csv"; ext=csv; args=(--kind lps-tdoa) ;;
      beacons) src="$WORK/beacons.csv"; ext=csv; args=(--kind beacons) ;;
      nmea) src="$WORK/gps.log"; ext=log; args=(--format nmea) ;;
      gaitmap) src="$WORK/gaitmap.csv"; ext=csv; args=(--format gaitmap) ;;
      ros) src="$WORK/A3.csv"; ext=csv; args=(--format ros) ;;
      broad) src="$WORK/broad.hdf5"; ext=hdf5; args=(--format broad) ;;
    esac
    M="$WORK/m$trial.$ext"
    mutate "$src" "$M" "$k"
    cp "$P" "$WORK/before.athlos"
    timeout 120 "$ATHLOS" import "$P" "$M" --as "m$trial" "${args[@]}" >"$WORK/out" 2>"$WORK/err"; rc=$?
    if [ "$rc" -ge 124 ]; then
      crashes=$((crashes + 1)); cp "$M" "$WORK/kept-$trial.$ext"
      fail "$input mutant $trial (damage $((k % 4))): import exited $rc (crash or hang)"; continue
    fi
    if [ "$rc" -ne 0 ]; then
      refused=$((refused + 1))
      grep -q "athlos: " "$WORK/err" || fail "$input mutant $trial: refused without a reason"
      grep -q "m$trial.$ext" "$WORK/err" || fail "$input mutant $trial: the reason does not name the file: $(head -c 300 "$WORK/err")"
      cmp -s "$P" "$WORK/before.athlos" || fail "$input mutant $trial: the refused import changed the project"
    else
      accepted=$((accepted + 1))
      "$ATHLOS" info "$P" >/dev/null 2>"$WORK/err" || fail "$input mutant $trial: accepted, then the project is unreadable: $(cat "$WORK/err")"
    fi
  done
done
echo "damaged inputs: $trial imports, $refused refused, $accepted accepted, $crashes crashes or hangs"
[ "$refused" -ge 15 ] || fail "only $refused of $trial damaged inputs refused: is the mutation working?"
finish
