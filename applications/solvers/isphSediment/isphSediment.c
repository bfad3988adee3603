/*
 * isphSediment — two-phase ISPH for suspended sediment (Pan 2022 thesis
 * ch. 5; doc/theory.md S; src/isph/isph_solver.h for the step), 2-D: one
 * set of particles moving with the water, carrying the sediment volume
 * fraction alpha.sediment and velocity U.sediment.
 *
 * Reads   system/controlDict, system/isphSchemes, system/isphSolution,
 *         constant/transportProperties (rho, nu of the water),
 *         constant/sedimentProperties (rho, d, alphaMax), constant/g,
 *         constant/particlePatches (genParticles: dimension 2, dp),
 *         <startTime>/fluid.vtu (genParticles with `origin` on the tank
 *         corner and `wallLayers 1`; alpha.sediment and U.sediment if the
 *         cloud has them, else from isphSolution's alphaSediment)
 * Writes  <time>/fluid.vtu, fluid.pvd, postProcessing/
 *
 * Every key: isphSediment.reference beside this file.
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
#include "isph/isph_solver.h"
#include "solver/solver.h"

enum { ISPH_MAX_PATCHES = 64 };

struct sediment {
    struct solver sv;
    struct dict *transport, *sediment, *gravity, *schemes, *solution,
        *patches;
    const char *patch_names[ISPH_MAX_PATCHES];
    int npatches;
    struct isph_solver s;
    double dp;
    struct vtu_cloud cloud;
    struct vtu_field fields[STORE_MAX_FIELDS];
};

static int read_patches(struct sediment *f)
{
    int dim;
    return solver_read_patches(&f->sv, 2, &f->patches, &dim, &f->dp,
                               f->patch_names, ISPH_MAX_PATCHES, &f->npatches);
}

/* alphaSediment { type linear; value a0; gradient (gx gy 0); origin (x0
 * y0 0); }: alpha_s = a0 + g.(x - x0) (the thesis's cases 1a, 1b), or
 * { type cosine; peak a0; direction (0 1 0); from s0; to s1; }: with s =
 * x.direction, alpha_s = (a0/2) [1 + cos(2 pi ((s - s0)/(s1 - s0) -
 * 0.5))] on [s0, s1], 0 outside (eq. 5.51 of the settling test), or
 * { type box; value a0; min (x0 y0 0); max (x1 y1 0); }: a0 times the
 * part of the particle's dl x dl cell inside the box (the sand block of
 * the dumping tests: sum alpha_s V = a0 times the box's area, S0-10); on
 * the water particles, clipped at 0. */
static const struct model_head prof_linear = { "linear",
    "value + gradient.(x - origin), Pan 2022 sect. 5.3.1" };
static const struct model_head prof_cosine = { "cosine",
    "a raised cosine, Pan 2022 eq. 5.51" };
static const struct model_head prof_box = { "box",
    "value times the particle's cell fraction in the box, doc S0-10" };
static const struct model_head *const profile_table[] = { &prof_linear,
                                                          &prof_cosine,
                                                          &prof_box, NULL };

/* The fraction of [c - dl/2, c + dl/2] inside [lo, hi] (at most 1, so
 * that round-off cannot lift a full cell above alphaMax). */
static double overlap(double c, double dl, double lo, double hi)
{
    return fmin(1, fmax(0, fmin(c + dl / 2, hi) - fmax(c - dl / 2, lo)) / dl);
}

