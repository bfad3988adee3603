/*
 * test_channel.c — the coupling channel in normal operation, with two real
 * processes: checksum against a simple version, default names, message
 * layouts, data integrity over many frames, both start orders, capacity
 * growth from 1 to 10^6 grains, control messages, and an orderly close
 * that still delivers the frames in flight. Faults: test_channel_faults.c.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "chantest.h"
#include "coupling/protocol.h"

/* The checksum as channel.h defines it, one word at a time. */
static uint64_t rotl(uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }
static uint64_t checksum_ref(const unsigned char *b, size_t n, uint64_t seed)
{
    const uint64_t P1 = 0x9E3779B185EBCA87ULL, P2 = 0xC2B2AE3D27D4EB4FULL,
                   P3 = 0x165667B19E3779F9ULL;
    uint64_t h[4] = { seed + P1 + P2, seed + P2, seed, seed - P1 };
    for (size_t k = 0; 8 * k < n; k++) {
        uint64_t w = 0;
        for (size_t j = 0; j < 8 && 8 * k + j < n; j++)
            w |= (uint64_t)b[8 * k + j] << (8 * j);
        h[k % 4] = rotl(h[k % 4] + w * P2, 31) * P1;
    }
    uint64_t x = rotl(h[0], 1) + rotl(h[1], 7) + rotl(h[2], 12) +
                 rotl(h[3], 18);
    x ^= n;
    x ^= x >> 33;
    x *= P2;
    x ^= x >> 29;
    x *= P3;
    x ^= x >> 32;
    return x;
}

static void test_checksum_matches_reference(void **state)
{
    unsigned char buf[300];
    (void)state;
    srand(7);
    for (size_t i = 0; i < sizeof buf; i++)
        buf[i] = (unsigned char)rand();
    for (size_t n = 0; n <= 257; n++)
        for (uint64_t seed = 0; seed < 3; seed++)
            assert_true(channel_checksum(buf + (n % 5), n, seed) ==
                        checksum_ref(buf + (n % 5), n, seed));
    /* every single-bit flip of a 64-byte block changes the sum */
    uint64_t base = channel_checksum(buf, 64, 0);
    for (int bit = 0; bit < 512; bit++) {
        buf[bit / 8] ^= (unsigned char)(1u << (bit % 8));
        assert_true(channel_checksum(buf, 64, 0) != base);
        buf[bit / 8] ^= (unsigned char)(1u << (bit % 8));
    }
}

static void test_default_name(void **state)
{
    char a[CHANNEL_NAME_MAX], b[CHANNEL_NAME_MAX], c[CHANNEL_NAME_MAX],
        uid[32];
    (void)state;
    assert_int_equal(channel_default_name("/home/u/caseA", a, sizeof a), 0);
    assert_int_equal(channel_default_name("/home/u/caseA", b, sizeof b), 0);
    assert_int_equal(channel_default_name("/home/u/caseB", c, sizeof c), 0);
    assert_string_equal(a, b);
    assert_string_not_equal(a, c);
    snprintf(uid, sizeof uid, "-%u-", (unsigned)getuid());
    assert_non_null(strstr(a, uid));
    assert_true(a[0] == '/' && !strchr(a + 1, '/'));
    struct channel_settings s;
    assert_int_equal(channel_settings_default(&s, CHANNEL_FLUID, "x", "."),
                     0);
    assert_true(s.case_path[0] == '/');
    assert_int_equal(channel_settings_default(&s, 5, "x", "."),
                     SIM_ERR_INPUT);
    assert_int_equal(channel_settings_default(&s, 0, "x", "/nonexistent/q"),
                     SIM_ERR_IO);
}

