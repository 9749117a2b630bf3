# SPDX-License-Identifier: MIT
"""The exception raised for every error status of the library."""


class HystError(Exception):
    """An error status of the hyst library (include/hyst/status.h).

    Attributes: ``status`` (:class:`hyst.Status`, an int), ``name`` (its
    name, e.g. ``"ERR_NOT_INCREASING"``), ``message`` (the library's
    ``hyst_status_str()``) and ``context`` (which call failed).
    """

    def __init__(self, status, context=""):
        from ._hyst import Status, status_str

        try:
            self.status = Status(status)
            self.name = self.status.name
        except ValueError:
            self.status = int(status)
            self.name = "UNKNOWN"
        self.message = status_str(int(status))
        self.context = context
        prefix = f"{context}: " if context else ""
        super().__init__(f"{prefix}{self.message} ({self.name}, {int(status)})")


class FitWarning(UserWarning):
    """What :func:`hyst.fit`'s result was not tested on or determined by, as
    ``hyst fit`` warns of it: the automatic choice's last third whose inputs
    span less than half the record's range, or that holds no minor loop; f0
    of a given degree fitted on a drive with minor loops (biased); a grid
    whose masses the record's turning points do not determine."""
