#!/usr/bin/env python3
"""The factor of safety from a strength-reduction study (docs/theory/geotechnics.md §E2).

Reads a study's results.csv (default postProcessing/study/results.csv) and gives, for each
spacing and scheme, the runs' verdicts by F and the bracket of the factor of safety: the
largest F that stands below the smallest F that fails. A run fails if it did not come to rest
(staticState's atRest 0) or came to rest only after its largest displacement exceeded the limit
(default 5 gamma H^2/E = 10 cm for this slope: the criterion of docs/theory/geotechnics.md §E2).
The bracket's middle is compared with Griffiths & Lane's 1.4; the brackets for the limits 3 and
10 gamma H^2/E follow (the criterion's sensitivity). A verdict that is not monotonic in F (a run
that stands above one that fails) is flagged.

    python3 safety.py [results.csv] [--reference 1.4] [--limit 5]
"""
import csv
import sys

REFERENCE = 1.4  # Griffiths & Lane (1999), example 1
ELASTIC = 2038.7 * 9.81 * 10.0 ** 2 / 1e8  # gamma H^2 / E [m]: the elastic displacement scale


def factor(level):
    """F1p45 -> 1.45 (the study's level names)."""
    return float(level[1:].replace("p", "."))


def bracket(runs, limit):
    """(verdicts, low, high, monotonic) for [(F, atRest, largest displacement), ...]."""
    verdicts = [(F, rest == 1 and largest <= limit) for F, rest, largest in sorted(runs)]
    failing = [F for F, stands in verdicts if not stands]
    standing = [F for F, stands in verdicts if stands]
    low = max([F for F in standing if not failing or F < min(failing)], default=None)
    high = min(failing, default=None)
    monotonic = not (failing and any(F > min(failing) for F in standing))
    return verdicts, low, high, monotonic


def describe(low, high):
    if low is not None and high is not None:
        return "(%.2f, %.2f]" % (low, high)
    return "<= %.2f" % high if high is not None else "> %.2f" % low


def main(argv):
    path = "postProcessing/study/results.csv"
    reference, factor_limit = REFERENCE, 5.0
    args = list(argv)
    while args:
        a = args.pop(0)
        if a == "--reference":
            reference = float(args.pop(0))
        elif a == "--limit":
            factor_limit = float(args.pop(0))
        else:
            path = a
    groups, seconds = {}, {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["status"] != "finished" or row["atRest"] in ("", "nan"):
                continue
            key = (row["resolution"], row["scheme"])
            groups.setdefault(key, []).append(
                (factor(row["reduction"]), int(float(row["atRest"])),
                 float(row["largestDisplacement"])))
            seconds[key] = seconds.get(key, 0.0) + float(row["wallSeconds"])
    if not groups:
        sys.exit(path + ": no finished run with an atRest value")
    limit = factor_limit * ELASTIC
    print("A run fails if it does not come to rest or moved more than %.3g m (%g gamma H^2/E); "
          "S stands, X fails" % (limit, factor_limit))
    print("%-8s %-32s %-38s %-13s %-16s %s" % ("spacing", "scheme", "verdicts by F", "bracket",
                                              "middle vs %.2f" % reference,
                                              "limit 3 / 10 gamma H^2/E"))
    for key, runs in sorted(groups.items()):
        verdicts, low, high, monotonic = bracket(runs, limit)
        marks = " ".join("%.2f%s" % (F, "S" if stands else "X") for F, stands in verdicts)
        versus = "-"
        if low is not None and high is not None:
            middle = 0.5 * (low + high)
            versus = "%.3f (%+.1f %%)" % (middle, 100 * (middle / reference - 1))
        others = " / ".join(describe(*bracket(runs, k * ELASTIC)[1:3]) for k in (3.0, 10.0))
        note = "" if monotonic else "  (not monotonic in F)"
        print("%-8s %-32s %-38s %-13s %-16s %s  [%.0f s]%s" % (key[0], key[1], marks,
                                                             describe(low, high), versus,
                                                             others, seconds[key], note))


if __name__ == "__main__":
    main(sys.argv[1:])
