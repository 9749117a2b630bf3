/* SPDX-License-Identifier: MIT */
/* A board for the README's firmware example, compiled with it as written:
 * a drive signal, a sink for the published outputs, a flash, and the events
 * of the main loop. main() runs the example and checks what it published
 * against a model of its own (same f0), and the flash image by restoring
 * it. Exit status 0 when every check passed. */
#include "board.h"

#include <stdio.h>
#include <string.h>

#include "hyst/hyst.h"

static const hyst_poly_t eq20 = {3, 0.0, 40.0, {-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1}};
static float ref_xl[2048], ref_yl[2048], ref_xr[2048], ref_yr[2048];
static hyst_tcm_t ref;
static float drive, published;
static int faults, failing, rezeroed, flash_writes, failures;
static unsigned char flash[HYST_SNAPSHOT_SIZE(2048)];
static size_t flash_len;

void fault(void) { ++faults; }
float read_drive_voltage(void) { return drive; }
void publish(float um) { published = um; }
int power_failing(void) { return failing; }
int actuator_rezeroed(void) { return rezeroed; }

void write_flash(const unsigned char *data, size_t len)
{
    memcpy(flash, data, len);
    flash_len = len;
    ++flash_writes;
}

static void check(int ok, const char *what)
{
    if (!ok) {
        printf("FAIL: %s\n", what);
        ++failures;
    }
}

/* One sample through the example and through the reference. */
static void sample(float v)
{
    drive = v;
    adc_isr();
    check(published == hyst_f32_step(&ref, v), "published output is the model's");
}

int main(void)
{
    static hyst_tcm_t restored;
    static float rxl[2048], ryl[2048], rxr[2048], ryr[2048];
    int k;
    app_init();
    check(faults == 0, "app_init: the curve is valid");
    check(hyst_f32_init(&ref, &eq20, ref_xl, ref_yl, ref_xr, ref_yr, 2048) == HYST_OK, "ref");
    for (k = 0; k <= 80; ++k) { /* up to 40 V, down to 10, up to 30: turning points */
        sample((float)k * 0.5f);
    }
    for (k = 79; k >= 20; --k) {
        sample((float)k * 0.5f);
    }
    for (k = 21; k <= 60; ++k) {
        sample((float)k * 0.5f);
    }
    failing = 1; /* the main loop saves to flash */
    main_loop();
    failing = 0;
    check(flash_writes == 1 && flash_len > 0u, "main_loop wrote the snapshot");
    check(hyst_f32_init(&restored, &eq20, rxl, ryl, rxr, ryr, 2048) == HYST_OK &&
              hyst_snapshot_restore(&restored, flash, flash_len) == HYST_OK &&
              hyst_tp_count(&restored) == hyst_tp_count(&ref) &&
              hyst_f32_output(&restored) == hyst_f32_output(&ref),
          "the flash image restores the model's state");
    rezeroed = 1; /* the main loop requests a reset; the next sample applies it */
    main_loop();
    rezeroed = 0;
    sample(29.5f);
    hyst_reset(&ref); /* applied between that sample and the next, as hyst_reset() */
    sample(30.0f); /* the same output as a model reset there: the virgin branch */
    printf("readme example: %d checks failed\n", failures);
    return failures != 0;
}
