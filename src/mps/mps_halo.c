/*
 * mps_halo.c — the MPS step on one rank of a distributed run (issue 22;
 * doc/design.md §8; particles/halo.h).
 *
 * Every operator of the step is a sum over a particle's neighbours within
 * the list radius r_list, so a rank computes the rows of its own
 * particles as one process does when the ghosts within r_list carry the
 * owners' values of what the row reads. mps_step calls mps_halo_refresh
 * after each phase whose result a neighbour's row reads:
 *
 *   prediction, then the collision model   u*      (collision, r* = r + dt u*,
 *                                                   div u* of the PPE)
 *   number density and surface test        n, fs   (the PPE's Dirichlet
 *                                                   neighbours, its pattern)
 *   PPE, then the dummies' pressure        P       (the gradient, the
 *   (extrapolated: the walls' first)                dummies' partner value)
 *   the move, when shifting follows        r       (the shift's sums)
 *   volume exchange (coupled, volume-     phi, inv_eps, u
 *   FractionRelaxation > 0)
 *
 * The rows of the ghosts are computed too and thrown away: their sums miss
 * the particles beyond the halo. The PPE's unknowns are numbered per rank,
 * own ones first, and offset by the count of the ranks before (exscan);
 * the ghosts learn their owners' numbers, the matrix of the own rows gets
 * global columns, and the ranks solve it together (h->ops->solve).
 *
 * Each step ends with the ghosts at their owners' positions and
 * velocities, the state that a coupled run's exchange between steps and
 * the next step read. Where the neighbour list must be built again on some rank
 * (a particle moved more than half the skin), every rank rebuilds: the
 * particles that left the box escape (counted over all ranks), the
 * regions are cut afresh when the largest rank's weight exceeds the mean
 * by more than maxImbalance (system/decomposeParDict), the particles
 * migrate to the rank whose region holds them, and the ghosts are copied
 * afresh. Between builds the ghost sets hold for the same reason the
 * list does: a pair within r_e now was within r_e + skin at the build.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "mps/mps.h"
#include "mps/mps_impl.h"

int mps_own(const struct mps_solver *s)
{
    return s->halo ? s->halo->n_own : s->P.n;
}

/* "<file:line:col>: <what> does not run distributed ...", located at key
 * of d when the case's dictionary is at hand (d NULL or key absent: the
 * file's name alone). */
static int not_yet(const struct dict *d, const char *key, const char *file,
                   const char *what)
{
    char where[512];
    snprintf(where, sizeof where, "%s", file);
    if (d && key && dict_has(d, key))
        dict_where(d, key, where, sizeof where);
    return sim_error(SIM_ERR_INPUT, "%s: %s does not run distributed "
                     "(-parallel) yet: run the case in one process", where,
                     what);
}

int mps_distribute(struct mps_solver *s, struct pop_halo *h,
                   const struct dict *schemes)
{
    const struct mps_settings *S = &s->S;
    const struct dict *fs = NULL;
    if (schemes && dict_is_dict(schemes, "freeSurface"))
        TRY(dict_get_dict(schemes, "freeSurface", &fs));
    if (s->soil)
        return not_yet(NULL, NULL, "constant/soilProperties", "a case with "
                       "soil particles");
    if (S->fs_pressure == MPS_FS_P_EXTRAPOLATED && !S->fs_simultaneous) {
        /* the sequential fit reads values set earlier in its own loop, in
         * index order, which ranks cannot repeat */
        char where[512] = "system/mpsSchemes";
        if (fs)
            dict_where(fs, dict_has(fs, "sweep") ? "sweep" : "pressure",
                       where, sizeof where);
        log_warn("%s: freeSurface { pressure extrapolated; } runs "
                 "distributed with `sweep simultaneous;` (every surface "
                 "value from the last step's), not the sequential sweep: "
                 "results differ from one process's sequential fit (by "
                 "0.4 mm in damBreak2D's front after 2 s); set sweep "
                 "simultaneous to compare like for like", where);
        s->S.fs_simultaneous = 1;
    }
    for (int k = 0; k < S->n_wall_motion && S->wall_motion; k++)
        if (isfinite(S->wall_motion[k].remove_at))
            return not_yet(NULL, NULL, "system/particleDict", "a wall region "
                           "with removeAt");
    s->halo = h;
    s->S.renumber_interval = 0;   /* the own particles stay first */
    s->rebuild = 1;
    /* the whole cloud's list goes (its storage would stay as the run's
     * peak on every rank), and this rank's takes its place: what a
     * coupled run's first exchange reads (Model A's pressure gradient),
     * as one process reads the list its set-up built */
    mps_drop_list(s);
    s->P.n = (int)s->P.st.n;
    s->P.cap = (int)s->P.st.cap;
    TRY(mps_fit_work(s));
    return mps_neighbours(s);
}

