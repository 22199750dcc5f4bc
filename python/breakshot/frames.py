"""Dense frames of a run, for plots: breakshot.simulate(scenario, trace=True)."""

from __future__ import annotations

__all__ = ["Frames"]


class Frames:
    """The state of every ball at the time of every event (just after it)
    and at evenly spaced times from 0 to the end of the run, merged in time
    order: the frames that ``breakshot simulate --plot`` draws its SVG plots
    from, taken from the same single run as the result.

    Arrays (numpy, float64; m frames, n balls in scenario order):

    ``times`` (m,)
        seconds.
    ``positions`` (m, n, 2), ``velocities`` (m, n, 2), ``spins`` (m, n, 3)
        metres, m/s, rad/s.
    ``energy`` (m, n), ``energy_total`` (m,)
        kinetic energy, translational plus rotational (a solid sphere,
        I = 2/5 m r^2), in joules: the engine's ``kinetic_energy``.
    ``momentum`` (m, n, 2), ``momentum_total`` (m, 2)
        linear momentum m v in kg m/s: the engine's ``momentum``.

    Totals are summed over the balls in scenario order, as the CLI's plots
    sum them. The scenario's ``ids``, ``radii`` and ``masses`` (n,), its
    physics ``model`` ('ideal', 'friction' or 'pool') and its ``table`` (a
    dict: ``outline`` (k, 2), ``pockets`` as (name, x, y, radius),
    ``min``, ``max``, and for pool tables ``length`` and ``width``) come
    with them.
    """

    __slots__ = (
        "times", "positions", "velocities", "spins", "energy", "energy_total",
        "momentum", "momentum_total", "ids", "radii", "masses", "model", "table",
    )

    def __init__(self, data: dict):
        for name in self.__slots__:
            setattr(self, name, data[name])

    def __len__(self) -> int:
        """The number of frames, m."""
        return len(self.times)

    def __repr__(self) -> str:
        t = self.times
        span = f" t={t[0]:.6g}..{t[-1]:.6g}" if len(t) else ""
        return (f"<breakshot.Frames frames={len(t)} balls={len(self.ids)} "
                f"model={self.model}{span}>")
