/* distribute.c — see distribute.h and halo.h.
 *
 * A particle travels as one record: the bytes of each of its fields that
 * the store owns (views stay behind), in registration order. Index fields
 * hold particle ids while particles travel (ids are what two ranks share)
 * and local indices otherwise. */
#ifdef MPSDEM_HAVE_MPI

#include "particles/distribute.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "particles/decompose.h"

struct dist {
    struct pop_halo h;            /* first: the ops cast back          */
    struct pop_halo_ops ops;      /* h.ops: dist_ops and the solve      */
    MPI_Comm comm;
    int dim;
    double width;
    struct decompose_cut *cuts;   /* size - 1                          */
    /* the ghost plan: send_idx grouped by destination (scount, sdispl
     * particles each), ghosts from rank r at n_own + rdispl[r]        */
    int *scount, *sdispl, *rcount, *rdispl;
    int *bc, *bd, *rbc, *rbd;     /* the same in bytes (scratch)       */
    int32_t *send_idx, *dest, *keep;
    size_t send_cap, dest_cap, keep_cap;
    char *sbuf, *rbuf;
    size_t scap, rcap;
    int32_t *map;                 /* id -> local index                 */
    size_t map_cap;
    /* dist_gather's store on rank 0 and the owners' pointers of its
     * fields */
    struct store whole;
    void *slots[STORE_MAX_FIELDS];
    int whole_made;
    int64_t *order;
    size_t order_cap;
    /* statistics: particles sent to another owner, ghosts held, over the
     * exchanges so far */
    long migrated, exchanges, balances;
    double ghost_sum;
};

static int travels(const struct store_field *f)
{
    return !(f->flags & STORE_VIEW);
}

static size_t record_size(const struct store *st)
{
    size_t r = 0;
    for (int k = 0; k < st->nfields; k++)
        if (travels(&st->f[k]))
            r += st->f[k].elem;
    return r;
}

static double *points(const struct store *st)
{
    for (int k = 0; k < st->nfields; k++)
        if (st->f[k].flags & STORE_POINTS)
            return *st->f[k].ref;
    return NULL;
}

static int ids_of(const struct store *st, const int64_t **ids)
{
    const struct store_field *f = store_find(st, "id");
    if (!f || f->type != VTU_INT64 || f->ncomp != 1 || !points(st))
        return sim_error(SIM_ERR_INTERNAL, "distribute: the %s store needs "
                         "positions and an Int64 field 'id'", st->category);
    *ids = *f->ref;
    return SIM_OK;
}

/* ids: NULL copies index fields as they are; else they go as ids. */
static void pack(const struct store *st, size_t i, char *out,
                 const int64_t *ids)
{
    for (int k = 0; k < st->nfields; k++) {
        const struct store_field *f = &st->f[k];
        if (!travels(f))
            continue;
        memcpy(out, (const char *)*f->ref + i * f->elem, f->elem);
        if (ids && (f->flags & STORE_INDEX)) {
            int32_t v;
            memcpy(&v, out, sizeof v);
            if (v >= 0)
                v = (int32_t)ids[v];
            memcpy(out, &v, sizeof v);
        }
        out += f->elem;
    }
}

static void unpack(struct store *st, size_t i, const char *in)
{
    for (int k = 0; k < st->nfields; k++) {
        const struct store_field *f = &st->f[k];
        if (!travels(f))
            continue;
        memcpy((char *)*f->ref + i * f->elem, in, f->elem);
        in += f->elem;
    }
}

/* Room for n entries in each per-particle list (sim_reserve). */
static int grow_idx(struct dist *d, size_t n)
{
    TRY(sim_reserve((void **)&d->dest, &d->dest_cap, n, sizeof *d->dest));
    return sim_reserve((void **)&d->keep, &d->keep_cap, n, sizeof *d->keep);
}

/* Index fields of particles [0, n) from local indices to ids. Ids must
 * fit the fields' 32 bits. */
