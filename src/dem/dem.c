/*
 * dem.c — grain storage, set-up and the bookkeeping around forces:
 * neighbour rebuilds with history carry-over, domain checks, energies.
 * The force loop itself is in dem_forces.c.
 */
#include "dem/dem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

void dem_init(struct dem *d)
{
    memset(d, 0, sizeof *d);
    neighbour_half_init(&d->nl, 0);
    d->gravity[2] = -9.81;
    d->omp_min = DEM_OMP_MIN;
}

void dem_free(struct dem *d)
{
    store_free(&d->st);
    free(d->walls);
    if (d->motions)
        for (int k = 0; k < DEM_MAX_PATCHES; k++)
            wall_motion_free(&d->motions[k]);
    free(d->motions);
    neighbour_half_free(&d->nl);
    free(d->hist); free(d->whist); free(d->pair_c); free(d->wall_chi);
    free(d->wstart); free(d->wlist); free(d->wgrain);
    free(d->old_start); free(d->old_j); free(d->old_h);
    free(d->tbuf);
    memset(d, 0, sizeof *d);
}

/* The grains' fields; the order of the written ones is that of dem.vtu. */
static int register_fields(struct dem *d)
{
    struct store *st = &d->st;
    store_init(st, "field of the dem cloud");
    TRY(store_add(st, "position", "[m]", VTU_FLOAT64, 3, STORE_POINTS, &d->x));
    TRY(store_add(st, "radius", "[m]", VTU_FLOAT64, 1, STORE_WRITE, &d->r));
    TRY(store_add(st, "velocity", "[m/s]", VTU_FLOAT64, 3, STORE_WRITE,
                  &d->v));
    TRY(store_add(st, "omega", "[rad/s]", VTU_FLOAT64, 3, STORE_WRITE,
                  &d->w));
    TRY(store_add(st, "group", "", VTU_INT32, 1, STORE_WRITE, &d->group));
    TRY(store_add(st, "id", "persistent", VTU_INT64, 1, STORE_WRITE, &d->id));
    TRY(store_add(st, "mass", "[kg]", VTU_FLOAT64, 1, 0, &d->m));
    TRY(store_add(st, "inverseMass", "[1/kg]", VTU_FLOAT64, 1, 0,
                  &d->inv_m));
    TRY(store_add(st, "inverseInertia", "[1/(kg m^2)]", VTU_FLOAT64, 1, 0,
                  &d->inv_i));
    TRY(store_add(st, "acceleration", "[m/s^2]", VTU_FLOAT64, 3, 0,
                  &d->acc));
    TRY(store_add(st, "angularAcceleration", "[rad/s^2]", VTU_FLOAT64, 3, 0,
                  &d->alpha));
    TRY(store_add(st, "dragForce", "at the last evaluation [N]",
                  VTU_FLOAT64, 3, 0, &d->cpl.fd));
    TRY(store_add(st, "dragImpulse", "since the last exchange [N s]",
                  VTU_FLOAT64, 3, 0, &d->cpl.fd_sum));
    return SIM_OK;
}

int dem_resize(struct dem *d, size_t n)
{
    if (d->st.nfields == 0)
        TRY(register_fields(d));
    size_t old = d->st.n;
    TRY(store_reserve(&d->st, n > 0 ? n : 1));
    TRY(store_resize(&d->st, n));
    for (size_t i = old; i < n; i++)
        d->id[i] = (int64_t)i;
    d->n = n;
    return SIM_OK;
}

void dem_walls_at(struct dem *d, double t)
{
    if (!d->motions)   /* walls made without dem_read_walls stay fixed */
        return;
    for (int w = 0; w < d->nwalls; w++)
        if (d->walls[w].motion >= 0)
            wall_place(&d->walls[w], &d->motions[d->walls[w].motion], t);
}

/* Walls within reach of each grain (distance < R + skin) at the positions
 * x the list is built at (ARKode builds at its own state, not d->x),
 * valid as long as the neighbour list is: the force loop then skips the
 * far walls, as LIGGGHTS' wall neighbour lists do. A moving wall is
 * listed for every grain: the list's skin bounds the grains' travel, not
 * the wall's. */
