/* SPDX-License-Identifier: MIT */
/* The float work of the model written by hand: what the images below carry
 * besides hyst. */
volatile float drive, out;
static const float c[4] = {-6.1876e-6f, 1.1949e-3f, 8.6444e-2f, 5.8517e-1f};
int main(void)
{
    for (;;) {
        const float x = drive;
        out = ((c[0] * x + c[1]) * x + c[2]) * x + c[3];
    }
}
