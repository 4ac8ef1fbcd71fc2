#!/usr/bin/env bash
# Venues from coordinates: a pitch placed by its four corners in lat/lon (the project's geodetic
# origin) or local x, y; athlos prints its least-squares length, width, rotation and corner
# residuals and stores it; refusals name the option, leave the project unchanged.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P" --sport football

# A 100 × 64 m pitch rotated 30° (x axis from East, counter-clockwise), centre at (20, 10) m.
XY="-7.3013,-42.7128;79.3013,7.2872;47.3013,62.7128;-39.3013,12.7128"
expect_ok "corners x,y" "$ATHLOS" venue "$P" --name main --kind football --corners-xy "$XY"
grep -qE "length 100\.00 m, width 64\.00 m, rotation 30\.00 deg" "$WORK/out" || fail "xy pitch: $(cat "$WORK/out")"
grep -q "centre spot: x 20.00 m, y 10.00 m" "$WORK/out" || fail "centre: $(cat "$WORK/out")"
grep -q "corner residuals (m): 1: 0.00" "$WORK/out" || fail "residuals: $(cat "$WORK/out")"
"$ATHLOS" info "$P" --json > "$WORK/info.json" 2>/dev/null || fail "info --json"
grep -q '"main"' "$WORK/info.json" || fail "venue not listed by info"
expect_ok "list" "$ATHLOS" venue "$P"
grep -q "pitch 'main' (football): length 100.00 m" "$WORK/out" || fail "list: $(cat "$WORK/out")"
expect_ok "list json" "$ATHLOS" venue "$P" --json
grep -q '"rotation_convention"' "$WORK/out" || fail "json document: $(head -c 300 "$WORK/out")"
grep -q '"pitch_frame": "pitch"' "$WORK/out" || fail "frame names: $(head -c 300 "$WORK/out")"

# Same corners clockwise from another start: the same pitch.
expect_ok "other order" "$ATHLOS" venue "$P" --name main --overwrite --kind rugby \
  --corners-xy "47.3013,62.7128;79.3013,7.2872;-7.3013,-42.7128;-39.3013,12.7128"
grep -qE "\(rugby\): length 100\.00 m, width 64\.00 m, rotation 30\.00 deg" "$WORK/out" || fail "reordered: $(cat "$WORK/out")"
grep -q "outside World Rugby Law 1" "$WORK/err" || fail "no note on the law: $(cat "$WORK/err")"

# Lat/lon: a pitch in Dublin, length along East (about 105 × 68 m); the first corner becomes the
# project's origin, the next venue and GNSS imports share it.
P2="$WORK/ll.athlos"
expect_ok "new 2" "$ATHLOS" new "$P2"
LL="53.30000,-6.20000;53.30000,-6.198428;53.300611,-6.198428;53.300611,-6.20000"
expect_ok "corners lat,lon" "$ATHLOS" venue "$P2" --corners "$LL"
grep -qE "pitch 'pitch' \(football\): length 10[45]\.[0-9]+ m, width 6[78]\.[0-9]+ m, rotation -?0\.[0-9]+ deg" "$WORK/out" \
  || fail "lat/lon pitch: $(cat "$WORK/out")"
grep -q "geodetic origin is now 53.3, -6.2 (the first corner)" "$WORK/err" || fail "origin note: $(cat "$WORK/err")"
"$ATHLOS" info "$P2" --json > "$WORK/info2.json" 2>/dev/null
cp "$P2" "$WORK/before.athlos"

# Refusals: one line naming what to fix, the project unchanged.
expect_fail "not a rectangle" "corner 3 is [0-9.]+ m from the best-fitting rectangle \(max_residual 1 m\)" \
  "$ATHLOS" venue "$P2" --name kite --corners-xy "0,0;100,0;110,70;0,64"
expect_fail "crossing outline" "the outline 1-2-3-4 crosses itself" \
  "$ATHLOS" venue "$P2" --name bow --corners-xy "0,0;100,64;100,0;0,64"
