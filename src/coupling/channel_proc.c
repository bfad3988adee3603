/*
 * channel_proc.c — is the program that claimed a side of a segment still
 * running? A pid alone cannot say: pids are reused, and a killed process
 * stays a zombie until reaped. So each side records the start time of its
 * process (field 22 of /proc/<pid>/stat, clock ticks since boot), and a side
 * counts as alive only when a process with that pid and that start time
 * exists and is not a zombie.
 */
#include "coupling/channel_impl.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* /proc/<pid>/stat into buf; the address of its field 3 (the state), or
 * NULL. */
static char *read_stat(pid_t pid, char *buf, size_t size)
{
    char path[64];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    FILE *f = fopen(path, "re");
    if (!f)
        return NULL;
    size_t n = fread(buf, 1, size - 1, f);
    fclose(f);
    buf[n] = '\0';
    /* the command name (field 2) may hold spaces and ')' */
    char *p = strrchr(buf, ')');
    if (!p || p[1] != ' ')
        return NULL;
    return p + 2;
}

/* From field 3 at p on to field `field`, or NULL. */
static char *skip_to(char *p, int field)
{
    for (int f = 3; f < field && p; f++) {
        p = strchr(p, ' ');
        if (p)
            p++;
    }
    return p;
}

uint64_t chan_proc_start(pid_t pid)
{
    char buf[1024];
    char *p = read_stat(pid, buf, sizeof buf);
    if (!p || *p == 'Z' || *p == 'X' || *p == 'x')
        return 0;
    p = skip_to(p, 22);   /* the start time */
    return p ? strtoull(p, NULL, 10) : 0;
}

int chan_proc_cpu(pid_t pid, char *state, uint64_t *ticks)
{
    char buf[1024];
    char *p = read_stat(pid, buf, sizeof buf);
    if (!p)
        return 0;
    *state = *p;
    p = skip_to(p, 14);   /* utime, then stime */
    if (!p)
        return 0;
    char *end;
    uint64_t u = strtoull(p, &end, 10);
    *ticks = u + strtoull(end, NULL, 10);
    return 1;
}

int chan_side_alive(const struct chan_header *h, int s)
{
    const struct chan_side *side = &h->side[s];
    pid_t pid = atomic_load(&side->pid);
    int state = atomic_load(&side->state);

    if (pid <= 0 || state == SIDE_FREE || state == SIDE_CLOSED ||
        state == SIDE_FAILED)
        return 0;
    uint64_t start = chan_proc_start(pid);
    return start != 0 && start == side->start_ticks;
}
