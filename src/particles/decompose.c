/* decompose.c — see decompose.h.
 *
 * Bisection: the particles of a set are sorted along the cut axis (key,
 * then index: the same partition on every machine) and cut where the
 * running weight reaches the share of the lower side. Halo: particles are
 * taken subdomain by subdomain; a stamp per particle (the subdomain that
 * counted it last) counts each foreign particle once, a bit per subdomain
 * marks the neighbours. Subdomains are independent: one per thread. */
#include "particles/decompose.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/select.h"
#include "particles/cells.h"

struct key { double v; int32_t i; };

static int cmp_key(const void *a, const void *b)
{
    const struct key *p = a, *q = b;
    if (p->v != q->v)
        return p->v < q->v ? -1 : 1;
    return (p->i > q->i) - (p->i < q->i);
}

/* Cut idx[0, m) (sorted scratch k) for nparts subdomains from `first`;
 * with cuts, the cut of this set goes to cuts[node] (pre-order). */
static void bisect(int dim, const double *x, const double *w, int32_t *idx,
                   int m, int nparts, int first, struct key *k,
                   int32_t *part, struct decompose_cut *cuts, int node)
{
    if (nparts == 1 || (m == 0 && !cuts)) {
        for (int e = 0; e < m; e++)
            part[idx[e]] = first;
        return;
    }
    double lo[3] = { INFINITY, INFINITY, INFINITY };
    double hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    double total = 0;
    for (int e = 0; e < m; e++) {
        for (int a = 0; a < dim; a++) {
            lo[a] = fmin(lo[a], x[3 * idx[e] + a]);
            hi[a] = fmax(hi[a], x[3 * idx[e] + a]);
        }
        total += w ? w[idx[e]] : 1.0;
    }
    int axis = 0;
    for (int a = 1; a < dim; a++)
        if (hi[a] - lo[a] > hi[axis] - lo[axis])
            axis = a;
    for (int e = 0; e < m; e++)
        k[e] = (struct key){ x[3 * idx[e] + axis], idx[e] };
    qsort(k, (size_t)m, sizeof *k, cmp_key);
    const int left = nparts / 2;
    const double share = total * left / nparts;
    double run = 0;
    int cut = 0;
    /* the lower side takes particles while it is below its share (and
     * leaves at least one particle to each side that can have one) */
    while (cut < m) {
        double wc = w ? w[k[cut].i] : 1.0;
        if (run + 0.5 * wc > share)
            break;
        run += wc;
        cut++;
    }
    if (cut == 0 && m > 1)
        cut = 1;
    if (cut == m && m > 1)
        cut = m - 1;
    for (int e = 0; e < m; e++)
        idx[e] = k[e].i;
    if (cuts) {
        /* midway between the last particle below and the first above; an
         * empty set cuts anywhere (its subdomains start empty) */
        double v = m == 0 ? 0.0 : cut == 0 ? k[0].v
                 : cut == m ? nextafter(k[m - 1].v, INFINITY)
                 : 0.5 * (k[cut - 1].v + k[cut].v);
        cuts[node] = (struct decompose_cut){ axis, v };
    }
    bisect(dim, x, w, idx, cut, left, first, k, part, cuts, node + 1);
    bisect(dim, x, w, idx + cut, m - cut, nparts - left, first + left, k,
           part, cuts, node + left);
}

int decompose_rcb(int dim, const double *x, const double *weight, int n,
                  int nparts, int32_t *part)
{
    return decompose_rcb_cuts(dim, x, weight, n, nparts, part, NULL);
}

int decompose_rcb_cuts(int dim, const double *x, const double *weight, int n,
                       int nparts, int32_t *part, struct decompose_cut *cuts)
{
    if (nparts < 1)
        return sim_error(SIM_ERR_INPUT, "decompose: %d subdomains (at least "
                         "1)", nparts);
    for (int i = 0; i < n; i++)
        for (int a = 0; a < dim; a++)
            if (!isfinite(x[3 * i + a]))
                return sim_error(SIM_ERR_INPUT, "decompose: particle %d "
                                 "has a non-finite position", i);
    int32_t *idx = sim_malloc((size_t)(n > 0 ? n : 1) * sizeof *idx);
    struct key *k = sim_malloc((size_t)(n > 0 ? n : 1) * sizeof *k);
    if (!idx || !k) {
        free(idx);
        free(k);
        return SIM_ERR_NOMEM;
    }
    for (int i = 0; i < n; i++)
        idx[i] = i;
    bisect(dim, x, weight, idx, n, nparts, 0, k, part, cuts, 0);
    free(idx);
    free(k);
    return SIM_OK;
}

