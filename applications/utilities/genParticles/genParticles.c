/*
 * genParticles — blockMesh for particles: fill the regions of
 * system/particleDict and write the initial clouds
 *
 *   0/fluid.vtu   MPS fluid, wall and dummy particles
 *                 (type, patch, velocity, pressure, normal)
 *   0/dem.vtu     grains (radius, velocity, omega, group, id)
 *   fluid.pvd, dem.pvd        entries at time 0
 *   constant/particlePatches  patch index -> region name
 *
 * A phase without particles gets no file. Every input error is found
 * before anything is written; the outputs are written under temporary
 * names and renamed only when all of them are complete.
 */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/gravity.h"
#include "core/error.h"
#include "core/log.h"
#include "genParticles.h"
#include "io/vtu.h"

/* Largest kernel radius (in dp) named in system/mpsSchemes, 0 if none. */
static double kernel_radius_hint(const struct app *a)
{
    static const char *const keys[] = { "kernelRadius", "re",
                                        "reNumberDensity", "reGradient",
                                        "reLaplacian", NULL };
    char path[4096];
    struct dict *d;
    double re = 0;

    if (access(app_path(a, "system/mpsSchemes", path, sizeof path), R_OK))
        return 0;
    if (dict_read(path, &d) != SIM_OK) {
        sim_error_clear(); /* the solver will report it */
        return 0;
    }
    for (int i = 0; keys[i]; i++) {
        double v;
        if (dict_has(d, keys[i]) &&
            dict_get_scalar(d, keys[i], &v) == SIM_OK)
            re = fmax(re, v);
    }
    sim_error_clear();
    dict_free(d);
    return re;
}

/* writeFormat of system/controlDict, so that the initial clouds look like
 * what the solvers will write; binary when it is absent or unreadable. */
static int control_binary(const struct app *a)
{
    static const char *const formats[] = { "ascii", "binary", NULL };
    char path[4096];
    struct dict *d;
    int fmt = 1;

    if (access(app_path(a, "system/controlDict", path, sizeof path), R_OK))
        return 1;
    if (dict_read(path, &d) == SIM_OK) {
        if (dict_has(d, "writeFormat") &&
            dict_get_word(d, "writeFormat", formats, &fmt) != SIM_OK)
            fmt = 1; /* the solver will report it */
        dict_free(d);
    }
    sim_error_clear();
    return fmt;
}

/* rho and g, needed only for an initial hydrostatic pressure (a missing
 * constant/g is then the logged default, as in the solvers). */
static int read_physics(const struct app *a, struct gen_case *c)
{
    static const int dims_rho[7] = { 1, -3, 0, 0, 0, 0, 0 };
    struct dict *tp, *gd;
    char where[256];
    int any = 0, rc;

    int soil = 0;
    for (int i = 0; i < c->nregions; i++) {
        any |= c->r[i].hydrostatic;
        soil |= c->r[i].hydrostatic && c->r[i].type == REGION_SOIL;
    }
    if (!any)
        return SIM_OK;
    TRY(app_read_dict(a, "constant/transportProperties", &tp));
    rc = dict_get_scalar_dim(tp, "rho", dims_rho, &c->rho);
    if (rc == SIM_OK && !(c->rho > 0))
        rc = dict_error(tp, "rho", SIM_ERR_DICT, "rho must be positive");
    dict_free(tp);
    TRY(rc);
    if (soil) { /* the soil's density, for its hydrostatic pressure */
        TRY(app_read_dict(a, "constant/soilProperties", &tp));
        rc = dict_get_scalar_dim(tp, "rho", dims_rho, &c->rho_soil);
        if (rc == SIM_OK && !(c->rho_soil > 0))
            rc = dict_error(tp, "rho", SIM_ERR_DICT, "rho must be positive");
        dict_free(tp);
        TRY(rc);
    }
    rc = gravity_case(a, c->dim, c->g, &gd);
    if (rc != SIM_OK || !gd) { /* the default points along -vertical */
        dict_free(gd);
        return rc;
    }
    if (!(c->g[c->vertical] < 0))
        rc = dict_error(gd, "value", SIM_ERR_DICT, "hydrostaticPressure "
                        "needs gravity along -%c (%s): g = (%g %g %g)",
                        "xyz"[c->vertical], c->dim == 2 ? "2-D" : "3-D",
                        c->g[0], c->g[1], c->g[2]);
    dict_where(gd, "value", where, sizeof where);
    dict_free(gd);
    TRY(rc);
    for (int d = 0; d < c->dim; d++)
        if (d != c->vertical && c->g[d] != 0)
            log_warn("%s: the hydrostatic pressure uses only the vertical "
                     "component of g", where);
    return SIM_OK;
}

