/*
 * cells.h — cell lists (uniform bins of side h >= the largest cut-off) and
 * renumbering of particle arrays in cell order.
 *
 * Particles are binned by a counting sort, so that building costs O(n +
 * ncell) and needs no allocation once the capacities stop growing. A
 * particle whose position is not finite or lies outside the box given to
 * cells_build() goes to an extra "outside" bucket and has no neighbours:
 * this is how a solver notices particles that left the tank without the
 * grid growing with them.
 *
 * Positions are interleaved x y z (z = 0 in 2-D). Ownership: the grid owns
 * its arrays; cells_free() releases them.
 */
#ifndef MPSDEM_PARTICLES_CELLS_H
#define MPSDEM_PARTICLES_CELLS_H

#include <stddef.h>
#include <stdint.h>

struct cell_grid {
    int dim;             /* 2 or 3                                        */
    double h;            /* cell side [m]                                 */
    double lo[3];        /* lower corner of the box [m]                   */
    int nc[3];           /* cells per direction (nc[2] = 1 in 2-D)        */
    int64_t ncell;       /* nc[0]*nc[1]*nc[2]; bucket ncell = outside     */
    int64_t *start;      /* ncell+2: particles of cell c are              */
                         /* order[start[c] .. start[c+1])                 */
    int32_t *order;      /* n particle indices sorted by cell (stable)    */
    int64_t *cell_of;    /* n: cell of each particle (ncell = outside)    */
    int n;               /* particles binned                              */
    int n_outside;       /* particles in the outside bucket               */
    size_t cap_cells, cap_n;
};

/* Bin n particles into cells of side h. lo/hi: the box [m]; both NULL for
 * the bounding box of the finite positions. Fails with SIM_ERR_INPUT when
 * h <= 0 or the box would need more than 2^31 cells. */
int cells_build(struct cell_grid *g, int dim, const double *x, int n, double h,
                const double *lo, const double *hi);

void cells_free(struct cell_grid *g);

/* Cell coordinates of a point, clamped to the grid; returns 0 when the
 * point is outside the box (then ic is meaningless). */
int cells_locate(const struct cell_grid *g, const double *p, int ic[3]);

/* Apply a permutation to an array: new[i] = old[perm[i]] for n items of
 * `size` bytes each. scratch holds n*size bytes. */
void cells_permute(void *a, size_t size, const int32_t *perm, int n,
                   void *scratch);

#endif
