/*
 * mlpgFluid — the MLPG_R solver of Pan (2022, PhD thesis ch. 3-4) with its
 * improved wall scheme: incompressible 2-D flow on a cloud of fluid and
 * wall nodes (doc/theory.md M; src/mlpg/mlpg_solver.h for the step).
 *
 * Reads   system/controlDict, system/mlpgSchemes, system/mlpgSolution,
 *         constant/transportProperties (rho, nu), constant/g (optional),
 *         constant/particlePatches (genParticles: dimension 2, dp),
 *         <startTime>/fluid.vtu (genParticles with `origin` on the tank
 *         corner and `wallLayers 1`: one layer of wall nodes on the walls)
 * Writes  <time>/fluid.vtu, fluid.pvd, postProcessing/
 *
 * Every key: mlpgFluid.reference beside this file.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/gravity.h"
#include "core/log.h"
#include "functionObjects/functionObject.h"
#include "functionObjects/mps_functionObjects.h"
#include "io/vtu.h"
#include "mlpg/mlpg_solver.h"
#include "solver/solver.h"

enum { MLPG_MAX_PATCHES = 64 };

struct fluid {
    struct solver sv;
    struct dict *transport, *gravity, *schemes, *solution, *patches;
    const char *patch_names[MLPG_MAX_PATCHES];
    int npatches;
    struct mlpg_solver s;
    double dp, change;               /* max |u^{n+1} - u^n| / dt        */
    double steady;                   /* stop when change < steady       */
    double *uold;
    struct vtu_cloud cloud;
    struct vtu_field fields[STORE_MAX_FIELDS];
};

static int read_patches(struct fluid *f)
{
    int dim;
    return solver_read_patches(&f->sv, 2, &f->patches, &dim, &f->dp,
                               f->patch_names, MLPG_MAX_PATCHES, &f->npatches);
}

static int copy_cloud(struct fluid *f, const struct vtu_cloud *c,
                      const char *path)
{
    struct mlpg_solver *s = &f->s;
    int n;
    TRY(solver_wall_cloud_size(c, path, "node", &n));
    TRY(mlpg_fields_alloc(s, n));
    return solver_wall_cloud_copy(c, path, "node",
        &(struct solver_wall_cloud){ s->x, s->u, s->p, s->normal, s->type,
                                     s->patch, s->id, 0 });
}

/* walls { <name> { patch P; min (..); max (..); velocity (..); } } or
 * { ...; motion { type ...; } } of system/mlpgSolution: the wall nodes of
 * patch P inside the box slide in place at a velocity tangential to them
 * (a lid, a conveyor; nodes it is not tangential to, corners, keep 0;
 * doc/theory.md M0-14) or move rigidly with a motion model of
 * particles/motion (a piston). */
static int read_walls(struct fluid *f)
{
    struct mlpg_solver *s = &f->s;
    const struct dict *wd;
    TRY(dict_find_dict(f->solution, "walls", &wd));
    if (!wd)
        return SIM_OK;
    int ng = dict_size(wd);
    s->groups = sim_calloc((size_t)ng, sizeof *s->groups);
    s->group = sim_malloc((size_t)s->n * sizeof *s->group);
    if (!s->groups || !s->group)
        return SIM_ERR_NOMEM;
    for (int i = 0; i < s->n; i++)
        s->group[i] = -1;
    for (int e = 0; e < ng; e++) {
        struct mlpg_wall_group *G = &s->groups[e];
        const char *key = dict_key_at(wd, e), *name;
        const struct dict *d;
        double lo[3], hi[3];
        wall_motion_init(&G->motion);
        s->ngroups = e + 1;
        TRY(dict_get_dict(wd, key, &d));
        TRY(dict_get_string(d, "patch", &name));
        TRY(dict_get_vector(d, "min", 3, lo));
        TRY(dict_get_vector(d, "max", 3, hi));
        int moves = dict_has(d, "motion");
        if (moves == dict_has(d, "velocity"))
            return dict_error(d, NULL, SIM_ERR_DICT, "walls %s: give either "
                              "velocity (sliding in place) or motion { } "
                              "(moving)", key);
        if (moves) {
            TRY(wall_motion_read(d, 1, 2, f->sv.app.case_abs, &G->motion));
            if (isfinite(G->motion.remove_at))
                return dict_error(d, "removeAt", SIM_ERR_DICT, "mlpgFluid "
                                  "does not remove walls");
        }
        else
            TRY(dict_get_vector(d, "velocity", 3, G->U));
        int through = 0;
        TRY(dict_get_bool_or(d, "through", 0, &through));
        static const char *const conds[] = { "noSlip", "freeSlip", NULL };
        G->free_slip = -1;
        if (dict_has(d, "condition"))
            TRY(dict_get_word(d, "condition", conds, &G->free_slip));
        int k = -1;
        for (int q = 0; q < f->npatches; q++)
            if (!strcmp(f->patch_names[q], name))
                k = q;
        if (k < 0)
            return dict_error(d, "patch", SIM_ERR_DICT, "no patch '%s' in "
                              "constant/particlePatches", name);
        int count = 0;
        for (int i = 0; i < s->n; i++) {
            const double *nn = s->normal + 3 * i;
            if (s->patch[i] != k || s->type[i] != MLPG_WALL
                || !mlpg_in_box(s->x + 3 * i, lo, hi) || s->group[i] >= 0)
                continue;
            if (!moves && !through
                && fabs(G->U[0] * nn[0] + G->U[1] * nn[1])
                       > 1e-12 * hypot(G->U[0], G->U[1]))
                continue;
            s->group[i] = e;
            count++;
        }
        if (!count)
            return dict_error(d, "min", SIM_ERR_DICT, "walls %s: no wall "
                              "node of patch '%s' in the box%s", key, name,
                              moves ? "" : " that the velocity is tangential "
                              "to");
        if (moves)
            log_info("walls %s: %d wall nodes of patch %s move (motion %s)",
                     key, count, name, G->motion.ops->name);
        else
            log_info("walls %s: %d wall nodes of patch %s slide at (%g %g) "
                     "m/s", key, count, name, G->U[0], G->U[1]);
    }
    return SIM_OK;
}

