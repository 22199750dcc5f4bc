"""How a scenario given from Python becomes the JSON text the engine reads."""

from __future__ import annotations

import json
import os

from .errors import ScenarioError


def scenario_text(scenario) -> str:
    """JSON text from a dict, JSON text, or a path (str or os.PathLike).

    A str whose first non-blank character is ``{`` is JSON text; any other
    str is a path. Bytes are read as UTF-8 JSON text.
    """
    if isinstance(scenario, dict):
        try:
            return json.dumps(scenario, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise ScenarioError("", f"the dict is not JSON: {e}") from None
    if isinstance(scenario, (bytes, bytearray)):
        return bytes(scenario).decode("utf-8")
    if isinstance(scenario, str):
        if scenario.lstrip().startswith("{"):
            return scenario
        return _read(scenario)
    if isinstance(scenario, os.PathLike):
        return _read(os.fspath(scenario))
    raise TypeError(
        "a scenario is a breakshot.Scenario, a dict, JSON text or a path, "
        f"not {type(scenario).__name__}"
    )


def _read(path) -> str:
    with open(path, "rb") as f:
        return f.read().decode("utf-8")
