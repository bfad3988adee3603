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
 * drag and buoyancy (B) or pressureGradientForce (A) (couple_output.h).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/gravity.h"
#include "core/log.h"
#include "core/time.h"
#include "couplingDem/couple_dem.h"
#include "coupling/models.h"
#include "dem/dem.h"
#include "dem/dem_case.h"
#include "dem/functionObjects/dem_fo.h"
#include "io/vtu.h"

struct solid {
    struct app app;
    struct dict *control, *props, *solution, *particles, *gravity;
    struct dict *coupling, *transport;  /* coupled runs only            */
    int coupled;
    struct couple_dem cd;
    struct fo_value values[COUPLE_DEM_NVALUES];
    struct run_time rt;
    struct dem d;
    struct dem_solution sol;
    void *integ;
    struct fo_list *fos;
    struct fo_scene scene;
    struct vtu_cloud cloud;
    struct vtu_field fields[5];
    const char *patch_ptrs[DEM_MAX_PATCHES];
    int dim;
};

/* controlDict, and system/couplingDict if there is one: a coupled run
 * restarts (startFrom latestTime) only from a time that holds both
 * clouds. */
static int create_time(struct solid *s)
{
    TRY(app_read_dict(&s->app, "system/controlDict", &s->control));
    TRY(app_read_dict_optional(&s->app, "system/couplingDict", &s->coupling));
    TRY(couple_enabled(s->coupling, &s->coupled));
    static const char *const alone[] = { "dem.vtu", NULL };
    static const char *const both[] = { "dem.vtu", "fluid.vtu", NULL };
    return time_read(s->control, s->app.case_abs, s->coupled ? both : alone,
                     &s->rt);
}

static int create_grains(struct solid *s)
{
    struct dem *d = &s->d;
    char rel[256], path[4200];
    TRY(app_read_dict(&s->app, "constant/demProperties", &s->props));
    TRY(dem_read_properties(s->props, d));
    TRY(app_read_dict_optional(&s->app, "system/particleDict", &s->particles));
    s->dim = 3;
    if (s->particles)
        TRY(dem_read_walls(s->particles, s->app.case_abs, d, &s->dim));
    TRY(gravity_case(&s->app, s->dim, d->gravity, &s->gravity));
    snprintf(rel, sizeof rel, "%s/dem.vtu", s->rt.name);
    TRY(dem_read_grains(app_path(&s->app, rel, path, sizeof path), d));
    d->t = s->rt.value;
    TRY(dem_setup(d));                 /* radii, masses, Rayleigh step */
    TRY(app_read_dict(&s->app, "system/demSolution", &s->solution));
    TRY(dem_read_solution(s->solution, d, &s->sol));
    TRY(dem_setup(d));                 /* neighbour list with the skin  */
    log_info("Grains: %zu, R in [%g, %g] m, mass %g kg; walls: %d; "
             "Rayleigh step (eq. 38) %.4g s; fixed-step bound %.4g s; "
             "skin %g m", d->n, d->rmin, d->rmax, d->n ? d->m[0] : 0.0,
             d->nwalls, d->dt_rayleigh, d->dt_stable, d->nl.skin);
    TRY(dem_check_initial_overlap(d, &s->sol, path));
    int found;
    snprintf(rel, sizeof rel, "%s/demContacts", s->rt.name);
    TRY(dem_read_contacts(app_path(&s->app, rel, path, sizeof path), d,
                          &found));
    if (found)
        log_info("Contact histories read from %s", rel);
    if (s->coupled) {
        TRY(app_read_dict(&s->app, "constant/transportProperties",
                          &s->transport));
        TRY(couple_dem_init(&s->cd, s->coupling, s->transport, d->gravity));
    }
    return s->sol.integrator->create(d, &s->sol.params, &s->integ);
}

static void refresh_scene(struct solid *s)
{
    struct dem *d = &s->d;
    struct vtu_field f[5] = {
        {"radius", VTU_FLOAT64, 1, d->r},
        {"velocity", VTU_FLOAT64, 3, d->v},
        {"omega", VTU_FLOAT64, 3, d->w},
        {"group", VTU_INT32, 1, d->group},
        {"id", VTU_INT64, 1, d->id},
    };
    memcpy(s->fields, f, sizeof f);
    s->cloud = (struct vtu_cloud){.n = d->n, .points = d->x, .nfields = 5,
                                  .fields = s->fields, .time = d->t};
    for (int p = 0; p < d->npatches; p++)
        s->patch_ptrs[p] = d->patch_names[p];
    s->scene = (struct fo_scene){
        .time = s->rt.value, .dt = s->rt.dt, .step = s->rt.step,
        .dim = s->dim, .cloud_name = "dem", .cloud = &s->cloud,
        .spacing = 2 * d->rmax, .patch_names = s->patch_ptrs,
        .npatches = d->npatches, .solver = d};
    if (s->coupled) {
        couple_dem_values(&s->cd, d, s->values);
        s->scene.values = s->values;
        s->scene.nvalues = COUPLE_DEM_NVALUES;
    }
}