static int wall_candidates(struct dem *d, const double *x)
{
    size_t k = 0;
    d->wstart[0] = 0;
    for (size_t i = 0; i < d->n; i++) {
        for (int w = 0; w < d->nwalls; w++) {
            const struct dem_wall *wa = &d->walls[w];
            int moves = d->motions && wa->motion >= 0 && !wa->removed
                        && wall_motion_moves(&d->motions[wa->motion]);
            if (!moves && wall_distance(wa, &x[3 * i])
                              >= d->r[i] + d->nl.skin)
                continue;
            if (k == d->wlist_cap) {
                size_t cap = d->wlist_cap ? 2 * d->wlist_cap : 1024;
                SIM_GROW(d->wlist, cap);
                SIM_GROW(d->wgrain, cap);
                d->wlist_cap = cap;
            }
            d->wgrain[k] = (uint32_t)i;
            d->wlist[k++] = w;
        }
        d->wstart[i + 1] = k;
    }
    return SIM_OK;
}

/* Per-pair and per-grain constants of the contact law (chi, m*), set
 * after every build so that the force loop needs no division for them. */
static void pair_constants(struct dem *d)
{
    for (size_t i = 0; i < d->nl.n; i++) {
        d->wall_chi[i] = contact_chi(&d->law.c, d->r[i]);
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t j = d->nl.j[p];
            double rs = d->r[i] * d->r[j] / (d->r[i] + d->r[j]);
            d->pair_c[2 * p] = contact_chi(&d->law.c, rs);
            d->pair_c[2 * p + 1] = d->m[i] * d->m[j] / (d->m[i] + d->m[j]);
        }
    }
}

/* The contact candidates at x; non-finite positions mean the integration
 * blew up, which is what the user must read. */
static int build_list(struct dem *d, const double *x)
{
    int rc = neighbour_half_build(&d->nl, d->n, x, d->r);
    if (rc == SIM_ERR_NUMERIC)
        return sim_error(SIM_ERR_NUMERIC, "grain positions are not finite: "
                         "the integration blew up (a time step above the "
                         "contact stability limit?)");
    return rc;
}

static int reserve_histories(struct dem *d)
{
    if (d->n + 1 > d->wchi_cap) {
        SIM_GROW(d->wall_chi, d->n + 1);
        SIM_GROW(d->wstart, d->n + 1);
        d->wchi_cap = d->n + 1;
    }
    size_t np = d->nl.npairs > 0 ? d->nl.npairs : 1;
    if (np > d->hist_cap) {
        size_t cap = np + np / 2;
        SIM_GROW(d->hist, 3 * cap);
        SIM_GROW(d->pair_c, 2 * cap);
        d->hist_cap = cap;
    }
    size_t nw = d->n * (size_t)d->nwalls;
    nw = nw > 0 ? nw : 1;
    if (nw > d->whist_cap) {
        SIM_GROW(d->whist, 3 * nw);
        d->whist_cap = nw;
    }
    return SIM_OK;
}

int dem_setup(struct dem *d)
{
    double rho = d->law.c.rho;
    d->rmin = INFINITY, d->rmax = 0;
    d->rho_min_mass = INFINITY;
    for (size_t i = 0; i < d->n; i++) {
        double r = d->r[i];
        if (!(r > 0))
            return sim_error(SIM_ERR_INPUT,
                             "grain %zu (id %lld) has radius %g <= 0", i,
                             (long long)d->id[i], r);
        d->m[i] = rho * 4.0 / 3.0 * M_PI * r * r * r;
        d->inv_m[i] = 1.0 / d->m[i];
        d->inv_i[i] = 1.0 / (0.4 * d->m[i] * r * r);
        d->rmin = fmin(d->rmin, r);
        d->rho_min_mass = fmin(d->rho_min_mass, d->m[i]);
        d->rmax = fmax(d->rmax, r);
    }
    if (d->n == 0)
        d->rmin = d->rmax = 0;
    d->dt_rayleigh = d->n ? contact_rayleigh_step(&d->law.c, d->rmin) : 0;
    d->dt_stable = d->dt_rayleigh;
    if (d->n && d->law.normal == &contact_normal_linear) {
        /* a linear spring has a fixed frequency, omega^2 = k/m*, and an
         * explicit step must stay below 2/omega whatever eq. (38) says;
         * the stiffest contact is a wall (k = chi(R), m* = m) or a pair of
         * the smallest grains (k = chi(R/2), m* = m/2) */
        double mmin = d->rho_min_mass;
        double kw = d->law.c.kn_linear > 0 ? d->law.c.kn_linear
                                           : contact_chi(&d->law.c, d->rmax);
        double kp = d->law.c.kn_linear > 0 ? d->law.c.kn_linear
                                           : contact_chi(&d->law.c,
                                                         0.5 * d->rmax);
        double w2 = fmax(kw / mmin, 2.0 * kp / mmin);
        /* the sticking tangential spring acts on the mass m I/(I + m R^2)
         * = 2 m/7 of a sphere on a wall: its frequency is higher than the
         * normal one when kt/kn > 2/7 (tangentialStiffness mindlin) */
        w2 *= fmax(1.0, 3.5 * d->law.c.ratio_t);
        d->dt_stable = fmin(d->dt_stable, 2.0 / sqrt(w2));
    }
    if (d->nl.skin <= 0)
        d->nl.skin = 0.2 * d->rmax;   /* decision: 10 % of a diameter */
    dem_walls_at(d, d->t);
    TRY(build_list(d, d->x));
    d->stats.rebuilds++;
    TRY(reserve_histories(d));
    pair_constants(d);
    TRY(wall_candidates(d, d->x));
    memset(d->hist, 0, 3 * d->hist_cap * sizeof *d->hist);
    memset(d->whist, 0, 3 * d->whist_cap * sizeof *d->whist);
    dem_invalidate_forces(d);
    return SIM_OK;
}

