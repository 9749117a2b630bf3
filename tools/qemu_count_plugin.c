/* SPDX-License-Identifier: MIT */
/* A QEMU TCG plugin for tools/qemu_count.py: counts executed instructions
 * and reports the count at every store to the timing pin's register, so a
 * pulse's length is the difference of two counts. QEMU runs at its normal
 * speed (an inline add per instruction, a callback per store) instead of
 * logging every instruction.
 *
 * Prints, through QEMU's log (-d plugin):
 *   @pin <count>   at each store to PIN_ADDR (the FPGAIO LED register of the
 *                  MPS2 boards), count including the store itself; the stored
 *                  value is in the matching mps2_fpgaio_write trace event
 *   @pc <address>  with argument windows=FILE (pin store ranks, from 0, one
 *                  per line), each instruction executed after a listed pin
 *                  store up to and including the next pin store, in order
 *                  (the per-address profile of those pulses)
 *   @insn <address> <size> <disassembly>
 *                  with argument disas=on, each instruction translated (size
 *                  in bytes from its Thumb encoding: QEMU's own may include
 *                  the next halfword, read ahead by the translator)
 *   @total <count> at exit
 *
 * An instruction that QEMU restarts (an I/O store in the middle of a block
 * under -icount is rewound and re-executed alone) is counted once: the
 * re-executed block is instrumented for memory only.
 *
 * Built by tools/qemu_count.py with the host's C compiler:
 *   cc -shared -fPIC -O2 -o qemu_count_plugin.so qemu_count_plugin.c
 * The declarations below are the part of QEMU's plugin API (version 1, as
 * in QEMU 7.2) that this plugin calls; a QEMU that refuses the plugin makes
 * tools/qemu_count.py count from its instruction log instead. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXPORT __attribute__((visibility("default")))

/* ---- QEMU plugin API, version 1 ---- */
typedef uint64_t qemu_plugin_id_t;
typedef uint32_t qemu_plugin_meminfo_t;
struct qemu_plugin_tb;
struct qemu_plugin_insn;
typedef struct {
    const char *target_name;
    struct {
        int min;
        int cur;
    } version;
    int system_emulation; /* bool in QEMU; only the layout before it is read */
} qemu_info_prefix_t;
enum { PLUGIN_CB_NO_REGS = 0 };
enum { PLUGIN_MEM_W = 2 };
enum { PLUGIN_INLINE_ADD_U64 = 0 };
typedef void (*tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*vcpu_mem_cb_t)(unsigned int vcpu_index, qemu_plugin_meminfo_t info,
                              uint64_t vaddr, void *userdata);
typedef void (*udata_cb_t)(qemu_plugin_id_t id, void *userdata);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, tb_trans_cb_t cb);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb, size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
size_t qemu_plugin_insn_size(const struct qemu_plugin_insn *insn);
const void *qemu_plugin_insn_data(const struct qemu_plugin_insn *insn);
char *qemu_plugin_insn_disas(const struct qemu_plugin_insn *insn);
void qemu_plugin_register_vcpu_insn_exec_inline(struct qemu_plugin_insn *insn, int op, void *ptr,
                                                uint64_t imm);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn *insn, vcpu_udata_cb_t cb,
                                            int flags, void *userdata);
void qemu_plugin_register_vcpu_mem_cb(struct qemu_plugin_insn *insn, vcpu_mem_cb_t cb, int flags,
                                      int rw, void *userdata);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, udata_cb_t cb, void *userdata);
void qemu_plugin_outs(const char *string);
EXPORT extern int qemu_plugin_version;
EXPORT int qemu_plugin_version = 1;
/* ---- end of the API ---- */

#define PIN_ADDR 0x40028000u /* FPGAIO LED0..1 on mps2-an385/an386/an500 */
static uint64_t executed;          /* every instruction, inline */
static uint64_t pin_stores;        /* stores to PIN_ADDR so far */
static unsigned char *windows;     /* bit r: trace after the pin store of rank r */
static uint64_t n_window_bits;
static int tracing;                /* inside a window */
static int disas;                  /* print each translated instruction */

