#!/usr/bin/env python3
"""Stride lengths of `gait-parameters` against gaitmap's heel marker (docs/validation/gait-parameters.md).

usage: eval_gaitmap_heel.py mocap_sample.csv stride_borders_sample.csv left.csv right.csv

mocap_sample.csv: gaitmap's motion capture (100 Hz, mm; two header rows, marker and axis; heel = L_FCC,
R_FCC). stride_borders_sample.csv: reference strides in IMU samples (204.8 Hz; s_id, foot, start, end).
left.csv / right.csv: `athlos export` of the gait-parameters tables (start, end in s; stride_length in m).

Two comparisons:
- reference strides: each must contain the midpoint of exactly one estimated stride; the reference
  length is the heel marker's horizontal displacement between the reference stride's start and end;
- own borders: the heel marker's horizontal displacement between each estimated stride's own start
  and end (its mid-stances), so that only the integration is compared.
Standard library only (no numpy), so that it runs on a bare Debian."""
import csv
import math
import sys

IMU_RATE, MOCAP_RATE = 204.8, 100.0
MAX_TURN = 0.3  # rad: |turning_angle| below this is a straight stride


def read_heel(path):
    rows = list(csv.reader(open(path)))
    markers, axes = rows[0], rows[1]
    col = {(m, a): i for i, (m, a) in enumerate(zip(markers, axes))}
    heel = {}
    for r in rows[2:]:
        heel[int(float(r[0]))] = {
            foot: (float(r[col[(m, 'x')]]), float(r[col[(m, 'y')]]))
            for foot, m in (('left', 'L_FCC'), ('right', 'R_FCC'))}
    return heel


def heel_length(heel, foot, t0, t1):
    """Horizontal heel displacement (m) between two times (s)."""
    a, b = heel[round(t0 * MOCAP_RATE)][foot], heel[round(t1 * MOCAP_RATE)][foot]
    return math.hypot(b[0] - a[0], b[1] - a[1]) / 1000.0


def read_strides(path):
    return [{k: float(v) for k, v in r.items() if v not in ('', None)} for r in csv.DictReader(open(path))]


def summary(label, errors):
    if not errors:
        return
    print(f'{label}: {len(errors)} strides, mean |error| {100 * sum(abs(e) for e in errors) / len(errors):.2f} %, '
          f'mean error {100 * sum(errors) / len(errors):+.2f} %, worst {100 * max(abs(e) for e in errors):.2f} %')


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    heel = read_heel(sys.argv[1])
    refs = [(r['foot'], int(r['start']) / IMU_RATE, int(r['end']) / IMU_RATE) for r in csv.DictReader(open(sys.argv[2]))]
    est = {'left': read_strides(sys.argv[3]), 'right': read_strides(sys.argv[4])}

    errors, straight, unmatched, multiple = [], [], 0, 0
    for foot, t0, t1 in refs:
        reference = heel_length(heel, foot, t0, t1)
        hits = [s for s in est[foot] if t0 <= 0.5 * (s['start'] + s['end']) <= t1]
        if len(hits) != 1:
            unmatched += not hits
            multiple += len(hits) > 1
            print(f'{foot:5s} {t0:6.2f}-{t1:6.2f} s  heel {reference:.3f} m  {len(hits)} estimated strides')
            continue
        s = hits[0]
        e = s['stride_length'] / reference - 1.0
        errors.append(e)
        if abs(s.get('turning_angle', 0.0)) < MAX_TURN:
            straight.append(e)
        print(f"{foot:5s} {t0:6.2f}-{t1:6.2f} s  heel {reference:.3f} m  estimate {s['stride_length']:.3f} m "
              f"({s['start']:.2f}-{s['end']:.2f} s)  {100 * e:+6.2f} %")
    print(f'reference strides matched once: {len(refs) - unmatched - multiple}/{len(refs)} '
          f'(unmatched {unmatched}, more than one {multiple})')
    summary('reference strides', errors)
    summary(f'reference strides, straight (|turning_angle| < {MAX_TURN} rad)', straight)

    own = []
    for foot in ('left', 'right'):
        for s in est[foot]:
            reference = heel_length(heel, foot, s['start'], s['end'])
            if reference > 0.2:  # a shuffle on the spot has no meaningful relative error
                own.append(s['stride_length'] / reference - 1.0)
    summary('own borders (heel between the estimated mid-stances, heel moved > 0.2 m)', own)


if __name__ == '__main__':
    main()