static int index_to_ids(struct store *st, size_t n)
{
    const int64_t *ids;
    TRY(ids_of(st, &ids));
    for (int k = 0; k < st->nfields; k++) {
        if (!(st->f[k].flags & STORE_INDEX))
            continue;
        int32_t *v = *st->f[k].ref;
        for (size_t i = 0; i < n; i++)
            if (v[i] >= 0) {
                if (ids[v[i]] > INT32_MAX || ids[v[i]] < 0)
                    return sim_error(SIM_ERR_INPUT, "distribute: particle "
                                     "id %lld out of the range of field "
                                     "'%s'", (long long)ids[v[i]],
                                     st->f[k].name);
                v[i] = (int32_t)ids[v[i]];
            }
    }
    return SIM_OK;
}

/* ... and back, over every particle held (-1: not held here). */
static int ids_to_index(struct dist *d, struct store *st)
{
    const int64_t *ids;
    TRY(ids_of(st, &ids));
    int any = 0;
    for (int k = 0; k < st->nfields; k++)
        any |= (st->f[k].flags & STORE_INDEX) != 0;
    if (!any)
        return SIM_OK;
    int64_t top = -1;
    for (size_t i = 0; i < st->n; i++)
        top = ids[i] > top ? ids[i] : top;
    TRY(sim_reserve((void **)&d->map, &d->map_cap, (size_t)(top + 1),
                    sizeof *d->map));
    for (int64_t q = 0; q <= top; q++)
        d->map[q] = -1;
    for (size_t i = 0; i < st->n; i++)
        if (ids[i] >= 0)
            d->map[ids[i]] = (int32_t)i;
    for (int k = 0; k < st->nfields; k++) {
        if (!(st->f[k].flags & STORE_INDEX))
            continue;
        int32_t *v = *st->f[k].ref;
        for (size_t i = 0; i < st->n; i++)
            if (v[i] >= 0)
                v[i] = v[i] <= top ? d->map[v[i]] : -1;
    }
    return SIM_OK;
}

/* Send the particles listed per destination (list grouped by rank,
 * cnt/displ particles each) and append what comes to st; returns in
 * *got the received count per rank (rcnt) and their offsets (rdsp). */
static int swap_records(struct dist *d, struct store *st, const int32_t *list,
                        const int *cnt, const int *dsp, int *rcnt, int *rdsp)
{
    const int P = d->h.size;
    const size_t R = record_size(st);
    MPI_Alltoall(cnt, 1, MPI_INT, rcnt, 1, MPI_INT, d->comm);
    size_t ns = 0, nr = 0;
    for (int r = 0; r < P; r++) {
        rdsp[r] = (int)nr;
        ns += (size_t)cnt[r];
        nr += (size_t)rcnt[r];
        if ((ns + nr) * R > INT32_MAX)
            return sim_error(SIM_ERR_INPUT, "distribute: more than 2 GB "
                             "to exchange in one message");
    }
    TRY(sim_reserve((void **)&d->sbuf, &d->scap, ns * R, 1));
    TRY(sim_reserve((void **)&d->rbuf, &d->rcap, nr * R, 1));
    for (size_t e = 0; e < ns; e++)
        pack(st, (size_t)list[e], d->sbuf + e * R, NULL);
    for (int r = 0; r < P; r++) {
        d->bc[r] = cnt[r] * (int)R;
        d->bd[r] = dsp[r] * (int)R;
        d->rbc[r] = rcnt[r] * (int)R;
        d->rbd[r] = rdsp[r] * (int)R;
    }
    MPI_Alltoallv(d->sbuf, d->bc, d->bd, MPI_BYTE, d->rbuf, d->rbc, d->rbd,
                  MPI_BYTE, d->comm);
    size_t n0 = st->n;
    TRY(store_reserve(st, n0 + nr + (n0 + nr) / 8));
    TRY(store_resize(st, n0 + nr));
    for (size_t e = 0; e < nr; e++)
        unpack(st, n0 + e, d->rbuf + e * R);
    return SIM_OK;
}

