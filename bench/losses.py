#!/usr/bin/python3
"""How a player lost its pool games: reads game records (breakshot match
--records DIR) and sorts each game that the player named NAME lost by how
the opponent's winning visit began (docs/ai.md, "What limits the
champion").

    bench/losses.py NAME DIR/game-*.json      (NAME as the records name it)

A game is lost either from the opponent's break without NAME at the table
(the game ball on the break, or a run from the break) or after NAME's last
shot. That last shot is a foul, a declared safety (or push-out), a called
or attempted pot that did not keep the turn (a miss), or a shot that kept
nothing else. Also prints how long the opponent's winning visit was (its
shots). Standard library only.
"""

import collections
import json
import sys


def lost_how(record, seat):
    actions = record["actions"]
    last = actions[-1]
    if last["ruling"]["winner"] != 1 - seat:
        return None
    shots = [a for a in actions if a["action"]["type"] == "shoot"]
    mine = [a for a in shots if a["player"] == seat]
    if not mine:
        broke = shots and shots[0]["player"] == 1 - seat
        if len(shots) == 1 and broke:
            return "the game ball on the opponent's break", 1
        return "a run from the opponent's break", len(shots)
    i = max(k for k, a in enumerate(shots) if a["player"] == seat)
    visit = len(shots) - i - 1
    a = mine[-1]
    r = a["ruling"]
    act = a["action"]
    if r["fouls"]:
        why = "after its foul (" + ", ".join(r["fouls"]) + ")"
    elif act.get("push_out"):
        why = "after its push-out"
    elif act.get("safety"):
        why = "after its declared safety"
    elif act.get("call") is not None:
        why = "after a missed called pot"
    else:
        why = "after an uncalled shot (a safety where none is declared, or a kick)"
    return why, visit


def main():
    if len(sys.argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    name = sys.argv[1]
    reasons = collections.Counter()
    visits = collections.defaultdict(list)
    games = 0
    for path in sys.argv[2:]:
        with open(path) as f:
            rec = json.load(f)
        if name not in rec["players"]:
            sys.stderr.write(f"losses.py: {path} has no player {name!r} ({rec['players']})\n")
            return 2
        games += 1
        how = lost_how(rec, rec["players"].index(name))
        if how is None:
            continue
        reasons[how[0]] += 1
        visits[how[0]].append(how[1])
    lost = sum(reasons.values())
    print(f"{games} games, {name} lost {lost}")
    for why, n in reasons.most_common():
        v = sorted(visits[why])
        print(f"{n:4d}  {why}  (the winning visit's shots: {v})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
