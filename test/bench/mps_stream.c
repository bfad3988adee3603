/* mps_stream.c — memory bandwidth of this machine (STREAM-like triad
 * a = b + s c), for the PPE bandwidth-bound estimate of
 * test/bench/mpsThroughput.sh.
 *
 *   mps_stream [MB]   total size of the three arrays (default 768 MB: far
 *                     beyond the caches; give the CG working set to get
 *                     the bound of a problem that stays in cache)
 *
 * Prints "bandwidth_GBs <value> <MB>" (best of the repetitions, counting
 * 3 x 8 bytes per element, no write-allocate, as STREAM does). */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    double mb = argc > 1 ? atof(argv[1]) : 768.0;
    if (!(mb >= 0.03 && mb <= 65536.0)) {
        fprintf(stderr, "mps_stream: size %s MB out of [0.03, 65536]\n",
                argv[1]);
        return 2;
    }
    const long n = (long)(mb * 1048576.0 / 24.0);
    double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b),
           *c = malloc(n * sizeof *c);
    if (!a || !b || !c)
        return 1;
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; i++) {
        a[i] = 0;
        b[i] = 1;
        c[i] = 2;
    }
    /* at least ~2 GB moved in all, at least 5 repetitions */
    long reps = 5 + (long)(2e9 / (24.0 * n));
    double best = 0;
    for (long r = 0; r < reps; r++) {
        double t0 = omp_get_wtime();
#pragma omp parallel for schedule(static)
        for (long i = 0; i < n; i++)
            a[i] = b[i] + 3.0 * c[i];
        double t = omp_get_wtime() - t0, bw = 24.0 * n / t / 1e9;
        if (bw > best)
            best = bw;
    }
    printf("bandwidth_GBs %.3f %.1f (check %g)\n", best, mb, a[n / 2]);
    free(a);
    free(b);
    free(c);
    return 0;
}