/* The own particles [0, st->n) (index fields as ids) to their owners. */
static int migrate(struct dist *d, struct store *st)
{
    const int P = d->h.size, me = d->h.rank;
    const size_t n = st->n;
    const double *x = points(st);
    TRY(grow_idx(d, n));
    TRY(sim_reserve((void **)&d->send_idx, &d->send_cap, n + 1,
                    sizeof *d->send_idx));
    for (int r = 0; r < P; r++)
        d->scount[r] = 0;
    for (size_t i = 0; i < n; i++) {
        d->dest[i] = decompose_owner(d->cuts, P, x + 3 * i);
        d->scount[d->dest[i]] += d->dest[i] != me;
    }
    int off = 0;
    for (int r = 0; r < P; r++) {
        d->sdispl[r] = off;
        off += d->scount[r];
    }
    int *fill = d->rcount;        /* scratch until the swap */
    memcpy(fill, d->sdispl, sizeof *fill * (size_t)P);
    for (size_t i = 0; i < n; i++)
        if (d->dest[i] != me)
            d->send_idx[fill[d->dest[i]]++] = (int32_t)i;
    d->migrated += off;
    /* the newcomers are appended; then the leavers go */
    TRY(swap_records(d, st, d->send_idx, d->scount, d->sdispl, d->rcount,
                     d->rdispl));
    TRY(grow_idx(d, st->n));
    size_t m = 0;
    for (size_t i = 0; i < st->n; i++)
        if (i >= n || d->dest[i] == me)
            d->keep[m++] = (int32_t)i;
    TRY(store_compact_unmapped(st, d->keep, m));
    return SIM_OK;
}

/* Copies of the own particles [0, n_own) near each other rank's own
 * ones, appended to st; the plan of refresh. */
static int ghosts(struct dist *d, struct store *st)
{
    const int P = d->h.size, me = d->h.rank, dim = d->dim;
    const size_t n = st->n;
    const double *x = points(st);
    double box[6] = { INFINITY, INFINITY, INFINITY,
                      -INFINITY, -INFINITY, -INFINITY };
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < dim; a++) {
            box[a] = fmin(box[a], x[3 * i + a]);
            box[3 + a] = fmax(box[3 + a], x[3 * i + a]);
        }
    double *all = sim_malloc(6 * (size_t)P * sizeof *all);
    if (!all)
        return SIM_ERR_NOMEM;
    MPI_Allgather(box, 6, MPI_DOUBLE, all, 6, MPI_DOUBLE, d->comm);
    const struct store_field *rf = store_find(st, "haloReach");
    const double *reach = rf && rf->type == VTU_FLOAT64 ? *rf->ref : NULL;
    size_t total = 0;
    for (int pass = 0; pass < 2; pass++) {
        size_t e = 0;
        for (int r = 0; r < P; r++) {
            const double *b = all + 6 * r;
            d->sdispl[r] = (int)e;
            for (size_t i = 0; i < n && r != me; i++) {
                int in = 1;
                double w = reach ? fmax(d->width, reach[i]) : d->width;
                for (int a = 0; a < dim && in; a++)
                    in = x[3 * i + a] >= b[a] - w
                      && x[3 * i + a] <= b[3 + a] + w;
                if (in && pass == 1)
                    d->send_idx[e] = (int32_t)i;
                e += (size_t)in;
            }
            d->scount[r] = (int)e - d->sdispl[r];
        }
        total = e;
        if (pass == 0 && sim_reserve((void **)&d->send_idx, &d->send_cap,
                                     total + 1, sizeof *d->send_idx)) {
            free(all);
            return SIM_ERR_NOMEM;
        }
    }
    free(all);
    return swap_records(d, st, d->send_idx, d->scount, d->sdispl, d->rcount,
                        d->rdispl);
}

static int exchange(struct pop_halo *h, struct store *st)
{
    struct dist *d = (struct dist *)h;
    TRY(index_to_ids(st, (size_t)h->n_own));
    st->n = (size_t)h->n_own;            /* the ghosts go */
    TRY(migrate(d, st));
    h->n_own = (int)st->n;
    TRY(ghosts(d, st));
    d->exchanges++;
    d->ghost_sum += (double)(st->n - (size_t)h->n_own);
    return ids_to_index(d, st);
}