static void test_protocol_layout(void **state)
{
    size_t off[PROTO_MAX_FIELDS], bytes;
    (void)state;
    assert_int_equal(proto_layout(PROTO_DEM_STATE, 0, 5, off, &bytes), 4);
    /* 5 grains: 120 B vectors -> 128, 40 B radius -> 64 */
    assert_int_equal(off[0], 0);
    assert_int_equal(off[1], 128);
    assert_int_equal(off[2], 256);
    assert_int_equal(off[3], 320);
    assert_int_equal(bytes, 448);
    assert_int_equal(proto_layout(PROTO_FLUID_STATE, 0, 5, off, &bytes), 2);
    assert_int_equal(bytes, 192);
    assert_int_equal(proto_layout(PROTO_FLUID_STATE, PROTO_HAS_GRADP, 5, off,
                                  &bytes), 3);
    assert_int_equal(bytes, 320);
    assert_int_equal(proto_layout(PROTO_CONTROL, 0, 1, off, &bytes), 2);
    assert_int_equal(proto_layout(99, 0, 1, off, &bytes), -1);
    int nc;
    assert_string_equal(proto_field_name(PROTO_DEM_STATE, 3, &nc), "drag");
    assert_int_equal(nc, 3);
}

/* ---- a peer that sends numbered frames of varying size ------------------ */

struct stream {
    const char *name;
    long frames;
    int side;
    double delay;        /* before opening [s]                 */
    size_t (*size)(long k);
};

static size_t size_varied(long k) { return (size_t)((k * 7919) % 4000); }
/* bytes of DEM state frames (80 B per grain) of 1 ... 10^6 grains, the
 * ring growing from its 4 KiB start, then shrinking frames, then large
 * again (no regrowth needed) */
static size_t size_growing(long k)
{
    static const size_t grains[] = { 1, 10, 1000, 100000, 1000000, 10,
                                     1000000 };
    return 80 * grains[k % 7];
}

static unsigned char byte_of(long k, size_t i)
{
    return (unsigned char)(k * 31 + i * 7 + (i >> 8));
}

static int send_stream(void *arg)
{
    struct stream *st = arg;
    struct channel_settings s;
    struct channel *c;
    test_settings(&s, st->side, st->name);
    sleep_s(st->delay);
    if (channel_open(&s, &c))
        return 2;
    for (long k = 0; k < st->frames; k++) {
        size_t n = st->size(k);
        unsigned char *p;
        if (channel_send_begin(c, 7, 0, (uint64_t)k, 0.5 * k, n, n,
                               (void **)&p))
            return 3;
        for (size_t i = 0; i < n; i++)
            p[i] = byte_of(k, i);
        if (channel_send_commit(c))
            return 4;
    }
    return channel_close(c, SIM_OK) ? 5 : 0;
}

/* Receive st->frames frames and check every byte. */
static void receive_stream(struct stream *st, double delay)
{
    struct channel_settings s;
    struct channel *c;
    test_settings(&s, 1 - st->side, st->name);
    sleep_s(delay);
    assert_int_equal(channel_open(&s, &c), SIM_OK);
    for (long k = 0; k < st->frames; k++) {
        struct channel_frame f;
        const unsigned char *p;
        int rc = channel_recv(c, &f, (const void **)&p);
        if (rc)
            fail_msg("frame %ld: %s", k, sim_error_message());
        assert_int_equal(f.step, k);
        assert_int_equal(f.bytes, st->size(k));
        assert_true(f.time == 0.5 * k);
        size_t bad = 0;
        for (size_t i = 0; i < f.bytes; i++)
            bad += p[i] != byte_of(k, i);
        assert_int_equal(bad, 0);
        assert_int_equal(channel_recv_done(c), SIM_OK);
    }
    assert_int_equal(channel_close(c, SIM_OK), SIM_OK);
}

static void run_stream(size_t (*size)(long), long frames, int sender_side,
                       double sender_delay, double receiver_delay)
{
    char name[64];
    unique_name(name, sizeof name);
    struct stream st = { name, frames, sender_side, sender_delay, size };
    pid_t pid = spawn(send_stream, &st);
    receive_stream(&st, receiver_delay);
    assert_int_equal(reap(pid), 0);
    assert_false(segment_exists(name));
}

static void test_integrity_many_frames(void **state)
{
    (void)state;
    run_stream(size_varied, 20000, CHANNEL_SOLID, 0.0, 0.0);
}

