/**
 * @file snapshot.h
 * @brief Snapshot and restore of a TCM instance's memory (turning points).
 *
 * A piezo stage keeps its hysteresis state through a brown-out only if the
 * model does: save the instance to non-volatile memory, restore it at boot.
 * Restore checks everything first and changes nothing unless all checks pass.
 *
 * The byte format is defined in OCTETS, independent of CHAR_BIT: the buffer
 * is an array of unsigned char, each element holding one octet (0..255), so
 * a snapshot written on a 16-bit-char DSP (TI C28x) reads back on a PC.
 * Multi-octet integers are little-endian; reals are their IEEE-754 bit
 * patterns (binary32, or binary64 when hyst_real_t is a 64-bit double),
 * stored as little-endian integers.
 *
 * | offset        | octets    | field                                                  |
 * |---------------|-----------|--------------------------------------------------------|
 * | 0             | 4         | magic 0x48 0x59 0x53 0x53 ("HYSS")                     |
 * | 4             | 2         | format version, HYST_SNAPSHOT_VERSION                  |
 * | 6             | 1         | R: octets per real, 4 or 8 (HYST_SNAPSHOT_REAL_OCTETS) |
 * | 7             | 1         | reserved, 0                                            |
 * | 8             | 4         | L: total length in octets, CRC included                |
 * | 12            | 4         | curve id: hyst_crc32 of the curve, serialised as below |
 * | 16            | 4         | n_ltp: stored LTPs including the anchor A0 (>= 1)      |
 * | 20            | 4         | n_rtp: stored RTPs (n_ltp - 1 or n_ltp)                |
 * | 24            | 4         | sticky event flags (HYST_EVENT_*)                      |
 * | 28            | 2         | status of the last sample, 16-bit two's complement     |
 * | 30            | 2         | reserved, 0                                            |
 * | 32            | R         | last input x_prev                                      |
 * | 32 + R        | R         | last output y_prev                                     |
 * | 32 + 2R       | 2R n_ltp  | LTPs, oldest first: x, y                               |
 * | ...           | 2R n_rtp  | RTPs, oldest first: x, y                               |
 * | L - 8 - 3R    | 4         | stack level of the shallowest live merge, or 0xFFFFFFFF |
 * | L - 4 - 3R    | R         | error bound of the live merges (hyst_error_bound part) |
 * | L - 4 - 2R    | R         | deadband: widest skipped reversal of the open window   |
 * | L - 4 - R     | R         | deadband: its error bound                              |
 * | L - 4         | 4         | CRC-32 of octets [0, L - 4)                            |
 *
 * L = 40 + 2R (1 + n_ltp + n_rtp) + 3R. Curve serialisation for the id: kind and
 * degree (2 octets each), then lo, hi, f0(lo), f0(hi), 1/(hi - lo) and the
 * degree normalised coefficients (R octets each). The CRC is CRC-32/ISO-HDLC
 * (the zlib/Ethernet CRC: reflected polynomial 0xEDB88320, initial value and
 * final XOR 0xFFFFFFFF).
 */
#ifndef HYST_SNAPSHOT_H
#define HYST_SNAPSHOT_H

#include <float.h>

#include "hyst/config.h"
#include "hyst/status.h"
#include "hyst/tcm.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Format version written and accepted by this library. */
#define HYST_SNAPSHOT_VERSION 2u

/** Octets per real in a snapshot: 8 if hyst_real_t is an IEEE binary64, else 4. */
#if defined(HYST_USE_DOUBLE) && DBL_MANT_DIG == 53
#define HYST_SNAPSHOT_REAL_OCTETS 8u
#else
#define HYST_SNAPSHOT_REAL_OCTETS 4u
#endif

/**
 * @brief Buffer length, in octets (unsigned char elements), that holds a
 *        snapshot of any state of an instance of @p capacity entries.
 */
#define HYST_SNAPSHOT_SIZE(capacity) \
    (40u + 2u * HYST_SNAPSHOT_REAL_OCTETS * (1u + 2u * (size_t)(capacity)) + \
     3u * HYST_SNAPSHOT_REAL_OCTETS)

/**
 * @brief Length in octets of a snapshot of the current state of @p S.
 * @param[in] S initialised instance.
 * @return octets hyst_snapshot_save() will write (<= HYST_SNAPSHOT_SIZE(capacity)).
 */
size_t hyst_snapshot_size(const hyst_t *S);

/**
 * @brief Writes the instance's memory to a caller buffer.
 *
 * Saves the turning points, the last sample, its status and the sticky
 * events, plus the curve id, so that a restore continues bit-identically.
 *
 * @param[in]  S    initialised instance (not modified).
 * @param[out] buf  @p size elements; each receives one octet (0..255).
 * @param[in]  size elements available in @p buf.
 * @param[out] len  if not NULL: octets written (hyst_snapshot_size(S)).
 * @return HYST_OK, HYST_ERR_NULL, or HYST_ERR_NOSPACE (nothing written).
 */
hyst_status_t hyst_snapshot_save(const hyst_t *S, unsigned char *buf,
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
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_FORMAT (bad magic, truncated,
 *         inconsistent length or impossible state), HYST_ERR_VERSION,
 *         HYST_ERR_CRC (corrupted), HYST_ERR_CURVE (other curve) or
 *         HYST_ERR_CAPACITY (the instance cannot hold the saved TPs).
 */
hyst_status_t hyst_snapshot_restore(hyst_t *S, const unsigned char *buf,
                                    size_t len);

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
