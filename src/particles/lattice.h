/*
 * lattice.h — regular arrangements of particle sites, to fill regions
 * (genParticles) and to build test clouds.
 *
 * cubic:     square (2-D) or simple-cubic (3-D) lattice of side `spacing`;
 *            the MPS fluid lattice, and a loose grain packing.
 * hexagonal: triangular (2-D) or hexagonal close-packed (3-D, ABAB
 *            stacking of triangular layers along z, layer distance
 *            spacing sqrt(2/3)); every site has its nearest neighbours at
 *            exactly `spacing` (6 in 2-D, 12 in 3-D); for dense grains.
 *
 * Sites are x = origin + i a1 + j a2 + k a3 with the layer offsets above;
 * in 2-D, z = 0 and k = 0. Positions are interleaved x y z.
 */
#ifndef MPSDEM_PARTICLES_LATTICE_H
#define MPSDEM_PARTICLES_LATTICE_H

#include <stddef.h>
#include <stdint.h>

enum lattice_kind { LATTICE_CUBIC, LATTICE_HEXAGONAL };

/* "cubic" "hexagonal", indexed by enum lattice_kind, NULL terminated. */
extern const char *const lattice_kind_names[];

struct lattice {
    enum lattice_kind kind;
    int dim;          /* 2 or 3                              */
    double origin[3]; /* one site [m]                        */
    double spacing;   /* nearest-neighbour distance [m] > 0  */
};

/* Site (i, j, k). */
void lattice_site(const struct lattice *l, long i, long j, long k,
                  double x[3]);

/* Index ranges whose sites cover the box [lo, hi] (finite): sites with
 * first[d] <= index < first[d] + count[d] include every site in the box
 * (and a few outside). *nsites is the product of the counts. Fails with
 * SIM_ERR_INPUT for a bad lattice or box, or more than 2^40 sites. */
int lattice_range(const struct lattice *l, const double lo[3],
                  const double hi[3], long first[3], long count[3],
                  double *nsites);

/* Decide whether a site is kept; must be thread-safe (it is called from
 * several OpenMP threads at once). */
typedef int (*lattice_accept_fn)(const double x[3], void *ctx);

/* Sites inside the box [lo, hi] (to a tolerance of 1e-9 spacing) that
 * accept() keeps, in a deterministic order (k, j, i) independent of the
 * number of threads. *x is allocated (3 *n doubles; free()). accept may be
 * NULL (keep all). */
int lattice_fill(const struct lattice *l, const double lo[3],
                 const double hi[3], lattice_accept_fn accept, void *ctx,
                 double **x, size_t *n);

/* Move each point by an independent uniform random offset in
 * [-amplitude, amplitude] per used coordinate. The offset of point i
 * depends only on (seed, i), so results do not depend on threads. */
void lattice_jitter(double *x, size_t n, int dim, double amplitude,
                    uint64_t seed);

/* The lattice genParticles wrote into constant/particlePatches: its
 * dimension (2 or 3) and spacing dp (> 0); errors cite the file and line.
 * The keys patches, types, wallLayers are the caller's. */
struct dict;
int lattice_read_patches(const struct dict *patches, int *dim, double *dp);

#endif
