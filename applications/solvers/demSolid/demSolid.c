/*
 * demSolid — DEM solver for dry (standalone) granular flows, and the DEM
 * side of MPS-DEM coupling (doc/theory.md A.6; doc/design.md §4-5).
 *
 * Reads   system/controlDict, system/demSolution, constant/demProperties,
 *         constant/g (optional: a missing file is a logged default),
 *         system/particleDict (walls; optional),
 *         <startTime>/dem.vtu (+ <startTime>/demContacts on restart)
 * Writes  <time>/dem.vtu, <time>/demContacts, dem.pvd, postProcessing/
 *
 * controlDict's deltaT is the output/function-object (and, coupled, the
 * coupling) interval; the DEM sub-steps inside it are the integrator's
 * business (system/demSolution).
 *
 * Coupled (system/couplingDict present, `coupled yes`): also reads
 * constant/transportProperties (fluid rho, nu) and runs beside mpsFluid
 * (runTandem mpsFluid demSolid): the initial state is sent, then every
 * interval receives the fluid state, advances with drag and buoyancy /
 * pressure-gradient forces, and sends the new state (couple_dem.h).
 * Its dem.vtu also holds, per grain, porosity, fluidVelocity, slipVelocity,
 * drag and buoyancy (B) or pressureGradientForce (A) (couple_dem.h).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/gravity.h"
#include "core/log.h"
#include "couplingDem/couple_dem.h"
#include "coupling/models.h"
#include "dem/dem.h"
#include "dem/dem_case.h"
#include "dem/functionObjects/dem_fo.h"
#include "io/vtu.h"
#include "solver/solver.h"

struct solid {
    struct solver sv;                   /* first: the hooks cast back   */
    struct dict *props, *solution, *particles, *gravity;
    struct dict *transport;             /* coupled runs only            */
    struct couple_dem cd;
    struct fo_value values[COUPLE_DEM_NVALUES];
    struct dem d;
    struct dem_solution sol;
    void *integ;
    struct vtu_cloud cloud;
    struct vtu_field fields[STORE_MAX_FIELDS];
    const char *patch_ptrs[DEM_MAX_PATCHES];
    int dim;
};

static int create_grains(struct solid *s)
{
    struct dem *d = &s->d;
    char rel[256], path[4200];
    TRY(app_read_dict(&s->sv.app, "constant/demProperties", &s->props));
    TRY(dem_read_properties(s->props, d));
    TRY(app_read_dict_optional(&s->sv.app, "system/particleDict",
                               &s->particles));
    s->dim = 3;
    if (s->particles)
        TRY(dem_read_walls(s->particles, s->sv.app.case_abs, d, &s->dim));
    TRY(gravity_case(&s->sv.app, s->dim, d->gravity, &s->gravity));
    snprintf(rel, sizeof rel, "%s/dem.vtu", s->sv.rt.name);
    TRY(dem_read_grains(app_path(&s->sv.app, rel, path, sizeof path), d));
    d->t = s->sv.rt.value;
    TRY(dem_setup(d));                 /* radii, masses, Rayleigh step */
    TRY(app_read_dict(&s->sv.app, "system/demSolution", &s->solution));
    TRY(dem_read_solution(s->solution, d, &s->sol));
    TRY(dem_setup(d));                 /* neighbour list with the skin  */
    log_info("Grains: %zu, R in [%g, %g] m, mass %g kg; walls: %d; "
             "Rayleigh step (eq. 38) %.4g s; fixed-step bound %.4g s; "
             "skin %g m", d->n, d->rmin, d->rmax, d->n ? d->m[0] : 0.0,
             d->nwalls, d->dt_rayleigh, d->dt_stable, d->nl.skin);
    TRY(dem_check_initial_overlap(d, &s->sol, path));
    int found;
    snprintf(rel, sizeof rel, "%s/demContacts", s->sv.rt.name);
    TRY(dem_read_contacts(app_path(&s->sv.app, rel, path, sizeof path), d,
                          &found));
    if (found)
        log_info("Contact histories read from %s", rel);
    if (s->sv.coupled) {
        TRY(app_read_dict(&s->sv.app, "constant/transportProperties",
                          &s->transport));
        TRY(couple_dem_init(&s->cd, s->sv.coupling, s->transport, d->gravity));
    }
    return s->sol.integrator->create(d, &s->sol.params, &s->integ);
}

