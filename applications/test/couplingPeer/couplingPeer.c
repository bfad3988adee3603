/*
 * couplingPeer — TEST TOOL, not a solver. Stands in for mpsFluid (-side
 * fluid) or demSolid (-side solid) to exercise the coupling channel with
 * synthetic data, in the tests (test/cases/coupling*.sh) and the benchmark
 * (test/bench/couplingBench).
 *
 * The solid side sends PROTO_DEM_STATE frames whose every value is a known
 * function of (step, grain, component, field); the fluid side checks them
 * and answers with PROTO_FLUID_STATE values computed from what it received;
 * the solid side checks the answer. After -frames steps the solid side
 * sends PROTO_CMD_STOP and both close. A wrong value, a lost or corrupted
 * frame is an error.
 *
 * On any error it does what a solver must: prints a FATAL ERROR block,
 * writes its last complete state (here a marker file
 * <case>/<time>/uniform/couplingPeer.<side> holding the last complete step)
 * and closes the channel with the error code, then exits 1.
 */
#include "coupling/channel.h"
#include "coupling/protocol.h"
#include "core/error.h"
#include "core/log.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define DT 1e-4 /* synthetic coupling step [s], names the time directories */

struct opts {
    const char *side, *case_dir, *channel, *units, *digest;
    long frames, grains, grow, work_us, dim, slots;
    double timeout, heartbeat, slot_bytes;
    int gradp, bench, verify, quiet, print_name, oneway;
};

struct arrays {
    size_t cap;
    double *pos, *vel, *rad, *drag;  /* DEM state */
    double *u, *eps, *gradp;         /* fluid state */
};

static double dem_value(uint64_t step, size_t i, int comp, int field)
{
    return (double)step + 1e-3 * (double)i + 0.1 * comp + 10.0 * field;
}

static void usage(void)
{
    puts("Usage: couplingPeer -side fluid|solid [options]   (test tool)\n"
         "  -case DIR        case directory (default .)\n"
         "  -channel NAME    segment name (default: from uid and case)\n"
         "  -frames N        coupling steps (default 100)\n"
         "  -grains N        grains in the first frame (default 1000)\n"
         "  -grow M          grains added each step (default 0)\n"
         "  -work US         microseconds of 'computation' per step\n"
         "  -timeout S  -heartbeat S  -slots N  -slotBytes B\n"
         "  -dim D  -units U  -digest TEXT   what the handshake compares\n"
         "  -gradP           send grad P (Model A)\n"
         "  -noverify        skip value checks (benchmark)\n"
         "  -bench           solid side prints round-trip statistics\n"
         "  -printName       print the channel name and exit\n"
         "  -oneway          solid streams DEM states, fluid never answers\n"
         "  -quiet");
}

static int parse(int argc, char **argv, struct opts *o)
{
    *o = (struct opts){ .side = NULL, .case_dir = ".", .channel = "",
                        .units = "SI", .digest = "", .frames = 100,
                        .grains = 1000, .dim = 3, .slots = 2,
                        .timeout = 10, .heartbeat = 0.1,
                        .slot_bytes = 65536, .verify = 1 };
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
#define STR(f, field) if (!strcmp(a, f) && v) { o->field = v; i++; continue; }
#define NUM(f, field) if (!strcmp(a, f) && v) { o->field = strtod(v, NULL); i++; continue; }
        STR("-side", side) STR("-case", case_dir) STR("-channel", channel)
        STR("-units", units) STR("-digest", digest)
        NUM("-frames", frames) NUM("-grains", grains) NUM("-grow", grow)
        NUM("-work", work_us) NUM("-dim", dim) NUM("-slots", slots)
        NUM("-timeout", timeout) NUM("-heartbeat", heartbeat)
        NUM("-slotBytes", slot_bytes)
#undef STR
#undef NUM
        if (!strcmp(a, "-gradP")) { o->gradp = 1; continue; }
        if (!strcmp(a, "-bench")) { o->bench = 1; continue; }
        if (!strcmp(a, "-noverify")) { o->verify = 0; continue; }
        if (!strcmp(a, "-quiet")) { o->quiet = 1; continue; }
        if (!strcmp(a, "-printName")) { o->print_name = 1; continue; }
        if (!strcmp(a, "-oneway")) { o->oneway = 1; continue; }
        if (!strcmp(a, "-help")) { usage(); exit(0); }
        fprintf(stderr, "couplingPeer: unknown option '%s'\n", a);
        usage();
        return -1;
    }
    if (!o->side || (strcmp(o->side, "fluid") && strcmp(o->side, "solid"))) {
        fprintf(stderr, "couplingPeer: -side fluid|solid is required\n");
        return -1;
    }
    return 0;
}

