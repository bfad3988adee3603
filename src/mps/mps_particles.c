/* mps_particles.c — particle storage: allocation, removal of escaped
 * particles and renumbering in cell order (every per-particle array is
 * permuted; the dummy -> wall partner index is remapped). */
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"

int mps_particles_alloc(struct mps_particles *P, int n, int dim)
{
    memset(P, 0, sizeof *P);
    P->n = n;
    P->cap = n > 0 ? n : 1;
    P->dim = dim;
    size_t c = (size_t)P->cap;
    P->x = sim_calloc(3 * c, sizeof *P->x);
    P->u = sim_calloc(3 * c, sizeof *P->u);
    P->p = sim_calloc(c, sizeof *P->p);
    P->normal = sim_calloc(3 * c, sizeof *P->normal);
    P->type = sim_calloc(c, sizeof *P->type);
    P->patch = sim_calloc(c, sizeof *P->patch);
    P->id = sim_calloc(c, sizeof *P->id);
    P->partner = sim_calloc(c, sizeof *P->partner);
    P->nd = sim_calloc(c, sizeof *P->nd);
    P->fs = sim_calloc(c, sizeof *P->fs);
    if (!P->x || !P->u || !P->p || !P->normal || !P->type || !P->patch
        || !P->id || !P->partner || !P->nd || !P->fs) {
        mps_particles_free(P);
        return SIM_ERR_NOMEM;
    }
    for (int i = 0; i < n; i++) {
        P->partner[i] = -1;
        P->id[i] = i;
    }
    return SIM_OK;
}

void mps_particles_free(struct mps_particles *P)
{
    free(P->x); free(P->u); free(P->p); free(P->normal);
    free(P->type); free(P->patch); free(P->id); free(P->partner);
    free(P->nd); free(P->fs); free(P->inv_eps); free(P->f_ext);
    free(P->ppe_scale); free(P->corr_scale); free(P->phi);
    memset(P, 0, sizeof *P);
}

/* Permute every array by perm (new i <- old perm[i]), n entries kept. */
void mps_particles_permute(struct mps_solver *s, const int32_t *perm, int n)
{
    struct mps_particles *P = &s->P;
    void *scr = s->scratch;
    int nold = P->n;
    cells_permute(P->x, 3 * sizeof *P->x, perm, n, scr);
    cells_permute(P->u, 3 * sizeof *P->u, perm, n, scr);
    cells_permute(P->normal, 3 * sizeof *P->normal, perm, n, scr);
    cells_permute(P->p, sizeof *P->p, perm, n, scr);
    cells_permute(P->type, sizeof *P->type, perm, n, scr);
    cells_permute(P->patch, sizeof *P->patch, perm, n, scr);
    cells_permute(P->id, sizeof *P->id, perm, n, scr);
    cells_permute(P->nd, sizeof *P->nd, perm, n, scr);
    cells_permute(P->fs, sizeof *P->fs, perm, n, scr);
    if (P->inv_eps)
        cells_permute(P->inv_eps, sizeof *P->inv_eps, perm, n, scr);
    if (P->f_ext)
        cells_permute(P->f_ext, 3 * sizeof *P->f_ext, perm, n, scr);
    if (P->ppe_scale)
        cells_permute(P->ppe_scale, sizeof *P->ppe_scale, perm, n, scr);
    if (P->corr_scale)
        cells_permute(P->corr_scale, sizeof *P->corr_scale, perm, n, scr);
    if (P->phi)
        cells_permute(P->phi, sizeof *P->phi, perm, n, scr);
    /* The PPE warm start lives in p; partner indices must follow. */
    for (int i = 0; i < nold; i++)
        s->inv[i] = -1;
    for (int i = 0; i < n; i++)
        s->inv[perm[i]] = i;
    cells_permute(P->partner, sizeof *P->partner, perm, n, scr);
    for (int i = 0; i < n; i++)
        if (P->partner[i] >= 0)
            P->partner[i] = s->inv[P->partner[i]];
    P->n = n;
}

/* Remove the particles of the grid's outside bucket (left the box, or
 * non-finite position); returns how many fluid particles were removed. */
int mps_particles_drop_outside(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    const struct cell_grid *g = &s->grid;
    int m = 0, lost = 0;
    for (int i = 0; i < P->n; i++) {
        if (g->cell_of[i] != g->ncell)
            s->perm[m++] = i;
        else
            lost += P->type[i] == MPS_FLUID;
    }
    mps_particles_permute(s, s->perm, m);
    return lost;
}