static int refresh_scene(struct solver *sv)
{
    struct solid *s = (struct solid *)sv;
    struct dem *d = &s->d;
    store_cloud(&d->st, d->t, s->fields, &s->cloud);
    for (int p = 0; p < d->npatches; p++)
        s->patch_ptrs[p] = d->patch_names[p];
    s->sv.scene = (struct fo_scene){
        .time = s->sv.rt.value, .dt = s->sv.rt.dt, .step = s->sv.rt.step,
        .dim = s->dim, .cloud_name = "dem", .store = &d->st,
        .spacing = 2 * d->rmax, .patch_names = s->patch_ptrs,
        .npatches = d->npatches, .solver = d};
    if (s->sv.coupled) {
        couple_dem_values(&s->cd, d, s->values);
        s->sv.scene.values = s->values;
        s->sv.scene.nvalues = COUPLE_DEM_NVALUES;
    }
    return SIM_OK;
}

/* dem.vtu of a coupled run: the grains' fields and the coupling state of
 * the interval that ends now (couple_dem.h). */
static int write_coupled_grains(struct solid *s, const char *path)
{
    struct dem *d = &s->d;
    if (!couple_dem_output(&s->cd, d)) {
        log_warn("t = %s: grains were removed after the last exchange; "
                 "dem.vtu is written without the coupling fields",
                 s->sv.rt.name);
        return dem_write_grains(path, d, s->sv.rt.binary);
    }
    int a = s->cd.cs.model == COUPLING_MODEL_A;
    /* the grains' fields, then those of the coupling interval */
    struct vtu_field f[STORE_MAX_FIELDS + 5];
    struct vtu_cloud c;
    store_cloud(&d->st, d->t, f, &c);
    const struct vtu_field cpl[5] = {
        {"porosity", VTU_FLOAT64, 1, s->cd.eps},
        {"fluidVelocity", VTU_FLOAT64, 3, s->cd.uf},
        {"slipVelocity", VTU_FLOAT64, 3, s->cd.slip},
        {"drag", VTU_FLOAT64, 3, s->cd.Fapplied},
        {"", VTU_FLOAT64, 3, s->cd.fext},
    };
    memcpy(f + c.nfields, cpl, sizeof cpl);
    snprintf(f[c.nfields + 4].name, sizeof f[0].name, "%s",
             a ? "pressureGradientForce" : "buoyancy");
    c.nfields += 5;
    return vtu_write(path, &c, s->sv.rt.binary);
}

/* The grains and their contacts into dir (a time directory or
 * failed.<t>/). A failed write removes what it wrote, so that no half time
 * directory is left for latestTime. */
static int write_fields(struct solver *sv, const char *dir)
{
    struct solid *s = (struct solid *)sv;
    char path[4400];
    snprintf(path, sizeof path, "%s/dem.vtu", dir);
    int rc = sv->coupled && s->cd.exchanges > 0
           ? write_coupled_grains(s, path)
           : dem_write_grains(path, &s->d, sv->rt.binary);
    if (rc == SIM_OK) {
        snprintf(path, sizeof path, "%s/demContacts", dir);
        if ((rc = dem_write_contacts(path, &s->d)) != SIM_OK) {
            snprintf(path, sizeof path, "%s/dem.vtu", dir);
            unlink(path);
        }
    }
    return rc;
}

/* The time the DEM is advanced to. Between writes it is k deltaT with k
 * counted from time 0, not startTime + n deltaT: the two differ by an ulp,
 * and a restarted run (which starts at the written time) must see exactly
 * the times the continuous run saw, or the chaotic grain dynamics amplify
 * the ulp. At writes it is the write time itself, which a restart reads. */
static double target_time(const struct solid *s)
{
    const struct run_time *rt = &s->sv.rt;
    if (rt->write_now || rt->adjust || rt->dt != rt->delta_t)
        return rt->value;
    double k0 = floor(rt->start_time / rt->delta_t + 0.5);
    double tk = (k0 + (double)rt->step) * rt->delta_t;
    return fabs(tk - rt->value) < 1e-9 * rt->delta_t ? tk : rt->value;
}

static int advance(struct solver *sv)
{
    struct solid *s = (struct solid *)sv;
    return s->sol.integrator->advance(s->integ, &s->d, target_time(s));
}

static int check_domain(struct solver *sv)
{
    struct dem *d = &((struct solid *)sv)->d;
    long outside = dem_check_domain(d);
    if (outside < 0)
        return SIM_ERR_NOMEM;
    if (outside > 0)
        log_warn("t = %s: %ld grains outside the domain%s", sv->rt.name,
                 outside, d->remove_outside ? " (removed)" : "");
    return SIM_OK;
}

/* A restart starts the integrator and the neighbour list afresh from the
 * state written: the continuing run does the same, so that the two agree
 * to round-off. */
static int prepare_write(struct solver *sv)
{
    struct solid *s = (struct solid *)sv;
    if (s->sol.integrator->checkpoint)
        TRY(s->sol.integrator->checkpoint(s->integ, &s->d));
    return dem_rebuild_neighbours(&s->d);
}

