/*
 * chantest.h — helpers shared by the channel tests: settings with a unique
 * segment name, a forked peer process, timing, and the check that no
 * segment is left in /dev/shm. (Header-only: each test file is its own
 * executable.)
 */
#ifndef MPSDEM_TEST_CHANTEST_H
#define MPSDEM_TEST_CHANTEST_H

#include "coupling/channel.h"
#include "core/error.h"
#include "core/log.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static int chantest_serial;

static inline double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline void sleep_s(double s)
{
    struct timespec ts = { (time_t)s, (long)((s - (time_t)s) * 1e9) };
    while (nanosleep(&ts, &ts) != 0)
        ;
}

/* Fresh settings on a name unique to this test process and call. */
static inline void test_settings(struct channel_settings *s, int side,
                                 const char *name)
{
    channel_settings_default(s, side, side ? "testSolid" : "testFluid",
                             "/tmp");
    snprintf(s->name, sizeof s->name, "%s", name);
    s->timeout = 5.0;
    s->heartbeat_interval = 0.05;
    s->slot_bytes = 4096;
    s->quiet = 1;
}

static inline void unique_name(char *buf, size_t n)
{
    snprintf(buf, n, "/mpsdem-test-%d-%d", (int)getpid(), ++chantest_serial);
}

static inline int segment_exists(const char *name)
{
    char path[256];
    snprintf(path, sizeof path, "/dev/shm%s", name);
    return access(path, F_OK) == 0;
}

/* Run fn(arg) in a child process that exits with its return value. */
static inline pid_t spawn(int (*fn)(void *), void *arg)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        log_set_quiet(1);
        int rc = fn(arg);
        fflush(stdout);
        _exit(rc);
    }
    return pid;
}

/* Exit status of a child (128 + signal when it was killed). */
static inline int reap(pid_t pid)
{
    int st;
    if (waitpid(pid, &st, 0) != pid)
        return -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

#endif
