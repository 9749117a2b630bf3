/* SPDX-License-Identifier: MIT */
/* What the README's firmware example expects of its board (tests/readme). */
#ifndef README_BOARD_H
#define README_BOARD_H

#include <stddef.h>

void fault(void);
float read_drive_voltage(void);
void publish(float um);
int power_failing(void);
void write_flash(const unsigned char *data, size_t len);
int actuator_rezeroed(void);

/* The example's own functions, called by the board's main(). */
void app_init(void);
void adc_isr(void);
void main_loop(void);

#endif
