/* Generates c_exp.txt, the expected outputs of C's printf("%.16e") that
 * tests/reactive_output.rs checks walls_sim::reactive_output::c_exp against.
 * Each line: the double's bits in hex, a space, then printf("%.16e") of it.
 * Regenerate (glibc, round-to-nearest):
 *   cc -O2 -o /tmp/c_exp_gen c_exp_gen.c -lm && /tmp/c_exp_gen > c_exp.txt
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint64_t state = 0x9e3779b97f4a7c15ULL;
static uint64_t next(void) { /* xorshift64 */
    state ^= state << 13; state ^= state >> 7; state ^= state << 17; return state;
}
static void emit(double x) {
    uint64_t b; memcpy(&b, &x, 8);
    printf("%016llx %.16e\n", (unsigned long long)b, x);
}
static double from_bits(uint64_t b) { double x; memcpy(&x, &b, 8); return x; }

int main(void) {
    /* Hand-picked: zeros, ±1, extremes, subnormals, infinities, NaNs. */
    double fixed[] = {0.0, -0.0, 1.0, -1.0, 1e-300, 1.5e300, 123.456, -123.456, 0.1, 0.5,
                      2.5, 1e100, 1e-5, 9.99999999999999999e99, 0.99999999999999994,
                      9.9999999999999998e22, 1e23, 12345678901234567890.0,
                      1.7976931348623157e308, -1.7976931348623157e308,
                      2.2250738585072014e-308, 2.2250738585072009e-308,
                      4.9406564584124654e-324, -4.9406564584124654e-324, 1e-320,
                      HUGE_VAL, -HUGE_VAL};
    for (size_t i = 0; i < sizeof fixed / sizeof *fixed; i++) emit(fixed[i]);
    emit(from_bits(0x7ff8000000000000ULL)); /* nan */
    emit(from_bits(0xfff8000000000000ULL)); /* -nan */
    emit(from_bits(0x7ff0000000000001ULL)); /* signalling nan */
    emit(from_bits(0x000fffffffffffffULL)); /* largest subnormal */
    /* Exact ties at the 17th significant digit (glibc rounds them to even):
     * 18 significant digits ending in 5. */
    for (int i = 0; i < 60; i++) emit(1.0 + (double)((next() % 65536) * 2 + 1) / 131072.0);
    for (int i = 0; i < 40; i++) emit(0.5 + (double)((next() % 131072) * 2 + 1) / 524288.0);
    for (int i = 0; i < 40; i++) emit(-(16.0 + (double)((next() % 524288) * 2 + 1) / 65536.0));
    /* Around powers of ten: rounding that carries into the exponent. */
    for (int k = -320; k <= 308; k += 7) {
        char s[32]; snprintf(s, sizeof s, "1e%d", k);
        double p = strtod(s, NULL);
        emit(p); emit(nextafter(p, 0.0)); emit(nextafter(p, INFINITY));
    }
    /* Random bit patterns (any sign, exponent and mantissa). */
    for (int i = 0; i < 300; i++) emit(from_bits(next()));
    /* Random values of ordinary size. */
    for (int i = 0; i < 100; i++) emit(((double)(next() >> 11) / 9007199254740992.0 - 0.5) * 200.0);
    return 0;
}
