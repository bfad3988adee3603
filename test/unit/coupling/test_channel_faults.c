/*
 * test_channel_faults.c — the channel when things go wrong, with two real
 * processes: handshake mismatches, no peer (time-out), a signal during a
 * wait, a stale segment, a second pair, a peer killed or stopped at
 * several moments, a peer that exits without closing, a corrupted frame,
 * and a foreign file under the channel's name. Every case must end with a
 * distinct code, a message naming the cause, in bounded time, and no
 * segment left in /dev/shm.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "chantest.h"
#include "coupling/channel_impl.h"

#include <fcntl.h>
#include <sys/stat.h>

/* ---- handshake mismatch --------------------------------------------------- */

struct variant { const char *name; int what; };

static void alter(struct channel_settings *s, int what)
{
    switch (what) {
    case 0: s->dimension = 2; break;
    case 1: strcpy(s->units, "cgs"); break;
    case 2: s->digest = 12345; break;
    case 3: strcpy(s->case_path, "/tmp/otherCase"); break;
    case 4: s->end_time = 2.5; break;
    }
}

static int mismatched_peer(void *arg)
{
    struct variant *v = arg;
    struct channel_settings s;
    struct channel *c;
    test_settings(&s, CHANNEL_SOLID, v->name);
    alter(&s, v->what);
    int rc = channel_open(&s, &c);
    return rc == SIM_ERR_PEER && strstr(sim_error_message(), "differs")
               ? 0 : 10 + rc;
}

static void test_handshake_mismatch(void **state)
{
    static const char *const what[] = { "dimension differs",
                                        "units differs",
                                        "coupling settings",
                                        "case path differs",
                                        "endTime" };
    (void)state;
    for (int w = 0; w < 5; w++) {
        char name[64];
        struct channel_settings s;
        struct channel *c = NULL;
        unique_name(name, sizeof name);
        struct variant v = { name, w };
        pid_t pid = spawn(mismatched_peer, &v);
        test_settings(&s, CHANNEL_FLUID, name);
        assert_int_equal(channel_open(&s, &c), SIM_ERR_PEER);
        assert_null(c);
        assert_non_null(strstr(sim_error_message(), what[w]));
        assert_non_null(strstr(sim_error_message(), "testSolid (pid"));
        assert_int_equal(reap(pid), 0);
        assert_false(segment_exists(name));
    }
}

/* ---- no peer, signals ------------------------------------------------------ */

static void test_timeout_without_peer(void **state)
{
    char name[64];
    struct channel_settings s;
    struct channel *c;
    (void)state;
    unique_name(name, sizeof name);
    test_settings(&s, CHANNEL_FLUID, name);
    s.timeout = 0.3;
    double t0 = now_s();
    assert_int_equal(channel_open(&s, &c), SIM_ERR_TIMEOUT);
    double dt = now_s() - t0;
    assert_true(dt >= 0.29 && dt < 1.5);
    assert_non_null(strstr(sim_error_message(), "within 0.3 s"));
    assert_false(segment_exists(name));
}

static int interrupt_parent(void *arg)
{
    (void)arg;
    sleep_s(0.2);
    kill(getppid(), SIGINT);
    return 0;
}

static void test_signal_ends_wait(void **state)
{
    char name[64];
    struct channel_settings s;
    struct channel *c;
    (void)state;
    assert_int_equal(channel_signals_install(), SIM_OK);
    unique_name(name, sizeof name);
    test_settings(&s, CHANNEL_SOLID, name);
    double t0 = now_s();
    pid_t pid = spawn(interrupt_parent, NULL);
    assert_int_equal(channel_open(&s, &c), SIM_ERR_INTERRUPT);
    double dt = now_s() - t0;
    assert_true(dt >= 0.19 && dt < 1.5);
    assert_non_null(strstr(sim_error_message(), "signal INT"));
    assert_int_equal(channel_interrupted(), SIGINT);
    channel_interrupt_clear();
    signal(SIGINT, SIG_DFL);
    assert_int_equal(reap(pid), 0);
    assert_false(segment_exists(name));
}

/* A program that never checks for signals: the first SIGTERM is only
 * recorded; a second one, a second later, unlinks the segment name and
 * terminates it. */
