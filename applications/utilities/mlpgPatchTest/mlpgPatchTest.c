/*
 * mlpgPatchTest — the patch test of the MLPG_R pressure equation (Pan 2022
 * thesis sect. 4.3.1; doc/theory.md M.9.1, checks E3-06 ... E3-09):
 *
 *   lap p = 0 on [0, 1]^2,  dp/dx = 0 at x = 0, 1,  dp/dy = 0 at y = 0,
 *   dp/dy = pi sinh(pi) cos(pi x) at y = 1;  p = cosh(pi y) cos(pi x).
 *
 * Nodes on the square lattice of spacing dl = 1/N, (N + 1)^2 of them, the
 * boundary rows being wall nodes; each interior node is moved by
 * k (Rn - 0.5) dl per coordinate, wall nodes along their wall only,
 * corners fixed (doc M0-13). The system of src/mlpg (every fluid row, the
 * wall scheme's rows with the analytic Neumann data) is solved with one
 * node pinned to its analytic value (doc M0-08) and the solution shifted
 * so that sum p = sum p_a. Errors (doc M0-19):
 *
 *   Er   = sqrt(sum (p - p_a)^2 / sum p_a^2)           all nodes
 *   e_i  = |p_i - p_a,i| / sqrt(sum p_a^2 / n)          per node
 *   wall = mean of e_i over wall nodes;  max = max of e_i
 *
 * Reads system/patchTestDict; writes postProcessing/patchTest/errors.dat
 * (one line per wall scheme, k and dl: means over the seeds, and the wall
 * time per solve) and histogram.dat (the nodes per band of e_i / max e_i
 * at one (dl, k), mean over the seeds: the thesis's Fig. 4.6).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/files.h"
#include "core/log.h"
#include "linsolve/csr.h"
#include "mlpg/mlpg_solver.h"
#include "particles/cells.h"
#include "particles/lattice.h"
#include "particles/neighbour.h"

#define PI 3.141592653589793
#define MAXLIST 32
#define NBAND 10

struct settings {
    double dl[MAXLIST], k[MAXLIST];
    int ndl, nk, seeds;
    const struct mlpg_wall_ops *wall[4];
    int nwall, self_nodal;
    double support, radius, ref[2];
    double hist_dl, hist_k;
    const struct dict *ppe;
};

struct result {
    double er, wall, max, abs_max, seconds;
    int n, iters;
    double band[NBAND];
};

static double p_exact(const double *x)
{
    return cosh(PI * x[1]) * cos(PI * x[0]);
}

static void neumann(void *ctx, int i, int nseg, const double n[2][2],
                    double g[2])
{
    const double *x = (const double *)ctx + 3 * i;
    double gx = -PI * cosh(PI * x[1]) * sin(PI * x[0]);
    double gy = PI * sinh(PI * x[1]) * cos(PI * x[0]);
    for (int s = 0; s < nseg; s++)
        g[s] = n[s][0] * gx + n[s][1] * gy;
}

static int read_list(const struct dict *d, const char *key, double lo,
                     double hi, double *out, int *n)
{
    const struct dict_value *l;
    TRY(dict_get_list(d, key, &l));
    *n = dict_value_len(l);
    if (*n < 1 || *n > MAXLIST)
        return dict_error(d, key, SIM_ERR_DICT,
                          "%s: 1 to %d values expected, %d given", key,
                          MAXLIST, *n);
    for (int i = 0; i < *n; i++) {
        const struct dict_value *v = dict_value_at(l, i);
        TRY(dict_value_get_scalar(v, &out[i]));
        if (!(out[i] >= lo && out[i] <= hi))
            return dict_value_error(v, SIM_ERR_DICT,
                                    "%s: %g is out of range [%g, %g]", key,
                                    out[i], lo, hi);
    }
    return SIM_OK;
}

static int read_settings(const struct dict *d, struct settings *s)
{
    TRY(read_list(d, "spacings", 1e-3, 0.25, s->dl, &s->ndl));
    TRY(read_list(d, "randomness", 0, 0.9, s->k, &s->nk));
    long seeds;
    TRY(dict_get_label_or(d, "seeds", 10, &seeds));
    if (seeds < 1 || seeds > 1000)
        return dict_error(d, "seeds", SIM_ERR_DICT,
                          "seeds = %ld: 1 to 1000 expected", seeds);
    s->seeds = (int)seeds;
    const struct dict_value *l;
    TRY(dict_get_list(d, "wallSchemes", &l));
    s->nwall = dict_value_len(l);
    if (s->nwall < 1 || s->nwall > 4)
        return dict_error(d, "wallSchemes", SIM_ERR_DICT,
                          "wallSchemes: 1 to 4 names expected");
    for (int i = 0; i < s->nwall; i++) {
        const struct dict_value *v = dict_value_at(l, i);
        const char *name;
        char msg[512];
        TRY(dict_value_get_word(v, &name));
        s->wall[i] = model_find((const void *const *)mlpg_wall_schemes, name);
        if (!s->wall[i])
            return dict_value_error(
                v, SIM_ERR_DICT, "%s",
                model_unknown((const void *const *)mlpg_wall_schemes,
                              "wall scheme", name, msg, sizeof msg));
    }
    TRY(mlpg_rows_read(d, &s->self_nodal, &s->support, &s->radius));
    TRY(dict_get_vector_or(d, "reference", 2, (double[]){ 0.5, 0.5 },
                           s->ref));
    const struct dict *h;
    TRY(dict_get_dict(d, "histogram", &h));
    TRY(dict_get_scalar(h, "spacing", &s->hist_dl));
    TRY(dict_get_scalar(h, "randomness", &s->hist_k));
    TRY(dict_get_dict(d, "PPE", &s->ppe));
    return SIM_OK;
}

/* Nodes of one (dl, k, seed): wall rows first in lattice order. */
static int make_nodes(int N, double k, uint64_t seed, double **x,
                      int32_t **type, double **normal, double **sector)
{
    int n = (N + 1) * (N + 1);
    double dl = 1.0 / N;
    *x = sim_calloc(3 * (size_t)n, sizeof **x);
    *normal = sim_calloc(3 * (size_t)n, sizeof **normal);
    *sector = sim_calloc((size_t)n, sizeof **sector);
    *type = sim_calloc((size_t)n, sizeof **type);
    double *jit = sim_calloc(3 * (size_t)n, sizeof *jit);
    if (!*x || !*normal || !*sector || !*type || !jit) {
        free(jit);
        return SIM_ERR_NOMEM;
    }
    lattice_jitter(jit, (size_t)n, 2, k * dl / 2, seed);
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            int a = j * (N + 1) + i;
            double *p = *x + 3 * a, *nw = *normal + 3 * a;
            int bx = i == 0 ? 1 : i == N ? -1 : 0;
            int by = j == 0 ? 1 : j == N ? -1 : 0;
            p[0] = i * dl + (bx ? 0 : jit[3 * a]);
            p[1] = j * dl + (by ? 0 : jit[3 * a + 1]);
            if (!bx && !by) {
                (*type)[a] = MLPG_FLUID;
                (*sector)[a] = 2 * PI;
                continue;
            }
            (*type)[a] = MLPG_WALL;
            double len = sqrt((double)(bx * bx + by * by));
            nw[0] = bx / len;
            nw[1] = by / len;
            (*sector)[a] = bx && by ? PI / 2 : PI;
        }
    free(jit);
    return SIM_OK;
}

