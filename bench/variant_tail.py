#!/usr/bin/env python3
"""Variants of ours side by side on the tail, against the QECD rows of a reference CSV.

usage: variant_tail.py REFERENCE.csv VARIANT.csv [VARIANT.csv ...]

A tuning loop's scratch CSVs (scripts/bench_quality.sh --tuning --methods ours-... --csv F)
hold only the variants; QECD's rows come from the reference (bench/quality.csv, same samples).
One line per method found: per-run mean-error ratio to QECD (median, p90, p95, runs > 3x), the
CAD p90, the 10 % and 1 % p90, the max-error clamped gmean and p90, runs > 1 % folded where
QECD's < 1 %, and runs off target.
"""
import csv
import sys
from collections import defaultdict

from quality_report import gmean, off, quantile, ratio


def main():
    ref = defaultdict(dict)
    for row in csv.DictReader(open(sys.argv[1])):
        if row["method"] == "qecd" and row["output_faces"]:
            ref[(row["set"], row["mesh"], row["ratio"])] = row
    variants = defaultdict(dict)
    for path in sys.argv[2:]:
        for row in csv.DictReader(open(path)):
            if row["output_faces"]:
                variants[row["method"]][(row["set"], row["mesh"], row["ratio"])] = row
    print("| method | runs | median | p90 | p95 | > 3× | CAD p90 | 10 % p90 | 1 % p90 | "
          "max gmean | max p90 | folds | off |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for method, rows in sorted(variants.items()):
        keys = [k for k in rows if k in ref]
        mean = {k: ratio(rows[k]["error_mean"], ref[k]["error_mean"]) for k in keys}
        mx = [ratio(rows[k]["error_max"], ref[k]["error_max"]) for k in keys]
        v = list(mean.values())

        def p90(pick):
            return quantile([mean[k] for k in keys if pick(k)], 0.9)

        folds = sum(float(rows[k]["fold_area"] or 0) > 0.01 and float(ref[k]["fold_area"] or 0) < 0.01
                    for k in keys)
        print(f"| {method} | {len(keys)} | {quantile(v, 0.5):.3f} | {quantile(v, 0.9):.2f} | "
              f"{quantile(v, 0.95):.2f} | {sum(x > 3 for x in v)} | {p90(lambda k: k[0] == 'cad'):.2f} | "
              f"{p90(lambda k: k[2] == '0.1'):.2f} | {p90(lambda k: k[2] == '0.01'):.2f} | "
              f"{gmean(mx):.3f} | {quantile(mx, 0.9):.2f} | {folds} | {sum(off(rows[k]) for k in keys)} |")


if __name__ == "__main__":
    main()