expect_fail "three corners" "^athlos: --corners-xy: expected 4 corners separated by ';', got 3" \
  "$ATHLOS" venue "$P2" --name x --corners-xy "0,0;100,0;100,64"
expect_fail "not numbers" "--corners: corner 2 '53.3,west' is not a pair of numbers" \
  "$ATHLOS" venue "$P2" --name x --corners "53.3,-6.2;53.3,west;1,2;3,4"
expect_fail "latitude range" "corner 3 \(95, -6.2\): latitude must be in \[-90, 90\]" \
  "$ATHLOS" venue "$P2" --name x --corners "53.3,-6.2;53.3,-6.19;95,-6.2;53.31,-6.2"
expect_fail "bad kind" "--kind 'cricket': use one of football, rugby, rectangle" \
  "$ATHLOS" venue "$P2" --name x --kind cricket --corners-xy "0,0;100,0;100,64;0,64"
expect_fail "bad tolerance" "--max-residual 'none': expected a positive number of metres" \
  "$ATHLOS" venue "$P2" --name x --max-residual none --corners-xy "0,0;100,0;100,64;0,64"
expect_fail "both forms" "either --corners \(lat/lon\) or --corners-xy" \
  "$ATHLOS" venue "$P2" --corners "$LL" --corners-xy "0,0;100,0;100,64;0,64"
expect_fail "existing name" "venue 'pitch' already exists in the project \(--overwrite to replace it\)" \
  "$ATHLOS" venue "$P2" --corners-xy "0,0;100,0;100,64;0,64"
expect_fail "origin change" "geodetic origin is 53.3, -6.2, 0 m; it cannot change" \
  "$ATHLOS" venue "$P2" --name p2 --origin 53.31,-6.2 --corners "$LL"
expect_fail "missing project" "does not exist" "$ATHLOS" venue "$WORK/nope.athlos" --corners-xy "0,0;100,0;100,64;0,64"
cmp -s "$P2" "$WORK/before.athlos" || fail "a refused venue changed the project"

# A looser tolerance accepts the kite (a rectangle of the corners' best fit).
expect_ok "kite with tolerance" "$ATHLOS" venue "$P2" --name kite --kind rectangle --max-residual 8 --corners-xy "0,0;100,0;110,70;0,64"
grep -q "pitch 'kite' (rectangle)" "$WORK/out" || fail "kite: $(cat "$WORK/out")"

# A 400 m track by the two kerb ends of its home straight (84.39 m apart, towards North-East), and
# a polyline (documents a track parameter such as position-filter's can name).
expect_ok "track" "$ATHLOS" venue "$P" --name track400 --track iaaf-400m --straight-xy "0,0;59.673,59.673"
grep -qE "track 'track400' \(iaaf-400m\): centre x 4\.03 m, y 55\.65 m \(ENU\), rotation 45\.00 deg" "$WORK/out" \
  || fail "track pose: $(cat "$WORK/out")"
expect_fail "track straight too short" "straight: the two ends are 70.00 m apart, the home straight of 'iaaf-400m' is 84.39 m" \
  "$ATHLOS" venue "$P" --name t2 --track iaaf-400m --straight-xy "0,0;70,0"
expect_fail "straight without track" "--straight-xy needs --track" "$ATHLOS" venue "$P" --name t2 --straight-xy "0,0;84.39,0"
expect_ok "polyline lat/lon" "$ATHLOS" venue "$P2" --name road --polyline "53.3,-6.2;53.301,-6.2;53.301,-6.198"
grep -qE "polyline 'road': 3 points, 2[0-9][0-9]\.[0-9]+ m" "$WORK/out" || fail "polyline: $(cat "$WORK/out")"
expect_ok "list tracks" "$ATHLOS" venue "$P"
grep -q "track-oval 'track400': pose x 4.03 m, y 55.65 m, rotation 45.00 deg" "$WORK/out" || fail "track list: $(cat "$WORK/out")"
finish
