/* SPDX-License-Identifier: MIT */
/**
 * @file snapshot.h
 * @brief Snapshot and restore of a TCM instance's memory (turning points),
 *        and of a creep term's lags and a rate term's state.
 *
 * A piezo stage keeps its hysteresis state through a brown-out only if the
 * model does: save the instance to non-volatile memory, restore it at boot.
 * Restore checks everything first and changes nothing unless all checks pass.
 *
 * The byte format is defined in OCTETS, independent of CHAR_BIT: the buffer
 * is an array of unsigned char, each element holding one octet (0..255), so
 * a snapshot written on a 16-bit-char DSP (TI C28x) reads back on a PC.
 * Multi-octet integers are little-endian; reals are their IEEE-754 bit
 * patterns (binary32 for the f32 and code variants, binary64 for f64),
 * stored as little-endian integers; codes are 4-octet integers; the q31
 * variants' fixed-point numbers (the model's outputs, the compensator's
 * desired outputs and drives, q31.h) are 4-octet two's complement. One
 * format and one implementation serve every variant: "R" below is the
 * octets of an output of the instance's variant, "X" the octets of a
 * stored input (R for the real variants, 4 for codes and q31).
 *
 * | offset        | octets    | field                                                  |
 * |---------------|-----------|--------------------------------------------------------|
 * | 0             | 4         | magic 0x48 0x59 0x53 0x53 ("HYSS")                     |
 * | 4             | 2         | format version, HYST_SNAPSHOT_VERSION                  |
 * | 6             | 1         | R: octets per real, 4 or 8 (HYST_SNAPSHOT_REAL_OCTETS) |
 * | 7             | 1         | variant (hyst_variant_t)                               |
 * | 8             | 4         | L: total length in octets, CRC included                |
 * | 12            | 4         | curve id: hyst_crc32 of the curve, serialised as below |
 * | 16            | 4         | n_ltp: stored LTPs including the anchor A0 (>= 1)      |
 * | 20            | 4         | n_rtp: stored RTPs (n_ltp - 1 or n_ltp)                |
 * | 24            | 4         | sticky event flags (HYST_EVENT_*)                      |
 * | 28            | 2         | status of the last sample, 16-bit two's complement     |
 * | 30            | 2         | reserved, 0                                            |
 * | 32            | X         | last input x_prev                                      |
 * | 32 + X        | R         | last output y_prev                                     |
 * | 32 + X + R    | (X+R) n_ltp | LTPs, oldest first: x, y                             |
 * | ...           | (X+R) n_rtp | RTPs, oldest first: x, y                             |
 * | L - 8 - 2R - X | 4        | stack level of the shallowest live merge, or 0xFFFFFFFF |
 * | L - 4 - 2R - X | R        | error bound of the live merges (error_bound part)      |
 * | L - 4 - R - X | X         | deadband: widest skipped reversal of the open window   |
 * | L - 4 - R     | R         | deadband: error bound of the open window               |
 * | L - 4         | 4         | CRC-32 of octets [0, L - 4)                            |
 *
 * L = 40 + (X + R)(1 + n_ltp + n_rtp) + 2R + X. Curve identity (the id):
 * kind, degree or point count and variant, the domain, its values and scale,
 * every coefficient of a polynomial, every point of a piecewise-linear curve,
 * the start table of an inverted polynomial and the pieces of a tabulated
 * one, the per-direction tables of an asymmetric curve and every number of a
 * grid curve's table: a curve of the same ends but another shape is another
 * curve. The CRC is CRC-32/ISO-HDLC (the
 * zlib/Ethernet CRC: reflected polynomial 0xEDB88320, initial value and
 * final XOR 0xFFFFFFFF). Version 2 snapshots (real variants only, a weaker
 * curve id) are refused with HYST_ERR_VERSION.
 */
#ifndef HYST_SNAPSHOT_H
#define HYST_SNAPSHOT_H

#include "hyst/creep.h"
#include "hyst/rate.h"
#include "hyst/status.h"
#include "hyst/tcm.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Format version written and accepted by this library. */
#define HYST_SNAPSHOT_VERSION 3u

/**
 * @brief Buffer length, in octets (unsigned char elements), that holds a
 *        snapshot of any state of an instance of @p capacity entries, of
 *        any variant.
 */
#define HYST_SNAPSHOT_SIZE(capacity) (40u + 16u * (1u + 2u * (size_t)(capacity)) + 24u)

/**
 * @brief Length in octets of a snapshot of the current state of @p S.
 * @param[in] S initialised instance of any variant.
 * @return octets hyst_snapshot_save() will write now (<= HYST_SNAPSHOT_SIZE(capacity));
 *         0 for NULL or an uninitialised instance.
 */
size_t hyst_snapshot_size(const hyst_tcm_t *S);

