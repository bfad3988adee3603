/*
 * weights.h — the kernel weights an operator reads, aligned with the
 * entries of a neighbour list: stored (one array as long as the list), or
 * computed row by row from the list's distances where they are read.
 *
 * Why computed: in the 3-D Kleefsman tank the stored weights of two radii
 * were 93 MB of mpsFluid's 339 MB peak (dp = 0.025 m), more than the PPE
 * matrix; computed, a weight costs one kernel evaluation per read instead
 * of one per step plus a store and a load, and every operator reads them
 * once or twice a step. The values are those of the array, bit for bit:
 * the same function on the same distances.
 *
 * pop_weights_row(W, k0, r, n) gives the weights of the n entries of a
 * row from k0 on (w[k - k0]), r their distances (neighbour_row_r);
 * pop_weights_of(W, nl, i, k0, k1) the same for a caller that needs no
 * distances. Computed ones go into the calling thread's part of W's
 * buffer, valid until that thread asks W for the next row. The buffer
 * holds cap entries per thread: cap must be at least the list's longest
 * row (neighbour_list.max_row), for omp_get_max_threads() threads.
 */
#ifndef MPSDEM_PARTICLES_WEIGHTS_H
#define MPSDEM_PARTICLES_WEIGHTS_H

#include <omp.h>
#include <stddef.h>
#include <stdint.h>

#include "particles/neighbour.h"

/* w[k] = w(r[k]; re) for k < n, serial (the callers run in parallel). */
typedef void pop_weights_fn(const double *r, int64_t n, double re, double *w);

struct pop_weights {
    const double *w;      /* stored weights, or NULL: computed from the   */
    pop_weights_fn *fn;   /*   list's distances by the kernel              */
    double re;            /*   of radius re [m]                            */
    double *buf;          /*   into rows of cap entries per thread         */
    int64_t cap;
};

/* Stored weights w (aligned with the list), as an operator's argument:
 * pop_number_density(nl, POP_STORED(w), ...). */
#define POP_STORED(array) (&(const struct pop_weights){ .w = (array) })

static inline const double *pop_weights_row(const struct pop_weights *W,
                                            int64_t k0, const double *r,
                                            int64_t n)
{
    if (W->w)
        return W->w + k0;
    double *b = W->buf + (size_t)omp_get_thread_num() * (size_t)W->cap;
    W->fn(r, n, W->re, b);
    return b;
}

static inline const double *pop_weights_of(const struct pop_weights *W,
                                           const struct neighbour_list *nl,
                                           int i, int64_t k0, int64_t k1)
{
    if (W->w)
        return W->w + k0;
    return pop_weights_row(W, k0, neighbour_row_r(nl, i, k0, k1), k1 - k0);
}

#endif
