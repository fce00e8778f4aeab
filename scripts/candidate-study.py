#!/usr/bin/env python3
"""How learning's choice compares with every other candidate it tried, on the
rest of each route against the truth, and what other ways of choosing would
have read. Reads REPORT/candidates_on_route.csv, which

    build/apps/omnirange-experiment ini/NAME.ini --study-candidates

writes (docs/results.md, "Every candidate on the rest of the route").

    scripts/candidate-study.py results maze factory ...

Ways of choosing, each scored by the chosen candidate's rays within 5 cm of
the truth on the rest of the route:
  learned      what learning chose (the lowest held-aside score; a near tie to CHROMA)
  lowest       the lowest held-aside score, no tie rule
  best         the best candidate on the route: what no laser-trained rule can know
  fixed        leave one world out: the one configuration that reads best on
               average over the other worlds, used unchanged
  tie+prior    of the candidates within the held-aside frames' noise of the
               lowest score, the one that reads best over the other worlds
  shortfall w  the lowest score when the error from rays reading nearer than
               the laser counts w times (an obstacle the laser cannot see
               costs less), with the tie rule
"""
import csv
import math
import statistics
import sys

KEY = ["colour_space", "bins", "threshold", "obstacle_ratio", "histogram_smoothing", "N", "K",
       "boundary_model", "step_threshold", "step_sign"]


def load(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            rows.append(dict(
                key=tuple(r[k] for k in KEY), space=r["colour_space"], chosen=r["chosen"] == "1",
                score=float(r["score_m"]),
                w5=float(r["route_within_5cm"]),
                errors=[float(x) for x in r["frame_errors_m"].split()],
                shortfalls=[float(x) for x in r["frame_shortfalls_m"].split()]))
    return rows


def sign_test_tail(k, n):
    """P(X >= k), X ~ Binomial(n, 1/2)."""
    return sum(math.comb(n, i) for i in range(k, n + 1)) / 2 ** n


def within_noise(a, b):
    """ParameterLearning's withinNoiseOf on per-frame errors."""
    n = min(len(a), len(b))
    if n < 6:
        return False
    d = [a[i] - b[i] for i in range(n)]
    mean = sum(d) / n
    se = math.sqrt(sum((x - mean) ** 2 for x in d) / (n - 1) / n)
    worse = sum(x > 0 for x in d)
    differ = worse + sum(x < 0 for x in d)
    worse_on_most = 2 * worse > differ and 2 * sign_test_tail(worse, differ) < 0.05
    return mean <= 2 * se and not worse_on_most


def weighted(r, w):
    return [e - s + w * s for e, s in zip(r["errors"], r["shortfalls"])]


def lowest(rows, w=1.0, tie=True):
    errs = {id(r): weighted(r, w) for r in rows}
    # Unweighted, learning's own score (a mean over every ray, not over frames).
    score = (lambda r: r["score"]) if w == 1.0 else (lambda r: statistics.mean(errs[id(r)]))
    low = min(rows, key=score)
    if tie and low["space"] != "CHROMA":
        chroma = [r for r in rows if r["space"] == "CHROMA"]
        if chroma:
            c = min(chroma, key=score)
            if within_noise(errs[id(c)], errs[id(low)]):
                return c
    return low


def main():
    root, worlds = sys.argv[1], sys.argv[2:]
    data = {w: load(f"{root}/{w}/candidates_on_route.csv") for w in worlds}
    by_key = {w: {r["key"]: r for r in rows} for w, rows in data.items()}
    shared = set.intersection(*(set(k) for k in by_key.values()))
    ways = ["learned", "lowest", "best", "fixed", "tie+prior", "shortfall 0.75", "shortfall 0.5", "shortfall 0.25"]
    print("| world | " + " | ".join(ways) + " |")
    print("|---" * (len(ways) + 1) + "|")
    totals = dict.fromkeys(ways, 0.0)
    for w in worlds:
        rows = data[w]
        others = [o for o in worlds if o != w]
        prior = {k: statistics.mean(by_key[o][k]["w5"] for o in others) for k in shared} if others else {}
        low = lowest(rows, tie=False)
        tie_set = [r for r in rows if r is low or within_noise(r["errors"], low["errors"])]
        read = {
            "learned": next(r for r in rows if r["chosen"])["w5"],
            "lowest": low["w5"],
            "best": max(r["w5"] for r in rows),
            "fixed": by_key[w][max(sorted(shared), key=lambda k: prior[k])]["w5"] if prior else float("nan"),
            "tie+prior": max(tie_set, key=lambda r: prior.get(r["key"], -1))["w5"] if prior else float("nan"),
        }
        for x in (0.75, 0.5, 0.25):
            read[f"shortfall {x}"] = lowest(rows, x)["w5"]
        for k in ways:
            totals[k] += read[k]
        print(f"| {w} | " + " | ".join(f"{100 * read[k]:.1f} %" for k in ways) + " |")
    print("| mean | " + " | ".join(f"{100 * totals[k] / len(worlds):.1f} %" for k in ways) + " |")


if __name__ == "__main__":
    main()
