"""Solution.plot: draws with matplotlib when it is installed, and says what to install when
it is not."""

from __future__ import annotations

import sys

import numpy as np
import pytest

from orthoslip import Contact, Material


def test_plot_draws_p_q_and_the_stick_zone(ply: Material) -> None:
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    s = Contact(ply, 0.3).solve()
    ax = s.plot(points=101)
    p_line, q_line = ax.get_lines()
    x, p = p_line.get_data()
    assert len(x) == 101 and -1 < x[0] and x[-1] < 1
    np.testing.assert_array_equal(p, s.tractions(x)[0])
    np.testing.assert_array_equal(q_line.get_ydata(), s.tractions(x)[1])
    assert "stick zone" in ax.get_legend_handles_labels()[1][0]
    import matplotlib.pyplot as plt

    plt.close(ax.figure)


def test_plot_without_matplotlib_says_what_to_install(ply: Material, monkeypatch) -> None:
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.pyplot", None)
    with pytest.raises(ImportError, match="pip install matplotlib"):
        Contact(ply, 0.3).solve().plot()