static int initial_alpha(struct sediment *f)
{
    struct isph_solver *s = &f->s;
    const struct dict *d;
    int type;
    double a0, g[3] = { 0, 0, 0 }, o[3] = { 0, 0, 0 }, s0 = 0, s1 = 1;
    TRY(dict_find_dict(f->solution, "alphaSediment", &d));
    if (!d)
        return SIM_OK; /* clear water */
    TRY(model_select_index(d, "type", "initial sediment profile",
                           (const void *const *)profile_table, "linear",
                           &type));
    if (type == 0) {
        TRY(dict_get_scalar(d, "value", &a0));
        TRY(dict_get_vector_or(d, "gradient", 3, g, g));
        TRY(dict_get_vector_or(d, "origin", 3, o, o));
    } else if (type == 2) {
        TRY(dict_get_scalar(d, "value", &a0));
        TRY(dict_get_vector(d, "min", 3, o));
        TRY(dict_get_vector(d, "max", 3, g));
        if (!(g[0] > o[0] && g[1] > o[1]))
            return dict_error(d, "max", SIM_ERR_DICT, "max must exceed min "
                              "in x and y");
    } else {
        TRY(dict_get_scalar(d, "peak", &a0));
        TRY(dict_get_vector(d, "direction", 3, g));
        TRY(dict_get_scalar(d, "from", &s0));
        TRY(dict_get_scalar(d, "to", &s1));
        double len = hypot(g[0], g[1]);
        if (!(len > 0))
            return dict_error(d, "direction", SIM_ERR_DICT, "direction "
                              "must not be zero");
        if (!(s1 > s0))
            return dict_error(d, "to", SIM_ERR_DICT, "to must exceed from");
        g[0] /= len;
        g[1] /= len;
    }
    for (int i = 0; i < s->n; i++) {
        if (s->type[i] != ISPH_FLUID)
            continue;
        const double *x = s->x + 3 * i;
        double a;
        if (type == 0) {
            a = a0 + g[0] * (x[0] - o[0]) + g[1] * (x[1] - o[1]);
        } else if (type == 2) {
            a = a0 * overlap(x[0], f->dp, o[0], g[0])
                   * overlap(x[1], f->dp, o[1], g[1]);
        } else {
            double sx = g[0] * x[0] + g[1] * x[1];
            a = sx < s0 || sx > s1 ? 0
              : a0 / 2 * (1 + cos(2 * M_PI * ((sx - s0) / (s1 - s0) - 0.5)));
        }
        s->alpha[i] = fmax(a, 0);
    }
    return SIM_OK;
}

static int copy_cloud(struct sediment *f, const struct vtu_cloud *c,
                      const char *path)
{
    struct isph_solver *s = &f->s;
    const struct vtu_field *al = vtu_find(c, "alpha.sediment"),
        *us = vtu_find(c, "U.sediment"), *vo = vtu_find(c, "volume");
    int n;
    TRY(solver_wall_cloud_size(c, path, "particle", &n));
    if (al) TRY(vtu_require(c, path, "alpha.sediment", VTU_FLOAT64, 1, &al));
    if (us) TRY(vtu_require(c, path, "U.sediment", VTU_FLOAT64, 3, &us));
    if (vo) TRY(vtu_require(c, path, "volume", VTU_FLOAT64, 1, &vo));
    TRY(isph_fields_alloc(s, n));
    TRY(solver_wall_cloud_copy(c, path, "particle",
        &(struct solver_wall_cloud){ s->x, s->u, s->p, s->normal, s->type,
                                     s->patch, s->id, 1 }));
    memcpy(s->us, us ? us->data : (const void *)s->u, sizeof *s->us * 3 * n);
    if (al)
        memcpy(s->alpha, al->data, sizeof *s->alpha * n);
    if (vo)
        memcpy(s->V, vo->data, sizeof *s->V * n);
    return al ? SIM_OK : initial_alpha(f);
}

static int create(struct solver *sv)
{
    struct sediment *f = (struct sediment *)sv;
    struct isph_settings S = { 0 };
    struct linsolve *ls = NULL;
    const struct dict *ppe;
    char rel[256], path[4400];
    struct vtu_cloud c = { 0 };
    TRY(read_patches(f));
    TRY(app_read_dict(&sv->app, "constant/transportProperties",
                      &f->transport));
    TRY(app_read_dict(&sv->app, "constant/sedimentProperties",
                      &f->sediment));
    TRY(gravity_case(&sv->app, 2, S.g, &f->gravity));
    TRY(app_read_dict(&sv->app, "system/isphSchemes", &f->schemes));
    TRY(app_read_dict(&sv->app, "system/isphSolution", &f->solution));
    TRY(isph_settings_read(f->transport, f->sediment, f->schemes, &S));
    S.dl = f->dp;
    S.h *= f->dp;
    if (S.kernel->support * S.h < 2.5 * S.dl)
        return dict_error(f->schemes, "smoothingLength", SIM_ERR_DICT,
                          "smoothingLength %g: the kernel's support (%g dl) "
                          "must reach the free-surface detector's 2.5 dl",
                          S.h / S.dl, S.kernel->support * S.h / S.dl);
    if (S.volume_beta > 0 && S.wall != ISPH_WALL_DUMMY)
        return dict_error(f->schemes, "volumeRelaxation", SIM_ERR_DICT,
                          "volumeRelaxation %g needs `wall dummyLayers`: "
                          "next to one layer of wall particles the kernel "
                          "sum misses the part of the support behind the "
                          "wall (doc/theory.md S0-19)", S.volume_beta);
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
    int n_dummy = 0;
    for (int i = 0; i < f->s.n; i++)
        n_dummy += f->s.type[i] == ISPH_DUMMY;
    if ((S.wall == ISPH_WALL_DUMMY) != (n_dummy > 0))
        return dict_error(f->schemes, "wall", SIM_ERR_DICT, n_dummy
            ? "%s holds %d dummy particles (type 2): `wall dummyLayers;`, "
              "or one layer of wall particles (wallLayers 1 in "
              "system/particleDict)"
            : "%s holds no dummy particles: `wall dummyLayers` needs the "
              "layers behind the wall particles (wallLayers 3 in "
              "system/particleDict)", rel, n_dummy);
    TRY(linsolve_create(ppe, &ls));
    TRY(isph_solver_init(&f->s, &S, ls));
    TRY(solver_check_unused(sv, f->schemes));
    TRY(solver_check_unused(sv, f->solution));
    TRY(solver_check_unused(sv, f->sediment));
    return solver_check_unused(sv, f->transport);
}

