/* SPDX-License-Identifier: MIT */
/**
 * @file hyst_port_dsp28335.c
 * @brief hyst_port.h for a TI TMS320F28335 (C28x + FPU, 150 MHz): a GPIO pin
 * as the timing pin, SCI-A as a polled console.
 *
 * NOT COMPILED IN THIS REPOSITORY: it needs TI's C2000 compiler (cl2000),
 * which the project's machines do not have, and it has not run on a board.
 * Register addresses are written from TI's F2833x register map (SPRUFB0,
 * DSP2833x_Headers: GpioCtrlRegs at 0x6F80, GpioDataRegs at 0x6FC0, SciaRegs
 * at 0x7050); on C28x an address counts 16-bit words and unsigned long is
 * 32 bits. Check them against your device's data sheet before relying on it.
 *
 * This is the paper's measurement (Sec. 3.1): the pin goes high when a
 * sample's computation starts and low when it ends; a scope or logic
 * analyser reads the pulse width. Time a call, not the inside of hyst_step():
 *
 *     hyst_port_timing_begin();
 *     y = hyst_step(&axis, x);
 *     hyst_port_timing_end();
 *
 * The pin is any of GPIO0..GPIO31 (port A), HYST_DSP28335_TIMING_GPIO,
 * default 31 (an LED on TI's F28335 controlCARD; check your board). Each
 * edge is one 32-bit store to GPASET/GPACLEAR, which touch only that pin.
 * Startup (watchdog, PLL to 150 MHz, flash wait states, FPU) is the board
 * code's job, as in TI's DSP2833x_SysCtrl.c, before hyst_port_init().
 */
#include "hyst_port.h"

#ifndef HYST_DSP28335_TIMING_GPIO
#define HYST_DSP28335_TIMING_GPIO 31
#endif
#if HYST_DSP28335_TIMING_GPIO < 0 || HYST_DSP28335_TIMING_GPIO > 31
#error "HYST_DSP28335_TIMING_GPIO: this port drives GPIO0..31 (port A) only"
#endif

/* Low-speed peripheral clock (SYSCLKOUT / 4 after reset) and console baud. */
#ifndef HYST_DSP28335_LSPCLK_HZ
#define HYST_DSP28335_LSPCLK_HZ 37500000UL
#endif
#ifndef HYST_DSP28335_BAUD
#define HYST_DSP28335_BAUD 115200UL
#endif

#define REG32(addr) (*(volatile unsigned long *)(addr))
#define REG16(addr) (*(volatile unsigned int *)(addr))

/* GPIO control registers (EALLOW-protected), port A. */
#define GPAMUX1 REG32(0x6F86) /* GPIO0..15: 2 bits per pin, 00 = GPIO */
#define GPAMUX2 REG32(0x6F88) /* GPIO16..31 */
#define GPADIR REG32(0x6F8A)  /* 1 = output */
#define GPAMUX2_SCIA 0x05000000UL /* GPIO28 = SCIRXDA, GPIO29 = SCITXDA */
/* GPIO data registers: writing 1 sets / clears that pin, 0 leaves it. */
#define GPASET REG32(0x6FC2)
#define GPACLEAR REG32(0x6FC4)
/* SCI-A. */
#define SCICCR REG16(0x7050)
#define SCICTL1 REG16(0x7051)
#define SCIHBAUD REG16(0x7052)
#define SCILBAUD REG16(0x7053)
#define SCICTL2 REG16(0x7054)
#define SCITXBUF REG16(0x7059)
#define SCICTL2_TXRDY 0x0080u

#define PIN_MASK (1UL << HYST_DSP28335_TIMING_GPIO)
#define SCI_BRR (HYST_DSP28335_LSPCLK_HZ / (HYST_DSP28335_BAUD * 8UL) - 1UL)

void hyst_port_init(void)
{
    __asm(" EALLOW");
#if HYST_DSP28335_TIMING_GPIO < 16
    GPAMUX1 &= ~(3UL << (2 * HYST_DSP28335_TIMING_GPIO));
#else
    GPAMUX2 &= ~(3UL << (2 * (HYST_DSP28335_TIMING_GPIO - 16)));
#endif
    GPADIR |= PIN_MASK;
    GPAMUX2 |= GPAMUX2_SCIA;
    __asm(" EDIS");
    GPACLEAR = PIN_MASK;

    SCICCR = 0x0007u;  /* 1 stop bit, no parity, 8 data bits */
    SCICTL1 = 0x0003u; /* TX and RX enabled, held in reset */
    SCIHBAUD = (unsigned int)((SCI_BRR >> 8) & 0xFFu);
    SCILBAUD = (unsigned int)(SCI_BRR & 0xFFu);
    SCICTL1 = 0x0023u; /* out of reset */
}

void hyst_port_putc(char c)
{
    while ((SCICTL2 & SCICTL2_TXRDY) == 0u) {
    }
    SCITXBUF = (unsigned int)c & 0xFFu;
}

void hyst_port_puts(const char *s)
{
    while (*s != '\0') {
        if (*s == '\n') {
            hyst_port_putc('\r');
        }
        hyst_port_putc(*s++);
    }
}

void hyst_port_exit(int code)
{
    hyst_port_puts(code == 0 ? "\nEXIT 0\n" : "\nEXIT FAIL\n");
    for (;;) {
        __asm(" ESTOP0"); /* halts under a debugger, a no-op without one */
    }
}

/* One store each. The compiler must not move the timed work across them:
 * time a call (hyst_step is an external function) and use its result. */
void hyst_port_timing_begin(void) { GPASET = PIN_MASK; }

void hyst_port_timing_end(void) { GPACLEAR = PIN_MASK; }

/* No host link: test data is built into the image on this port. */
long hyst_port_file_open(const char *path, int mode_read_binary)
{
    (void)path;
    (void)mode_read_binary;
    return -1;
}

long hyst_port_file_read(long handle, void *buf, unsigned long len)
{
    (void)handle;
    (void)buf;
    (void)len;
    return -1;
}

void hyst_port_file_close(long handle) { (void)handle; }

long hyst_port_file_length(long handle)
{
    (void)handle;
    return -1;
}