static int run_case(const struct settings *set, int N, double k, uint64_t seed,
                    const struct mlpg_wall_ops *wall, struct linsolve *ls,
                    struct result *res)
{
    double *x = NULL, *normal = NULL, *sector = NULL, *R = NULL;
    double *p = NULL, *b = NULL;
    int32_t *type = NULL;
    uint8_t *dir = NULL;
    struct cell_grid grid = { 0 };
    struct neighbour_list nl = { 0 };
    struct csr_matrix A = { 0 };
    size_t cap = 0;
    int rc;
    const double dl = 1.0 / N;
    const int n = (N + 1) * (N + 1);
    double t0 = app_wall_time();
    TRY_GOTO(rc, make_nodes(N, k, seed, &x, &type, &normal, &sector), out);
    R = sim_calloc((size_t)n, sizeof *R);
    p = sim_calloc((size_t)n, sizeof *p);
    b = sim_calloc((size_t)n, sizeof *b);
    dir = sim_calloc((size_t)n, 1);
    if (!R || !p || !b || !dir) {
        rc = SIM_ERR_NOMEM;
        goto out;
    }
    const double rcut = (set->support + set->radius) * dl * 1.001;
    TRY_GOTO(rc, cells_build(&grid, 2, x, n, rcut / 2, NULL, NULL), out);
    TRY_GOTO(rc, neighbour_build(&nl, &grid, x, rcut), out);
    struct mlpg_cloud c = {
        .n = n, .dl = dl, .rs = set->support * dl, .R0 = set->radius * dl,
        .x = x, .type = type, .normal = normal, .sector = sector, .R = R,
        .dirichlet = dir, .nl = &nl, .self_nodal = set->self_nodal,
    };
    mlpg_radii(&c, R);
    /* the reference node: nearest to set->ref */
    int pin = 0;
    double best = HUGE_VAL;
    for (int i = 0; i < n; i++) {
        double d = hypot(x[3 * i] - set->ref[0], x[3 * i + 1] - set->ref[1]);
        if (d < best) {
            best = d;
            pin = i;
        }
    }
    dir[pin] = 1;
    double pa_pin = p_exact(x + 3 * pin);
    struct mlpg_system S = { .wall = wall, .neumann = neumann, .ctx = x,
                             .p_given = NULL };
    double *given = p; /* p_given: 0 but at the pin */
    given[pin] = pa_pin;
    S.p_given = given;
    TRY_GOTO(rc, mlpg_assemble(&c, &S, &A, &cap, b), out);
    memset(p, 0, (size_t)n * sizeof *p);
    struct linsolve_stats st;
    TRY_GOTO(rc, linsolve_solve(ls, &A, b, p, &st), out);
    res->seconds = app_wall_time() - t0;
    res->iters = st.iters;
    /* shift: sum p = sum p_a */
    double sp = 0, sa = 0, sa2 = 0;
    for (int i = 0; i < n; i++) {
        double pa = p_exact(x + 3 * i);
        sp += p[i];
        sa += pa;
        sa2 += pa * pa;
    }
    double shift = (sa - sp) / n, rms = sqrt(sa2 / n), se2 = 0, wsum = 0;
    int nw = 0;
    res->max = res->abs_max = 0;
    for (int i = 0; i < n; i++) {
        double e = fabs(p[i] + shift - p_exact(x + 3 * i));
        se2 += e * e;
        res->abs_max = fmax(res->abs_max, e);
        if (type[i] == MLPG_WALL) {
            wsum += e / rms;
            nw++;
        }
        p[i] = e / rms;
        res->max = fmax(res->max, p[i]);
    }
    res->er = sqrt(se2 / sa2);
    res->wall = wsum / nw;
    res->n = n;
    for (int q = 0; q < NBAND; q++)
        res->band[q] = 0;
    for (int i = 0; i < n; i++) {
        int q = (int)(NBAND * p[i] / res->max);
        res->band[q < NBAND ? q : NBAND - 1] += 1;
    }
    rc = SIM_OK;
out:
    csr_free(&A);
    neighbour_free(&nl);
    cells_free(&grid);
    free(x), free(normal), free(sector), free(type), free(R), free(p);
    free(b), free(dir);
    return rc;
}

