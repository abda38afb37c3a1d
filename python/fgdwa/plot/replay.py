"""replay.png of ``fgdwa replay BAG`` (:mod:`fgdwa.adapters.replay`): the commands
fgdwa_node recorded and the replayed ones, over time."""

from __future__ import annotations

from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from fgdwa.plot.episode import save_figure  # noqa: E402


def plot_replay(cycles: Sequence, path, title: str = "") -> Path:
    """The recorded and replayed v and omega over the node's time, the differing cycles marked
    (``cycles``: fgdwa.adapters.replay.ReplayCycle)."""
    t = np.array([c.time for c in cycles])
    bad = np.array([not c.matches for c in cycles], dtype=bool)
    fig, axes = plt.subplots(2, 1, figsize=(9, 5), sharex=True)
    for ax, (name, unit, rec, rep) in zip(axes, [
            ("v", "m/s", [c.v_recorded for c in cycles], [c.v_replayed for c in cycles]),
            ("omega", "rad/s", [c.omega_recorded for c in cycles], [c.omega_replayed for c in cycles])]):
        ax.plot(t, rec, color="0.3", lw=2.0, label="recorded (fgdwa_node)")
        ax.plot(t, rep, color="tab:orange", lw=1.0, ls="--", label="replayed")
        if bad.any():
            ax.scatter(t[bad], np.asarray(rec)[bad], color="tab:red", s=14, zorder=3, label="differs")
        ax.set_ylabel(f"{name} ({unit})")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="best", fontsize=8)
    axes[-1].set_xlabel("node time (s)")
    axes[0].set_title(f"{title}: {int(np.sum(~bad))} of {len(cycles)} commands the same")
    fig.tight_layout()
    return save_figure(fig, path, dpi=110)
