"""breakshot: exact, event-driven billiards physics, games and AI.

    import breakshot
    result = breakshot.simulate("examples/lab/two_balls.json")
    print(result.events[0])

Every name is documented in docs/python.md.
"""

from __future__ import annotations

from . import _core
from .errors import ScenarioError
from .result import Result
from .game import (Call, Decide, Game, LegalActions, Outcome, PlaceCue, Player, Shot, State,
                   action_from_dict, games, match, match_json, mix_seed, players)

__version__ = _core.version
Scenario = _core.Scenario

__all__ = ["__version__", "Scenario", "ScenarioError", "Result", "simulate"]
__all__ += ["Game", "State", "LegalActions", "Outcome", "Shot", "PlaceCue", "Decide", "Call",
            "action_from_dict", "Player", "games", "players", "match", "match_json", "mix_seed"]


def simulate(scenario) -> Result:
    """Simulate a scenario and return its Result.

    ``scenario`` is a dict, JSON text, a path or a breakshot.Scenario.
    ``simulate(s).to_json()`` is byte for byte what ``breakshot simulate``
    writes for the same scenario. Raises ScenarioError (a ValueError) naming
    the field when the scenario is invalid.
    """
    return Result(_core.simulate_text(scenario))
