/*
 * pairs.c — grain / MPS-particle pairs (doc/theory.md A.10 step 1) and
 * their weights w_s of eq. (29); see pairs.h. The search is the particle
 * layer's cross list (particles/neighbour_cross.c); here every build or
 * update is followed by one pass that turns its distances into weights,
 * w_s(r) with r as the search computed it, and copies them to the
 * particle-major rows.
 */
#include "coupling/pairs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "coupling/porosity.h"

/* A grain with a non-finite position means the DEM side blew up: say so
 * in the coupling's words. */
static int search_failed(int rc)
{
    if (rc != SIM_ERR_NUMERIC)
        return rc;
    char why[256];
    snprintf(why, sizeof why, "%s", sim_error_message());
    return sim_error(rc, "coupling pairs: a grain has a non-finite "
                     "position (%s)", why);
}

/* The list's view and the weights of its pairs. */
static int weights(struct coupling_pairs *P, double re)
{
    const struct neighbour_cross *X = &P->X;
    size_t c = P->cap_w;
    TRY(sim_reserve((void **)&P->gw, &c, (size_t)X->npair + 1, sizeof *P->gw));
    c = P->cap_w;
    TRY(sim_reserve((void **)&P->pw, &c, (size_t)X->npair + 1, sizeof *P->pw));
    P->cap_w = c;
    TRY(sim_reserve((void **)&P->gwork, &P->cap_gw, 3 * (size_t)X->na + 3,
                    sizeof *P->gwork));
    P->dim = X->dim;
    P->re = re;
    P->ng = X->na;
    P->np = X->nb;
    P->npair = X->npair;
    P->gstart = X->astart;
    P->gj = X->aj;
    P->pstart = X->bstart;
    P->pk = X->bk;
    const int64_t n = X->npair;
#pragma omp parallel for schedule(static)
    for (int64_t e = 0; e < n; e++)
        P->gw[e] = coupling_ws(X->ar[e], re);
#pragma omp parallel for schedule(static)
    for (int64_t e = 0; e < n; e++)
        P->pw[e] = P->gw[X->bmap[e]];
    return SIM_OK;
}

int coupling_pairs_build(struct coupling_pairs *P, int dim, double re,
                         int ng, const double *xg, int np, const double *xp)
{
    TRY(search_failed(neighbour_cross_build(&P->X, dim, re, ng, xg, np,
                                            xp)));
    return weights(P, re);
}

int coupling_pairs_build_brute(struct coupling_pairs *P, int dim, double re,
                               int ng, const double *xg, int np,
                               const double *xp)
{
    TRY(search_failed(neighbour_cross_build_brute(&P->X, dim, re, ng, xg,
                                                  np, xp)));
    return weights(P, re);
}

int coupling_pairs_update(struct coupling_pairs *P, int dim, double re,
                          double skin, int ng, const double *xg, int np,
                          const double *xp, int *searched)
{
    TRY(search_failed(neighbour_cross_update(&P->X, dim, re, skin, ng, xg,
                                             np, xp, searched)));
    return weights(P, re);
}

void coupling_pairs_invalidate(struct coupling_pairs *P)
{
    neighbour_cross_invalidate(&P->X);
}

void coupling_pairs_free(struct coupling_pairs *P)
{
    neighbour_cross_free(&P->X);
    free(P->gw);
    free(P->pw);
    free(P->gwork);
    memset(P, 0, sizeof *P);
}