static int reserve(struct arrays *a, size_t n)
{
    if (n <= a->cap)
        return SIM_OK;
    double **v[] = { &a->pos, &a->vel, &a->rad, &a->drag, &a->u, &a->eps,
                     &a->gradp };
    int ncomp[] = { 3, 3, 1, 3, 3, 1, 3 };
    for (int k = 0; k < 7; k++) {
        double *p = sim_realloc(*v[k], n * ncomp[k] * sizeof(double));
        if (!p)
            return SIM_ERR_NOMEM;
        *v[k] = p;
    }
    a->cap = n;
    return SIM_OK;
}

static void work(long us)
{
    if (us > 0)
        nanosleep(&(struct timespec){ us / 1000000, (us % 1000000) * 1000 },
                  NULL);
}

/* The fluid's answer to grain i, from the DEM state it received. */
static void fluid_answer(const struct arrays *a, size_t i, double u[3],
                         double *eps, double g[3])
{
    for (int c = 0; c < 3; c++) {
        u[c] = 2.0 * a->pos[3 * i + c] + a->vel[3 * i + c];
        g[c] = -3.0 * a->drag[3 * i + c];
    }
    *eps = 1.0 - 0.5 * a->rad[i];
}

static int bad_value(const char *what, uint64_t step, size_t i, double got,
                     double want)
{
    return sim_error(SIM_ERR_PEER, "wrong %s of grain %zu at step %llu: %.17g"
                     " instead of %.17g", what, i, (unsigned long long)step,
                     got, want);
}

/* ---- solid side ----------------------------------------------------------- */

static int solid_step(struct channel *c, const struct opts *o,
                      struct arrays *a, uint64_t k, size_t n)
{
    struct channel_frame f;
    const void *payload;
    struct proto_fluid_state fs;

    /* with -noverify (benchmark) the data are made once per size, so that
     * the round trip times the channel and not the synthetic physics */
    int fill = o->verify || n > a->cap;
    TRY(reserve(a, n));
    for (size_t i = 0; fill && i < n; i++) {
        for (int cc = 0; cc < 3; cc++) {
            a->pos[3 * i + cc] = dem_value(k, i, cc, 0);
            a->vel[3 * i + cc] = dem_value(k, i, cc, 1);
            a->drag[3 * i + cc] = dem_value(k, i, cc, 3);
        }
        a->rad[i] = dem_value(k, i, 0, 2);
    }
    struct proto_dem_state ds = { n, a->pos, a->vel, a->rad, a->drag };
    TRY(proto_send_dem_state(c, k, k * DT, &ds));
    if (o->oneway)
        return SIM_OK;
    TRY(channel_recv(c, &f, &payload));
    TRY(proto_view_fluid_state(&f, payload, &fs));
    if (fs.n != n || f.step != k)
        return sim_error(SIM_ERR_PEER, "answer for step %llu with %zu grains"
                         " instead of step %llu with %zu",
                         (unsigned long long)f.step, fs.n,
                         (unsigned long long)k, n);
    if (!!fs.grad_p != o->gradp)
        return sim_error(SIM_ERR_PEER, "gradP %s in the fluid answer",
                         o->gradp ? "missing" : "unexpected");
    memcpy(a->u, fs.velocity, 3 * n * sizeof(double));
    memcpy(a->eps, fs.porosity, n * sizeof(double));
    if (fs.grad_p)
        memcpy(a->gradp, fs.grad_p, 3 * n * sizeof(double));
    TRY(channel_recv_done(c));
    for (size_t i = 0; o->verify && i < n; i++) {
        double u[3], eps, g[3];
        fluid_answer(a, i, u, &eps, g);
        for (int cc = 0; cc < 3; cc++) {
            if (a->u[3 * i + cc] != u[cc])
                return bad_value("fluid velocity", k, i, a->u[3 * i + cc],
                                 u[cc]);
            if (o->gradp && a->gradp[3 * i + cc] != g[cc])
                return bad_value("gradP", k, i, a->gradp[3 * i + cc], g[cc]);
        }
        if (a->eps[i] != eps)
            return bad_value("porosity", k, i, a->eps[i], eps);
    }
    return SIM_OK;
}

