/*
 * solver.c — the run around a particle solver's algorithm (solver.h).
 */
#include "solver/solver.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"
#include "coupling/models.h"
#include "io/vtu.h"
#include "particles/lattice.h"

#ifdef MPSDEM_HAVE_MPI
#include <mpi.h>

/* A rank that stops on an error (app_fatal exits) takes the job down: the
 * others may wait in a collective for it. A complete run finalises
 * before it exits, so this aborts only after an error. */
static int mpi_started, mpi_rank;

static void abort_job(void)
{
    int init = 0, done = 0;
    MPI_Initialized(&init);
    MPI_Finalized(&done);
    if (!init || done)
        return;
    /* ranks that stop together (a coupled exchange that failed on rank
     * 0) leave rank 0 the time to log why before the job goes down */
    if (mpi_rank > 0)
        sleep(2);
    MPI_Abort(MPI_COMM_WORLD, 1);
}
#endif

/* -parallel among the arguments: MPI starts before anything is logged, so
 * that only rank 0 logs. */
static int start_parallel(struct solver *sv, int argc, char **argv)
{
    int want = 0;
    sv->rank = 0;
    for (int k = 1; k < argc; k++)
        want |= !strcmp(argv[k], "-parallel");
    if (!want)
        return SIM_OK;
    if (!sv->ops->parallel)
        return sim_error(SIM_ERR_INPUT, "-parallel: %s runs in one process "
                         "only", sv->ops->name);
#ifdef MPSDEM_HAVE_MPI
    if (MPI_Init(&argc, &argv) != MPI_SUCCESS)
        return sim_error(SIM_ERR_EXTERNAL, "-parallel: MPI_Init failed");
    mpi_started = 1;
    sv->distributed = 1;
    atexit(abort_job);
    MPI_Comm_rank(MPI_COMM_WORLD, &sv->rank);
    mpi_rank = sv->rank;
    if (sv->rank > 0)
        log_set_quiet(1);
    return SIM_OK;
#else
    return sim_error(SIM_ERR_INPUT, "-parallel: this %s was built without "
                     "MPI; build the MPI one with `make MPI=1` and run "
                     "`mpirun -np N bin-hypre/%s -parallel`", sv->ops->name,
                     sv->ops->name);
#endif
}

static int root(const struct solver *sv)
{
    return sv->rank == 0;
}

int solver_check_unused(struct solver *sv, const struct dict *d)
{
    if (sv->nchecked == SOLVER_MAX_CHECKED)
        return sim_error(SIM_ERR_INTERNAL, "solver_check_unused: more than "
                         "%d dictionaries", SOLVER_MAX_CHECKED);
    sv->checked[sv->nchecked++] = d;
    return SIM_OK;
}

/* controlDict, and system/couplingDict if there is one: a coupled run
 * restarts (startFrom latestTime) only from a time that holds both
 * clouds, because the peer restarts from the same time. */
static int create_time(struct solver *sv)
{
    char own[64], peer[64];
    TRY(app_read_dict(&sv->app, "system/controlDict", &sv->control));
    TRY(app_read_dict_optional(&sv->app, "system/couplingDict",
                               &sv->coupling));
    TRY(couple_enabled(sv->coupling, &sv->coupled));
    if (sv->coupled && !sv->ops->coupling)
        return sim_error(SIM_ERR_INPUT, "system/couplingDict: %s cannot "
                         "run coupled", sv->ops->name);
    /* a distributed run writes the cloud in pieces (<cloud>.pvtu) */
    if (sv->ops->parallel)
        snprintf(own, sizeof own, "%s.vtu|%s.pvtu", sv->ops->cloud,
                 sv->ops->cloud);
    else
        snprintf(own, sizeof own, "%s.vtu", sv->ops->cloud);
    /* the peer may run distributed (its cloud in pieces) */
    snprintf(peer, sizeof peer, "%s.vtu|%s.pvtu",
             sv->ops->peer_cloud ? sv->ops->peer_cloud : "",
             sv->ops->peer_cloud ? sv->ops->peer_cloud : "");
    const char *const alone[] = { own, NULL };
    const char *const both[] = { own, peer, NULL };
    return time_read(sv->control, sv->app.case_abs,
                     sv->coupled && sv->ops->peer_cloud ? both : alone,
                     &sv->rt);
}

