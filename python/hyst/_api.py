# SPDX-License-Identifier: MIT
"""Constructors that pick the library's variant by numpy dtype, and fit()."""
import numpy as np

from . import _hyst

#: Turning-point entries per array: never full for inputs taking 4096
#: distinct values (a 12-bit DAC), HYST_CAPACITY(4096).
DEFAULT_CAPACITY = 2048

_METHODS = {"joint": 1, "reflect": 2}


def _variant(dtype, f32, f64):
    dt = np.dtype(dtype)
    if dt == np.float64:
        return f64
    if dt == np.float32:
        return f32
    raise TypeError(f"dtype must be float32 or float64, not {dt}")


def Model(coeffs, lo, hi, *, dtype=np.float64, capacity=DEFAULT_CAPACITY, deadband=0.0):
    """A TCM model with polynomial f0 (coefficients highest power first) on [lo, hi].

    float64 runs the library's ``hyst_f64_*`` variant, float32 ``hyst_f32_*``.
    The instance owns ``capacity`` entries per turning-point array.
    """
    m = _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, coeffs)), float(lo), float(hi), int(capacity), False)
    if deadband:
        m.deadband = deadband
    return m


def Compensator(coeffs, lo, hi, *, dtype=np.float64, capacity=DEFAULT_CAPACITY):
    """The inverse model of Model(coeffs, lo, hi): desired output in, drive out."""
    return _variant(dtype, _hyst.ModelF32, _hyst.ModelF64)(
        list(map(float, coeffs)), float(lo), float(hi), int(capacity), True)


def PI(thresholds, weights, *, dtype=np.float64):
    """A Prandtl-Ishlinskii model; ``.inverse()`` gives its inverse."""
    return _variant(dtype, _hyst.PIF32, _hyst.PIF64)(
        list(map(float, thresholds)), list(map(float, weights)))


class Fit:
    """An identified f0 (hyst_ident_fit()) and the model it defines.

    Attributes: ``coeffs`` (highest power first), ``lo``, ``hi``, ``degree``,
    ``method``, ``rms`` and ``max_abs`` (residuals of the measured samples
    against the major loop), ``used``, ``rising``, ``falling``,
    ``increasing``, ``y_lo_est``, ``y_hi_est``, and ``model``, a Model with
    this f0 at A0. Model calls (``process``, ``step``, ``reset``...) go to
    ``model``, so a Fit is used as the model itself.
    """

    def __init__(self, result, dtype, capacity):
        self.__dict__.update(result)
        self.method = {v: k for k, v in _METHODS.items()}[result["method"]]
        self.model = Model(self.coeffs, self.lo, self.hi, dtype=dtype, capacity=capacity)

    def __getattr__(self, name):
        # only called for names not found on the Fit itself
        return getattr(self.__dict__["model"], name)

    def predict(self, x):
        """Outputs of a fresh model (at A0) for the inputs x; ``model`` is untouched."""
        m = Model(self.coeffs, self.lo, self.hi, dtype=self.model.dtype,
                  capacity=self.model.capacity)
        return m.process(np.ascontiguousarray(x, dtype=self.model.dtype))

    def __repr__(self):
        c = ", ".join(f"{v:.9g}" for v in self.coeffs)
        return (f"Fit(coeffs=[{c}], lo={self.lo:.9g}, hi={self.hi:.9g}, "
                f"rms={self.rms:.6g}, max_abs={self.max_abs:.6g}, method={self.method!r})")


def fit(x, y, degree=3, *, method="joint", domain=None, skip=0, delay=0,
        dtype=np.float64, capacity=DEFAULT_CAPACITY):
    """Identifies f0 from a recorded drive ``x`` and response ``y`` (hyst_ident_fit()).

    Sample i (skip <= i < n - delay) pairs x[i] with y[i + delay]; the domain
    is ``domain=(lo, hi)`` or the range of those inputs. ``method`` is
    ``"joint"`` (both branches in one least-squares problem) or
    ``"reflect"`` (the paper's Eq. 14). Returns a :class:`Fit`.
    """
    if method not in _METHODS:
        raise ValueError(f"method must be one of {sorted(_METHODS)}, not {method!r}")
    lo, hi = (0.0, 0.0) if domain is None else (float(domain[0]), float(domain[1]))
    res = _hyst.fit(np.ascontiguousarray(x, dtype=np.float64),
                    np.ascontiguousarray(y, dtype=np.float64),
                    int(degree), _METHODS[method], lo, hi, int(skip), int(delay))
    return Fit(res, dtype, capacity)