/* Reads the ranks of FILE into the windows bitmap; 0 on failure. */
static int read_windows(const char *path)
{
    FILE *f = fopen(path, "r");
    unsigned long long rank;
    if (f == NULL) {
        return 0;
    }
    while (fscanf(f, "%llu", &rank) == 1) {
        if (rank >= n_window_bits) {
            const uint64_t bits = (rank + 1u) * 2u;
            unsigned char *grown = realloc(windows, (size_t)((bits + 7u) / 8u));
            if (grown == NULL) {
                fclose(f);
                return 0;
            }
            memset(grown + (n_window_bits + 7u) / 8u, 0,
                   (size_t)((bits + 7u) / 8u - (n_window_bits + 7u) / 8u));
            windows = grown;
            n_window_bits = bits;
        }
        windows[rank / 8u] = (unsigned char)(windows[rank / 8u] | (1u << (rank % 8u)));
    }
    fclose(f);
    return 1;
}

static void on_store(unsigned int vcpu, qemu_plugin_meminfo_t info, uint64_t vaddr, void *udata)
{
    char line[48];
    (void)vcpu;
    (void)info;
    (void)udata;
    if (vaddr != PIN_ADDR) {
        return;
    }
    (void)snprintf(line, sizeof line, "@pin %llu\n", (unsigned long long)executed);
    qemu_plugin_outs(line);
    tracing = pin_stores < n_window_bits && (windows[pin_stores / 8u] >> (pin_stores % 8u)) & 1u;
    ++pin_stores;
}

static void on_insn(unsigned int vcpu, void *udata)
{
    char line[32];
    (void)vcpu;
    if (tracing) {
        (void)snprintf(line, sizeof line, "@pc %lx\n", (unsigned long)(uintptr_t)udata);
        qemu_plugin_outs(line);
    }
}

/* 2 or 4: a Thumb instruction is 32-bit when its first halfword starts with
 * 0b11101, 0b11110 or 0b11111 (the MPS2 cores run Thumb only). */
static unsigned thumb_size(const struct qemu_plugin_insn *insn)
{
    const unsigned char *b = qemu_plugin_insn_data(insn);
    if (qemu_plugin_insn_size(insn) < 2u) {
        return (unsigned)qemu_plugin_insn_size(insn);
    }
    return ((unsigned)b[1] >> 3) >= 0x1du ? 4u : 2u;
}

static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    const size_t n = qemu_plugin_tb_n_insns(tb);
    size_t i;
    (void)id;
    for (i = 0; i < n; ++i) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        qemu_plugin_register_vcpu_insn_exec_inline(insn, PLUGIN_INLINE_ADD_U64, &executed, 1u);
        qemu_plugin_register_vcpu_mem_cb(insn, on_store, PLUGIN_CB_NO_REGS, PLUGIN_MEM_W, NULL);
        if (disas) {
            char *text = qemu_plugin_insn_disas(insn);
            char line[160];
            (void)snprintf(line, sizeof line, "@insn %lx %u %s\n",
                           (unsigned long)qemu_plugin_insn_vaddr(insn),
                           thumb_size(insn), text != NULL ? text : "?");
            qemu_plugin_outs(line);
            free(text);
        }
        if (n_window_bits > 0u) {
            qemu_plugin_register_vcpu_insn_exec_cb(
                insn, on_insn, PLUGIN_CB_NO_REGS,
                (void *)(uintptr_t)qemu_plugin_insn_vaddr(insn));
        }
    }
}

static void on_qemu_exit(qemu_plugin_id_t id, void *udata)
{
    char line[48];
    (void)id;
    (void)udata;
    (void)snprintf(line, sizeof line, "@total %llu\n", (unsigned long long)executed);
    qemu_plugin_outs(line);
}

EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_prefix_t *info, int argc,
                               char **argv);
EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_prefix_t *info, int argc,
                               char **argv)
{
    int a;
    (void)info;
    for (a = 0; a < argc; ++a) {
        if (strncmp(argv[a], "windows=", 8u) == 0) {
            if (!read_windows(argv[a] + 8)) {
                return 1;
            }
        } else if (strcmp(argv[a], "disas=on") == 0) {
            disas = 1;
        } else {
            return 1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
    qemu_plugin_register_atexit_cb(id, on_qemu_exit, NULL);
    return 0;
}
