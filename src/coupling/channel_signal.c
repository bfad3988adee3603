/*
 * channel_signal.c — SIGINT/SIGTERM/SIGHUP handling and the registry of
 * open channels, so that the segment is unlinked on every way out:
 *
 *   normal end or error   the application calls channel_close();
 *   exit() without close  (e.g. app_fatal) an atexit handler closes every
 *                         channel still open, as failed;
 *   first signal          the handler only records it; every wait returns
 *                         SIM_ERR_INTERRUPT within one sleep slice and the
 *                         application closes the channel on its error path;
 *   second signal, >= 1 s later
 *                         the program did not stop: unlink the names of the
 *                         open segments (unlink is async-signal-safe; the
 *                         peer keeps its mapping) and die of the signal;
 *   SIGKILL, crash        nothing runs here: the peer notices (pidfd) and,
 *                         being the last, unlinks at its close; if both die,
 *                         the next run finds the segment stale.
 * A repeated signal within one second is ignored because runTandem forwards
 * Ctrl-C to programs that also got it from the terminal.
 */
#include "coupling/channel_impl.h"
#include "core/error.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define REG_MAX 8

static volatile sig_atomic_t got_signal;
static volatile sig_atomic_t got_at_s; /* CLOCK_MONOTONIC seconds */
static struct channel *registry[REG_MAX];
static char reg_path[REG_MAX][CHANNEL_NAME_MAX + 16];
static volatile sig_atomic_t reg_used[REG_MAX];
static int atexit_done;

int channel_interrupted(void) { return got_signal; }
void channel_interrupt_clear(void) { got_signal = 0; }

static void on_signal(int sig)
{
    struct timespec ts;

    clock_gettime(CLOCK_MONOTONIC, &ts);
    if (!got_signal) {
        got_signal = sig;
        got_at_s = (sig_atomic_t)ts.tv_sec;
        return;
    }
    if (ts.tv_sec - got_at_s < 1)
        return;
    for (int i = 0; i < REG_MAX; i++)
        if (reg_used[i])
            unlink(reg_path[i]);
    signal(sig, SIG_DFL);
    raise(sig);
}

int channel_signals_install(void)
{
    static const int sigs[] = { SIGINT, SIGTERM, SIGHUP };
    struct sigaction sa;

    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; /* no SA_RESTART: a blocked call returns EINTR */
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        struct sigaction old;
        /* respect nohup; SIGINT is caught even when the shell ignored it
         * for a background job, because runTandem forwards Ctrl-C as SIGINT */
        if (sigs[i] == SIGHUP && sigaction(SIGHUP, NULL, &old) == 0 &&
            old.sa_handler == SIG_IGN)
            continue;
        if (sigaction(sigs[i], &sa, NULL) != 0)
            return sim_error(SIM_ERR_INTERNAL, "sigaction(%d) failed", sigs[i]);
    }
    return SIM_OK;
}

static void close_all_at_exit(void)
{
    /* a forked child inherits the list but not the heartbeat threads nor
     * the right to speak for its parent's side: it leaves them alone */
    for (int i = 0; i < REG_MAX; i++)
        if (registry[i] && registry[i]->owner == getpid())
            channel_close(registry[i], SIM_ERR_INTERNAL);
}

int chan_registry_add(struct channel *c)
{
    if (!atexit_done) {
        atexit(close_all_at_exit);
        atexit_done = 1;
    }
    for (int i = 0; i < REG_MAX; i++) {
        if (registry[i])
            continue;
        registry[i] = c;
        snprintf(reg_path[i], sizeof reg_path[i], "/dev/shm%s", c->set.name);
        reg_used[i] = 1;
        c->registry_slot = i;
        return SIM_OK;
    }
    return sim_error(SIM_ERR_INPUT, "more than %d coupling channels open in "
                     "one program", REG_MAX);
}

void chan_registry_remove(struct channel *c)
{
    int i = c->registry_slot;
    if (i < 0)
        return;
    reg_used[i] = 0;
    registry[i] = NULL;
    c->registry_slot = -1;
}