static int create_functions(struct solid *s)
{
    static const struct fo_ops *const *const tables[] = {
        fo_generic_table, dem_fo_table, couple_fo_table, NULL};
    refresh_scene(s);
    return fo_list_create(s->rt.functions, tables, &s->scene,
                          s->app.case_abs, s->rt.start_time, s->rt.precision,
                          &s->fos);
}

/* dem.vtu of a coupled run: the grains' fields and the coupling state of
 * the interval that ends now (couple_output.h). */
static int write_coupled_grains(struct solid *s, const char *path)
{
    struct dem *d = &s->d;
    if (!couple_dem_output(&s->cd, d)) {
        log_warn("t = %s: grains were removed after the last exchange; "
                 "dem.vtu is written without the coupling fields",
                 s->rt.name);
        return dem_write_grains(path, d, s->rt.binary);
    }
    int a = s->cd.cs.model == COUPLING_MODEL_A;
    struct vtu_field f[10] = {
        {"radius", VTU_FLOAT64, 1, d->r},
        {"velocity", VTU_FLOAT64, 3, d->v},
        {"omega", VTU_FLOAT64, 3, d->w},
        {"group", VTU_INT32, 1, d->group},
        {"id", VTU_INT64, 1, d->id},
        {"porosity", VTU_FLOAT64, 1, s->cd.eps},
        {"fluidVelocity", VTU_FLOAT64, 3, s->cd.uf},
        {"slipVelocity", VTU_FLOAT64, 3, s->cd.slip},
        {"drag", VTU_FLOAT64, 3, s->cd.Fapplied},
        {"", VTU_FLOAT64, 3, s->cd.fext},
    };
    snprintf(f[9].name, sizeof f[9].name, "%s",
             a ? "pressureGradientForce" : "buoyancy");
    struct vtu_cloud c = {.n = d->n, .points = d->x, .nfields = 10,
                          .fields = f, .time = d->t};
    return vtu_write(path, &c, s->rt.binary);
}

/* The grains and their contacts into <t>/ (prefix "") and the .pvd, or
 * into failed.<t>/ (prefix "failed.": not a time to restart from, not in
 * the .pvd). A failed write removes what it wrote, so that no half time
 * directory is left for latestTime. */
static int write_fields(struct solid *s, const char *prefix)
{
    char dir[4200], path[4400], pvd[4200], rel[256];
    TRY(time_make_dir(&s->rt, s->app.case_abs, prefix, dir, sizeof dir));
    snprintf(path, sizeof path, "%s/dem.vtu", dir);
    int rc = s->coupled && s->cd.exchanges > 0
           ? write_coupled_grains(s, path)
           : dem_write_grains(path, &s->d, s->rt.binary);
    if (rc == SIM_OK) {
        snprintf(path, sizeof path, "%s/demContacts", dir);
        if ((rc = dem_write_contacts(path, &s->d)) != SIM_OK) {
            snprintf(path, sizeof path, "%s/dem.vtu", dir);
            unlink(path);
        }
    }
    if (rc) {
        time_dir_discard(dir);
        return rc;
    }
    if (prefix[0])
        return SIM_OK;
    snprintf(rel, sizeof rel, "%s/dem.vtu", s->rt.name);
    return pvd_add(app_path(&s->app, "dem.pvd", pvd, sizeof pvd), s->rt.value,
                   rel);
}

static int start_output(struct solid *s)
{
    char pvd[4200], rel[256];
    app_path(&s->app, "dem.pvd", pvd, sizeof pvd);
    if (access(pvd, F_OK) == 0)
        TRY(pvd_truncate(pvd, s->rt.value));
    snprintf(rel, sizeof rel, "%s/dem.vtu", s->rt.name);
    TRY(pvd_add(pvd, s->rt.value, rel));
    return app_write_used_parameters(&s->app);
}

/* The time the DEM is advanced to. Between writes it is k deltaT with k
 * counted from time 0, not startTime + n deltaT: the two differ by an ulp,
 * and a restarted run (which starts at the written time) must see exactly
 * the times the continuous run saw, or the chaotic grain dynamics amplify
 * the ulp. At writes it is the write time itself, which a restart reads. */
static double target_time(const struct solid *s)
{
    const struct run_time *rt = &s->rt;
    if (rt->write_now || rt->adjust || rt->dt != rt->delta_t)
        return rt->value;
    double k0 = floor(rt->start_time / rt->delta_t + 0.5);
    double tk = (k0 + (double)rt->step) * rt->delta_t;
    return fabs(tk - rt->value) < 1e-9 * rt->delta_t ? tk : rt->value;
}

