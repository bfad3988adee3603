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

uint64_t chan_proc_start(pid_t pid)
{
    char path[64], buf[1024];
    FILE *f;
    size_t n;

    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    f = fopen(path, "re");
    if (!f)
        return 0;
    n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    /* the command name (field 2) may hold spaces and ')' */
    char *p = strrchr(buf, ')');
    if (!p || p[1] != ' ')
        return 0;
    p += 2;
    if (*p == 'Z' || *p == 'X' || *p == 'x')
        return 0;
    /* p is at field 3; the start time is field 22 */
    for (int field = 3; field < 22; field++) {
        p = strchr(p, ' ');
        if (!p)
            return 0;
        p++;
    }
    return strtoull(p, NULL, 10);
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
