"""Exceptions raised by breakshot."""

from __future__ import annotations

__all__ = ["ScenarioError"]


class ScenarioError(ValueError):
    """A scenario that breakshot cannot simulate.

    ``path`` is the JSON path of the field at fault (``"balls[1].radius"``),
    ``reason`` what is wrong with it. ``str(error)`` is the message of
    ``breakshot simulate`` for the same file, without its ``breakshot: ``
    prefix. ``unsupported`` is True when the scenario asks for something
    valid that the engine does not implement yet (the command's exit
    status 1 rather than 2).
    """

    def __init__(self, path: str, reason: str, unsupported: bool = False):
        self.path = path
        self.reason = reason
        self.unsupported = bool(unsupported)
        kind = "not supported yet" if self.unsupported else "invalid scenario"
        super().__init__(f"{kind}: {path}: {reason}")

    def __reduce__(self):
        return (type(self), (self.path, self.reason, self.unsupported))
