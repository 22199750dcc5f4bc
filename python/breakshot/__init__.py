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
from .batch import STRIKE_COLUMNS, ShotResults, shots

__version__ = _core.version
Scenario = _core.Scenario
Simulation = _core.Simulation

__all__ = ["__version__", "Scenario", "ScenarioError", "Result", "simulate",
           "Simulation", "shots", "ShotResults", "STRIKE_COLUMNS"]


def simulate(scenario) -> Result:
    """Simulate a scenario and return its Result.

    ``scenario`` is a dict, JSON text, a path or a breakshot.Scenario.
    ``simulate(s).to_json()`` is byte for byte what ``breakshot simulate``
    writes for the same scenario. Raises ScenarioError (a ValueError) naming
    the field when the scenario is invalid.
    """
    return Result(_core.simulate_text(scenario))
