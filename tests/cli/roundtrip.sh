#!/usr/bin/env bash
# new → import CSV → info --json → export → the exported values equal the input values.
source "$(dirname "$0")/lib/common.bash" "$@"
P="$WORK/p.athlos"
make_imu_csv "$WORK/imu.csv" 2500

expect_ok "new" "$ATHLOS" new "$P"
expect_ok "import" "$ATHLOS" import "$P" "$WORK/imu.csv" --as rec --kind imu
expect_ok "info --json" "$ATHLOS" info "$P" --json
grep -q '"path": "rec/imu"' "$WORK/out" || fail "info --json does not list rec/imu"
grep -q '"samples": 2500' "$WORK/out" || fail "info --json does not report 2500 samples"
grep -q '"kind": "imu"' "$WORK/out" || fail "info --json does not report kind imu"
expect_ok "info" "$ATHLOS" info "$P"
grep -q "rec/imu" "$WORK/out" || fail "info text does not list rec/imu"

expect_ok "export csv" "$ATHLOS" export "$P" rec/imu --to "$WORK/out.csv"
[ "$(head -1 "$WORK/out.csv")" = "$(head -1 "$WORK/imu.csv")" ] || fail "exported header differs: $(head -1 "$WORK/out.csv")"
# Same values (the text may differ: 1.500000 vs 1.5), compared as numbers with a relative 1e-12.
awk -F, 'NR==FNR{for(i=1;i<=NF;i++)a[FNR,i]=$i; n=FNR; next}
  {for(i=1;i<=NF;i++){d=a[FNR,i]-$i; if(d<0)d=-d; s=(a[FNR,i]<0?-a[FNR,i]:a[FNR,i]); if(d>1e-12*(s+1e-300)&&d!=0){print "line " FNR " col " i ": " a[FNR,i] " vs " $i; bad=1; exit}}}
  END{if(FNR!=n){print "rows " FNR " vs " n; bad=1} exit bad}' "$WORK/imu.csv" "$WORK/out.csv" || fail "exported values differ"
# Exporting the export again is byte-identical (export → import → export is exact).
expect_ok "re-import" "$ATHLOS" import "$P" "$WORK/out.csv" --as again --kind imu
expect_ok "re-export" "$ATHLOS" export "$P" again/imu --to "$WORK/out2.csv"
cmp -s "$WORK/out.csv" "$WORK/out2.csv" || fail "export → import → export is not byte-identical"
expect_ok "export h5" "$ATHLOS" export "$P" rec/imu --to "$WORK/out.h5"
[ -s "$WORK/out.h5" ] || fail "HDF5 export is empty"
finish
