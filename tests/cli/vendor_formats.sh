#!/usr/bin/env bash
# Vendor exports in with one command, detected from their content: a STATSports session as a GNSS
# stream (whole session, in metres too), a GPX track with --origin, a Metrica team file as one stream
# per player.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"
{
  echo 'Player Display Name,Time,Elapsed Time (s),Lat,Lon,Speed (m/s),Instantaneous Acceleration Impulse,Heart Rate (bpm)'
  for i in $(seq 0 99); do
    printf 'Anna Berg,10:00:%02d.%d,%s,53.2700%02d,-6.2011,3.5,0.1,150\n' $((i / 10)) $((i % 10)) "$i" "$i"
  done
} > "$WORK/session.csv"
expect_ok "statsports" "$ATHLOS" import "$P" "$WORK/session.csv" --as match --origin 53.27,-6.2011
grep -q "imported match/gnss" "$WORK/out" || fail "stream: $(cat "$WORK/out")"
"$ATHLOS" info "$P" --json > "$WORK/info.json" 2>/dev/null || fail "info --json"
grep -q '"samples": *100' "$WORK/info.json" || fail "the whole session: $(grep samples "$WORK/info.json")"
grep -q '"athlete": *"Anna Berg"' "$WORK/info.json" || fail "athlete"
expect_ok "export" "$ATHLOS" export "$P" match/gnss --to "$WORK/g.csv"
head -1 "$WORK/g.csv" | grep -q ',x,y$' || fail "no ENU x, y: $(head -1 "$WORK/g.csv")"
awk -F, 'NR==101 { if ($NF < 10.5 || $NF > 11.5) exit 1 }' "$WORK/g.csv" || fail "y after 0.000099 deg north: $(tail -1 "$WORK/g.csv")"

printf '<gpx version="1.1">\n<trk><trkseg>\n<trkpt lat="53.27" lon="-6.2011"><time>2024-05-01T06:00:00Z</time></trkpt>\n<trkpt lat="53.2701" lon="-6.2011"><time>2024-05-01T06:00:01Z</time></trkpt>\n</trkseg></trk></gpx>\n' > "$WORK/run.gpx"
expect_ok "gpx" "$ATHLOS" import "$P" "$WORK/run.gpx" --as run
expect_fail "another origin" "geodetic origin is 53.27, -6.2011, 0 m; it cannot change" \
  "$ATHLOS" import "$P" "$WORK/run.gpx" --as run2 --origin 1,1

printf ',,,Home,,Home,,\n,,,11,,1,,\nPeriod,Frame,Time [s],Player11,,Player1,,Ball,\n1,1,0.04,0.1,0.5,0.5,0.5,NaN,NaN\n1,2,0.08,0.11,0.5,0.5,0.51,0.5,0.5\n' > "$WORK/metrica.csv"
expect_ok "metrica" "$ATHLOS" import "$P" "$WORK/metrica.csv" --as game
grep -q "imported game/home-11" "$WORK/out" && grep -q "imported game/ball" "$WORK/out" || fail "players: $(cat "$WORK/out")"
finish