static int cmp_u64(const void *x, const void *y)
{
    uint64_t a = *(const uint64_t *)x, b = *(const uint64_t *)y;
    return (a > b) - (a < b);
}

static void print_bench(const struct opts *o, uint64_t *rt, long nrt,
                        size_t n)
{
    size_t b1, b2;
    proto_layout(PROTO_DEM_STATE, 0, n, NULL, &b1);
    proto_layout(PROTO_FLUID_STATE, o->gradp ? PROTO_HAS_GRADP : 0, n, NULL,
                 &b2);
    qsort(rt, (size_t)nrt, sizeof *rt, cmp_u64);
    double med = rt[nrt / 2] * 1e-3, p10 = rt[nrt / 10] * 1e-3,
           p90 = rt[nrt * 9 / 10] * 1e-3;
    printf("BENCH grains %zu bytesPerRoundTrip %zu frames %ld "
           "median_us %.2f p10_us %.2f p90_us %.2f GBps %.2f\n", n, b1 + b2,
           nrt, med, p10, p90, (double)(b1 + b2) / (med * 1e-6) * 1e-9);
}

static int run_solid(struct channel *c, const struct opts *o,
                     struct arrays *a, uint64_t *done)
{
    uint64_t *rt = o->bench ? sim_calloc((size_t)o->frames, 8) : NULL;
    struct timespec t0, t1;

    if (o->bench && !rt)
        return SIM_ERR_NOMEM;
    for (uint64_t k = 1; k <= (uint64_t)o->frames; k++) {
        size_t n = (size_t)(o->grains + o->grow * (long)(k - 1));
        clock_gettime(CLOCK_MONOTONIC, &t0);
        int rc = solid_step(c, o, a, k, n);
        if (rc) {
            free(rt);
            return rc;
        }
        clock_gettime(CLOCK_MONOTONIC, &t1);
        if (rt)
            rt[k - 1] = (uint64_t)((t1.tv_sec - t0.tv_sec) * 1000000000LL +
                                   (t1.tv_nsec - t0.tv_nsec));
        *done = k;
        work(o->work_us);
    }
    if (rt) {
        print_bench(o, rt, o->frames, (size_t)o->grains);
        free(rt);
    }
    return proto_send_control(c, *done, *done * DT, PROTO_CMD_STOP, 0.0);
}

/* ---- fluid side ----------------------------------------------------------- */

static int fluid_step(struct channel *c, const struct opts *o,
                      struct arrays *a, const struct channel_frame *f,
                      const void *payload)
{
    struct proto_dem_state ds;

    TRY(proto_view_dem_state(f, payload, &ds));
    size_t n = ds.n;
    TRY(reserve(a, n));
    memcpy(a->pos, ds.position, 3 * n * sizeof(double));
    memcpy(a->vel, ds.velocity, 3 * n * sizeof(double));
    memcpy(a->rad, ds.radius, n * sizeof(double));
    memcpy(a->drag, ds.drag, 3 * n * sizeof(double));
    TRY(channel_recv_done(c));
    for (size_t i = 0; o->verify && i < n; i++) {
        for (int cc = 0; cc < 3; cc++) {
            if (a->pos[3 * i + cc] != dem_value(f->step, i, cc, 0))
                return bad_value("position", f->step, i, a->pos[3 * i + cc],
                                 dem_value(f->step, i, cc, 0));
            if (a->drag[3 * i + cc] != dem_value(f->step, i, cc, 3))
                return bad_value("drag", f->step, i, a->drag[3 * i + cc],
                                 dem_value(f->step, i, cc, 3));
        }
    }
    for (size_t i = 0; o->verify && i < n; i++)
        fluid_answer(a, i, &a->u[3 * i], &a->eps[i], &a->gradp[3 * i]);
    work(o->work_us);
    if (o->oneway)
        return SIM_OK;
    struct proto_fluid_state fs = { n, a->u, a->eps,
                                    o->gradp ? a->gradp : NULL };
    return proto_send_fluid_state(c, f->step, f->time, &fs);
}