static int create_functions(struct solver *sv)
{
    TRY(sv->ops->refresh_scene(sv));
    if (!root(sv))
        return SIM_OK;
    return fo_list_create(sv->rt.functions, sv->ops->fo_tables, &sv->scene,
                          sv->app.case_abs, sv->rt.start_time,
                          sv->rt.precision, &sv->fos);
}

/* "<t>/<cloud>.vtu" of the current time, relative to the case, or its
 * .pvtu where that is what the time holds (a distributed run's). */
static const char *cloud_file(const struct solver *sv, char *buf, size_t n)
{
    char path[4400];
    snprintf(buf, n, "%s/%s.pvtu", sv->rt.name, sv->ops->cloud);
    app_path(&sv->app, buf, path, sizeof path);
    if (access(path, F_OK) != 0)
        snprintf(buf, n, "%s/%s.vtu", sv->rt.name, sv->ops->cloud);
    return buf;
}

static const char *pvd_path(const struct solver *sv, char *buf, size_t n)
{
    char rel[96];
    snprintf(rel, sizeof rel, "%s.pvd", sv->ops->cloud);
    return app_path(&sv->app, rel, buf, n);
}

/* A restart drops the times after the start from the .pvd (they are
 * recomputed), then lists the start time itself. */
static int start_output(struct solver *sv)
{
    char pvd[4200], rel[256];
    if (!root(sv))
        return SIM_OK;
    pvd_path(sv, pvd, sizeof pvd);
    if (access(pvd, F_OK) == 0)
        TRY(pvd_truncate(pvd, sv->rt.value));
    TRY(pvd_add(pvd, sv->rt.value, cloud_file(sv, rel, sizeof rel)));
    return app_write_used_parameters(&sv->app);
}

int solver_write(struct solver *sv, const char *prefix)
{
    char dir[4200], pvd[4200], rel[256];
    int rc = SIM_OK;
    if (root(sv))
        rc = time_make_dir(&sv->rt, sv->app.case_abs, prefix, dir, sizeof dir);
    else
        time_dir_path(&sv->rt, sv->app.case_abs, prefix, dir, sizeof dir);
#ifdef MPSDEM_HAVE_MPI
    /* the other ranks write their pieces into the directory rank 0 made */
    if (sv->distributed)
        MPI_Bcast(&rc, 1, MPI_INT, 0, MPI_COMM_WORLD);
#endif
    if (rc)
        return rc;
    rc = sv->ops->write(sv, dir);
    if (rc) {
        if (root(sv))
            time_dir_discard(dir);
        return rc;
    }
    if (prefix[0] || !root(sv))
        return SIM_OK;
    return pvd_add(pvd_path(sv, pvd, sizeof pvd), sv->rt.value,
                   cloud_file(sv, rel, sizeof rel));
}

/* A failed advance (PPE not converged, NaN, too many escapes): keep the
 * state reached for inspection; the error stays the advance's. */
static int failed(struct solver *sv, int rc)
{
    char msg[1024];
    if (sv->distributed)
        return rc;   /* the ranks that did not fail cannot take part */
    snprintf(msg, sizeof msg, "%s", sim_error_message());
    if (solver_write(sv, "failed.") == SIM_OK)
        log_info("State at the failure written to failed.%s/%s.vtu (to "
                 "inspect; not a time to restart from)", sv->rt.name,
                 sv->ops->cloud);
    return sim_error(rc, "%s", msg);
}

/* The exchange with the peer failed (the peer failed, a signal came, a
 * time-out, the intervals disagree): the wait is never inside an advance,
 * so the state is at a complete coupling time. Write it, then tell the
 * peer why we leave. A signal stops both programs, which both write: a
 * time to restart from. Otherwise the peer writes nothing, and our state
 * alone goes to failed.<t>/. */