/**
 * @brief Writes the instance's memory to a caller buffer.
 *
 * Saves the turning points, the last sample, its status and the sticky
 * events, plus the curve id, so that a restore continues bit-identically.
 *
 * @param[in]  S    initialised instance (not modified).
 * @param[out] buf  @p size elements; each receives one octet (0..255).
 * @param[in]  size elements available in @p buf.
 * May be called from a context that the stepping context preempts (tcm.h,
 * "Concurrency"): the copy is checked against the state's sequence counter
 * and retried, so the octets always describe one state the model was in,
 * and never go past @p size, whatever the steps do meanwhile.
 *
 * @param[out] len  if not NULL: octets written (hyst_snapshot_size(S)).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (not initialised),
 *         HYST_ERR_NOSPACE (nothing written, or an earlier attempt's octets
 *         with the magic cleared), or HYST_ERR_BUSY (slow samples changed
 *         the state during every attempt; the magic is cleared, so the
 *         buffer restores as nothing).
 */
hyst_status_t hyst_snapshot_save(const hyst_tcm_t *S, unsigned char *buf,
                                 size_t size, size_t *len);

/**
 * @brief Restores a saved state into an instance initialised with the same curve.
 *
 * Checks, in this order: magic, version and real width, length, CRC, curve
 * id, capacity, and that the state is one the model can reach (counts,
 * alternation, strict nesting, finite values inside [lo, hi], A0 at
 * (lo, f0(lo))). On any error @p S is left exactly as it was.
 *
 * The bounded-memory bookkeeping (live merges, deadband window) is saved
 * too, so a restored instance continues bit for bit, error bound included.
 *
 * @param[in,out] S    instance initialised (hyst_init) with the snapshot's curve;
 *                     its capacity may differ but must hold the saved TPs.
 * @param[in]     buf  snapshot octets.
 * @param[in]     len  octets available in @p buf (>= the snapshot's L).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (S not initialised),
 *         HYST_ERR_FORMAT (bad magic, truncated,
 *         inconsistent length or impossible state), HYST_ERR_VERSION (other format version or
 *         variant), HYST_ERR_CRC (corrupted), HYST_ERR_CURVE (other curve) or
 *         HYST_ERR_CAPACITY (the instance cannot hold the saved TPs).
 */
hyst_status_t hyst_snapshot_restore(hyst_tcm_t *S, const unsigned char *buf,
                                    size_t len);

/**
 * @name Creep snapshots
 * @brief The lags of a creep term (creep.h) through a brown-out, beside the
 *        hysteresis model's snapshot: a compensator with a creep term
 *        restores both to continue bit for bit.
 *
 * Octets as above (little-endian, reals as IEEE-754 bits; R octets per
 * real of the instance's variant, 4 for f32, 8 for f64):
 *
 * | offset  | octets | field                                                |
 * |---------|--------|------------------------------------------------------|
 * | 0       | 4      | magic 0x48 0x59 0x53 0x43 ("HYSC")                   |
 * | 4       | 2      | format version, HYST_CREEP_SNAPSHOT_VERSION          |
 * | 6       | 1      | R: octets per real, 4 or 8                           |
 * | 7       | 1      | variant (hyst_variant_t)                             |
 * | 8       | 4      | L: total length in octets, CRC included              |
 * | 12      | 4      | creep id: hyst_crc32 of the variant, n and every a_k |
 * |         |        | and w_k, serialised as here                          |
 * | 16      | 4      | n: lags                                              |
 * | 20      | 4      | sticky event flags (HYST_EVENT_*)                    |
 * | 24      | 2      | status of the last sample, 16-bit two's complement   |
 * | 26      | 2      | reserved, 0                                          |
 * | 28      | R n    | the lags' states s_k                                 |
 * | L - 4   | 4      | CRC-32 of octets [0, L - 4)                          |
 *
 * L = 32 + R n. Save may run in a context the stepping one preempts (the
 * copy is taken between two reads of the instance's sequence counter,
 * retried, at worst HYST_ERR_BUSY with the magic cleared); restore only
 * where no step can run, and it changes nothing unless every check passes.
 */
/**@{*/
/** Format version written and accepted by this library. */
#define HYST_CREEP_SNAPSHOT_VERSION 1u
/** Buffer length, in octets, that holds a snapshot of any creep instance. */
#define HYST_CREEP_SNAPSHOT_SIZE (32u + 8u * HYST_CREEP_MAX_TERMS)

/**
 * @brief Length in octets of a snapshot of @p C (32 + R n).
 * @return that length; 0 for NULL or an instance not initialised.
 */
size_t hyst_creep_snapshot_size(const hyst_creep_t *C);

/**
 * @brief Writes the lags, the status and the sticky events of @p C, with
 *        its creep id, into @p buf.
 * @param[in]  C    initialised instance (not modified).
 * @param[out] buf  @p size elements; each receives one octet (0..255).
 * @param[in]  size elements available in @p buf.
 * @param[out] len  if not NULL: octets written.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (not initialised),
 *         HYST_ERR_NOSPACE (nothing written) or HYST_ERR_BUSY (a step
 *         changed the state during every attempt; the magic is cleared).
 */
