"""breakshot: exact, event-driven billiards physics, games and AI.

    import breakshot
    result = breakshot.simulate("examples/lab/two_balls.json")
    print(result.events[0])

Every name is documented in docs/python.md.
"""

from __future__ import annotations

from . import _core
from .errors import ScenarioError
from .frames import Frames
from .pot_maps import PotMap, pot_chance, pot_map
from .result import Result
from .game import (Call, Decide, Game, LegalActions, Outcome, PlaceCue, Player, Shot, State,
                   action_from_dict, games, match, match_json, mix_seed, physics_of, players)
from .batch import STRIKE_COLUMNS, ShotResults, shots

__version__ = _core.version
Scenario = _core.Scenario
Simulation = _core.Simulation

__all__ = ["__version__", "Scenario", "ScenarioError", "Result", "simulate",
           "Simulation", "shots", "ShotResults", "STRIKE_COLUMNS"]
__all__ += ["Game", "State", "LegalActions", "Outcome", "Shot", "PlaceCue", "Decide", "Call",
            "action_from_dict", "Player", "games", "players", "match", "match_json", "mix_seed",
            "physics_of"]
__all__ += ["Frames", "PotMap", "pot_chance", "pot_map"]


def simulate(scenario, *, trace=False) -> Result:
    """Simulate a scenario and return its Result.

    ``scenario`` is a dict, JSON text, a path or a breakshot.Scenario.
    ``simulate(s).to_json()`` is byte for byte what ``breakshot simulate``
    writes for the same scenario. Raises ScenarioError (a ValueError) naming
    the field when the scenario is invalid.

    ``trace=True`` also records dense frames for plots (``result.frames``, a
    breakshot.Frames: every event's time and 2000 evenly spaced times, as
    ``breakshot simulate --plot``); an int asks for that many evenly spaced
    times instead. The run is the same single run: ``to_json()`` does not
    change.
    """
    if trace is False or trace is None:
        return Result(_core.simulate_text(scenario))
    if trace is True:
        points = 2000
    elif isinstance(trace, int) and trace >= 2:
        points = trace
    else:
        raise ValueError(f"trace must be True, False or a number of points >= 2, not {trace!r}")
    data = _core.simulate_traced(scenario, points)
    return Result(data.pop("text"), Frames(data))


def __getattr__(name):
    # breakshot.plot is imported on first use, so that `import breakshot`
    # works without matplotlib.
    if name == "plot":
        import importlib

        return importlib.import_module(".plot", __name__)
    raise AttributeError(f"module 'breakshot' has no attribute {name!r}")
