#!/usr/bin/env python3
"""How a player's snooker visits end, from recorded frames (docs/ai.md,
"Snooker", "What ends the breaks").

    breakshot match --game snooker --players champion,baseline --games 20 \
        --seed 1 --noise tournament --records /tmp/records
    bench/snooker_visits.py --player champion /tmp/records/game-*.json

A visit is the player's run of shots at the table; it scores when it pots
at least one ball on. For the scoring visits, printed: how many there
are, their mean (the match summary's mean break), and how many ended after
1, 2, 3, ... pots (the shot that ended it being the next one: after one
pot, the colour after the first red, or the red after the first colour).
Reads the records' rulings only; plain Python, no breakshot module.
"""

import argparse
import collections
import json
import sys


def visits(record, player):
    """(points, pots) of each of `player`'s scoring visits in `record`."""
    seat = record["players"].index(player)
    out = []
    points = pots = 0
    at_table = False
    for a in record["actions"]:
        if a["action"]["type"] != "shoot":
            continue
        ruling = a["ruling"]
        if a["player"] != seat:
            continue
        scored = (ruling.get("snooker") or {}).get("points", 0) if not ruling["fouls"] else 0
        if not at_table:
            points = pots = 0
            at_table = True
        if scored > 0:
            points += scored
            pots += 1
        if not ruling["turn_continues"]:
            if points > 0:
                out.append((points, pots))
            at_table = False
    if at_table and points > 0:
        out.append((points, pots))  # the frame ended in the visit
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--player", default="champion")
    parser.add_argument("records", nargs="+")
    args = parser.parse_args()
    found = []
    for path in args.records:
        with open(path, encoding="utf-8") as f:
            record = json.load(f)
        if args.player not in record["players"]:
            sys.exit(f"snooker_visits: {path}: no player {args.player!r} "
                     f"(players: {', '.join(record['players'])})")
        if record["config"]["game"] != "snooker":
            sys.exit(f"snooker_visits: {path}: not a snooker record")
        found += visits(record, args.player)
    if not found:
        print(f"{args.player}: no scoring visits")
        return
    mean = sum(p for p, _ in found) / len(found)
    print(f"{args.player}: {len(found)} scoring visits, mean break {mean:.1f}, "
          f"highest {max(p for p, _ in found)}")
    ends = collections.Counter(min(n, 10) for _, n in found)
    print("visits by pots made before the visit ended (10: ten or more):")
    for n in sorted(ends):
        print(f"  {n:2d}: {ends[n]}")


if __name__ == "__main__":
    main()