static int step(struct solid *s)
{
    struct dem *d = &s->d;
    time_set_step(&s->rt, s->rt.delta_t);
    if (s->coupled)
        TRY(couple_dem_recv(&s->cd, d));       /* fluid state at d->t */
    time_increment(&s->rt);
    TRY(s->sol.integrator->advance(s->integ, d, target_time(s)));
    if (s->coupled) {
        TRY(couple_dem_after(&s->cd, d));
        if (!s->cd.concurrent || time_running(&s->rt))   /* couple_dem.h */
            TRY(couple_dem_send(&s->cd, d, s->rt.step, d->t));
    }
    long outside = dem_check_domain(d);
    if (outside < 0)
        return SIM_ERR_NOMEM;
    if (outside > 0)
        log_warn("t = %s: %ld grains outside the domain%s", s->rt.name,
                 outside, d->remove_outside ? " (removed)" : "");
    refresh_scene(s);
    TRY(fo_list_execute(s->fos, &s->scene, s->rt.write_now));
    if (s->rt.write_now) {
        if (s->sol.integrator->checkpoint)
            TRY(s->sol.integrator->checkpoint(s->integ, d));
        TRY(dem_rebuild_neighbours(d));
        TRY(write_fields(s, ""));
        app_log_times(&s->app);
    }
    char extra[256];
    snprintf(extra, sizeof extra, "substeps %ld rejected %ld forceEvals %ld "
             "contacts %ld+%ld", d->stats.steps, d->stats.rejected,
             d->stats.fevals + d->stats.hist_evals, d->ncontacts,
             d->nwall_contacts);
    time_log_progress(&s->rt, extra);
    return SIM_OK;
}

static void final_stats(const struct solid *s)
{
    const struct dem_stats *st = &s->d.stats;
    double cpu = app_cpu_time() - s->app.cpu0;
    double wall = app_wall_time() - s->app.wall0;
    double ps = (double)s->d.n * (double)st->steps;
    log_info("\nDEM statistics (%s)", s->sol.integrator->name);
    log_info("    steps taken          %ld", st->steps);
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

/* A coupled run stopped by the peer, a signal or a time-out: the grains
 * are at a complete coupling time (the wait comes before or after an
 * advance, never inside one), so write them, then tell the peer why we
 * leave. A failure of the DEM itself leaves no consistent state to write. */
static void coupled_failure(struct solid *s, int rc)
{
    char msg[1024];
    /* A signal stops both programs, which both write: a restart time.
     * Otherwise the peer writes nothing: failed.<t>/ (mpsFluid.c). */
    const char *prefix = rc == SIM_ERR_INTERRUPT ? "" : "failed.";
    snprintf(msg, sizeof msg, "%s", sim_error_message());
    if ((rc == SIM_ERR_PEER || rc == SIM_ERR_INTERRUPT
         || rc == SIM_ERR_TIMEOUT) && s->rt.step > 0
        && write_fields(s, prefix) == SIM_OK)
        log_info("Last complete state (t = %g s) written to %s%s/dem.vtu",
                 s->d.t, prefix, s->rt.name);
    couple_dem_close(&s->cd, rc);
    sim_error(rc, "%s", msg);
}

static void cleanup(struct solid *s)
{
    couple_dem_free(&s->cd);
    dict_free(s->coupling);
    dict_free(s->transport);
    if (s->integ)
        s->sol.integrator->destroy(s->integ);
    fo_list_free(s->fos);
    dem_free(&s->d);
    dict_free(s->control);
    dict_free(s->props);
    dict_free(s->solution);
    dict_free(s->particles);
    dict_free(s->gravity);
}

int main(int argc, char **argv)
{
    static struct solid s;
    int rc;

    const char *list = NULL;
    const struct app_option opts[] = {
        { "-listModels", 0, NULL, "print every model choice (dictionary "
          "key name) and exit", &list },
        { NULL, 0, NULL, NULL, NULL }
    };
    app_init(&s.app, "demSolid", "DEM solver: spheres, contact sub-models, "
             "ARKode or Verlet sub-stepping", argc, argv, opts, 0);
    if (list) {
        model_choices_print(dem_choices, NULL, NULL);
        model_choices_print(coupling_choices, NULL, NULL);
        return 0;
    }
    dem_init(&s.d);
    if ((rc = app_lock_case(&s.app)) || (rc = create_time(&s))
        || (rc = create_grains(&s))
        || (rc = create_functions(&s)) || (rc = start_output(&s)))
        app_fatal(&s.app, rc);
    dict_mark_used(s.control, "application");  /* read by scripts */
    dict_warn_unused(s.control);
    dict_warn_unused(s.props);
    dict_warn_unused(s.solution);
    if (s.coupled) {
        if ((rc = couple_dem_open(&s.cd, s.coupling, s.app.case_abs,
                                  "demSolid", s.dim, s.rt.end_time))
            || (rc = couple_dem_send(&s.cd, &s.d, s.rt.step, s.d.t)))
            coupled_failure(&s, rc), app_fatal(&s.app, rc);
        dict_warn_unused(s.coupling);
    }
    log_info("\nStarting time loop\n");
    while (time_running(&s.rt))
        if ((rc = step(&s))) {
            if (s.coupled)
                coupled_failure(&s, rc);
            app_fatal(&s.app, rc);
        }
    if (s.coupled)
        couple_dem_close(&s.cd, SIM_OK);
    final_stats(&s);
    cleanup(&s);
    return app_end(&s.app);
}