int main(int argc, char **argv)
{
    struct app app;
    app_init(&app, "mlpgPatchTest",
             "patch test of the MLPG_R pressure equation (E3-06..E3-09)",
             argc, argv, NULL, 0);
    struct dict *d;
    struct settings set;
    struct linsolve *ls;
    int rc = app_read_dict(&app, "system/patchTestDict", &d);
    if (rc == SIM_OK)
        rc = read_settings(d, &set);
    if (rc == SIM_OK)
        rc = linsolve_create(set.ppe, &ls);
    if (rc == SIM_OK)
        rc = dict_warn_unused(d);
    if (rc != SIM_OK)
        app_fatal(&app, rc);
    char dir[4200], path[4300];
    app_path(&app, "postProcessing/patchTest", dir, sizeof dir);
    if ((rc = files_mkdir_p(dir)) != SIM_OK)
        app_fatal(&app, rc);
    snprintf(path, sizeof path, "%s/errors.dat", dir);
    FILE *fe = fopen(path, "w");
    snprintf(path, sizeof path, "%s/histogram.dat", dir);
    FILE *fh = fopen(path, "w");
    if (!fe || !fh)
        app_fatal(&app, sim_error(SIM_ERR_IO, "cannot write %s", path));
    const char *head = "# scheme k dl nodes Er Er_sd wallMean max "
                       "absMax iterations seconds   (means over %d seeds; "
                       "e_i = |p - p_a| / rms(p_a), doc/theory.md M0-19)\n";
    fprintf(fe, head, set.seeds);
    log_info(head, set.seeds);
    fprintf(fh, "# band lo hi  nodes per band of e_i/max(e_i) at dl %g, "
                "k %g (mean over %d seeds), one column per scheme:",
            set.hist_dl, set.hist_k, set.seeds);
    for (int w = 0; w < set.nwall; w++)
        fprintf(fh, " %s", set.wall[w]->name);
    fprintf(fh, "\n");
    double hist[4][NBAND] = { { 0 } };
    for (int w = 0; w < set.nwall; w++)
        for (int ik = 0; ik < set.nk; ik++)
            for (int id = 0; id < set.ndl; id++) {
                int N = (int)lround(1 / set.dl[id]);
                struct result sum = { 0 }, r = { 0 };
                double er2 = 0;
                int hist_case = fabs(1.0 / N - set.hist_dl) < 1e-6
                             && fabs(set.k[ik] - set.hist_k) < 1e-9;
                for (int sd = 1; sd <= set.seeds; sd++) {
                    rc = run_case(&set, N, set.k[ik], (uint64_t)sd,
                                  set.wall[w], ls, &r);
                    if (rc != SIM_OK)
                        app_fatal(&app, rc);
                    sum.er += r.er;
                    er2 += r.er * r.er;
                    sum.wall += r.wall;
                    sum.max += r.max;
                    sum.abs_max += r.abs_max;
                    sum.seconds += r.seconds;
                    sum.iters += r.iters;
                    if (hist_case)
                        for (int q = 0; q < NBAND; q++)
                            hist[w][q] += r.band[q] / set.seeds;
                }
                double m = set.seeds, er = sum.er / m;
                double sd = sqrt(fmax(er2 / m - er * er, 0));
                char line[512];
                snprintf(line, sizeof line,
                         "%-9s %.2f %.6f %6d %.4e %.2e %.4e %.4e %.4e "
                         "%6.1f %.4f\n",
                         set.wall[w]->name, set.k[ik], 1.0 / N, r.n, er, sd,
                         sum.wall / m, sum.max / m, sum.abs_max / m,
                         sum.iters / m, sum.seconds / m);
                fputs(line, fe);
                fflush(fe);
                log_info("%s", line);
            }
    for (int q = 0; q < NBAND; q++) {
        fprintf(fh, "%d %.1f %.1f", q, (double)q / NBAND,
                (double)(q + 1) / NBAND);
        for (int w = 0; w < set.nwall; w++)
            fprintf(fh, " %.1f", hist[w][q]);
        fprintf(fh, "\n");
    }
    if (fclose(fe) != 0 || fclose(fh) != 0)
        app_fatal(&app, sim_error(SIM_ERR_IO, "cannot write %s", dir));
    linsolve_free(ls);
    dict_free(d);
    return app_end(&app);
}