void dem_invalidate_forces(struct dem *d)
{
    d->forces_valid = 0;
}

/* Rebuild with the histories following their pairs. `map` (old index ->
 * new index, or SIZE_MAX for a removed grain) is NULL when the numbering
 * did not change. */
static int rebuild(struct dem *d, const double *x, const size_t *map,
                   size_t old_n)
{
    size_t on = d->nl.n;
    size_t onp = d->nl.npairs;
    /* scratch copies of the old list, kept between rebuilds so that the
     * time loop does not allocate once they have reached their size */
    if (on + 1 > d->old_rows_cap) {
        SIM_GROW(d->old_start, on + 1 + on / 4);
        d->old_rows_cap = on + 1 + on / 4;
    }
    if (onp + 1 > d->old_pairs_cap) {
        size_t cap = onp + 1 + onp / 4;
        SIM_GROW(d->old_j, cap);
        SIM_GROW(d->old_h, 3 * cap);
        d->old_pairs_cap = cap;
    }
    size_t *ostart = d->old_start;
    uint32_t *oj = d->old_j;
    double *oh = d->old_h;
    /* Renumber the old list into the new numbering (monotone, so rows stay
     * sorted); pairs of removed grains are dropped. */
    size_t k = 0, row = 0;
    ostart[0] = 0;
    for (size_t i = 0; i < on; i++) {
        size_t ni = map ? map[i] : i;
        if (map && ni == SIZE_MAX)
            continue;
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t nj = map ? map[d->nl.j[p]] : d->nl.j[p];
            if (nj == SIZE_MAX)
                continue;
            oj[k] = (uint32_t)nj;
            memcpy(&oh[3 * k], &d->hist[3 * p], 3 * sizeof *oh);
            k++;
        }
        ostart[++row] = k;
    }
    (void)old_n;
    int rc = build_list(d, x);
    if (rc == SIM_OK)
        rc = reserve_histories(d);
    if (rc == SIM_OK) {
        neighbour_half_carry(&d->nl, ostart, oj, row, oh, 3, d->hist);
        pair_constants(d);
        rc = wall_candidates(d, x);
    }
    d->stats.rebuilds++;
    return rc;
}

int dem_rebuild_neighbours(struct dem *d)
{
    return rebuild(d, d->x, NULL, d->n);
}

int dem_update_neighbours(struct dem *d, const double *x)
{
    if (!neighbour_half_stale(&d->nl, d->n, x))
        return SIM_OK;
    return rebuild(d, x, NULL, d->n);
}

static int outside(const struct dem *d, size_t i)
{
    for (int a = 0; a < 3; a++) {
        double xa = d->x[3 * i + a];
        if (!(xa >= d->dom_lo[a] && xa <= d->dom_hi[a]))
            return 1;
    }
    return 0;
}

long dem_check_domain(struct dem *d)
{
    if (!d->have_domain)
        return 0;
    long count = 0;
    for (size_t i = 0; i < d->n; i++)
        count += outside(d, i);
    if (count == 0 || !d->remove_outside)
        return count;
    size_t *map = sim_malloc(d->n * sizeof *map);
    int32_t *kept = sim_malloc(d->n * sizeof *kept);
    if (!map || !kept) {
        free(map);
        free(kept);
        return count;  /* keep them: memory is too short to remove */
    }
    size_t k = 0, old_n = d->n;
    for (size_t i = 0; i < old_n; i++) {
        if (outside(d, i)) {
            map[i] = SIZE_MAX;
            continue;
        }
        map[i] = k;
        kept[k] = (int32_t)i;
        /* wall histories: nwalls per grain, not a per-grain field */
        if (k != i)
            for (int wl = 0; wl < d->nwalls; wl++)
                memcpy(&d->whist[3 * (k * d->nwalls + wl)],
                       &d->whist[3 * (i * d->nwalls + wl)], 3 * sizeof(double));
        k++;
    }
    int rc = store_compact(&d->st, kept, k);
    free(kept);
    if (rc) {
        free(map);
        return -1;
    }
    d->n = k;
    d->stats.removed += count;
    dem_invalidate_forces(d);   /* forces of the removed grains acted */
    rc = rebuild(d, d->x, map, old_n);
    free(map);
    return rc == SIM_OK ? count : -1;
}