hyst_status_t hyst_creep_snapshot_save(const hyst_creep_t *C, unsigned char *buf, size_t size,
                                       size_t *len);

/**
 * @brief Restores a creep snapshot into an instance initialised with the
 *        same lags and weights (the same creep id).
 *
 * Checks, in this order: magic, version and real width, length, CRC, creep
 * id, then the values (states finite in the type, a known status and known
 * events, reserved octets 0). On any error @p C is left exactly as it was.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (C not initialised),
 *         HYST_ERR_FORMAT (bad magic, truncated, inconsistent length,
 *         impossible values), HYST_ERR_VERSION (other version or variant),
 *         HYST_ERR_CRC (corrupted) or HYST_ERR_CURVE (other time constants
 *         or weights).
 */
hyst_status_t hyst_creep_snapshot_restore(hyst_creep_t *C, const unsigned char *buf, size_t len);
/**@}*/

/**
 * @name Rate snapshots
 * @brief The state of a rate term (rate.h), p (the drive taken last) and
 *        v (the low-pass of its changes), through a brown-out, beside the
 *        hysteresis model's snapshot and the creep term's: restored, the
 *        term continues bit for bit.
 *
 * Octets as above (R octets per real of the instance's variant):
 *
 * | offset  | octets | field                                                |
 * |---------|--------|------------------------------------------------------|
 * | 0       | 4      | magic 0x48 0x59 0x53 0x52 ("HYSR")                   |
 * | 4       | 2      | format version, HYST_RATE_SNAPSHOT_VERSION           |
 * | 6       | 1      | R: octets per real, 4 or 8                           |
 * | 7       | 1      | variant (hyst_variant_t)                             |
 * | 8       | 4      | L: total length in octets, CRC included              |
 * | 12      | 4      | rate id: hyst_crc32 of the variant, a and w,         |
 * |         |        | serialised as here                                   |
 * | 16      | 4      | sticky event flags (HYST_EVENT_*)                    |
 * | 20      | 2      | status of the last sample, 16-bit two's complement   |
 * | 22      | 2      | reserved, 0                                          |
 * | 24      | R      | p, the drive taken last                              |
 * | 24 + R  | R      | v, the low-pass of the drive's change                |
 * | L - 4   | 4      | CRC-32 of octets [0, L - 4)                          |
 *
 * L = 28 + 2 R. Save and restore as the creep snapshot's: save may run in a
 * context the stepping one preempts, restore only where no step can run.
 */
/**@{*/
/** Format version written and accepted by this library. */
#define HYST_RATE_SNAPSHOT_VERSION 1u
/** Buffer length, in octets, that holds a snapshot of any rate instance. */
#define HYST_RATE_SNAPSHOT_SIZE 44u

/**
 * @brief Length in octets of a snapshot of @p R (28 + 2 R).
 * @return that length; 0 for NULL or an instance not initialised.
 */
size_t hyst_rate_snapshot_size(const hyst_rate_t *R);

/**
 * @brief Writes p, v, the status and the sticky events of @p R, with its
 *        rate id, into @p buf.
 * @param[in]  R    initialised instance (not modified).
 * @param[out] buf  @p size elements; each receives one octet (0..255).
 * @param[in]  size elements available in @p buf.
 * @param[out] len  if not NULL: octets written.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (not initialised),
 *         HYST_ERR_NOSPACE (nothing written) or HYST_ERR_BUSY (a step
 *         changed the state during every attempt; the magic is cleared).
 */
hyst_status_t hyst_rate_snapshot_save(const hyst_rate_t *R, unsigned char *buf, size_t size,
                                      size_t *len);

/**
 * @brief Restores a rate snapshot into an instance initialised with the
 *        same time constant and weight (the same rate id).
 *
 * Checks, in this order: magic, version and real width, length, CRC, rate
 * id, then the values (p within the instance's drive limit, v finite and
 * within twice it, a known status and known events, reserved octets 0).
 * On any error @p R is left exactly as it was.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (R not initialised),
 *         HYST_ERR_FORMAT (bad magic, truncated, inconsistent length,
 *         impossible values), HYST_ERR_VERSION (other version or variant),
 *         HYST_ERR_CRC (corrupted) or HYST_ERR_CURVE (other time constant
 *         or weight).
 */
hyst_status_t hyst_rate_snapshot_restore(hyst_rate_t *R, const unsigned char *buf, size_t len);
/**@}*/

/**
 * @brief CRC-32/ISO-HDLC of octets (as used by snapshots), for callers that
 *        frame or check data of their own.
 * @param[in] crc  0 to start, or the result of the previous call to continue.
 * @param[in] buf  @p n elements, one octet each (higher bits ignored).
 * @param[in] n    element count.
 * @return the CRC, 0..0xFFFFFFFF; "123456789" gives 0xCBF43926.
 */
unsigned long hyst_crc32(unsigned long crc, const unsigned char *buf, size_t n);

#ifdef __cplusplus
}
#endif

#endif /* HYST_SNAPSHOT_H */
