/* mps_particles.c — the fluid's fields in the particle registry
 * (particles/store.h): allocation, the optional coupling fields, removal
 * of escaped particles and renumbering in cell order. The registry moves
 * every field; the dummy -> wall partner index is a STORE_INDEX field and
 * follows its wall particle. */
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"

int mps_particles_alloc(struct mps_particles *P, int n, int dim)
{
    memset(P, 0, sizeof *P);
    P->dim = dim;
    struct store *st = &P->st;
    store_init(st, "field of the fluid cloud");
    /* the order of the STORE_WRITE fields is that of fluid.vtu */
    int rc = store_add(st, "position", "[m]", VTU_FLOAT64, 3, STORE_POINTS,
                       &P->x);
    if (!rc) rc = store_add(st, "type", "0 fluid, 1 wall, 2 dummy",
                            VTU_INT32, 1, STORE_WRITE, &P->type);
    if (!rc) rc = store_add(st, "patch", "-1 fluid, else the wall patch",
                            VTU_INT32, 1, STORE_WRITE, &P->patch);
    if (!rc) rc = store_add(st, "velocity", "[m/s]", VTU_FLOAT64, 3,
                            STORE_WRITE, &P->u);
    if (!rc) rc = store_add(st, "pressure", "[Pa]", VTU_FLOAT64, 1,
                            STORE_WRITE, &P->p);
    if (!rc) rc = store_add(st, "normal", "wall/dummy, fluid -> solid",
                            VTU_FLOAT64, 3, STORE_WRITE, &P->normal);
    if (!rc) rc = store_add(st, "id", "persistent", VTU_INT64, 1,
                            STORE_WRITE, &P->id);
    if (!rc) rc = store_add(st, "numberDensity", "n_i/n0", VTU_FLOAT64, 1,
                            STORE_WRITE, &P->nd);
    if (!rc) rc = store_add(st, "freeSurface", "0 inner, 1 surface, 2 dry "
                            "wall", VTU_UINT8, 1, STORE_WRITE, &P->fs);
    if (!rc) rc = store_add(st, "partner", "wall particle of a dummy",
                            VTU_INT32, 1, STORE_INDEX, &P->partner);
    if (!rc) rc = store_reserve(st, n > 0 ? (size_t)n : 1);
    if (!rc) rc = store_resize(st, (size_t)n);
    if (rc) {
        mps_particles_free(P);
        return rc;
    }
    P->n = n;
    P->cap = (int)st->cap;
    for (int i = 0; i < n; i++) {
        P->partner[i] = -1;
        P->id[i] = i;
    }
    return SIM_OK;
}

int mps_particles_add(struct mps_particles *P, unsigned which)
{
    struct store *st = &P->st;
    if ((which & MPS_P_INV_EPS) && !P->inv_eps)
        TRY(store_add(st, "inversePorosity", "1/eps, or phi/eps",
                      VTU_FLOAT64, 1, 0, &P->inv_eps));
    if ((which & MPS_P_F_EXT) && !P->f_ext)
        TRY(store_add(st, "externalAcceleration", "[m/s^2]", VTU_FLOAT64, 3,
                      0, &P->f_ext));
    if ((which & MPS_P_PPE_SCALE) && !P->ppe_scale)
        TRY(store_add(st, "ppeScale", "PPE source factor", VTU_FLOAT64, 1,
                      0, &P->ppe_scale));
    if ((which & MPS_P_CORR_SCALE) && !P->corr_scale)
        TRY(store_add(st, "correctionScale", "pressure correction factor",
                      VTU_FLOAT64, 1, 0, &P->corr_scale));
    if ((which & MPS_P_PHI) && !P->phi)
        TRY(store_add(st, "volumeFraction", "fluid volume / dp^d",
                      VTU_FLOAT64, 1, STORE_WRITE, &P->phi));
    if ((which & MPS_P_SOIL) && !P->phase) {
        TRY(store_add(st, "phase", "1 soil, 0 water and walls", VTU_INT32,
                      1, STORE_WRITE, &P->phase));
        TRY(store_add(st, "acceleration", "of the last step [m/s^2]",
                      VTU_FLOAT64, 3, STORE_WRITE, &P->accel));
        TRY(store_add(st, "soilFraction", "soil share of a wall particle's "
                      "fluid neighbours", VTU_FLOAT64, 1, STORE_WRITE,
                      &P->soil_frac));
    }
    return SIM_OK;
}

void mps_particles_free(struct mps_particles *P)
{
    store_free(&P->st);
    memset(P, 0, sizeof *P);
}

/* The registry's count back into P->n (int: the solver's loops). */
static int synced(struct mps_particles *P, int rc)
{
    P->n = (int)P->st.n;
    return rc;
}

int mps_particles_permute(struct mps_solver *s, const int32_t *perm, int n)
{
    return synced(&s->P, store_permute(&s->P.st, perm, (size_t)n));
}

/* Remove the particles of the grid's outside bucket (left the box, or
 * non-finite position); *lost: how many of them were fluid. */
int mps_particles_drop_outside(struct mps_solver *s, int *lost)
{
    struct mps_particles *P = &s->P;
    const struct cell_grid *g = &s->grid;
    int m = 0;
    *lost = 0;
    for (int i = 0; i < P->n; i++) {
        if (g->cell_of[i] != g->ncell)
            s->perm[m++] = i;
        else
            *lost += P->type[i] == MPS_FLUID;
    }
    return synced(P, store_compact(&P->st, s->perm, (size_t)m));
}
