#!/usr/bin/python3
"""The AI's target figures from the summaries bench/ai_targets.sh wrote.

    bench/ai_targets_report.py OUT

Reads OUT/<match>.json (the summed summaries) and OUT/timing-<game>.json
and prints one line per figure of docs/ai.md, "Targets of the
rules-driven AI", beside its target; a match not (yet) played is said
to be missing. Standard library only.
"""

import json
import os
import sys


def load(out, name):
    path = os.path.join(out, name + ".json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def won(s, seat=0):
    p = s["players"]
    return f"{p[seat]['games_won']} : {p[1 - seat]['games_won']} of {s['games_played']}", \
        p[seat]["games_won"] / s["games_played"]


def line(what, value, target, met):
    mark = "" if met is None else "met" if met else "NOT met"
    print(f"{what:58s} {value:28s} {target:22s} {mark}")


def main():
    if len(sys.argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    out = sys.argv[1]
    print(f"{'figure':58s} {'measured':28s} {'target':22s}")
    for name, label, share in [("nine", "9-ball champion vs baseline", 0.95),
                               ("eight", "8-ball champion vs baseline", 0.98),
                               ("ten", "10-ball champion vs baseline", 0.90)]:
        s = load(out, name)
        if s is None:
            print(f"{label:58s} missing")
            continue
        text, frac = won(s)
        line(label + ", games", f"{text} ({100 * frac:.1f} %)", f">= {100 * share:.0f} %",
             frac >= share)
        c = s["players"][0]
        line(label + ", pots made", f"{c['pots_made']} / {c['pot_attempts']} "
             f"({100 * c['pot_rate']:.1f} %)", "", None)
        if name == "eight":
            line("8-ball break-and-runs per 100 breaks (champion)",
                 f"{c['break_and_runs']} / {c['breaks']}", ">= 40 per 100",
                 c["breaks"] > 0 and 100 * c["break_and_runs"] / c["breaks"] >= 40)
    for pair in ["amateur-beginner", "club-amateur", "expert-club", "champion-expert"]:
        s = load(out, "ten-" + pair)
        label = "10-ball " + pair.replace("-", " vs ")
        if s is None:
            print(f"{label:58s} missing")
            continue
        text, frac = won(s)
        line(label, f"{text} ({100 * frac:.1f} %)", "upper wins more", frac > 0.5)
    s = load(out, "snooker")
    if s is None:
        print(f"{'snooker champion vs baseline':58s} missing")
    else:
        text, frac = won(s)
        line("snooker champion vs baseline, frames", f"{text} ({100 * frac:.1f} %)", ">= 95 %",
             frac >= 0.95)
        k = s["players"][0]["snooker"]
        line("snooker champion, mean break (scoring visits)",
             f"{k['mean_break']:.1f} ({k['scoring_visits']} visits)", ">= 18", k["mean_break"] >= 18)
    s = load(out, "snooker-half")
    if s is None:
        print(f"{'snooker champion@0.5x vs baseline':58s} missing")
    else:
        k = s["players"][0]["snooker"]
        n = s["games_played"]
        line("snooker champion@0.5x, mean break", f"{k['mean_break']:.1f}", ">= 40",
             k["mean_break"] >= 40)
        line(f"snooker champion@0.5x, centuries in {n} frames", f"{k['breaks_100']}",
             ">= 10 per 100", 100 * k["breaks_100"] / n >= 10)
    s = load(out, "carom")
    if s is None:
        print(f"{'three-cushion champion vs champion':58s} missing")
    else:
        p = s["players"]
        pts = sum(x["carom"]["points"] for x in p) if "carom" in p[0] else None
        inn = sum(x["innings"] for x in p)
        if pts is not None and inn:
            line("three-cushion general average, champion vs champion", f"{pts / inn:.3f}",
                 ">= 1.5", pts / inn >= 1.5)
        else:
            print("three-cushion: no carom figures in the summary")
    for game in ["eight_ball", "nine_ball", "ten_ball", "snooker"]:
        s = load(out, "timing-" + game)
        if s is None:
            print(f"{'champion decision time, ' + game:58s} missing")
            continue
        t = s["players"][0].get("timing") or s["players"][0].get("decision_seconds")
        if t is None:
            print(f"champion decision time, {game}: no timing in the summary")
            continue
        line(f"champion decision time, {game}", f"median {t['median']:.2f} s, max {t['max']:.2f} s",
             "<= 0.5 s, max <= 3 s", t["median"] <= 0.5 and t["max"] <= 3.0)
    return 0


if __name__ == "__main__":
    sys.exit(main())