static void print_summary(const struct gen_case *c, const struct mps_cloud *m)
{
    size_t tot[4] = { 0, 0, 0, 0 };
    double fluid = 0; /* fluid volume in dp^d (volume fractions if any) */
    for (size_t k = 0; k < m->n; k++)
        if (m->type[k] == TYPE_FLUID)
            fluid += m->phi ? m->phi[k] : 1.0;

    log_info("\nCreating particles: dimension %d, dp = %g m, %d wall "
             "layer(s) (1 wall + %d dummy), lattice origin (%g %g %g)",
             c->dim, c->dp, c->layers, c->layers - 1, c->origin[0],
             c->origin[1], c->origin[2]);
    log_info("\n    %-5s %-16s %-9s %-9s %10s %10s %10s %10s", "patch",
             "region", "type", "shape", "fluid", "wall", "dummy", "grains");
    for (int i = 0; i < c->nregions; i++) {
        const struct region *r = &c->r[i];
        log_info("    %-5d %-16s %-9s %-9s %10zu %10zu %10zu %10zu", i,
                 r->name, region_type_names[r->type],
                 region_shape_names[r->shape], r->count[0], r->count[1],
                 r->count[2], r->count[3]);
        for (int k = 0; k < 4; k++)
            tot[k] += r->count[k];
    }
    log_info("    %-5s %-16s %-9s %-9s %10zu %10zu %10zu %10zu\n", "",
             "total", "", "", tot[0], tot[1], tot[2], tot[3]);
    log_info("MPS particles: %zu (fluid volume %g m^%d); grains: %zu",
             tot[0] + tot[1] + tot[2], fluid * pow(c->dp, c->dim),
             c->dim, tot[3]);
}

/* Outputs written under temporary names, renamed together at the end. */
struct staged {
    int n;
    char tmp[3][4200], dst[3][4200];
    char zero_dir[4096];
    int made_dir;
};

static const char *stage(struct staged *s, const struct app *a,
                         const char *rel)
{
    char path[4096];
    app_path(a, rel, path, sizeof path);
    snprintf(s->dst[s->n], sizeof s->dst[0], "%s", path);
    snprintf(s->tmp[s->n], sizeof s->tmp[0], "%s.new.%ld", path,
             (long)getpid());
    return s->tmp[s->n++];
}

static void unstage(struct staged *s)
{
    for (int i = 0; i < s->n; i++)
        unlink(s->tmp[i]);
    if (s->made_dir)
        rmdir(s->zero_dir);
}

/* Write n points with the given fields plus an `id` field 0..n-1 (the
 * last entry of f, whose data this fills). */
static int write_with_ids(const struct gen_case *c, size_t n, double *x,
                          struct vtu_field *f, int nf, const char *path)
{
    struct vtu_cloud cl = { n, x, nf, f, 0.0 };
    int64_t *id = sim_malloc((n ? n : 1) * sizeof *id);
    int rc;

    if (!id)
        return SIM_ERR_NOMEM;
    for (size_t k = 0; k < n; k++)
        id[k] = (int64_t)k;
    f[nf - 1].data = id;
    rc = vtu_write(path, &cl, c->binary);
    free(id);
    return rc;
}

static int write_fluid(const struct gen_case *c, const struct mps_cloud *m,
                       const char *path)
{
    struct vtu_field f[] = {
        { "type", VTU_INT32, 1, m->type },
        { "patch", VTU_INT32, 1, m->patch },
        { "velocity", VTU_FLOAT64, 3, m->u },
        { "pressure", VTU_FLOAT64, 1, m->p },
        { "normal", VTU_FLOAT64, 3, m->normal },
        { "volumeFraction", VTU_FLOAT64, 1, m->phi },
        { "phase", VTU_INT32, 1, m->phase },
        { "id", VTU_INT64, 1, NULL },
    };
    /* optional fields only where the case has them, so that a case
     * without grains or soil writes the file it always wrote */
    int nf = 0;
    for (size_t k = 0; k < sizeof f / sizeof *f; k++)
        if (f[k].data || !strcmp(f[k].name, "id"))
            f[nf++] = f[k];
    return write_with_ids(c, m->n, m->x, f, nf, path);
}

static int write_dem(const struct gen_case *c, const struct dem_cloud *m,
                     const char *path)
{
    struct vtu_field f[] = {
        { "radius", VTU_FLOAT64, 1, m->radius },
        { "velocity", VTU_FLOAT64, 3, m->u },
        { "omega", VTU_FLOAT64, 3, m->omega },
        { "group", VTU_INT32, 1, m->group },
        { "id", VTU_INT64, 1, NULL },
    };
    return write_with_ids(c, m->n, m->x, f, 5, path);
}

