from __future__ import annotations

import sys
from pathlib import Path

import cv2

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from tools.paper.plot import failure_figure, failure_plot  # noqa: E402

CURVES = {"baseline": [(0.0, 1.0), (60.0, 0.5), (120.0, 0.0)], "no_wait": [(0.0, 1.0), (120.0, 0.2)]}


def test_figure11_has_our_curves_the_papers_marks_axes_and_units() -> None:
    fig = failure_figure(CURVES, "a title")
    ax = fig.axes[0]
    labels = [line.get_label() for line in ax.get_lines()]
    assert labels[:2] == ["ours: baseline", "ours: no_wait"]
    assert any(label.startswith("paper: mean task time (28.9 min)") for label in labels)
    assert any(label.startswith("paper: time allowed (35 min)") for label in labels)
    assert [t.get_text() for t in ax.get_legend().get_texts()] == labels
    assert ax.get_xlabel() == "maximum time allowed (minutes)"
    assert ax.get_ylabel() == "failure rate (%)"
    xs, ys = ax.get_lines()[0].get_data()
    assert list(xs) == [0.0, 1.0, 2.0] and list(ys) == [100.0, 50.0, 0.0]


def test_failure_plot_writes_a_png(tmp_path: Path) -> None:
    failure_plot(CURVES, tmp_path / "f.png", "t")
    image = cv2.imread(str(tmp_path / "f.png"))
    assert image is not None and image.shape[:2] == (450, 750)
