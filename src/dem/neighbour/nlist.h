/*
 * nlist.h — DEM contact candidates: a half neighbour list (pairs i < j with
 * |x_i - x_j| < R_i + R_j + skin) built with a cell grid, reused until some
 * grain has moved more than half the skin since the build (Verlet 1967).
 * Rows are in CSR form with partners sorted ascending, which lets the
 * per-pair contact history be carried from the old list to the new one by
 * a merge (nlist_carry), so tangential springs survive rebuilds.
 */
#ifndef MPSDEM_DEM_NLIST_H
#define MPSDEM_DEM_NLIST_H

#include <stddef.h>
#include <stdint.h>

/* Loops over fewer grains than this run on one thread. */
#define DEM_OMP_MIN 2000

struct dem_nlist {
    size_t n;          /* grains at the last build                       */
    size_t *start;     /* n + 1 row offsets                              */
    uint32_t *j;       /* npairs partners, j > i, ascending per row      */
    size_t npairs, cap;
    double skin;       /* [m]                                            */
    double *x0;        /* 3n positions at the build                      */
    size_t ncap;       /* capacity of per-grain arrays                   */
    /* cell grid scratch */
    int64_t *head, *next;
    size_t ncells_cap;
    long nbuilds;
};

void nlist_init(struct dem_nlist *nl, double skin);
void nlist_free(struct dem_nlist *nl);

/* Build from positions x (3n) and radii r. */
int nlist_build(struct dem_nlist *nl, size_t n, const double *x,
                const double *r);

/* Largest displacement since the build [m]. */
double nlist_max_displacement(const struct dem_nlist *nl, const double *x);

/* Non-zero when a rebuild is due (some grain moved more than skin/2, or the
 * grain count changed). */
int nlist_stale(const struct dem_nlist *nl, size_t n, const double *x);

/* Carry per-pair data of width w (doubles) from an old list (ostart, oj,
 * onpairs, indices in the new numbering) to the list nl: pairs present in
 * both keep their values, new pairs get zeros. */
void nlist_carry(const struct dem_nlist *nl, const size_t *ostart,
                 const uint32_t *oj, size_t on, const double *oval, int w,
                 double *val);

#endif
