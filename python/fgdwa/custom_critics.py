"""Critics written in Python, registered by name like the built-in ones.

A critic class is built with the numeric parameters and word options given in
its ``CriticConfig`` (``PlannerParams(critics=[("my_critic", 0.3, {"k": 2.0})])``
calls ``MyCritic(k=2.0)``) and has:

- ``sense``: ``"reward"`` (larger is better, the default) or ``"cost"``;
- ``needs_path`` (optional, default False): the planner refuses to run it
  without a global path;
- ``prepare(context)`` (optional), once per control cycle, with a dict of
  ``pose`` (x, y, theta), ``velocity`` (v, omega), ``goal``, ``target`` (what
  the heading aims at), ``dt`` and ``path`` ((n, 2) points or None);
- ``score_batch(poses, commands, min_clearance) -> (n,) array``: ``poses``
  (n, steps, 3) of the admissible rollouts, ``commands`` (n, 2) v and omega,
  ``min_clearance`` (n,) metres. A NaN score vetoes that sample: it is rejected
  with reason ``Critic`` and counted against this critic. Every other score
  must be finite.

Cost: the planner copies the rollouts into numpy arrays and calls back into
Python once per cycle: a critic returning zeros added 18-19 us to a 76 us plan
of 441 samples of 20 poses (open space, measured on 2 cores), before the
critic's own numpy work; a C++ critic costs a few microseconds. The
registry is per process: a Dask worker or a pool process must register the
critic too (e.g. in the module that defines it, imported by the task).
"""

from __future__ import annotations

from fgdwa._core import FgdwaError, register_python_critic
from fgdwa.file_limits import short_repr


def register_critic(name: str, cls) -> None:
    """Make ``cls`` buildable as critic ``name`` (see the module's docstring);
    FgdwaError when the name is empty or taken, or ``cls`` lacks ``score_batch``."""
    if not isinstance(name, str):
        raise FgdwaError(f"register_critic: name = {short_repr(name)}: expected a string")
    register_python_critic(name, cls)