static int write_patches(const struct gen_case *c, const char *path)
{
    FILE *f = fopen(path, "w");
    int bad;

    if (!f)
        return sim_error(SIM_ERR_IO, "%s: cannot create: %s", path,
                         strerror(errno));
    fprintf(f, "/* Written by genParticles from %s: do not edit. */\n"
               "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
               "    class       dictionary;\n    object      particlePatches;\n"
               "}\n\n// Region (patch) names by index: the 'patch' field of "
               "fluid.vtu and the\n// 'group' field of dem.vtu.\npatches\n(\n",
            c->dict_path);
    for (int i = 0; i < c->nregions; i++)
        fprintf(f, "    %s\n", c->r[i].name);
    fprintf(f, ");\n\n// Region types, same order.\ntypes\n(\n");
    for (int i = 0; i < c->nregions; i++)
        fprintf(f, "    %s\n", region_type_names[c->r[i].type]);
    fprintf(f, ");\n\ndimension   %d;\ndp          %.17g;\nwallLayers  %d;\n",
            c->dim, c->dp, c->layers);
    bad = ferror(f);
    if (fclose(f) != 0 || bad)
        return sim_error(SIM_ERR_IO, "%s: write failed", path);
    return SIM_OK;
}

static int write_all(const struct app *a, const struct gen_case *c,
                     const struct mps_cloud *m, const struct dem_cloud *g)
{
    struct staged s = { 0 };
    struct stat st;
    char pvd[4096];
    int rc = SIM_OK;

    app_path(a, "0", s.zero_dir, sizeof s.zero_dir);
    if (stat(s.zero_dir, &st) != 0) {
        if (mkdir(s.zero_dir, 0777) != 0)
            return sim_error(SIM_ERR_IO, "%s: cannot create: %s", s.zero_dir,
                             strerror(errno));
        s.made_dir = 1;
    }
    if (m->n)
        TRY_GOTO(rc, write_fluid(c, m, stage(&s, a, "0/fluid.vtu")), fail);
    if (g->n)
        TRY_GOTO(rc, write_dem(c, g, stage(&s, a, "0/dem.vtu")), fail);
    TRY_GOTO(rc, write_patches(c, stage(&s, a, "constant/particlePatches")),
             fail);
    for (int i = 0; i < s.n; i++)
        if (rename(s.tmp[i], s.dst[i]) != 0) {
            rc = sim_error(SIM_ERR_IO, "%s: cannot rename onto it: %s",
                           s.dst[i], strerror(errno));
            goto fail;
        }
    for (int i = 0; i < s.n; i++)
        log_info("Writing %s", s.dst[i]);
    if (m->n)
        TRY(pvd_add(app_path(a, "fluid.pvd", pvd, sizeof pvd), 0.0,
                    "0/fluid.vtu"));
    if (g->n)
        TRY(pvd_add(app_path(a, "dem.pvd", pvd, sizeof pvd), 0.0,
                    "0/dem.vtu"));
    return SIM_OK;
fail:
    unstage(&s);
    return rc;
}

static int run(const struct app *a)
{
    struct dict *d = NULL;
    struct gen_case c = { 0 };
    struct mps_cloud m = { 0 };
    struct dem_cloud g = { 0 };
    char path[4096];
    int rc;

    app_path(a, "system/particleDict", path, sizeof path);
    TRY_GOTO(rc, app_read_dict(a, "system/particleDict", &d), out);
    TRY_GOTO(rc, gen_read(&c, a, d, path, kernel_radius_hint(a),
                           control_binary(a)), out);
    TRY_GOTO(rc, read_physics(a, &c), out);
    TRY_GOTO(rc, gen_check_memory(&c), out);
    TRY_GOTO(rc, gen_mps(&c, &m), out);
    TRY_GOTO(rc, gen_dem(&c, &g), out);
    TRY_GOTO(rc, gen_grain_volume(a, &c, &m, &g), out);
    TRY_GOTO(rc, gen_hydrostatic(&c, &m), out);
    dict_warn_unused(d);
    print_summary(&c, &m);
    TRY_GOTO(rc, write_all(a, &c, &m, &g), out);
out:
    mps_cloud_free(&m);
    dem_cloud_free(&g);
    gen_case_free(&c);
    dict_free(d);
    return rc;
}

int main(int argc, char **argv)
{
    struct app app;
    int rc;

    app_init(&app, "genParticles",
             "fill the regions of system/particleDict with fluid, wall and "
             "dummy particles and grains; write 0/fluid.vtu, 0/dem.vtu",
             argc, argv, NULL, 0);
    rc = run(&app);
    if (rc == SIM_OK)
        rc = app_write_used_parameters(&app);
    if (rc != SIM_OK)
        app_fatal(&app, rc);
    return app_end(&app);
}
