# SPDX-License-Identifier: MIT
"""plot(): the loop, prediction vs measurement and the error (matplotlib, optional)."""
import numpy as np


def _pyplot():
    try:
        import matplotlib

        if not hasattr(matplotlib, "get_backend"):
            raise ImportError("matplotlib is incomplete")
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise ImportError(
            "hyst.plot needs matplotlib, which is not installed: "
            "pip install matplotlib (or pip install 'hyst[plot]')") from e
    return plt


def plot(x, y_model, y_measured=None, *, path=None, title=None):
    """Draws input vs output (the hysteresis loop) and, given measurements,
    prediction vs measurement over the samples and the error.

    ``y_model`` is an array of outputs or a model (anything with
    ``process``), which is then run on ``x`` as it is (not reset); a
    :class:`Fit` with its delay: the prediction of measured output k is its
    output for input k - delay (its output at the start before), as
    ``hyst sim --model`` delays it.
    Saves the figure to ``path`` if given; returns the matplotlib figure.
    matplotlib is imported here only: without it this raises ImportError.
    """
    plt = _pyplot()
    x = np.asarray(x)
    if hasattr(y_model, "process"):
        # a Fit's delay is the measurement's: its output k is the model's for
        # input k - delay, the model at rest before (as hyst sim --model)
        delay = int(getattr(y_model, "delay", 0) or 0)
        rest = y_model.output
        y_model = np.asarray(y_model.process(np.asarray(x, dtype=y_model.dtype)), dtype=np.float64)
        if delay > 0:
            y_model = np.concatenate([np.full(min(delay, y_model.size), float(rest)),
                                      y_model[:max(y_model.size - delay, 0)]])
    y_model = np.asarray(y_model, dtype=np.float64)
    rows = 1 if y_measured is None else 3
    fig, axes = plt.subplots(rows, 1, figsize=(7, 3 + 2.5 * (rows - 1)), squeeze=False)
    axes = axes[:, 0]
    loop = axes[0]
    if y_measured is not None:
        y_measured = np.asarray(y_measured, dtype=np.float64)
        loop.plot(x, y_measured, ".", ms=2, color="0.6", label="measured")
    loop.plot(x, y_model, "-", lw=1, label="model")
    loop.set_xlabel("input")
    loop.set_ylabel("output")
    loop.set_title(title or "hysteresis loop")
    loop.legend(loc="best")
    if y_measured is not None:
        k = np.arange(x.size)
        axes[1].plot(k, y_measured, color="0.6", lw=1, label="measured")
        axes[1].plot(k, y_model, lw=1, label="model")
        axes[1].set_ylabel("output")
        axes[1].legend(loc="best")
        err = y_model - y_measured
        rms = float(np.sqrt(np.mean(err ** 2))) if err.size else 0.0
        axes[2].plot(k, err, lw=1, color="C3")
        axes[2].set_ylabel("model - measured")
        axes[2].set_xlabel("sample")
        axes[2].set_title(f"error (RMS {rms:.4g})")
    fig.tight_layout()
    if path is not None:
        fig.savefig(path)
    return fig
