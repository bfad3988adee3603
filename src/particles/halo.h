/*
 * halo.h — a particle cloud spread over the ranks of a distributed run, as
 * a solver sees it (doc/design.md §8, "Distributed runs").
 *
 * Each rank holds the particles it owns, [0, n_own), followed by copies of
 * the other ranks' particles within the halo width of its own (ghosts),
 * [n_own, n). A solver computes every row as in one process; the rows of
 * its own particles are right wherever the values it reads at the ghosts
 * are the owners'. `refresh` brings the owners' values of one field to the
 * ghosts, after each phase whose result a neighbour reads. `exchange`
 * (before a step) lets particles that left a rank's region migrate to
 * their new owner and builds the ghosts afresh; index fields
 * (STORE_INDEX) travel as particle ids and come back as local indices (-1
 * where the particle they name is not held here).
 *
 * A particle that must reach further than the halo width (a wall particle
 * whose dummy lies farther) carries the Float64 field "haloReach" [m] in
 * the store: it is a ghost wherever that distance reaches.
 *
 * The interface holds no MPI type, so that libraries above it (src/mps)
 * build without MPI; particles/distribute.c implements it with MPI.
 */
#ifndef MPSDEM_PARTICLES_HALO_H
#define MPSDEM_PARTICLES_HALO_H

#include <stddef.h>
#include <stdint.h>

struct store;
struct linsolve;
struct linsolve_stats;
struct csr_matrix;

enum pop_reduce { POP_SUM, POP_MIN, POP_MAX };

struct pop_halo;

struct pop_halo_ops {
    /* Migrate and rebuild the ghosts of store st (its STORE_POINTS field
     * the positions, its "id" field the ids); sets h->n_own, st->n. */
    int (*exchange)(struct pop_halo *h, struct store *st);
    /* The owners' values of field data (elem bytes per particle) into the
     * ghosts. Collective. */
    int (*refresh)(struct pop_halo *h, void *data, size_t elem);
    /* v[0, n) combined over the ranks, in place. Collective. */
    void (*reduce)(struct pop_halo *h, double *v, int n, enum pop_reduce op);
    /* bytes of data from rank 0 to every rank. Collective. */
    void (*bcast)(struct pop_halo *h, void *data, size_t bytes);
    /* The sum of v over the ranks before this one; *total over all. */
    int64_t (*exscan)(struct pop_halo *h, int64_t v, int64_t *total);
    /* When the largest rank's weight (per own particle; NULL: 1 each)
     * exceeds the mean by more than h->max_imbalance, cut the regions
     * afresh (recursive coordinate bisection of every rank's own
     * particles); the next exchange migrates. *done: 1 when it did.
     * Collective. */
    int (*balance)(struct pop_halo *h, const struct store *st,
                   const double *weight, int *done);
    /* Solve the rows [row0, row0 + A->n) of a system of nglobal unknowns
     * (A's columns global) with the solver and tolerances of ls; x holds
     * the start on entry. Collective. */
    int (*solve)(struct pop_halo *h, struct linsolve *ls,
                 const struct csr_matrix *A, int64_t row0, int64_t nglobal,
                 const double *b, double *x, struct linsolve_stats *st);
};

struct pop_halo {
    const struct pop_halo_ops *ops;
    int rank, size;
    int n_own;            /* particles [0, n_own) are this rank's */
    double max_imbalance; /* balance when max/mean weight exceeds it;
                             0: never                                  */
    int balance_all;      /* weight 1 for every particle (else the
                             solver's own choice, e.g. its fluid)      */
};

/* One value combined over the ranks. */
static inline double pop_halo_reduce1(struct pop_halo *h, double v,
                                      enum pop_reduce op)
{
    h->ops->reduce(h, &v, 1, op);
    return v;
}

#endif
