"""Figure 11 as a PNG, drawn with matplotlib: failure rate against the maximum time allowed."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from matplotlib.figure import Figure

from tools.paper.reference import PAPER_LIMIT_SECONDS, PAPER_MEAN_MINUTES

PAPER_LIMIT_MINUTES = PAPER_LIMIT_SECONDS / 60


def failure_plot(curves: dict[str, Sequence[tuple[float, float]]], path: Path, title: str) -> None:
    """Write `failure_figure` as a PNG."""
    fig = failure_figure(curves, title)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, metadata={"Software": None})


def failure_figure(curves: dict[str, Sequence[tuple[float, float]]], title: str) -> Figure:
    """Each curve: (limit in seconds, failure rate) points, as a step line; the paper's mean task
    time and its limit are drawn beside ours (the paper gives no points of its own curve)."""
    fig = Figure(figsize=(7.5, 4.5), dpi=100)
    ax = fig.subplots()
    for i, (name, points) in enumerate(curves.items()):
        minutes = [limit / 60 for limit, _ in points]
        rates = [100 * rate for _, rate in points]
        ax.step(minutes, rates, where="post", label=f"ours: {name}", linewidth=2.5 if i == 0 else 1.5)
    ax.axvline(PAPER_MEAN_MINUTES, color="grey", linestyle="--", linewidth=1,
               label=f"paper: mean task time ({PAPER_MEAN_MINUTES} min)")
    ax.axvline(PAPER_LIMIT_MINUTES, color="black", linestyle=":", linewidth=1,
               label=f"paper: time allowed ({PAPER_LIMIT_MINUTES:g} min)")
    ax.set_xlabel("maximum time allowed (minutes)")
    ax.set_ylabel("failure rate (%)")
    ax.set_ylim(-2, 102)
    ax.set_xlim(left=0)
    ax.set_title(title, fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    return fig