int decompose_owner(const struct decompose_cut *cuts, int nparts,
                    const double *x)
{
    int node = 0, first = 0;
    while (nparts > 1) {
        const int left = nparts / 2;
        if (x[cuts[node].axis] < cuts[node].value) {
            node += 1;
            nparts = left;
        } else {
            node += left;
            first += left;
            nparts -= left;
        }
    }
    return first;
}

int decompose_halo(int dim, const double *x, const double *weight, int n,
                   const int32_t *part, int nparts, double rc,
                   struct decompose_part *out)
{
    if (!(rc > 0))
        return sim_error(SIM_ERR_INPUT, "decompose: halo radius %g must be "
                         "> 0", rc);
    struct cell_grid g = { 0 };
    TRY(cells_build(&g, dim, x, n, rc, NULL, NULL));
    /* the particles of each subdomain, contiguous */
    int64_t *first = sim_calloc((size_t)nparts + 1, sizeof *first);
    int32_t *members = sim_malloc((size_t)(n > 0 ? n : 1) * sizeof *members);
    int err = first && members ? SIM_OK : SIM_ERR_NOMEM;
    for (int i = 0; i < n && !err; i++)
        first[part[i] + 1]++;
    for (int p = 0; p < nparts && !err; p++)
        first[p + 1] += first[p];
    for (int i = 0; i < n && !err; i++)
        members[first[part[i]]++] = i;
    for (int p = nparts; p > 0 && !err; p--)
        first[p] = first[p - 1];
    if (!err)
        first[0] = 0;
    const size_t words = ((size_t)nparts + 63) / 64;
    const double rc2 = rc * rc;
#pragma omp parallel if (!err)
    {
        int32_t *stamp = sim_malloc((size_t)(n > 0 ? n : 1) * sizeof *stamp);
        uint64_t *seen = sim_malloc(words * sizeof *seen);
        if (!stamp || !seen) {
#pragma omp atomic write
            err = SIM_ERR_NOMEM;
        } else {
            for (int i = 0; i < n; i++)
                stamp[i] = -1;
        }
#pragma omp barrier
#pragma omp for schedule(dynamic, 1)
        for (int p = 0; p < nparts; p++) {
            if (err)
                continue;
            struct decompose_part s = { 0 };
            memset(seen, 0, words * sizeof *seen);
            for (int64_t e = first[p]; e < first[p + 1]; e++) {
                int i = members[e];
                struct cell_run rn[CELLS_MAX_RUNS];
                int64_t len;
                s.owned++;
                s.weight += weight ? weight[i] : 1.0;
                if (g.cell_of[i] == g.ncell)
                    continue;
                int nr = cells_runs(&g, x + 3 * i, rc, rn, &len);
                for (int r = 0; r < nr; r++)
                    for (int64_t q = rn[r].a; q < rn[r].b; q++) {
                        int j = g.order[q];
                        if (part[j] == p || stamp[j] == p)
                            continue;
                        double d2 = 0;
                        for (int a = 0; a < 3; a++)
                            d2 += (x[3 * j + a] - x[3 * i + a])
                                * (x[3 * j + a] - x[3 * i + a]);
                        if (d2 >= rc2)
                            continue;
                        stamp[j] = p;
                        s.halo++;
                        if (!(seen[part[j] / 64] >> (part[j] % 64) & 1)) {
                            seen[part[j] / 64] |= 1ULL << (part[j] % 64);
                            s.neighbours++;
                        }
                    }
            }
            out[p] = s;
        }
        free(stamp);
        free(seen);
    }
    free(first);
    free(members);
    cells_free(&g);
    return err;
}

static const struct model_head method_rcb = {
    "rcb", "recursive coordinate bisection, Berger & Bokhari 1987"};
static const struct model_head *const method_table[] = { &method_rcb, NULL };
static const char *const balance_words[] = { "fluid", "all", NULL };

int decompose_settings_read(const struct dict *d, struct decompose_settings *s)
{
    int method;
    TRY(dict_get_label(d, "numberOfSubdomains", &s->nparts));
    if (!(s->nparts >= 1 && s->nparts <= 1000000))
        return dict_error(d, "numberOfSubdomains", SIM_ERR_DICT,
                          "numberOfSubdomains %ld must be in [1, 1000000]",
                          s->nparts);
    TRY(model_select_index(d, "method", "decomposition method",
                           (const void *const *)method_table, "rcb",
                           &method));
    TRY(dict_get_word_or(d, "balance", balance_words, 0, &s->balance_all));
    s->max_imbalance = 1.2;
    if (dict_has(d, "maxImbalance")) {
        TRY(dict_get_scalar(d, "maxImbalance", &s->max_imbalance));
        if (!(s->max_imbalance == 0 || s->max_imbalance > 1))
            return dict_error(d, "maxImbalance", SIM_ERR_DICT,
                              "maxImbalance %g: give a factor > 1, or 0 "
                              "for never", s->max_imbalance);
    }
    return SIM_OK;
}