static int deaf_peer(void *arg)
{
    struct channel_settings s;
    struct channel *c;
    channel_signals_install();
    test_settings(&s, CHANNEL_SOLID, arg);
    if (channel_open(&s, &c))
        return 2;
    double x = 1.0;
    struct channel_frame f = { .kind = 1, .bytes = sizeof x };
    if (channel_send(c, &f, &x))   /* tells the parent we are past open */
        return 3;
    for (;;)
        sleep_s(0.05);
}

static void test_second_signal_unlinks_and_kills(void **state)
{
    char name[64];
    struct channel_settings s;
    struct channel *c;
    struct channel_frame f;
    const void *data;
    (void)state;
    unique_name(name, sizeof name);
    pid_t pid = spawn(deaf_peer, name);
    test_settings(&s, CHANNEL_FLUID, name);
    assert_int_equal(channel_open(&s, &c), SIM_OK);
    assert_int_equal(channel_recv(c, &f, &data), SIM_OK);
    assert_int_equal(channel_recv_done(c), SIM_OK);
    kill(pid, SIGTERM);
    sleep_s(1.2);
    assert_int_equal(waitpid(pid, NULL, WNOHANG), 0);  /* still running */
    assert_true(segment_exists(name));
    kill(pid, SIGTERM);
    assert_int_equal(reap(pid), 128 + SIGTERM);
    assert_false(segment_exists(name));                /* it unlinked it */
    assert_int_equal(channel_recv(c, &f, &data), SIM_ERR_PEER);
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
}

/* ---- peers for the cases below -------------------------------------------- */

struct peer { const char *name; int side; double sleep; int action; };
enum { OPEN_THEN_KILL, OPEN_THEN_STOP, OPEN_THEN_EXIT, OPEN_SEND_WAIT,
       OPEN_THEN_CLOSE, OPEN_COMPUTE_SILENT, OPEN_SUSPEND_OTHER };

static int peer_main(void *arg)
{
    struct peer *p = arg;
    struct channel_settings s;
    struct channel *c;
    struct channel_frame f = { .kind = 1, .bytes = 8 };
    const void *data;
    double x = 1.0;

    test_settings(&s, p->side, p->name);
    s.timeout = 3.0;
    if (channel_open(&s, &c))
        return 2;
    switch (p->action) {
    case OPEN_THEN_KILL:
        sleep_s(p->sleep);
        raise(SIGKILL);
        break;
    case OPEN_THEN_STOP:
        raise(SIGSTOP);
        break;
    case OPEN_THEN_EXIT:          /* as app_fatal: exit() without close */
        sleep_s(p->sleep);
        exit(3);
    case OPEN_SEND_WAIT:
        if (channel_send(c, &f, &x))
            return 4;
        /* wait for the other side to give up on the frame */
        return channel_recv(c, &f, &data) == SIM_ERR_PEER &&
               channel_close(c, SIM_ERR_PEER) == SIM_OK ? 0 : 5;
    case OPEN_THEN_CLOSE:
        sleep_s(p->sleep);
        break;
    case OPEN_SUSPEND_OTHER:
        /* stop the other program (waiting for our frame) for longer than
         * its time-out, continue it, then send: Ctrl-Z and fg */
        sleep_s(0.2);             /* the other is waiting by then */
        kill(getppid(), SIGSTOP);
        sleep_s(p->sleep);
        kill(getppid(), SIGCONT);
        sleep_s(0.1);             /* it looks again before the frame */
        if (channel_send(c, &f, &x))
            return 4;
        return channel_recv(c, &f, &data) == SIM_ERR_PEER &&
               channel_close(c, SIM_ERR_PEER) == SIM_OK ? 0 : 5;
    case OPEN_COMPUTE_SILENT: {
        /* a starved program: no heartbeat (as when the scheduler gives a
         * niced run no CPU for seconds), but running, then it sends */
        chan_heartbeat_stop(c);
        double t0 = now_s();
        volatile double acc = 0;
        while (now_s() - t0 < p->sleep)
            acc += 1e-9;
        if (channel_send(c, &f, &x))
            return 4;
        return channel_recv(c, &f, &data) == SIM_ERR_PEER &&
               channel_close(c, SIM_ERR_PEER) == SIM_OK ? 0 : 5;
    }
    }
    return channel_close(c, SIM_OK) ? 6 : 0;
}

