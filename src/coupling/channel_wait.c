/*
 * channel_wait.c — how a channel waits without ever waiting forever:
 * futex sleeps in short slices, the peer watched through a pidfd, its state
 * word and its heartbeat, and a heartbeat thread of our own.
 *
 * Why a pidfd: kill(pid, 0) still succeeds for a killed process that its
 * parent has not reaped yet (a zombie), and pids are reused; a pidfd becomes
 * readable the moment the process exits, zombie or not (doc/libraries.md §4).
 * Why spin first, and yield while spinning: a sequential coupling step
 * hands the turn back within microseconds for small frames; a pure spin
 * would starve a peer that waits for this same core (measured: 77 us per
 * round trip on one core, 3.4 us with a yield every 32 spins, 1.7 us on two
 * cores), and a pure sleep costs a futex wake-up (5-7 us) every time.
 * Why a heartbeat thread: the main thread may compute for minutes between
 * messages; the beat shows the program is alive, and its absence shows a
 * program that is stopped (SIGSTOP) or wedged.
 */
#include "coupling/channel_impl.h"
#include "core/error.h"

#include <errno.h>
#include <limits.h>
#include <linux/futex.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <string.h>
#include <sys/pidfd.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#define PEER_GONE (-2) /* peer_pidfd when pidfd_open found no process */

uint64_t chan_now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000ULL + (uint64_t)ts.tv_nsec;
}

/* No FUTEX_PRIVATE_FLAG: the word is shared between processes. */
static void futex_wait(_Atomic uint32_t *word, uint32_t val, long ns)
{
    struct timespec ts = { ns / 1000000000L, ns % 1000000000L };
    syscall(SYS_futex, (uint32_t *)word, FUTEX_WAIT, val, &ts, NULL, 0);
}

void chan_futex_wake(_Atomic uint32_t *word)
{
    atomic_fetch_add(word, 1);
    syscall(SYS_futex, (uint32_t *)word, FUTEX_WAKE, INT_MAX, NULL, NULL, 0);
}

void chan_set_state(struct channel *c, int state)
{
    atomic_store(&c->hdr->side[c->side].state, state);
    chan_futex_wake(&c->hdr->state_futex);
    /* a peer asleep on a ring must notice too */
    for (int r = 0; r < 2; r++) {
        chan_futex_wake(&c->hdr->ring[r].head_futex);
        chan_futex_wake(&c->hdr->ring[r].tail_futex);
    }
}

int chan_check_signal(const struct channel *c)
{
    int sig = channel_interrupted();
    if (sig)
        return sim_error(SIM_ERR_INTERRUPT,
                         "%s: interrupted by signal %s while coupled with "
                         "%s through %s", c->set.program, sigabbrev_np(sig),
                         c->peer_program[0] ? c->peer_program : "its peer",
                         c->set.name);
    return SIM_OK;
}

int chan_watch_peer(struct channel *c)
{
    const struct chan_side *p = &c->hdr->side[c->peer];
    pid_t pid = atomic_load(&p->pid);

    if (c->peer_pidfd != -1 || pid <= 0)
        return SIM_OK;
    /* the program name was written before the pid */
    c->peer_pid = pid;
    memcpy(c->peer_program, p->program, sizeof c->peer_program);
    c->peer_program[sizeof c->peer_program - 1] = '\0';
    if (!c->peer_program[0])
        strcpy(c->peer_program, c->peer == CHANNEL_FLUID ? "fluid program"
                                                          : "solid program");
    c->peer_pidfd = pidfd_open(pid, 0);
    if (c->peer_pidfd >= 0)
        return SIM_OK;
    if (errno != ESRCH) {
        c->peer_pidfd = -1;
        return sim_error(SIM_ERR_IO, "%s: pidfd_open(%d): %s",
                         c->set.program, (int)pid, strerror(errno));
    }
    /* gone already: what it published (a mismatch, a failure) may still
     * explain why, so the verdict is left to the caller's next check */
    c->peer_pidfd = PEER_GONE;
    return SIM_OK;
}