static void test_start_order_receiver_first(void **state)
{
    (void)state;
    run_stream(size_varied, 50, CHANNEL_SOLID, 0.2, 0.0);
}

static void test_start_order_sender_first(void **state)
{
    (void)state;
    run_stream(size_varied, 50, CHANNEL_FLUID, 0.0, 0.2);
}

static void test_growth_1_to_1e6_grains(void **state)
{
    (void)state;
    run_stream(size_growing, 7, CHANNEL_SOLID, 0.0, 0.0);
}

/* ---- protocol messages through a channel ---------------------------------- */

struct dem_peer { const char *name; size_t n; };

static void dem_arrays(size_t n, double *pos, double *vel, double *rad,
                       double *drag)
{
    for (size_t i = 0; i < 3 * n; i++) {
        pos[i] = 0.001 * i;
        vel[i] = -0.5 * i;
        drag[i] = 1e-3 * i + 2;
    }
    for (size_t i = 0; i < n; i++)
        rad[i] = 0.00135 + 1e-9 * i;
}

/* A peer that fills or checks 1e6 grains' arrays (80 MB) may be silent
 * for seconds on a loaded machine: the 5 s of chantest.h then measure the
 * load, not the channel (a timeout seen at load 11). */
static double big_timeout(size_t n)
{
    return n > 1000 ? 60.0 : 5.0;
}

static int dem_side(void *arg)
{
    struct dem_peer *dp = arg;
    struct channel_settings s;
    struct channel *c;
    size_t n = dp->n;
    double *buf = malloc(10 * n * sizeof(double));
    struct channel_frame f;
    const void *p;
    struct proto_fluid_state fs;
    int cmd;
    double v;

    test_settings(&s, CHANNEL_SOLID, dp->name);
    s.timeout = big_timeout(n);
    if (!buf || channel_open(&s, &c))
        return 2;
    dem_arrays(n, buf, buf + 3 * n, buf + 6 * n, buf + 7 * n);
    struct proto_dem_state ds = { n, buf, buf + 3 * n, buf + 6 * n,
                                  buf + 7 * n };
    if (proto_send_dem_state(c, 3, 3e-4, &ds))
        return 3;
    if (channel_recv(c, &f, &p) || proto_view_fluid_state(&f, p, &fs))
        return 4;
    if (fs.n != n || !fs.grad_p || fs.velocity[3 * n - 1] != 1.5 * (3 * n - 1)
        || fs.porosity[n - 1] != 0.4 || fs.grad_p[0] != -9810.0)
        return 5;
    channel_recv_done(c);
    if (channel_recv(c, &f, &p) || proto_view_control(&f, p, &cmd, &v) ||
        cmd != PROTO_CMD_SET_DT || v != 2e-4)
        return 6;
    channel_recv_done(c);
    free(buf);
    return channel_close(c, SIM_OK) ? 7 : 0;
}

static void exchange_messages(size_t n)
{
    char name[64];
    unique_name(name, sizeof name);
    struct dem_peer dp = { name, n };
    pid_t pid = spawn(dem_side, &dp);
    struct channel_settings s;
    struct channel *c;
    struct channel_frame f;
    const void *p;
    struct proto_dem_state ds;

    test_settings(&s, CHANNEL_FLUID, name);
    s.timeout = big_timeout(n);
    assert_int_equal(channel_open(&s, &c), SIM_OK);
    assert_int_equal(channel_recv(c, &f, &p), SIM_OK);
    /* a view of the wrong kind is refused */
    struct proto_fluid_state wrong;
    assert_int_equal(proto_view_fluid_state(&f, p, &wrong), SIM_ERR_PEER);
    assert_non_null(strstr(sim_error_message(), "expected a fluid state"));
    assert_int_equal(proto_view_dem_state(&f, p, &ds), SIM_OK);
    assert_int_equal(f.step, 3);
    assert_int_equal(ds.n, n);
    double *ref = malloc(10 * n * sizeof(double));
    dem_arrays(n, ref, ref + 3 * n, ref + 6 * n, ref + 7 * n);
    assert_memory_equal(ds.position, ref, 3 * n * sizeof(double));
    assert_memory_equal(ds.velocity, ref + 3 * n, 3 * n * sizeof(double));
    assert_memory_equal(ds.radius, ref + 6 * n, n * sizeof(double));
    assert_memory_equal(ds.drag, ref + 7 * n, 3 * n * sizeof(double));
    assert_int_equal(channel_recv_done(c), SIM_OK);
    double *u = ref, *eps = ref + 3 * n, *g = ref + 4 * n;
    for (size_t i = 0; i < 3 * n; i++) {
        u[i] = 1.5 * i;
        g[i] = -9810.0;
    }
    for (size_t i = 0; i < n; i++)
        eps[i] = 0.4;
    struct proto_fluid_state fs = { n, u, eps, g };
    assert_int_equal(proto_send_fluid_state(c, 3, 3e-4, &fs), SIM_OK);
    assert_int_equal(proto_send_control(c, 3, 3e-4, PROTO_CMD_SET_DT, 2e-4),
                     SIM_OK);
    free(ref);
    assert_int_equal(reap(pid), 0);
    assert_int_equal(channel_close(c, SIM_OK), SIM_OK);
    assert_false(segment_exists(name));
}

