/* SPDX-License-Identifier: MIT */
/**
 * @file hyst_port_host.h
 * @brief Host-only additions to hyst_port.h.
 */
#ifndef HYST_PORT_HOST_H
#define HYST_PORT_HOST_H

#include "hyst_port.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief Seconds spent between hyst_port_timing_begin() and _end() since
 * hyst_port_init(), summed over all timed regions (CLOCK_MONOTONIC).
 */
double hyst_port_host_elapsed_s(void);

#ifdef __cplusplus
}
#endif

#endif /* HYST_PORT_HOST_H */
