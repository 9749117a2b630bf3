# SPDX-License-Identifier: MIT
"""hyst: hysteresis models (trajectory construction method) for actuators.

Every number is computed by the C library that runs on the target (the
extension ``hyst._hyst`` is built from the repository's ``src/``): identify
f0 on a PC, check the model against measurements, deploy the coefficients.

>>> import numpy as np, hyst
>>> m = hyst.Model([-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1], lo=0, hi=40)
>>> y = m.process(np.array([0.0, 20.0, 10.0, 40.0]))

See docs/python.md in the repository.
"""
from ._errors import FitWarning, HystError
from ._hyst import (
    CODE_MAX,
    CREEP_MAX_TERMS,
    EVERETT_MAX_DEGREE,
    EVENT_CLAMPED,
    EVENT_FULL,
    EVENT_NONFINITE,
    MAX_DEGREE,
    SNAPSHOT_VERSION,
    CodeModel,
    CreepF32,
    CreepF64,
    ModelF32,
    ModelF64,
    PIF32,
    PIF64,
    Status,
    Tcm,
    __version__,
    status_str,
)
from ._api import (
    DEFAULT_CAPACITY,
    EVERETT_INV_INTERVALS,
    EVERETT_INV_ROWS,
    INV_TABLE,
    PI,
    SPLINE_MAX_INTERVALS,
    Compensator,
    Creep,
    Fit,
    Model,
    ModelFromEverett,
    ModelFromEverettGrid,
    ModelFromPoints,
    ModelFromSpline,
    compensator_from,
    fit,
    model_from,
    outside_identified,
)
from ._model_file import ModelFileError, header_text, load_model, save_model
from ._plot import plot

__all__ = [
    "CODE_MAX", "CREEP_MAX_TERMS", "EVERETT_MAX_DEGREE", "EVENT_CLAMPED", "EVENT_FULL",
    "EVENT_NONFINITE", "MAX_DEGREE", "SNAPSHOT_VERSION", "SPLINE_MAX_INTERVALS",
    "DEFAULT_CAPACITY",
    "EVERETT_INV_INTERVALS", "EVERETT_INV_ROWS", "INV_TABLE", "CodeModel", "Compensator",
    "Creep", "CreepF32", "CreepF64", "Fit", "FitWarning",
    "HystError", "Model", "ModelFromEverett", "ModelFromEverettGrid",
    "ModelFromPoints", "ModelFromSpline", "ModelF32", "ModelF64", "PI",
    "PIF32", "PIF64", "Status", "Tcm", "__version__", "compensator_from", "fit", "model_from",
    "outside_identified", "plot", "status_str",
    "ModelFileError", "header_text", "load_model", "save_model",
]