static int refresh(struct pop_halo *h, void *data, size_t elem)
{
    struct dist *d = (struct dist *)h;
    const int P = h->size;
    size_t ns = 0;
    for (int r = 0; r < P; r++) {
        ns += (size_t)d->scount[r];
        d->bc[r] = d->scount[r] * (int)elem;
        d->bd[r] = d->sdispl[r] * (int)elem;
        d->rbc[r] = d->rcount[r] * (int)elem;
        d->rbd[r] = d->rdispl[r] * (int)elem;
    }
    TRY(sim_reserve((void **)&d->sbuf, &d->scap, ns * elem, 1));
    const char *src = data;
    for (size_t e = 0; e < ns; e++)
        memcpy(d->sbuf + e * elem, src + (size_t)d->send_idx[e] * elem, elem);
    MPI_Alltoallv(d->sbuf, d->bc, d->bd, MPI_BYTE,
                  (char *)data + (size_t)h->n_own * elem, d->rbc, d->rbd,
                  MPI_BYTE, d->comm);
    return SIM_OK;
}

static void reduce(struct pop_halo *h, double *v, int n, enum pop_reduce op)
{
    struct dist *d = (struct dist *)h;
    MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, op == POP_SUM ? MPI_SUM
                  : op == POP_MIN ? MPI_MIN : MPI_MAX, d->comm);
}

static void bcast(struct pop_halo *h, void *data, size_t bytes)
{
    struct dist *d = (struct dist *)h;
    for (size_t off = 0; off < bytes; off += INT32_MAX) {
        size_t m = bytes - off < INT32_MAX ? bytes - off : INT32_MAX;
        MPI_Bcast((char *)data + off, (int)m, MPI_BYTE, 0, d->comm);
    }
}

static int64_t exscan(struct pop_halo *h, int64_t v, int64_t *total)
{
    struct dist *d = (struct dist *)h;
    int64_t before = 0;
    MPI_Exscan(&v, &before, 1, MPI_INT64_T, MPI_SUM, d->comm);
    if (h->rank == 0)
        before = 0;             /* MPI leaves rank 0's result undefined */
    MPI_Allreduce(&v, total, 1, MPI_INT64_T, MPI_SUM, d->comm);
    return before;
}

/* Every rank's own positions and weights on every rank (in rank order,
 * so that each computes the same cuts). */
static int balance(struct pop_halo *h, const struct store *st,
                   const double *weight, int *done)
{
    struct dist *d = (struct dist *)h;
    const int P = h->size, n = h->n_own;
    double mine = 0;
    for (int i = 0; i < n; i++)
        mine += weight ? weight[i] : 1.0;
    double wmax = mine, wsum = mine;
    MPI_Allreduce(&mine, &wmax, 1, MPI_DOUBLE, MPI_MAX, d->comm);
    MPI_Allreduce(&mine, &wsum, 1, MPI_DOUBLE, MPI_SUM, d->comm);
    *done = 0;
    if (!(h->max_imbalance > 0) || P == 1 || wsum <= 0
        || wmax <= h->max_imbalance * wsum / P)
        return SIM_OK;
    const double *x = points(st);
    double *mx = sim_malloc(4 * ((size_t)n + 1) * sizeof *mx);
    if (!mx)
        return SIM_ERR_NOMEM;
    for (int i = 0; i < n; i++) {
        memcpy(mx + 4 * i, x + 3 * i, 3 * sizeof *mx);
        mx[4 * i + 3] = weight ? weight[i] : 1.0;
    }
    int cnt = 4 * n;
    MPI_Allgather(&cnt, 1, MPI_INT, d->rbc, 1, MPI_INT, d->comm);
    size_t total = 0;
    for (int r = 0; r < P; r++) {
        d->rbd[r] = (int)total;
        total += (size_t)d->rbc[r];
    }
    double *all = sim_malloc((total + 4) * sizeof *all);
    double *xa = sim_malloc((3 * total / 4 + 3) * sizeof *xa);
    double *wa = sim_malloc((total / 4 + 1) * sizeof *wa);
    int32_t *part = sim_malloc((total / 4 + 1) * sizeof *part);
    int rc = all && xa && wa && part ? SIM_OK : SIM_ERR_NOMEM;
    if (total > INT32_MAX)
        rc = sim_error(SIM_ERR_INPUT, "distribute: too many particles to "
                       "balance");
    if (!rc) {
        MPI_Allgatherv(mx, cnt, MPI_DOUBLE, all, d->rbc, d->rbd, MPI_DOUBLE,
                       d->comm);
        const size_t m = total / 4;
        for (size_t e = 0; e < m; e++) {
            memcpy(xa + 3 * e, all + 4 * e, 3 * sizeof *xa);
            wa[e] = all[4 * e + 3];
        }
        rc = decompose_rcb_cuts(d->dim, xa, weight ? wa : NULL, (int)m, P,
                                part, d->cuts);
        if (!rc) {
            d->balances++;
            *done = 1;
        }
    }
    free(mx);
    free(all);
    free(xa);
    free(wa);
    free(part);
    return rc;
}