static int refresh_scene(struct solver *sv)
{
    struct sediment *f = (struct sediment *)sv;
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
    struct sediment *f = (struct sediment *)sv;
    return isph_step(&f->s, sv->rt.dt);
}

static int write_fields(struct solver *sv, const char *dir)
{
    struct sediment *f = (struct sediment *)sv;
    char path[4400];
    TRY(refresh_scene(sv));
    snprintf(path, sizeof path, "%s/fluid.vtu", dir);
    return vtu_write(path, &f->cloud, sv->rt.binary);
}

static void progress(struct solver *sv, char *buf, size_t n)
{
    const struct sediment *f = (const struct sediment *)sv;
    snprintf(buf, n, "PPE: %d iterations, residual %.3g  surface %ld  "
             "isolated %ld  alpha clipped %ld  pushedBack %ld",
             f->s.last.iters, f->s.last.res_rel, f->s.n_surface,
             f->s.cl.n_isolated, f->s.n_clipped, f->s.n_pushed);
}

static void final_stats(struct solver *sv)
{
    const struct sediment *f = (const struct sediment *)sv;
    const struct isph_timers *t = &f->s.t;
    double ns = (double)f->s.n * (double)(t->steps ? t->steps : 1);
    log_info("\nISPH statistics");
    log_info("    steps                 %ld", t->steps);
    app_log_peak_memory(f->s.n);
    log_info("    PPE iterations        %ld (%.1f per step)", t->ppe_iters,
             t->steps ? (double)t->ppe_iters / t->steps : 0.0);
    log_info("    time per particle-step [us]: neighbours %.3f  explicit "
             "%.3f  PPE %.3f  correction %.3f", 1e6 * t->neighbours / ns,
             1e6 * t->explicit_ / ns, 1e6 * t->ppe / ns,
             1e6 * t->correction / ns);
}

static void cleanup(struct solver *sv)
{
    struct sediment *f = (struct sediment *)sv;
    isph_solver_free(&f->s);
    dict_free(f->transport);
    dict_free(f->sediment);
    dict_free(f->gravity);
    dict_free(f->schemes);
    dict_free(f->solution);
    dict_free(f->patches);
}

static const struct model_choice profile_choices[] = {
    { "system/isphSolution", "alphaSediment/type",
      (const void *const *)profile_table },
    { NULL, NULL, NULL },
};

static void list_models(void)
{
    model_choices_print(isph_solver_choices, NULL, NULL);
    model_choices_print(profile_choices, NULL, NULL);
    model_choices_print(linsolve_choices, "system/isphSolution", "PPE/");
}

static const struct fo_ops *const *const fo_tables[] = {
    fo_generic_table, mps_fo_table, NULL };

static const struct solver_ops sediment_ops = {
    .name = "isphSediment",
    .description = "two-phase ISPH for suspended sediment (2-D)",
    .cloud = "fluid",
    .list_models = list_models,
    .create = create,
    .fo_tables = fo_tables,
    .refresh_scene = refresh_scene,
    .advance = advance,
    .dump_failed_advance = 1,
    .write = write_fields,
    .progress = progress,
    .stats = final_stats,
    .cleanup = cleanup,
};

int main(int argc, char **argv)
{
    static struct sediment f;
    return solver_main(&sediment_ops, &f.sv, argc, argv);
}
