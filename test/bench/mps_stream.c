/* mps_stream.c — memory bandwidth of this machine (STREAM-like triad
 * a = b + s c over arrays much larger than the caches), for the PPE
 * bandwidth-bound estimate of test/bench/mpsThroughput.sh. Prints
 * "bandwidth_GBs <value>" (best of 5, counting 3 x 8 bytes per element). */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

int main(void)
{
    const long n = 1L << 25; /* 32 M doubles = 256 MB per array */
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b),
           *c = malloc(n * sizeof *c);
    if (!a || !b || !c)
        return 1;
#pragma omp parallel for
    for (long i = 0; i < n; i++) {
        a[i] = 0;
        b[i] = 1;
        c[i] = 2;
    }
    double best = 0;
    for (int r = 0; r < 5; r++) {
        double t0 = omp_get_wtime();
#pragma omp parallel for
        for (long i = 0; i < n; i++)
            a[i] = b[i] + 3.0 * c[i];
        double t = omp_get_wtime() - t0, bw = 24.0 * n / t / 1e9;
        if (bw > best)
            best = bw;
    }
    printf("bandwidth_GBs %.3f (check %g)\n", best, a[n / 2]);
    free(a);
    free(b);
    free(c);
    return 0;
}