/* fixedPressure { <name> { min (..); max (..); value p; } } of
 * system/mlpgSolution: the fluid nodes in the box have p = value (an
 * outlet; doc/theory.md M0-15). */
static int read_fixed_pressure(struct fluid *f)
{
    struct mlpg_solver *s = &f->s;
    const struct dict *fd;
    TRY(dict_find_dict(f->solution, "fixedPressure", &fd));
    if (!fd)
        return SIM_OK;
    s->nfixed_p = dict_size(fd);
    s->fixed_p = sim_calloc((size_t)s->nfixed_p, sizeof *s->fixed_p);
    if (!s->fixed_p)
        return SIM_ERR_NOMEM;
    for (int e = 0; e < s->nfixed_p; e++) {
        struct mlpg_fixed_pressure *F = &s->fixed_p[e];
        const char *key = dict_key_at(fd, e);
        const struct dict *d;
        TRY(dict_get_dict(fd, key, &d));
        TRY(dict_get_vector(d, "min", 3, F->lo));
        TRY(dict_get_vector(d, "max", 3, F->hi));
        TRY(dict_get_scalar_or(d, "value", 0, &F->value));
        int count = 0;
        for (int i = 0; i < s->n; i++)
            count += s->type[i] == MLPG_FLUID
                  && mlpg_in_box(s->x + 3 * i, F->lo, F->hi);
        if (!count)
            return dict_error(d, "min", SIM_ERR_DICT, "fixedPressure %s: no "
                              "fluid node in the box", key);
        log_info("fixedPressure %s: %d fluid nodes at p = %g Pa", key, count,
                 F->value);
    }
    return SIM_OK;
}

static int create(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    struct mlpg_settings S = { 0 };
    struct linsolve *ls = NULL;
    const struct dict *ppe;
    char rel[256], path[4400];
    struct vtu_cloud c = { 0 };
    TRY(read_patches(f));
    TRY(app_read_dict(&sv->app, "constant/transportProperties",
                      &f->transport));
    TRY(gravity_case(&sv->app, 2, S.g, &f->gravity));
    TRY(app_read_dict(&sv->app, "system/mlpgSchemes", &f->schemes));
    TRY(app_read_dict(&sv->app, "system/mlpgSolution", &f->solution));
    TRY(mlpg_settings_read(f->transport, f->schemes, f->solution, &S));
    S.dl = f->dp;
    TRY(dict_get_dict(f->solution, "PPE", &ppe));
    snprintf(rel, sizeof rel, "%s/fluid.vtu", sv->rt.name);
    app_path(&sv->app, rel, path, sizeof path);
    int rc = vtu_read(path, &c);
    if (!rc)
        rc = vtu_check_finite(&c, path);
    if (!rc)
        rc = copy_cloud(f, &c, path);
    vtu_cloud_free(&c);
    if (rc)
        return rc;
    TRY(read_walls(f));
    TRY(read_fixed_pressure(f));
    TRY(dict_get_scalar_or(f->solution, "steadyTolerance", 0, &f->steady));
    TRY(dict_range(f->solution, "steadyTolerance", f->steady, 0, 1e30, 0));
    TRY(linsolve_create(ppe, &ls));
    TRY(mlpg_solver_init(&f->s, &S, ls));
    f->s.time = sv->rt.value;
    f->uold = sim_calloc(3 * (size_t)f->s.n, sizeof *f->uold);
    if (!f->uold)
        return SIM_ERR_NOMEM;
    TRY(solver_check_unused(sv, f->schemes));
    TRY(solver_check_unused(sv, f->solution));
    return solver_check_unused(sv, f->transport);
}