static int run_fluid(struct channel *c, const struct opts *o,
                     struct arrays *a, uint64_t *done)
{
    for (;;) {
        struct channel_frame f;
        const void *payload;
        int cmd;
        double value;

        TRY(channel_recv(c, &f, &payload));
        if (f.kind == PROTO_CONTROL) {
            TRY(proto_view_control(&f, payload, &cmd, &value));
            TRY(channel_recv_done(c));
            if (cmd == PROTO_CMD_STOP)
                return SIM_OK;
            continue;
        }
        if (f.step != *done + 1)
            return sim_error(SIM_ERR_PEER, "frame of step %llu after step "
                             "%llu: a frame was lost",
                             (unsigned long long)f.step,
                             (unsigned long long)*done);
        TRY(fluid_step(c, o, a, &f, payload));
        *done = f.step;
    }
}

/* ---- the solver's pattern on failure -------------------------------------- */

static void write_last_state(const char *case_dir, const char *side,
                             uint64_t step)
{
    char dir[4096], path[4200];
    snprintf(dir, sizeof dir, "%s/%g", case_dir, step * DT);
    mkdir(dir, 0755);
    snprintf(dir + strlen(dir), sizeof dir - strlen(dir), "/uniform");
    mkdir(dir, 0755);
    snprintf(path, sizeof path, "%s/couplingPeer.%s", dir, side);
    FILE *f = fopen(path, "w");
    if (f) {
        fprintf(f, "lastCompleteStep %llu;\ntime %g;\n",
                (unsigned long long)step, step * DT);
        fclose(f);
    }
    printf("Wrote last complete state (step %llu) to %s\n",
           (unsigned long long)step, dir);
}

static void fatal(int rc)
{
    const char *m = sim_error_message(), *t = sim_error_trace();
    printf("\n--> FATAL ERROR (%s)\n%s\n%s", sim_strerror(rc), m, t);
    fprintf(stderr, "\n--> FATAL ERROR (%s)\n%s\n%s", sim_strerror(rc), m, t);
    fflush(stdout);
}

int main(int argc, char **argv)
{
    struct opts o;
    struct channel_settings s;
    struct channel *c = NULL;
    struct arrays a = { 0 };
    uint64_t done = 0;
    int rc, solid;

    if (parse(argc, argv, &o))
        return 1;
    solid = !strcmp(o.side, "solid");
    setvbuf(stdout, NULL, _IOLBF, 0);
    TRY_GOTO(rc, channel_signals_install(), out);
    TRY_GOTO(rc, channel_settings_default(&s, solid, solid ? "demSolid"
                                          : "mpsFluid", o.case_dir), out);
    snprintf(s.name, sizeof s.name, "%s", o.channel);
    s.timeout = o.timeout;
    s.heartbeat_interval = o.heartbeat;
    s.nslots = (int)o.slots;
    s.slot_bytes = (size_t)o.slot_bytes;
    s.dimension = (int)o.dim;
    snprintf(s.units, sizeof s.units, "%s", o.units);
    s.digest = channel_checksum(o.digest, strlen(o.digest), 0);
    s.quiet = o.quiet;
    if (o.print_name) {
        if (!s.name[0])
            TRY_GOTO(rc, channel_default_name(s.case_path, s.name,
                                              sizeof s.name), out);
        puts(s.name);
        return 0;
    }
    printf("couplingPeer (test tool) side %s pid %d\n", o.side, (int)getpid());
    TRY_GOTO(rc, channel_open(&s, &c), out);
    rc = solid ? run_solid(c, &o, &a, &done) : run_fluid(c, &o, &a, &done);
out:
    if (rc != SIM_OK) {
        fatal(rc);
        write_last_state(o.case_dir, o.side, done);
    }
    int rc2 = channel_close(c, rc);
    if (rc == SIM_OK && rc2 != SIM_OK)
        fatal(rc = rc2);
    free(a.pos), free(a.vel), free(a.rad), free(a.drag);
    free(a.u), free(a.eps), free(a.gradp);
    if (rc == SIM_OK)
        printf("End: %llu coupling steps checked\n", (unsigned long long)done);
    return rc == SIM_OK ? 0 : 1;
}
