#!/usr/bin/env bash
# Time as real files write it: `--time-column 'Time:hh:mm:ss'` (split at the format, not the last ':'),
# --date for clock times, Unix nanoseconds, and an NMEA log that starts with binary bytes and a no-fix
# epoch at 23:59:59 followed by fixes after midnight: auto-detected, the right duration and start.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
expect_ok "new" "$ATHLOS" new "$P"

printf 'Time,AccX\n23:59:59,1\n00:00:00,2\n00:00:01,3\n' > "$WORK/clock.csv"
expect_ok "clock time column" "$ATHLOS" import "$P" "$WORK/clock.csv" --as clock --kind imu \
  --time-column 'Time:hh:mm:ss' --column AccX=acc_x --date 2024-12-31
"$ATHLOS" info "$P" --json > "$WORK/info.json" 2>/dev/null || fail "info --json"
grep -q '"t0_utc": *"2024-12-31T23:59:59Z"' "$WORK/info.json" || fail "clock start: $(grep t0 "$WORK/info.json")"
grep -qE '"t_end": *2(,|$)' "$WORK/info.json" || fail "clock duration: $(grep t_end "$WORK/info.json")"
expect_fail "bad time format" "--time-column 'Time:fortnights': unknown time format 'fortnights' \(accepted: s, ms" \
  "$ATHLOS" import "$P" "$WORK/clock.csv" --as c2 --kind imu --time-column 'Time:fortnights'
expect_fail "bad date" "--date '31.12.2024': expected YYYY-MM-DD" \
  "$ATHLOS" import "$P" "$WORK/clock.csv" --as c2 --kind imu --time-column 'Time:hh:mm:ss' --date 31.12.2024
printf 'Time,AccX\n23:59:59,1\n00:0x:00,2\n' > "$WORK/badclock.csv"
expect_fail "bad clock cell" "badclock\.csv:3:1 \(column 'Time'\): '00:0x:00' is not a clock time" \
  "$ATHLOS" import "$P" "$WORK/badclock.csv" --as c3 --kind imu --time-column 'Time:hh:mm:ss'

printf 'stamp,acc_x\n1734501485317590607,1\n1734501485417273454,2\n' > "$WORK/ns.csv"
expect_ok "unix ns" "$ATHLOS" import "$P" "$WORK/ns.csv" --as ns --kind imu --time-column stamp:unix_ns
"$ATHLOS" info "$P" --json > "$WORK/info.json" 2>/dev/null
grep -q '"t0_utc": *"2024-12-18T05:58:05.317590607Z"' "$WORK/info.json" || fail "ns start"

# The NMEA log: binary noise, a no-fix epoch at 23:59:59, then ten minutes of 1 Hz fixes after midnight.
nmea() { local s=0 i c; for ((i = 0; i < ${#1}; i++)); do printf -v c '%d' "'${1:i:1}"; s=$((s ^ c)); done
  printf '$%s*%02X\r\n' "$1" "$s"; }
{
  printf '\x00\x01\xb5\x62\x06\x01\xff binary\n'
  nmea 'GPGGA,235959.00,,,,,0,00,99.9,,M,,M,,'
  nmea 'GPRMC,235959.00,V,,,,,,,311224,,'
  for s in $(seq 0 600); do
    hms=$(printf '%02d%02d%02d.00' $((s / 3600)) $((s / 60 % 60)) $((s % 60)))
    nmea "GPGGA,$hms,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"
    nmea "GPRMC,$hms,A,4807.038,N,01131.000,E,0.0,0.0,010125,,"
  done
} > "$WORK/drive.log"
expect_ok "nmea auto-detected" "$ATHLOS" import "$P" "$WORK/drive.log" --as drive
"$ATHLOS" info "$P" --json > "$WORK/info.json" 2>/dev/null
grep -q '"t0_utc": *"2025-01-01T00:00:00Z"' "$WORK/info.json" || fail "nmea start: $(grep t0 "$WORK/info.json")"
grep -qE '"t_end": *600(,|$)' "$WORK/info.json" || fail "nmea duration: $(grep t_end "$WORK/info.json")"
finish
