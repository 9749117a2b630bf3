/* SPDX-License-Identifier: MIT */
/* Human-readable status names. */
#include "hyst/status.h"

const char *hyst_status_str(int status)
{
    switch (status) {
    case HYST_OK: return "ok";
    case HYST_WARN_CLAMPED: return "input clamped to the domain";
    case HYST_WARN_FULL: return "turning-point memory full, innermost loop forgotten";
    case HYST_ERR_NULL: return "null pointer";
    case HYST_ERR_DOMAIN: return "domain not finite, lo >= hi, or hi - lo overflows";
    case HYST_ERR_DEGREE: return "degree out of range";
    case HYST_ERR_CAPACITY: return "capacity too small";
    case HYST_ERR_COEFF: return "coefficient not finite or curve overflows";
    case HYST_ERR_NOT_INCREASING: return "f0 not increasing on the domain";
    case HYST_ERR_NONFINITE: return "sample not finite";
    case HYST_ERR_ARG: return "invalid argument";
    case HYST_ERR_NOSPACE: return "buffer too small";
    case HYST_ERR_SINGULAR: return "too few distinct inputs for the fit";
    case HYST_ERR_FORMAT: return "not a valid snapshot (magic, length or state)";
    case HYST_ERR_CRC: return "checksum mismatch: a snapshot, a prebuilt table or a sealed curve is corrupted";
    case HYST_ERR_VERSION: return "snapshot version or real type differs";
    case HYST_ERR_CURVE: return "a snapshot or a prebuilt table of a different curve";
    case HYST_ERR_BREAKPOINTS: return "breakpoints/thresholds not finite or not strictly increasing";
    case HYST_ERR_WEIGHTS: return "PI weights not finite or a partial sum not positive";
    case HYST_ERR_NOT_INVERTIBLE: return "curve not strictly increasing, no inverse";
    case HYST_ERR_LAYOUT: return "layout options or variant differ from the library's";
    case HYST_ERR_OVERLAP: return "caller arrays overlap";
    case HYST_ERR_BUSY: return "state kept changing during the copy; try again";
    case HYST_ERR_ILL_CONDITIONED:
        return "curve too ill-conditioned for this number type (use f64 or a lower degree)";
    case HYST_ERR_NOT_MONOTONE:
        return "branch function E not increasing in a and decreasing in b on the triangle";
    default: return "unknown status";
    }
}