static int coupled_stop(struct solver *sv, int rc)
{
    const struct solver_coupling *c = sv->ops->coupling;
    const char *prefix = rc == SIM_ERR_INTERRUPT ? "" : "failed.";
    char msg[1024];
    snprintf(msg, sizeof msg, "%s", sim_error_message());
    if ((!c->keeps_state || c->keeps_state(rc)) && sv->rt.step > 0
        && solver_write(sv, prefix) == SIM_OK)
        log_info("Last complete state (t = %s s) written to %s%s/%s.%s",
                 sv->rt.name, prefix, sv->rt.name, sv->ops->cloud,
                 sv->distributed ? "pvtu" : "vtu");
    c->close(sv, rc);
    return sim_error(rc, "%s", msg);
}

/* The program's advance; a failure that leaves a state dumps it. */
static int advance(struct solver *sv)
{
    int rc = sv->ops->advance(sv);
    return rc && sv->ops->dump_failed_advance ? failed(sv, rc) : rc;
}

/* The progress line of the step just taken. */
static void log_progress(struct solver *sv)
{
    char extra[256] = "";
    if (sv->ops->progress)
        sv->ops->progress(sv, extra, sizeof extra);
    time_log_progress(&sv->rt, extra);
}

/* Are the scene and the function objects due at this step? Always in one
 * process; a distributed run gathers its cloud on rank 0 for them, which
 * costs O(N) there, only at the steps where one of them runs (rank 0
 * holds the list and tells the others). */
static int scene_due(struct solver *sv)
{
    if (!sv->distributed)
        return 1;
    int due = root(sv) && fo_list_due(sv->fos, sv->rt.value, sv->rt.step,
                                      sv->rt.dt, sv->rt.write_now);
#ifdef MPSDEM_HAVE_MPI
    MPI_Bcast(&due, 1, MPI_INT, 0, MPI_COMM_WORLD);
#endif
    return due;
}

static int step(struct solver *sv)
{
    const struct solver_ops *o = sv->ops;
    const struct solver_coupling *c = sv->coupled ? o->coupling : NULL;
    int rc;
    time_set_step(&sv->rt, o->propose_dt ? o->propose_dt(sv)
                                         : sv->rt.delta_t);
    if (c && (rc = c->before_step(sv)))
        return coupled_stop(sv, rc);
    time_increment(&sv->rt);
    TRY(advance(sv));
    if (c && c->after_step && (rc = c->after_step(sv)))
        return coupled_stop(sv, rc);
    if (o->check)
        TRY(o->check(sv));
    if (scene_due(sv)) {
        TRY(o->refresh_scene(sv));
        if (root(sv))
            TRY(fo_list_execute(sv->fos, &sv->scene, sv->rt.write_now));
    }
    if (sv->rt.write_now) {
        if (o->prepare_write)
            TRY(o->prepare_write(sv));
        TRY(solver_write(sv, ""));
        app_log_times(&sv->app);
    }
    log_progress(sv);
    return SIM_OK;
}

/* -relax T: T s of the program alone from the start time, with no
 * function object and no output; that state at rest then replaces the
 * start time's cloud (written as any write: a temporary file renamed over
 * the old one, so a failure leaves the old cloud). Why: a lattice is not
 * the arrangement the particles keep (doc/theory.md A0-25). */
static int relax(struct solver *sv, const char *arg)
{
    const struct solver_ops *o = sv->ops;
    char *end, dir[4200];
    double span = strtod(arg, &end);
    if (end == arg || *end || !isfinite(span) || !(span > 0))
        return sim_error(SIM_ERR_INPUT, "-relax %s: the relaxation time "
                         "must be a number > 0 [s]", arg);
    if (sv->coupled)
        return sim_error(SIM_ERR_INPUT, "system/couplingDict: -relax runs "
                         "%s alone: set coupled no for the relaxation, and "
                         "back to yes for the run", o->name);
    if (sv->distributed)
        return sim_error(SIM_ERR_INPUT, "-relax runs in one process: run it "
                         "without -parallel, then the distributed run");
    TRY(o->rest(sv));
    struct run_time start = sv->rt;
    sv->rt.end_time = start.value + span;
    log_info("\nRelaxing for %g s from t = %s (no function objects, no "
             "output)\n", span, start.name);
    while (time_running(&sv->rt)) {
        time_set_step(&sv->rt, o->propose_dt ? o->propose_dt(sv)
                                             : sv->rt.delta_t);
        time_increment(&sv->rt);
        TRY(advance(sv));
        if (o->check)
            TRY(o->check(sv));
        log_progress(sv);
    }
    long steps = sv->rt.step;
    sv->rt = start;
    TRY(o->rest(sv));
    if (o->prepare_write)
        TRY(o->prepare_write(sv));
    TRY(time_make_dir(&sv->rt, sv->app.case_abs, "", dir, sizeof dir));
    TRY(o->write(sv, dir));
    log_info("\nRelaxed state (%ld steps) at rest written to %s/%s.vtu as "
             "the start of t = %s", steps, start.name, o->cloud, start.name);
    return SIM_OK;
}