static int peer_left(struct channel *c, int state)
{
    const struct chan_side *p = &c->hdr->side[c->peer];
    int code = atomic_load(&p->exit_code);

    if (state == SIDE_CLOSED)
        return sim_error(SIM_ERR_PEER, "%s: peer %s (pid %d) closed the "
                         "channel %s", c->set.program, c->peer_program,
                         (int)c->peer_pid, c->set.name);
    return sim_error(SIM_ERR_PEER, "%s: peer %s (pid %d) stopped with an "
                     "error (%s)", c->set.program, c->peer_program,
                     (int)c->peer_pid, sim_strerror(code));
}

/* Silence is counted on our own clock while we keep checking: when our
 * checks were far apart (we computed, or the whole tandem was suspended
 * with Ctrl-Z and resumed), the count starts again, so that only a peer
 * that stays silent while we watch is declared hung.
 *
 * A silent peer that is runnable, or has used CPU time since half the
 * silence, is starved, not stopped: a run at nice 19 on a busy machine
 * went 2 s without being scheduled for its heartbeat (2026-11-28, two
 * coupled runs beside a 2-thread benchmark on 2 cores) and was killed as
 * hung. Its silence starts again; a stopped ('T') or frozen peer keeps
 * neither state nor CPU time moving and is declared hung as before. */
static int peer_silent(struct channel *c, uint64_t beat)
{
    uint64_t now = chan_now_ns();
    int away = now - c->last_check > c->hung_ns / 4;

    c->last_check = now;
    if (beat != c->beat_seen || away) {
        c->beat_seen = beat;
        c->beat_seen_at = now;
        c->peer_ticks_set = 0;
        return 0;
    }
    uint64_t quiet = now - c->beat_seen_at;
    if (quiet <= c->hung_ns / 2)
        return 0;
    char state;
    uint64_t ticks;
    if (chan_proc_cpu(c->peer_pid, &state, &ticks)) {
        if (state == 'R' || (c->peer_ticks_set && ticks != c->peer_ticks)) {
            c->beat_seen_at = now;   /* starved: count again */
            c->peer_ticks_set = 0;
            return 0;
        }
        if (!c->peer_ticks_set) {
            c->peer_ticks = ticks;
            c->peer_ticks_set = 1;
        }
    }
    return quiet > c->hung_ns;
}

int chan_check_peer(struct channel *c)
{
    const struct chan_side *p = &c->hdr->side[c->peer];
    int state = atomic_load(&p->state);

    TRY(chan_check_signal(c));
    TRY(chan_watch_peer(c));
    if (state == SIDE_CLOSED || state == SIDE_FAILED)
        return peer_left(c, state);
    if (c->peer_pidfd == PEER_GONE)
        return sim_error(SIM_ERR_PEER, "%s: peer %s (pid %d) exited before "
                         "the handshake ended", c->set.program,
                         c->peer_program, (int)c->peer_pid);
    if (c->peer_pidfd >= 0) {
        struct pollfd pfd = { .fd = c->peer_pidfd, .events = POLLIN };
        if (poll(&pfd, 1, 0) > 0)
            return sim_error(SIM_ERR_PEER, "%s: peer %s (pid %d) died "
                             "without closing the channel (killed or "
                             "crashed)", c->set.program, c->peer_program,
                             (int)c->peer_pid);
        if (peer_silent(c, atomic_load(&p->heartbeat_ns))) {
            c->peer_hung = 1;
            return sim_error(SIM_ERR_PEER, "%s: peer %s (pid %d) sent no "
                             "heartbeat for %.1f s: it is stopped or hung",
                             c->set.program, c->peer_program,
                             (int)c->peer_pid,
                             (double)(chan_now_ns() - c->beat_seen_at) * 1e-9);
        }
    }
    return SIM_OK;
}

static inline void cpu_relax(void)
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