static const struct pop_halo_ops dist_ops = {
    .balance = balance,
    .exchange = exchange,
    .refresh = refresh,
    .reduce = reduce,
    .bcast = bcast,
    .exscan = exscan,
};

int dist_create(MPI_Comm comm, int dim, double width, struct dist **out)
{
    struct dist *d = sim_calloc(1, sizeof *d);
    if (!d)
        return SIM_ERR_NOMEM;
    d->comm = comm;
    d->dim = dim;
    d->width = width;
    MPI_Comm_rank(comm, &d->h.rank);
    MPI_Comm_size(comm, &d->h.size);
    d->ops = dist_ops;
    d->h.ops = &d->ops;
    const size_t P = (size_t)d->h.size;
    d->cuts = sim_calloc(P, sizeof *d->cuts);
    int **arr[] = { &d->scount, &d->sdispl, &d->rcount, &d->rdispl,
                    &d->bc, &d->bd, &d->rbc, &d->rbd };
    int ok = d->cuts != NULL;
    for (size_t k = 0; k < sizeof arr / sizeof *arr; k++)
        ok &= (*arr[k] = sim_calloc(P, sizeof(int))) != NULL;
    *out = d;
    return ok ? SIM_OK : SIM_ERR_NOMEM;
}

void dist_free(struct dist *d)
{
    if (!d)
        return;
    free(d->cuts);
    free(d->scount); free(d->sdispl); free(d->rcount); free(d->rdispl);
    free(d->bc); free(d->bd); free(d->rbc); free(d->rbd);
    free(d->send_idx); free(d->dest); free(d->keep);
    free(d->sbuf); free(d->rbuf); free(d->map); free(d->order);
    if (d->whole_made)
        store_free(&d->whole);
    free(d);
}

struct pop_halo *dist_halo(struct dist *d)
{
    return &d->h;
}

void dist_set_solve(struct dist *d,
                    int (*solve)(struct pop_halo *, struct linsolve *,
                                 const struct csr_matrix *, int64_t, int64_t,
                                 const double *, double *,
                                 struct linsolve_stats *))
{
    d->ops.solve = solve;
}

MPI_Comm dist_comm(const struct pop_halo *h)
{
    return ((const struct dist *)h)->comm;
}

int dist_split(struct dist *d, struct store *st, const double *weight)
{
    const size_t n = st->n;
    if (n > INT32_MAX)
        return sim_error(SIM_ERR_INPUT, "distribute: too many particles");
    int32_t *part = sim_malloc((n + 1) * sizeof *part);
    if (!part)
        return SIM_ERR_NOMEM;
    int rc = decompose_rcb_cuts(d->dim, points(st), weight, (int)n,
                                d->h.size, part, d->cuts);
    free(part);
    TRY(rc);
    TRY(grow_idx(d, n));
    TRY(index_to_ids(st, n));
    /* ownership by region (decompose_owner), as every later migration */
    const double *x = points(st);
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
        if (decompose_owner(d->cuts, d->h.size, x + 3 * i) == d->h.rank)
            d->keep[m++] = (int32_t)i;
    TRY(store_compact_unmapped(st, d->keep, m));
    d->h.n_own = (int)m;
    TRY(ghosts(d, st));
    return ids_to_index(d, st);
}