static void progress(struct solver *sv, char *buf, size_t n)
{
    const struct dem *d = &((struct solid *)sv)->d;
    snprintf(buf, n, "substeps %ld rejected %ld forceEvals %ld "
             "contacts %ld+%ld", d->stats.steps, d->stats.rejected,
             d->stats.fevals + d->stats.hist_evals, d->ncontacts,
             d->nwall_contacts);
}

static void final_stats(struct solver *sv)
{
    const struct solid *s = (const struct solid *)sv;
    const struct dem_stats *st = &s->d.stats;
    double cpu = app_cpu_time() - s->sv.app.cpu0;
    double wall = app_wall_time() - s->sv.app.wall0;
    double ps = (double)s->d.n * (double)st->steps;
    log_info("\nDEM statistics (%s)", s->sol.integrator->name);
    log_info("    steps taken          %ld", st->steps);
    app_log_peak_memory(s->d.n);
    log_info("    steps rejected       %ld", st->rejected);
    log_info("    stability-limited    %ld", st->stab_limited);
    log_info("    force evaluations    %ld (+ %ld spring projections and "
             "slip-event checks)",
             st->fevals, st->hist_evals);
    log_info("    neighbour builds     %ld", st->rebuilds);
    log_info("    grains removed       %ld", st->removed);
    log_info("    grains               %zu", s->d.n);
    log_info("    particle-steps/s     %.4g (wall), %.4g per CPU second",
             wall > 0 ? ps / wall : 0.0, cpu > 0 ? ps / cpu : 0.0);
}

static void cleanup(struct solver *sv)
{
    struct solid *s = (struct solid *)sv;
    couple_dem_free(&s->cd);
    dict_free(s->transport);
    if (s->integ)
        s->sol.integrator->destroy(s->integ);
    dem_free(&s->d);
    dict_free(s->props);
    dict_free(s->solution);
    dict_free(s->particles);
    dict_free(s->gravity);
}

static int create(struct solver *sv)
{
    struct solid *s = (struct solid *)sv;
    dem_init(&s->d);
    TRY(create_grains(s));
    TRY(solver_check_unused(sv, s->props));
    return solver_check_unused(sv, s->solution);
}

static void list_models(void)
{
    model_choices_print(dem_choices, NULL, NULL);
    model_choices_print(coupling_choices, NULL, NULL);
}

/* Coupled (doc/design.md §4): the initial state goes to mpsFluid; each
 * interval receives the fluid state, advances, and sends the new state. */
static int couple_open(struct solver *sv)
{
    struct solid *s = (struct solid *)sv;
    TRY(couple_dem_open(&s->cd, sv->coupling, sv->app.case_abs, "demSolid",
                        s->dim, sv->rt.end_time));
    return couple_dem_send(&s->cd, &s->d, sv->rt.step, s->d.t);
}

static int couple_before(struct solver *sv)
{
    struct solid *s = (struct solid *)sv;
    return couple_dem_recv(&s->cd, &s->d);     /* fluid state at d->t */
}

static int couple_after(struct solver *sv)
{
    struct solid *s = (struct solid *)sv;
    TRY(couple_dem_after(&s->cd, &s->d));
    if (!s->cd.concurrent || time_running(&sv->rt))     /* couple_dem.h */
        TRY(couple_dem_send(&s->cd, &s->d, sv->rt.step, s->d.t));
    return SIM_OK;
}

/* The peer stopped, a signal came or a time-out: the grains are at a
 * complete coupling time (the wait comes before or after an advance,
 * never inside one). A failure of the DEM itself leaves no consistent
 * state to write. */
static int couple_keeps_state(int rc)
{
    return rc == SIM_ERR_PEER || rc == SIM_ERR_INTERRUPT
        || rc == SIM_ERR_TIMEOUT;
}

static void couple_close(struct solver *sv, int rc)
{
    couple_dem_close(&((struct solid *)sv)->cd, rc);
}

static const struct solver_coupling coupling = {
    .open = couple_open,
    .before_step = couple_before,
    .after_step = couple_after,
    .keeps_state = couple_keeps_state,
    .close = couple_close,
};

static const struct fo_ops *const *const fo_tables[] = {
    fo_generic_table, dem_fo_table, couple_fo_table, NULL };

static const struct solver_ops solid_ops = {
    .name = "demSolid",
    .description = "DEM solver: spheres, contact sub-models, ARKode or "
                   "Verlet sub-stepping",
    .cloud = "dem",
    .peer_cloud = "fluid",
    .list_models = list_models,
    .create = create,
    .fo_tables = fo_tables,
    .refresh_scene = refresh_scene,
    .advance = advance,
    .check = check_domain,
    .prepare_write = prepare_write,
    .write = write_fields,
    .progress = progress,
    .stats = final_stats,
    .cleanup = cleanup,
    .coupling = &coupling,
};

int main(int argc, char **argv)
{
    static struct solid s;
    return solver_main(&solid_ops, &s.sv, argc, argv);
}