int chan_wait(struct channel *c, int (*ready)(struct channel *, void *),
              void *arg, _Atomic uint32_t *word, _Atomic uint32_t *waiting,
              double timeout, const char *what)
{
    /* a peer that always answers at once must not hide a signal */
    TRY(chan_check_signal(c));
    for (int i = 0; i < CHAN_SPIN; i++) {
        if (ready(c, arg))
            return SIM_OK;
        /* the peer may be waiting for this very core (2 cores, OpenMP
         * threads, other jobs): offer it now and then */
        if (i % 32 == 31)
            sched_yield();
        else
            cpu_relax();
    }
    /* The time-out counts the time we waited: a gap between two looks far
     * longer than one sleep means this process was stopped (Ctrl-Z and fg
     * of the tandem, a debugger) or not scheduled (a niced run on a busy
     * machine), and does not count. Before, a tandem stopped for longer
     * than the time-out (600 s in the tutorials) stopped with "no frame
     * within 600 s" as soon as it was continued (2026-11-28). */
    uint64_t t0 = chan_now_ns(), last = t0, limit = (uint64_t)(timeout * 1e9);
    for (;;) {
        if (waiting)
            atomic_store(waiting, 1);
        uint32_t v = atomic_load(word);
        if (ready(c, arg))
            break;
        uint64_t used = chan_now_ns() - t0;
        long slice = used >= limit ? 0 : (long)(limit - used);
        futex_wait(word, v, slice < CHAN_SLICE_NS ? slice : CHAN_SLICE_NS);
        if (waiting)
            atomic_store(waiting, 0);
        if (ready(c, arg))
            return SIM_OK;
        TRY(chan_check_peer(c));
        uint64_t now = chan_now_ns();
        if (now - last > (uint64_t)CHAN_AWAY_NS)
            t0 += now - last - (uint64_t)CHAN_SLICE_NS;
        last = now;
        if (now - t0 >= limit)
            return sim_error(SIM_ERR_TIMEOUT, "%s: no %s within %g s "
                             "(timeout in system/couplingDict)",
                             c->set.program, what, timeout);
    }
    if (waiting)
        atomic_store(waiting, 0);
    return SIM_OK;
}

/* ---- heartbeat ------------------------------------------------------------ */

static void *heartbeat_main(void *arg)
{
    struct channel *c = arg;
    _Atomic uint64_t *beat = &c->hdr->side[c->side].heartbeat_ns;
    long period = (long)(c->set.heartbeat_interval * 1e9);

    pthread_mutex_lock(&c->hb_lock);
    while (!c->hb_stop) {
        atomic_store(beat, chan_now_ns());
        struct timespec ts;
        clock_gettime(CLOCK_MONOTONIC, &ts);
        ts.tv_nsec += period % 1000000000L;
        ts.tv_sec += period / 1000000000L + ts.tv_nsec / 1000000000L;
        ts.tv_nsec %= 1000000000L;
        pthread_cond_timedwait(&c->hb_cond, &c->hb_lock, &ts);
    }
    pthread_mutex_unlock(&c->hb_lock);
    return NULL;
}

int chan_heartbeat_start(struct channel *c)
{
    pthread_condattr_t ca;
    sigset_t all, old;
    int rc;

    atomic_store(&c->hdr->side[c->side].heartbeat_ns, chan_now_ns());
    pthread_mutex_init(&c->hb_lock, NULL);
    pthread_condattr_init(&ca);
    pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
    pthread_cond_init(&c->hb_cond, &ca);
    pthread_condattr_destroy(&ca);
    /* signals belong to the main thread, whose waits must see them */
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &old);
    rc = pthread_create(&c->hb_thread, NULL, heartbeat_main, c);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (rc != 0)
        return sim_error(SIM_ERR_IO, "%s: cannot start the heartbeat "
                         "thread: %s", c->set.program, strerror(rc));
    c->hb_running = 1;
    return SIM_OK;
}

void chan_heartbeat_stop(struct channel *c)
{
    if (!c->hb_running)
        return;
    pthread_mutex_lock(&c->hb_lock);
    c->hb_stop = 1;
    pthread_cond_signal(&c->hb_cond);
    pthread_mutex_unlock(&c->hb_lock);
    pthread_join(c->hb_thread, NULL);
    pthread_cond_destroy(&c->hb_cond);
    pthread_mutex_destroy(&c->hb_lock);
    c->hb_running = 0;
}