void dist_stats(struct dist *d, struct dist_stats *out)
{
    long m = d->migrated;
    double g[2] = { d->ghost_sum, (double)d->exchanges }, own = d->h.n_own,
           gmax = d->exchanges ? d->ghost_sum / d->exchanges : 0;
    MPI_Allreduce(&d->migrated, &m, 1, MPI_LONG, MPI_SUM, d->comm);
    MPI_Allreduce(MPI_IN_PLACE, g, 2, MPI_DOUBLE, MPI_SUM, d->comm);
    MPI_Allreduce(MPI_IN_PLACE, &gmax, 1, MPI_DOUBLE, MPI_MAX, d->comm);
    double omin = own, omax = own;
    MPI_Allreduce(&own, &omin, 1, MPI_DOUBLE, MPI_MIN, d->comm);
    MPI_Allreduce(&own, &omax, 1, MPI_DOUBLE, MPI_MAX, d->comm);
    *out = (struct dist_stats){
        .ranks = d->h.size, .migrated = m,
        .exchanges = d->exchanges, .balances = d->balances,
        .ghosts_mean = g[1] > 0 ? g[0] / g[1] : 0, .ghosts_max = gmax,
        .own_min = (long)omin, .own_max = (long)omax };
}

static int cmp_id(const void *a, const void *b)
{
    const int64_t *p = a, *q = b;
    return (p[0] > q[0]) - (p[0] < q[0]);
}

int dist_gather(struct dist *d, const struct store *st, struct store **whole)
{
    const int P = d->h.size, root = d->h.rank == 0;
    const size_t R = record_size(st);
    const int64_t *ids;
    TRY(ids_of(st, &ids));
    const int mine = d->h.n_own;
    TRY(sim_reserve((void **)&d->sbuf, &d->scap, (size_t)mine * R, 1));
    for (int i = 0; i < mine; i++)
        pack(st, (size_t)i, d->sbuf + (size_t)i * R, ids);
    int cnt = mine * (int)R;
    MPI_Gather(&cnt, 1, MPI_INT, d->rbc, 1, MPI_INT, 0, d->comm);
    size_t total = 0;
    if (root)
        for (int r = 0; r < P; r++) {
            d->rbd[r] = (int)total;
            total += (size_t)d->rbc[r];
            if (total > INT32_MAX)
                return sim_error(SIM_ERR_INPUT, "distribute: more than 2 GB "
                                 "to gather for output");
        }
    TRY(sim_reserve((void **)&d->rbuf, &d->rcap, total + 1, 1));
    MPI_Gatherv(d->sbuf, cnt, MPI_BYTE, d->rbuf, d->rbc, d->rbd, MPI_BYTE, 0,
                d->comm);
    *whole = NULL;
    if (!root)
        return SIM_OK;
    if (!d->whole_made) {
        store_init(&d->whole, st->category);
        for (int k = 0; k < st->nfields; k++) {
            const struct store_field *f = &st->f[k];
            if (travels(f))
                TRY(store_add(&d->whole, f->name, f->doc, f->type, f->ncomp,
                              f->flags & ~STORE_INDEX, &d->slots[k]));
        }
        d->whole_made = 1;
    }
    /* sort the records by id: the id's offset in a record */
    size_t id_off = 0;
    for (int k = 0; k < st->nfields; k++) {
        if (!travels(&st->f[k]))
            continue;
        if (!strcmp(st->f[k].name, "id"))
            break;
        id_off += st->f[k].elem;
    }
    const size_t n = total / R;
    TRY(sim_reserve((void **)&d->order, &d->order_cap, 2 * n + 2,
                    sizeof *d->order));
    for (size_t e = 0; e < n; e++) {
        memcpy(&d->order[2 * e], d->rbuf + e * R + id_off, sizeof(int64_t));
        d->order[2 * e + 1] = (int64_t)e;
    }
    qsort(d->order, n, 2 * sizeof *d->order, cmp_id);
    d->whole.n = 0;
    TRY(store_resize(&d->whole, n));
    for (size_t e = 0; e < n; e++)
        unpack(&d->whole, e, d->rbuf + (size_t)d->order[2 * e + 1] * R);
    *whole = &d->whole;
    return SIM_OK;
}

#endif