/* Stop on an error; a coupled run tells the peer first (a second close
 * after coupled_stop is a no-op). */
static void stop(struct solver *sv, int rc) __attribute__((noreturn));
static void stop(struct solver *sv, int rc)
{
    if (sv->coupled && sv->ops->coupling)
        sv->ops->coupling->close(sv, rc);
    app_fatal(&sv->app, rc);
}

/* The end of a complete run (or relaxation): statistics, then free. */
static int finish(struct solver *sv)
{
    if (sv->ops->stats)
        sv->ops->stats(sv);
    if (sv->ops->cleanup)
        sv->ops->cleanup(sv);
    fo_list_free(sv->fos);
    dict_free(sv->coupling);
    dict_free(sv->control);
    int rc = app_end(&sv->app);
#ifdef MPSDEM_HAVE_MPI
    if (mpi_started)
        MPI_Finalize();
#endif
    return rc;
}

int solver_main(const struct solver_ops *ops, struct solver *sv, int argc,
                char **argv)
{
    const char *list = NULL, *relax_time = NULL, *parallel = NULL;
    struct app_option opts[4] = { { 0 } };
    int rc, nopts = 0;

    if (ops->list_models)
        opts[nopts++] = (struct app_option){ "-listModels", 0, NULL,
            "print every model choice (dictionary key name) and exit",
            &list };
    if (ops->parallel)
        opts[nopts++] = (struct app_option){ "-parallel", 0, NULL,
            "run on the ranks of mpirun (mpirun -np N ... -parallel; the "
            "MPI build, make MPI=1)", &parallel };
    if (ops->rest)
        opts[nopts++] = (struct app_option){ "-relax", 1, "T",
            "a relaxed start: run T s from the start time without output, "
            "then write that state at rest as the start time's cloud, and "
            "exit", &relax_time };
    sv->ops = ops;
    rc = start_parallel(sv, argc, argv);
    app_init(&sv->app, ops->name, ops->description, argc, argv,
             nopts ? opts : NULL, 0);
    if (rc)
        app_fatal(&sv->app, rc);
    if (list) {
        ops->list_models();
        return 0;
    }
    if ((root(sv) && (rc = app_lock_case(&sv->app))) || (rc = create_time(sv))
        || (rc = ops->create(sv)))
        app_fatal(&sv->app, rc);
    if (relax_time) {
        if ((rc = relax(sv, relax_time)))
            app_fatal(&sv->app, rc);
        return finish(sv);
    }
    if ((rc = create_functions(sv)) || (rc = start_output(sv)))
        app_fatal(&sv->app, rc);
    dict_mark_used(sv->control, "application");  /* read by scripts */
    dict_warn_unused(sv->control);
    for (int k = 0; k < sv->nchecked; k++)
        dict_warn_unused(sv->checked[k]);
    if (sv->coupled) {
        if ((rc = ops->coupling->open(sv)))
            coupled_stop(sv, rc), app_fatal(&sv->app, rc);
        dict_warn_unused(sv->coupling);
    }
    log_info("\nStarting time loop\n");
    while (time_running(&sv->rt))
        if ((rc = step(sv)))
            stop(sv, rc);
    if (sv->coupled) {
        if (ops->coupling->finish)
            ops->coupling->finish(sv);
        ops->coupling->close(sv, SIM_OK);
    }
    return finish(sv);
}

