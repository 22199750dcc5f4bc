"""The result of breakshot.simulate."""

from __future__ import annotations

import json
from functools import cached_property

__all__ = ["Result"]


class Result:
    """A finished run: the result file of ``breakshot simulate``, read.

    ``to_json()`` gives the file's exact text; ``complete``, ``events``,
    ``final``, ``samples`` (and ``cue``, when the scenario had a strike)
    are that file's fields as plain Python values (docs/contract.md).
    ``frames`` holds the dense frames of ``simulate(..., trace=True)``
    (breakshot.Frames), else None.
    """

    __slots__ = ("_text", "frames", "__dict__")

    def __init__(self, text: str, frames=None):
        self._text = text
        self.frames = frames

    def to_json(self) -> str:
        """The result file's text, byte for byte what the CLI prints."""
        return self._text

    @cached_property
    def _data(self) -> dict:
        return json.loads(self._text)

    @property
    def complete(self) -> bool:
        """False when the run stopped at the scenario's max_events."""
        return self._data["complete"]

    @property
    def events(self) -> list:
        """Every event in time order, as dicts (time, type, balls, ...)."""
        return self._data["events"]

    @property
    def final(self) -> dict:
        """The state at the end: time and every ball's state."""
        return self._data["final"]

    @property
    def samples(self) -> list:
        """The sampled states (empty unless the scenario asks for them)."""
        return self._data.get("samples", [])

    @property
    def cue(self):
        """What the cue strike did (a dict), or None without a strike."""
        return self._data.get("cue")

    def __eq__(self, other):
        return isinstance(other, Result) and other._text == self._text

    def __hash__(self):
        return hash(self._text)

    def __repr__(self):
        d = self._data
        return (
            f"<breakshot.Result complete={d['complete']} events={len(d['events'])} "
            f"t={d['final']['time']:.6g}"
            + (f" frames={len(self.frames)}" if self.frames is not None else "")
            + ">"
        )
