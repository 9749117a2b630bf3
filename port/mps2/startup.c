/* SPDX-License-Identifier: MIT */
/**
 * @file startup.c
 * @brief Vector table and reset code for the MPS2 boards of port/mps2
 * (AN385 Cortex-M3, AN386 Cortex-M4F, AN500 Cortex-M7) under QEMU.
 *
 * Replaces crt0 (link with -nostartfiles). Reset order matters: with an FPU
 * (__ARM_FP: -mfpu=... with a hard or softfp float ABI) it is enabled before
 * anything that might touch an FP register. Without one (Cortex-M3, or a
 * -mfloat-abi=soft build) no FP instruction is ever emitted and CPACR is
 * left alone. The fault handler uses Thumb-2 (IT, MRS with a condition): the
 * port needs ARMv7-M or ARMv7E-M; ARMv6-M (Cortex-M0/M0+) has no port here.
 */
#include "semihost.h"

#if !defined(__ARM_ARCH_7M__) && !defined(__ARM_ARCH_7EM__)
#error "port/mps2 needs an ARMv7-M/ARMv7E-M core (cortex-m3, cortex-m4f, cortex-m7)"
#endif

#include <stdint.h>
#include <stdlib.h>

/* Linker script symbols (mps2_sections.ld). */
extern uint32_t __stack_top[];
extern uint32_t __data_load[], __data_start[], __data_end[];
extern uint32_t __bss_start[], __bss_end[];
extern void (*__preinit_array_start[])(void), (*__preinit_array_end[])(void);
extern void (*__init_array_start[])(void), (*__init_array_end[])(void);

int main(void);

__attribute__((noreturn)) void Reset_Handler(void);
void Default_Handler(void);
void NMI_Handler(void) __attribute__((weak, alias("Default_Handler")));
void HardFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void MemManage_Handler(void) __attribute__((weak, alias("Default_Handler")));
void BusFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void UsageFault_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SVC_Handler(void) __attribute__((weak, alias("Default_Handler")));
void DebugMon_Handler(void) __attribute__((weak, alias("Default_Handler")));
void PendSV_Handler(void) __attribute__((weak, alias("Default_Handler")));
void SysTick_Handler(void) __attribute__((weak, alias("Default_Handler")));

/* Entry 0 is a data address (initial SP), the rest are code: a union keeps
 * both without an ISO-forbidden object/function pointer cast. */
typedef union {
    void (*handler)(void);
    uint32_t *sp;
} vector_t;

#define IRQ4 {Default_Handler}, {Default_Handler}, {Default_Handler}, \
    {Default_Handler}

__attribute__((section(".vectors"), used))
static const vector_t vectors[16 + 32] = {
    {.sp = __stack_top},
    {Reset_Handler},
    {NMI_Handler},
    {HardFault_Handler},
    {MemManage_Handler},
    {BusFault_Handler},
    {UsageFault_Handler},
    {0}, {0}, {0}, {0},
    {SVC_Handler},
    {DebugMon_Handler},
    {0},
    {PendSV_Handler},
    {SysTick_Handler},
    /* AN385, AN386 and AN500 have 32 external interrupts; none is used,
     * all are reported. */
    IRQ4, IRQ4, IRQ4, IRQ4, IRQ4, IRQ4, IRQ4, IRQ4
};

#if defined(__ARM_FP)
#define SCB_CPACR (*(volatile uint32_t *)0xE000ED88u)
#endif

void Reset_Handler(void)
{
#if defined(__ARM_FP)
    /* Full access to CP10/CP11 (the FPU); the barriers make it take effect
     * before the next instruction. */
    SCB_CPACR |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif

    const uint32_t *src = __data_load;
    for (uint32_t *dst = __data_start; dst < __data_end; ++dst) {
        *dst = *src++;
    }
    for (uint32_t *dst = __bss_start; dst < __bss_end; ++dst) {
        *dst = 0u;
    }
    /* Constructors: none in C, but newlib or C++ test code may add some. */
    for (void (**f)(void) = __preinit_array_start; f < __preinit_array_end;
         ++f) {
        (*f)();
    }
    for (void (**f)(void) = __init_array_start; f < __init_array_end; ++f) {
        (*f)();
    }

    /* Through a volatile pointer: with LTO, main() would otherwise be
     * inlined and its FP instructions could be scheduled above the CPACR
     * write. exit() flushes stdio, then _exit() (syscalls.c) ends QEMU. */
    int (*volatile entry)(void) = main;
    exit(entry());
}

static void put_hex(uint32_t v)
{
    char s[11] = "0x";
    for (int i = 0; i < 8; ++i) {
        s[2 + i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 0xFu];
    }
    s[10] = '\0';
    semihost_write0(s);
}

/* Called with the stacked exception frame; frame[6] is the faulting PC.
 * Reports without libc (its state may be what broke) and exits 128 + the
 * exception number, so a fault never looks like a test's own exit code. */
void hyst_fault_report(const uint32_t *frame);
__attribute__((used, noreturn)) void hyst_fault_report(const uint32_t *frame)
{
    uint32_t ipsr;
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    ipsr &= 0x1FFu;
    semihost_write0("\nhyst: unhandled exception ");
    put_hex(ipsr);
    semihost_write0(" pc=");
    put_hex(frame[6]);
    semihost_write0(" cfsr=");
    put_hex(*(volatile const uint32_t *)0xE000ED28u);
    semihost_write0("\n");
    semihost_exit(128 + (int)ipsr);
}

/* Naked: pick the stack the frame was pushed on before any prologue moves
 * SP (bit 2 of EXC_RETURN: 0 = MSP, 1 = PSP). */
__attribute__((naked)) void Default_Handler(void)
{
    __asm__ volatile(
        "tst lr, #4\n\t"
        "ite eq\n\t"
        "mrseq r0, msp\n\t"
        "mrsne r0, psp\n\t"
        "b hyst_fault_report\n\t");
}