static struct channel *open_with(struct peer *p, pid_t *pid)
{
    struct channel_settings s;
    struct channel *c;
    *pid = spawn(peer_main, p);
    test_settings(&s, 1 - p->side, p->name);
    assert_int_equal(channel_open(&s, &c), SIM_OK);
    return c;
}

/* ---- a peer that dies or hangs ----------------------------------------- */

static void test_peer_killed_while_receiving(void **state)
{
    char name[64];
    struct channel_frame f;
    const void *data;
    pid_t pid;
    (void)state;
    unique_name(name, sizeof name);
    struct peer p = { name, CHANNEL_SOLID, 0.3, OPEN_THEN_KILL };
    struct channel *c = open_with(&p, &pid);
    /* not reaped: the dead peer stays a zombie, which kill(pid, 0) misses */
    double t0 = now_s();
    assert_int_equal(channel_recv(c, &f, &data), SIM_ERR_PEER);
    double dt = now_s() - t0;
    assert_true(dt < 0.3 + 2.0);
    assert_non_null(strstr(sim_error_message(), "died without closing"));
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
    assert_int_equal(reap(pid), 128 + SIGKILL);
    assert_false(segment_exists(name));
}

static void test_peer_killed_while_sending(void **state)
{
    char name[64];
    pid_t pid;
    double x[64] = { 0 };
    struct channel_frame f = { .kind = 1, .bytes = sizeof x };
    int rc = SIM_OK, k;
    (void)state;
    unique_name(name, sizeof name);
    struct peer p = { name, CHANNEL_SOLID, 0.3, OPEN_THEN_KILL };
    struct channel *c = open_with(&p, &pid);
    double t0 = now_s();
    for (k = 0; k < 10 && rc == SIM_OK; k++)  /* 2 slots: the 3rd blocks */
        rc = channel_send(c, &f, x);
    assert_int_equal(rc, SIM_ERR_PEER);
    assert_int_equal(k, 3);
    assert_true(now_s() - t0 < 0.3 + 2.0);
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
    assert_int_equal(reap(pid), 128 + SIGKILL);
    assert_false(segment_exists(name));
}

static void test_peer_stopped_is_hung(void **state)
{
    char name[64];
    struct channel_frame f;
    const void *data;
    pid_t pid;
    (void)state;
    unique_name(name, sizeof name);
    struct peer p = { name, CHANNEL_SOLID, 0, OPEN_THEN_STOP };
    struct channel *c = open_with(&p, &pid);
    double t0 = now_s();
    assert_int_equal(channel_recv(c, &f, &data), SIM_ERR_PEER);
    double dt = now_s() - t0;
    /* CHANNEL_HUNG_HEARTBEATS x 0.05 s = 1 s of silence; the time-out (5 s)
     * must not be what ends the wait */
    assert_true(dt > 0.8 && dt < 4.0);
    assert_non_null(strstr(sim_error_message(), "no heartbeat"));
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
    kill(pid, SIGKILL);
    assert_int_equal(reap(pid), 128 + SIGKILL);
    assert_false(segment_exists(name));
}

/* Silent but running (state R, CPU time growing) is starved, not hung: the
 * wait goes on past three heartbeat silences and takes the frame. */
static void test_peer_starved_not_hung(void **state)
{
    char name[64];
    struct channel_frame f;
    const void *data;
    pid_t pid;
    (void)state;
    unique_name(name, sizeof name);
    struct peer p = { name, CHANNEL_SOLID, 3.0, OPEN_COMPUTE_SILENT };
    struct channel *c = open_with(&p, &pid);
    double t0 = now_s();
    assert_int_equal(channel_recv(c, &f, &data), SIM_OK);
    assert_true(now_s() - t0 > 2.5);
    assert_int_equal(channel_recv_done(c), SIM_OK);
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
    assert_int_equal(reap(pid), 0);
}

/* A wait stopped (SIGSTOP, as Ctrl-Z) for longer than its time-out goes
 * on when continued: the stopped time is not waiting time. */
