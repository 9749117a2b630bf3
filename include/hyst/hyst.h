/* SPDX-License-Identifier: MIT */
/**
 * @file hyst.h
 * @brief hyst: allocation-free hysteresis modelling and compensation (TCM).
 *
 * Include this one header. Start with docs/architecture.md. Modules:
 *  - hyst/version.h: the version;
 *  - hyst/config.h: every compile-time option, with its default;
 *  - hyst/types.h:  number types and the named variants (f32, f64, code);
 *  - hyst/status.h: status codes and event flags;
 *  - hyst/curve.h:  the major ascending curve f0;
 *  - hyst/tcm.h:    the TCM instance (init, reset, step, process);
 *  - hyst/code.h:   the same TCM over integer DAC codes;
 *  - hyst/q31.h:    the same over codes in fixed point (cores without an FPU);
 *  - hyst/ident.h:  identification of f0 from measured data.
 *  - hyst/snapshot.h: save/restore of an instance's memory (CRC-checked);
 *  - hyst/inverse.h: the inverse TCM, a feedforward compensator;
 *  - hyst/pi.h:     the Prandtl-Ishlinskii model and its inverse;
 *  - hyst/creep.h:  creep, lags of the drive added to any model's output,
 *                   and their identification.
 */
#ifndef HYST_HYST_H
#define HYST_HYST_H

#include "hyst/version.h"
#include "hyst/config.h"
#include "hyst/types.h"
#include "hyst/status.h"
#include "hyst/curve.h"
#include "hyst/tcm.h"
#include "hyst/code.h"
#include "hyst/q31.h"
#include "hyst/ident.h"
#include "hyst/snapshot.h"
#include "hyst/inverse.h"
#include "hyst/pi.h"
#include "hyst/creep.h"
#include "hyst/rate.h"

#endif /* HYST_HYST_H */
