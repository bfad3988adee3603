/*
 * cells.h — the one cell grid of the particle layer: uniform bins, the runs
 * of cells around a point (cells_runs), a cell-ordered copy of positions
 * (cells_gather), and renumbering of particle arrays in cell order. Every
 * neighbour builder (neighbour.h: full CSR self lists, neighbour_half.h:
 * half self lists with per-pair history, neighbour_cross.h: lists between
 * two clouds) searches through it.
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
    double lim[3];       /* a point with (p - lo)/h >= lim along an axis  */
                         /* is outside; up to lim it is clamped into the  */
                         /* last cell                                     */
    int n;               /* particles binned                              */
    int n_outside;       /* particles in the outside bucket               */
    size_t cap_cells, cap_n;
};

/* Bin n particles into cells of side h. lo/hi: the box [m]; both NULL for
 * the bounding box of the finite positions. Fails with SIM_ERR_INPUT when
 * h <= 0 or the box would need more than 2^31 cells. */
int cells_build(struct cell_grid *g, int dim, const double *x, int n, double h,
                const double *lo, const double *hi);

/* Bin n points into a grid of given geometry: lower corner lo, cell side
 * h, nc cells per axis (nc[2] = 1 in 2-D), points up to `over` cells past
 * the last cell of an axis clamped into it (a caller whose box ends inside
 * its last cell). cells_build() is this with the box's own geometry. */
int cells_build_grid(struct cell_grid *g, int dim, const double *x, int n,
                     double h, const double lo[3], const int nc[3],
                     double over);

void cells_free(struct cell_grid *g);

/* A run of order[]: the particles of consecutive cells along x. */
struct cell_run { int64_t a, b; };
enum { CELLS_MAX_RUNS = 64 };

/* Runs of order[] (at most CELLS_MAX_RUNS, in cell order: z, then y, then
 * x) holding every binned particle within rc of p, and others: per row
 * of cells along x, only the x-extent left by the row's distance in y and
 * z. Requires g->h >= rc / 2 (then at most 25 runs). Returns the number of
 * runs, their total length in *len. */
int cells_runs(const struct cell_grid *g, const double *p, double rc,
               struct cell_run *rn, int64_t *len);

/* Runs of the cells within `reach` cells of cell ic along each axis
 * (clipped to the grid; in cell order): (2 reach + 1)^(dim - 1) runs at
 * most, reach <= 3. Cheaper than cells_runs when the cells are as large as
 * the cut-off (reach 1: the 27 cells around a point), where trimming rows
 * saves little. Returns the number of runs, their total length in *len. */
int cells_runs_box(const struct cell_grid *g, const int ic[3], int reach,
                   struct cell_run *rn, int64_t *len);

/* Cell coordinates of binned particle i (not in the outside bucket). */
static inline void cells_coords(const struct cell_grid *g, int i, int ic[3])
{
    int64_t c = g->cell_of[i];
    ic[0] = (int)(c % g->nc[0]);
    c /= g->nc[0];
    ic[1] = (int)(c % g->nc[1]);
    ic[2] = (int)(c / g->nc[1]);
}

/* Positions of the binned (not outside) particles in cell order:
 * xs[3 e + k] = x[3 order[e] + k] for e < start[ncell]. */
void cells_gather(const struct cell_grid *g, const double *x, double *xs);

/* Cell coordinates of a point, clamped to the grid; returns 0 when the
 * point is outside the box (then ic is meaningless). */
int cells_locate(const struct cell_grid *g, const double *p, int ic[3]);

#endif
