/*
 * kernel.h — MPS weight functions w(r; r_e), selected by name
 * (`kernel zhang2014;` in system/mpsSchemes).
 *
 * The kernel is a per-pair law, so (doc/design.md C4) its ops table has an
 * array-level entry: the operators evaluate the weights of a neighbour
 * row where they read them (particles/operators/weights.h), one indirect
 * call per row.
 *
 * Contract of an implementation:
 *   w(r, re)            weight of a neighbour at distance r [m] for the
 *                       radius re [m]; 0 for r >= re; >= 0; non-increasing.
 *   weights(r, n, re, w) the same for n distances (w[k] = w(r[k], re)),
 *                       bit for bit; serial (its callers run in
 *                       parallel over rows), vectorised.
 *   finite_at_zero      1 when w(0) is finite (coincident particles are
 *                       then harmless); 0 for singular kernels.
 */
#ifndef MPSDEM_MPS_KERNEL_H
#define MPSDEM_MPS_KERNEL_H

#include <stdint.h>

struct mps_kernel_ops {
    const char *name;
    const char *reference;
    double (*w)(double r, double re);
    void (*weights)(const double *r, int64_t n, double re, double *w);
    int finite_at_zero;
};

extern const struct mps_kernel_ops mps_kernel_zhang2014;
extern const struct mps_kernel_ops mps_kernel_koshizuka1996;
extern const struct mps_kernel_ops mps_kernel_poly6;

/* Every kernel; NULL-terminated (kernel_register.c is the only list). */
extern const struct mps_kernel_ops *const mps_kernel_table[];

#endif