static int refresh_scene(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    mlpg_wall_stress(&f->s);
    store_cloud(&f->s.st, sv->rt.value, f->fields, &f->cloud);
    sv->scene = (struct fo_scene){
        .time = sv->rt.value, .dt = sv->rt.dt, .step = sv->rt.step,
        .dim = 2, .cloud_name = "fluid", .store = &f->s.st,
        .spacing = f->dp, .patch_names = f->patch_names,
        .npatches = f->npatches, .solver = &f->s };
    return SIM_OK;
}

static int advance(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    memcpy(f->uold, f->s.u, 3 * sizeof *f->uold * (size_t)f->s.n);
    TRY(mlpg_step(&f->s, sv->rt.dt));
    double m = 0;
    for (int i = 0; i < 3 * f->s.n; i++)
        m = fmax(m, fabs(f->s.u[i] - f->uold[i]));
    f->change = m / sv->rt.dt;
    return SIM_OK;
}

/* steadyTolerance: a steady state ends the run, written (doc M0-14). */
static int check(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    if (f->steady > 0 && f->change < f->steady) {
        log_info("Steady: max|du|/dt = %.3g < steadyTolerance %g at t = %g "
                 "s: the run ends here", f->change, f->steady, sv->rt.value);
        sv->rt.end_time = sv->rt.value;
        sv->rt.write_now = 1;
    }
    return SIM_OK;
}

static int write_fields(struct solver *sv, const char *dir)
{
    struct fluid *f = (struct fluid *)sv;
    char path[4400];
    TRY(refresh_scene(sv));
    snprintf(path, sizeof path, "%s/fluid.vtu", dir);
    return vtu_write(path, &f->cloud, sv->rt.binary);
}

static void progress(struct solver *sv, char *buf, size_t n)
{
    const struct fluid *f = (const struct fluid *)sv;
    snprintf(buf, n, "PPE: %d iterations, residual %.3g  max|du|/dt %.3g"
             "  surface %ld", f->s.last.iters, f->s.last.res_rel, f->change,
             f->s.n_surface);
}

static void final_stats(struct solver *sv)
{
    const struct fluid *f = (const struct fluid *)sv;
    const struct mlpg_timers *t = &f->s.t;
    double ns = (double)f->s.n * (double)(t->steps ? t->steps : 1);
    log_info("\nMLPG statistics");
    log_info("    steps                 %ld (neighbour lists built %ld)",
             t->steps, t->builds);
    app_log_peak_memory(f->s.n);
    log_info("    PPE iterations        %ld (%.1f per step)", t->ppe_iters,
             t->steps ? (double)t->ppe_iters / t->steps : 0.0);
    log_info("    time per node-step [us]: neighbours %.3f  explicit %.3f  "
             "assembly %.3f  PPE %.3f  correction %.3f",
             1e6 * t->neighbours / ns, 1e6 * t->explicit_ / ns,
             1e6 * t->assembly / ns, 1e6 * t->ppe / ns,
             1e6 * t->correction / ns);
}

static void cleanup(struct solver *sv)
{
    struct fluid *f = (struct fluid *)sv;
    mlpg_solver_free(&f->s);
    free(f->uold);
    dict_free(f->transport);
    dict_free(f->gravity);
    dict_free(f->schemes);
    dict_free(f->solution);
    dict_free(f->patches);
}

static void list_models(void)
{
    model_choices_print(mlpg_solver_choices, NULL, NULL);
    model_choices_print(linsolve_choices, "system/mlpgSolution", "PPE/");
}

static const struct fo_ops *const *const fo_tables[] = {
    fo_generic_table, mps_fo_table, NULL };

static const struct solver_ops fluid_ops = {
    .name = "mlpgFluid",
    .description = "MLPG_R solver with the improved wall scheme (2-D)",
    .cloud = "fluid",
    .list_models = list_models,
    .create = create,
    .fo_tables = fo_tables,
    .refresh_scene = refresh_scene,
    .advance = advance,
    .dump_failed_advance = 1,
    .check = check,
    .write = write_fields,
    .progress = progress,
    .stats = final_stats,
    .cleanup = cleanup,
};

int main(int argc, char **argv)
{
    static struct fluid f;
    return solver_main(&fluid_ops, &f.sv, argc, argv);
}