int solver_wall_cloud_size(const struct vtu_cloud *c, const char *path,
                           const char *noun, int *n)
{
    const struct vtu_field *f, *id = vtu_find(c, "id");
    TRY(vtu_require(c, path, "type", VTU_INT32, 1, &f));
    TRY(vtu_require(c, path, "patch", VTU_INT32, 1, &f));
    TRY(vtu_require(c, path, "velocity", VTU_FLOAT64, 3, &f));
    TRY(vtu_require(c, path, "pressure", VTU_FLOAT64, 1, &f));
    TRY(vtu_require(c, path, "normal", VTU_FLOAT64, 3, &f));
    if (id)
        TRY(vtu_require(c, path, "id", VTU_INT64, 1, &id));
    if (c->n > 100000000)
        return sim_error(SIM_ERR_INPUT, "%s: too many %ss", path, noun);
    *n = (int)c->n;
    return SIM_OK;
}

static int wall_cloud_check(const char *path, const char *noun, int n,
                            const double *x, const int32_t *type,
                            const double *normal, int dummies)
{
    for (int i = 0; i < n; i++) {
        if (type[i] == 2 && !dummies)
            return sim_error(SIM_ERR_INPUT, "%s: %s %d is a dummy particle "
                             "(type 2): this solver has one layer of wall "
                             "particles on the wall (system/particleDict: "
                             "wallLayers 1, origin on the tank's corner)",
                             path, noun, i);
        if (type[i] != 0 && type[i] != 1 && type[i] != 2)
            return sim_error(SIM_ERR_INPUT, "%s: %s %d has type %d (0 "
                             "fluid, 1 wall%s)", path, noun, i, type[i],
                             dummies ? ", 2 dummy" : "");
        if (x[3 * i + 2] != 0)
            return sim_error(SIM_ERR_INPUT, "%s: %s %d has z = %g (2-D)",
                             path, noun, i, x[3 * i + 2]);
        const double *nn = normal + 3 * i;
        if (type[i] == 1 && fabs(hypot(nn[0], nn[1]) - 1) > 1e-6)
            return sim_error(SIM_ERR_INPUT, "%s: wall %s %d has no unit "
                             "normal in the x-y plane", path, noun, i);
    }
    return SIM_OK;
}

int solver_wall_cloud_copy(const struct vtu_cloud *c, const char *path,
                           const char *noun,
                           const struct solver_wall_cloud *w)
{
    int n = (int)c->n;
    const struct vtu_field *id = vtu_find(c, "id");
    memcpy(w->x, c->points, sizeof *w->x * 3 * n);
    memcpy(w->u, vtu_find(c, "velocity")->data, sizeof *w->u * 3 * n);
    memcpy(w->p, vtu_find(c, "pressure")->data, sizeof *w->p * n);
    memcpy(w->normal, vtu_find(c, "normal")->data, sizeof *w->normal * 3 * n);
    memcpy(w->type, vtu_find(c, "type")->data, sizeof *w->type * n);
    memcpy(w->patch, vtu_find(c, "patch")->data, sizeof *w->patch * n);
    for (int i = 0; i < n; i++)
        w->id[i] = id ? ((const int64_t *)id->data)[i] : i;
    return wall_cloud_check(path, noun, n, w->x, w->type, w->normal,
                            w->dummies);
}

int solver_read_patches(struct solver *sv, int only_dim, struct dict **patches,
                        int *dim, double *dp, const char **names, int max,
                        int *n)
{
    TRY(app_read_dict(&sv->app, "constant/particlePatches", patches));
    TRY(lattice_read_patches(*patches, dim, dp));
    if (only_dim && *dim != only_dim)
        return dict_error(*patches, "dimension", SIM_ERR_DICT, "%s is %d-D: "
                          "dimension must be %d", sv->ops->name, only_dim,
                          only_dim);
    dict_mark_used(*patches, "types");
    dict_mark_used(*patches, "wallLayers");
    return dict_get_words(*patches, "patches", max, names, n);
}
