/*
 * distribute.h — the MPI implementation of a distributed particle cloud
 * (halo.h; doc/design.md §8). Only in MPI builds (`make MPI=1`, which
 * defines MPSDEM_HAVE_MPI).
 *
 * Ownership is geometric: recursive coordinate bisection of the start
 * cloud (decompose.h) gives each rank a region, bounded by the recorded
 * cuts, and a particle belongs to the rank whose region holds it, so a
 * particle that moves across a cut migrates at the next exchange.
 * Ghosts: every particle within `width` of the bounding box of another
 * rank's own particles is copied there (a superset of the particles
 * within `width` of one of them). Messages go through MPI_Alltoallv: one
 * per pair of ranks that share particles.
 *
 * dist_gather collects the own particles of every rank into a store on
 * rank 0 (its fields registered like the source's), sorted by id: the
 * whole cloud for output and function objects, as one process has it.
 */
#ifndef MPSDEM_PARTICLES_DISTRIBUTE_H
#define MPSDEM_PARTICLES_DISTRIBUTE_H

#ifdef MPSDEM_HAVE_MPI

#include <mpi.h>

#include "particles/halo.h"
#include "particles/store.h"

struct dist;

/* A distributed cloud on comm for particles of dimension dim, with ghosts
 * to distance width. */
int dist_create(MPI_Comm comm, int dim, double width, struct dist **out);
void dist_free(struct dist *d);

/* The interface the solvers use (h->ops, rank, size, n_own); its solve
 * is the caller's (a library above this one: linsolve_solve_dist). */
struct pop_halo *dist_halo(struct dist *d);
void dist_set_solve(struct dist *d,
                    int (*solve)(struct pop_halo *, struct linsolve *,
                                 const struct csr_matrix *, int64_t, int64_t,
                                 const double *, double *,
                                 struct linsolve_stats *));
/* The communicator of the cloud h belongs to. */
MPI_Comm dist_comm(const struct pop_halo *h);

/* Every rank holds the same whole cloud in st: cut it into one region per
 * rank, balancing weight (per particle; NULL for 1 each), keep the own
 * particles, then build the ghosts (exchange). */
int dist_split(struct dist *d, struct store *st, const double *weight);

/* The own particles of every rank into *whole on rank 0 (created on the
 * first call with st's fields, reused; NULL elsewhere), sorted by id. */
int dist_gather(struct dist *d, const struct store *st, struct store **whole);

/* What the run cost in messages (collective): particles migrated over
 * all ranks, the times the regions were cut afresh, the ghosts a rank
 * held per exchange (mean over the ranks and the exchanges, and the
 * largest rank's mean), own particles now. */
struct dist_stats {
    int ranks;
    long migrated, exchanges, balances;
    double ghosts_mean, ghosts_max;
    long own_min, own_max;
};
void dist_stats(struct dist *d, struct dist_stats *out);

#endif
#endif
