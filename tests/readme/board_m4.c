/* SPDX-License-Identifier: MIT */
/* A bare Cortex-M4F board for sizing the README's firmware example
 * (readme_figures.sh): the board calls as volatile accesses, and a main()
 * that runs the example's three functions. Linked once with the example
 * and once with empty ones (README_EMPTY_EXAMPLE); the difference is what
 * the example costs in flash. */
#include <stddef.h>

#include "board.h"

static volatile float drive, out;
static volatile int flags;
static volatile size_t written;

void fault(void) { flags = -1; }
float read_drive_voltage(void) { return drive; }
void publish(float um) { out = um; }
int power_failing(void) { return flags & 1; }
int actuator_rezeroed(void) { return flags & 2; }
void write_flash(const unsigned char *data, size_t len) { written = len + (size_t)data[0]; }

#ifdef README_EMPTY_EXAMPLE
void app_init(void) {}
void adc_isr(void) {}
void main_loop(void) {}
#endif

int main(void)
{
    app_init();
    for (;;) {
        adc_isr();
        main_loop();
    }
}