int dem_contact_near(const struct dem *d, const double *x, const double *v)
{
    if (d->ncontacts + d->nwall_contacts > 0)
        return 1;
    const double H = d->stop_horizon, cap = 0.5 * d->nl.skin;
    if (!(H > 0))
        return 0;
    for (size_t i = 0; i < d->n && i < d->nl.n; i++) {
        const double *xi = x + 3 * i, *vi = v + 3 * i;
        double si = sqrt(vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t j = d->nl.j[p];
            const double *vj = v + 3 * j;
            double sj = sqrt(vj[0] * vj[0] + vj[1] * vj[1] + vj[2] * vj[2]);
            double reach = d->r[i] + d->r[j] + fmin(cap, (si + sj) * H);
            double d2 = 0;
            for (int a = 0; a < 3; a++)
                d2 += (x[3 * j + a] - xi[a]) * (x[3 * j + a] - xi[a]);
            if (d2 < reach * reach)
                return 1;
        }
        const double wreach = d->r[i] + fmin(cap, si * H);
        for (int wl = 0; wl < d->nwalls; wl++)
            if (wall_distance(&d->walls[wl], xi) < wreach)
                return 1;
    }
    return 0;
}

void dem_overlap_stats(struct dem *d, double frac, long *count,
                       double *max_rel)
{
    long c = 0;
    double mr = 0;
    for (size_t i = 0; i < d->n; i++) {
        for (size_t p = d->nl.start[i]; p < d->nl.start[i + 1]; p++) {
            size_t j = d->nl.j[p];
            double d2 = 0;
            for (int a = 0; a < 3; a++) {
                double dx = d->x[3 * j + a] - d->x[3 * i + a];
                d2 += dx * dx;
            }
            double rel = (d->r[i] + d->r[j] - sqrt(d2))
                         / fmin(d->r[i], d->r[j]);
            mr = fmax(mr, rel);
            c += rel > frac;
        }
        for (int wl = 0; wl < d->nwalls; wl++) {
            double n[3], delta;
            if (wall_contact(&d->walls[wl], &d->x[3 * i], d->r[i], n, &delta)) {
                double rel = delta / d->r[i];
                mr = fmax(mr, rel);
                c += rel > frac;
            }
        }
    }
    *count = c;
    *max_rel = mr;
}

double dem_contact_step(const struct dem *d)
{
    if (d->ncontacts + d->nwall_contacts == 0)
        return 0;
    double h = d->dt_rayleigh;
    if (d->omega2_max > 0)
        h = fmin(h, 2.0 / sqrt(d->omega2_max));
    return h;
}

double dem_kinetic_energy(const struct dem *d)
{
    double e = 0;
    #pragma omp parallel for reduction(+ : e) schedule(static) \
        if (d->n > DEM_OMP_MIN)
    for (size_t i = 0; i < d->n; i++) {
        double v2 = 0, w2 = 0;
        for (int a = 0; a < 3; a++) {
            v2 += d->v[3 * i + a] * d->v[3 * i + a];
            w2 += d->w[3 * i + a] * d->w[3 * i + a];
        }
        e += 0.5 * d->m[i] * v2 + 0.5 * w2 / d->inv_i[i];
    }
    return e;
}

void dem_coupling_set(struct dem *d, const double *fext, const double *uf,
                      const double *eps, dem_drag_fn drag, void *drag_ctx)
{
    d->cpl.fext = fext;
    d->cpl.uf = uf;
    d->cpl.eps = eps;
    d->cpl.drag = drag;
    d->cpl.drag_ctx = drag_ctx;
    /* a new fluid state (or the same arrays refilled): the drag and
     * external force of the last evaluation are stale */
    dem_invalidate_forces(d);
}

double dem_mean_drag(struct dem *d, double *fd)
{
    double T = d->cpl.sum_time;
    for (size_t k = 0; k < 3 * d->n; k++) {
        fd[k] = T > 0 ? d->cpl.fd_sum[k] / T : 0.0;
        d->cpl.fd_sum[k] = 0;
    }
    d->cpl.sum_time = 0;
    return T;
}