static void test_suspended_wait_goes_on(void **state)
{
    char name[64];
    struct channel_settings s;
    struct channel_frame f;
    struct channel *c;
    const void *data;
    pid_t pid;
    (void)state;
    unique_name(name, sizeof name);
    struct peer p = { name, CHANNEL_SOLID, 1.5, OPEN_SUSPEND_OTHER };
    pid = spawn(peer_main, &p);
    test_settings(&s, CHANNEL_FLUID, name);
    s.timeout = 0.5;
    assert_int_equal(channel_open(&s, &c), SIM_OK);
    double t0 = now_s();
    assert_int_equal(channel_recv(c, &f, &data), SIM_OK);
    assert_true(now_s() - t0 > 1.5);
    assert_int_equal(channel_recv_done(c), SIM_OK);
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
    assert_int_equal(reap(pid), 0);
}

static void test_peer_exit_without_close(void **state)
{
    char name[64];
    struct channel_frame f;
    const void *data;
    pid_t pid;
    (void)state;
    unique_name(name, sizeof name);
    struct peer p = { name, CHANNEL_SOLID, 0.2, OPEN_THEN_EXIT };
    struct channel *c = open_with(&p, &pid);
    assert_int_equal(channel_recv(c, &f, &data), SIM_ERR_PEER);
    /* the atexit safety net closed it as failed */
    assert_non_null(strstr(sim_error_message(), "stopped with an error"));
    assert_int_equal(reap(pid), 3);
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
    assert_false(segment_exists(name));
}

static void test_timeout_on_live_silent_peer(void **state)
{
    char name[64];
    struct channel_settings s;
    struct channel *c;
    struct channel_frame f;
    const void *data;
    (void)state;
    unique_name(name, sizeof name);
    struct peer p = { name, CHANNEL_SOLID, 1.5, OPEN_THEN_CLOSE };
    pid_t pid = spawn(peer_main, &p);
    test_settings(&s, CHANNEL_FLUID, name);
    s.timeout = 0.4;
    assert_int_equal(channel_open(&s, &c), SIM_OK);
    double t0 = now_s();
    assert_int_equal(channel_recv(c, &f, &data), SIM_ERR_TIMEOUT);
    double dt = now_s() - t0;
    assert_true(dt >= 0.39 && dt < 1.5);
    assert_int_equal(channel_close(c, SIM_ERR_TIMEOUT), SIM_OK);
    assert_int_equal(reap(pid), 0);
    assert_false(segment_exists(name));
}

/* ---- stale segment, second pair, foreign file ----------------------------- */

static int open_alone(void *arg)
{
    struct channel_settings s;
    struct channel *c;
    test_settings(&s, CHANNEL_FLUID, arg);
    return channel_open(&s, &c);  /* killed while it waits */
}

static void test_stale_segment_replaced(void **state)
{
    char name[64];
    pid_t pid, dead;
    (void)state;
    unique_name(name, sizeof name);
    dead = spawn(open_alone, name);
    for (int i = 0; i < 200 && !segment_exists(name); i++)
        sleep_s(0.01);
    assert_true(segment_exists(name));
    kill(dead, SIGKILL);
    assert_int_equal(reap(dead), 128 + SIGKILL);
    assert_true(segment_exists(name));          /* left by the "crash" */
    struct peer p = { name, CHANNEL_SOLID, 0.1, OPEN_THEN_CLOSE };
    struct channel *c = open_with(&p, &pid);    /* fluid side, as the dead */
    assert_int_equal(channel_peer_pid(c), pid);
    assert_int_equal(reap(pid), 0);
    assert_int_equal(channel_close(c, SIM_OK), SIM_OK);
    assert_false(segment_exists(name));
}

static void test_second_pair_refused(void **state)
{
    char name[64];
    struct channel_settings s;
    struct channel *c = NULL;
    (void)state;
    unique_name(name, sizeof name);
    struct peer a = { name, CHANNEL_SOLID, 0, OPEN_SEND_WAIT };
    struct peer b = { name, CHANNEL_FLUID, 1.0, OPEN_THEN_CLOSE };
    pid_t pa = spawn(peer_main, &a), pb = spawn(peer_main, &b);
    sleep_s(0.3);
    for (int side = 0; side < 2; side++) {
        test_settings(&s, side, name);
        double t0 = now_s();
        assert_int_equal(channel_open(&s, &c), SIM_ERR_INPUT);
        assert_true(now_s() - t0 < 2.0);
        assert_non_null(strstr(sim_error_message(), "already coupled"));
        assert_non_null(strstr(sim_error_message(), "second pair"));
    }
    /* the first pair was not disturbed */
    assert_int_equal(reap(pb), 0);
    assert_int_equal(reap(pa), 0);
    assert_false(segment_exists(name));
}