int mps_halo_reach(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    for (int i = 0; i < P->n; i++) {
        int w = P->partner[i];
        if (P->type[i] != MPS_DUMMY || w < 0)
            continue;
        double r2 = 0;
        for (int q = 0; q < 3; q++) {
            double d = P->x[3 * i + q] - P->x[3 * w + q];
            r2 += d * d;
        }
        double r = sqrt(r2) * (1 + 1e-9);
        if (r <= s->r_list)
            continue;
        if (!P->halo_reach)
            TRY(store_add(&P->st, "haloReach", "the farthest dummy leaning "
                          "on this wall particle [m]", VTU_FLOAT64, 1, 0,
                          &P->halo_reach));
        P->halo_reach[w] = fmax(P->halo_reach[w], r);
    }
    return SIM_OK;
}

int mps_halo_prepare(struct mps_solver *s)
{
    struct pop_halo *h = s->halo;
    if (!h)
        return SIM_OK;
    struct mps_particles *P = &s->P;
    /* the ghosts moved with their owners (the end of mps_step); while the
     * list holds on every rank (the skin), so do the ghost sets, as the
     * list's candidates do in one process */
    if (s->walls_move)
        TRY(mps_halo_refresh(s, P->normal, 3 * sizeof *P->normal));
    if (pop_halo_reduce1(h, mps_list_valid(s), POP_MIN) > 0)
        return SIM_OK;
    /* own particles outside the box escape here, as cells_build would
     * find them; the ghosts are dropped by the exchange anyway */
    int m = 0, lost = 0, ic[3];
    for (int i = 0; i < h->n_own; i++) {
        if (cells_locate(&s->grid, P->x + 3 * i, ic))
            s->perm[m++] = i;
        else
            lost += P->type[i] == MPS_FLUID;
    }
    const int own = m;
    for (int i = h->n_own; i < P->n; i++)
        s->perm[m++] = i;
    if (m < P->n) {
        TRY(store_compact(&P->st, s->perm, (size_t)m));
        P->n = m;
        h->n_own = own;
    }
    long all = (long)pop_halo_reduce1(h, lost, POP_SUM);
    if (all)
        TRY(mps_escaped(s, all));
    if (h->max_imbalance > 0) {
        /* the weights of decomposeParDict's balance: the fluid rows are
         * the step's work; walls and dummies have rows only near water */
        double *w = s->b;    /* free until the PPE */
        mps_balance_weights(P, h->n_own, h->balance_all, w);
        int done;
        TRY(h->ops->balance(h, &P->st, w, &done));
        if (done)
            log_info("    regions cut afresh: a rank's weight exceeded the "
                     "mean by more than maxImbalance %g", h->max_imbalance);
    }
    TRY(h->ops->exchange(h, &P->st));
    P->n = (int)P->st.n;
    P->cap = (int)P->st.cap;
    s->rebuild = 1;
    return mps_fit_work(s);
}

void mps_balance_weights(const struct mps_particles *P, int n, int all,
                         double *w)
{
    for (int i = 0; i < n; i++)
        w[i] = all || P->type[i] == MPS_FLUID ? 1.0 : 0.0;
}

int mps_halo_refresh(struct mps_solver *s, void *field, size_t elem)
{
    return s->halo ? s->halo->ops->refresh(s->halo, field, elem) : SIM_OK;
}