static void test_messages_one_grain(void **state)
{
    (void)state;
    exchange_messages(1);
}

static void test_messages_1e6_grains(void **state)
{
    (void)state;
    exchange_messages(1000000);
}

/* ---- orderly close with frames in flight ----------------------------------- */

static int send_two_and_close(void *arg)
{
    struct channel_settings s;
    struct channel *c;
    double x = 42.0;
    test_settings(&s, CHANNEL_SOLID, arg);
    if (channel_open(&s, &c)) {
        fprintf(stderr, "child: %s\n", sim_error_message());
        return 2;
    }
    for (int k = 0; k < 2; k++) {
        struct channel_frame f = { .kind = 1, .step = (uint64_t)k,
                                   .bytes = sizeof x };
        if (channel_send(c, &f, &x))
            return 3;
    }
    return channel_close(c, SIM_OK) ? 4 : 0;
}

static void test_close_delivers_frames_in_flight(void **state)
{
    char name[64];
    struct channel_settings s;
    struct channel *c;
    struct channel_frame f;
    const void *p;
    (void)state;

    unique_name(name, sizeof name);
    pid_t pid = spawn(send_two_and_close, name);
    test_settings(&s, CHANNEL_FLUID, name);
    assert_int_equal(channel_open(&s, &c), SIM_OK);
    assert_int_equal(reap(pid), 0); /* the peer has left */
    for (int k = 0; k < 2; k++) {
        assert_int_equal(channel_recv(c, &f, &p), SIM_OK);
        assert_int_equal(f.step, k);
        assert_true(*(const double *)p == 42.0);
        assert_int_equal(channel_recv_done(c), SIM_OK);
    }
    /* sending to a peer that left is an error, not a silent loss */
    double y = 1.0;
    struct channel_frame g = { .kind = 1, .bytes = sizeof y };
    assert_int_equal(channel_send(c, &g, &y), SIM_ERR_PEER);
    assert_non_null(strstr(sim_error_message(), "closed the channel"));
    double t0 = now_s();
    assert_int_equal(channel_recv(c, &f, &p), SIM_ERR_PEER);
    assert_true(now_s() - t0 < 2.0);
    assert_non_null(strstr(sim_error_message(), "closed the channel"));
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
    assert_false(segment_exists(name));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_checksum_matches_reference),
        cmocka_unit_test(test_default_name),
        cmocka_unit_test(test_protocol_layout),
        cmocka_unit_test(test_integrity_many_frames),
        cmocka_unit_test(test_start_order_receiver_first),
        cmocka_unit_test(test_start_order_sender_first),
        cmocka_unit_test(test_growth_1_to_1e6_grains),
        cmocka_unit_test(test_messages_one_grain),
        cmocka_unit_test(test_messages_1e6_grains),
        cmocka_unit_test(test_close_delivers_frames_in_flight),
    };
    log_set_quiet(1);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