static void test_foreign_file_refused(void **state)
{
    char name[64], path[128];
    struct channel_settings s;
    struct channel *c;
    (void)state;
    unique_name(name, sizeof name);
    snprintf(path, sizeof path, "/dev/shm%s", name);
    int fd = open(path, O_CREAT | O_WRONLY, 0600);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, "hello", 5), 5);
    close(fd);
    test_settings(&s, CHANNEL_FLUID, name);
    assert_int_equal(channel_open(&s, &c), SIM_ERR_INPUT);
    assert_non_null(strstr(sim_error_message(), "not a coupling channel"));
    assert_true(segment_exists(name));  /* not ours: left alone */
    unlink(path);
}

static void test_other_protocol_version_refused(void **state)
{
    char name[64], path[128];
    struct channel_settings s;
    struct channel *c;
    struct chan_header h;
    (void)state;
    unique_name(name, sizeof name);
    snprintf(path, sizeof path, "/dev/shm%s", name);
    memset(&h, 0, sizeof h);
    h.magic = CHAN_MAGIC;
    h.version = CHANNEL_PROTOCOL_VERSION + 1;
    int fd = open(path, O_CREAT | O_WRONLY, 0600);
    assert_true(fd >= 0);
    assert_int_equal(write(fd, &h, sizeof h), (ssize_t)sizeof h);
    close(fd);
    test_settings(&s, CHANNEL_SOLID, name);
    assert_int_equal(channel_open(&s, &c), SIM_ERR_INPUT);
    char want[64];
    snprintf(want, sizeof want, "protocol version %d",
             CHANNEL_PROTOCOL_VERSION);
    assert_non_null(strstr(sim_error_message(), want));
    snprintf(want, sizeof want, "version %d)", CHANNEL_PROTOCOL_VERSION + 1);
    assert_non_null(strstr(sim_error_message(), want));
    unlink(path);
}

/* ---- corruption ----------------------------------------------------------- */

static void test_corrupted_frame_detected(void **state)
{
    char name[64];
    struct channel_frame f;
    const void *data;
    pid_t pid;
    (void)state;
    unique_name(name, sizeof name);
    struct peer p = { name, CHANNEL_SOLID, 0, OPEN_SEND_WAIT };
    struct channel *c = open_with(&p, &pid);
    struct chan_ring *ring = &c->hdr->ring[CHANNEL_SOLID];
    for (int i = 0; i < 300 && atomic_load(&ring->head) == 0; i++)
        sleep_s(0.01);
    assert_int_equal(atomic_load(&ring->head), 1);
    unsigned char *slot = (unsigned char *)c->base + ring->offset;
    slot[64 + 3] ^= 0x10;  /* one bit of the payload */
    assert_int_equal(channel_recv(c, &f, &data), SIM_ERR_PEER);
    assert_non_null(strstr(sim_error_message(), "corrupted"));
    assert_int_equal(channel_close(c, SIM_ERR_PEER), SIM_OK);
    assert_int_equal(reap(pid), 0);
    assert_false(segment_exists(name));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_handshake_mismatch),
        cmocka_unit_test(test_timeout_without_peer),
        cmocka_unit_test(test_signal_ends_wait),
        cmocka_unit_test(test_second_signal_unlinks_and_kills),
        cmocka_unit_test(test_peer_killed_while_receiving),
        cmocka_unit_test(test_peer_killed_while_sending),
        cmocka_unit_test(test_peer_stopped_is_hung),
        cmocka_unit_test(test_peer_starved_not_hung),
        cmocka_unit_test(test_suspended_wait_goes_on),
        cmocka_unit_test(test_peer_exit_without_close),
        cmocka_unit_test(test_timeout_on_live_silent_peer),
        cmocka_unit_test(test_stale_segment_replaced),
        cmocka_unit_test(test_second_pair_refused),
        cmocka_unit_test(test_foreign_file_refused),
        cmocka_unit_test(test_other_protocol_version_refused),
        cmocka_unit_test(test_corrupted_frame_detected),
    };
    log_set_quiet(1);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
