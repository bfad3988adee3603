/* time.c — run time control (see time.h). */
#include "core/time.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/app.h"
#include "core/dict.h"
#include "core/error.h"
#include "core/log.h"

static const char *const start_from_words[] = {"startTime", "latestTime", NULL};
static const char *const write_control_words[] = {
    "timeStep", "runTime", "adjustableRunTime", "clockTime", "cpuTime", NULL};
static const char *const write_format_words[] = {"ascii", "binary", NULL};

const char *time_name(double t, int precision, char *buf, size_t n)
{
    if (fabs(t) < 1e-300)
        t = 0.0; /* never "-0" */
    snprintf(buf, n, "%.*g", precision, t);
    return buf;
}

/* A time directory name: a finite number ("0.05", "1e-05"). */
static int time_dir_value(const char *name, double *v)
{
    char *end;
    *v = strtod(name, &end);
    return end != name && *end == '\0' && isfinite(*v);
}

/* The first of `need` that dir lacks (a regular file), or NULL. An entry
 * "a|b" is there when either is (a cloud written whole or in pieces). */
static const char *missing_file(const char *dir, const char *const *need)
{
    for (; need && *need; need++) {
        const char *alt = *need;
        int found = 0;
        while (!found && *alt) {
            size_t len = strcspn(alt, "|");
            char path[4400];
            struct stat st;
            snprintf(path, sizeof path, "%s/%.*s", dir, (int)len, alt);
            found = stat(path, &st) == 0 && S_ISREG(st.st_mode);
            alt += len + (alt[len] == '|');
        }
        if (!found)
            return *need;
    }
    return NULL;
}

int time_latest(const char *case_dir, const char *const *need, double *t,
                char *name, size_t n)
{
    DIR *d = opendir(case_dir);
    if (!d)
        return sim_error(SIM_ERR_IO, "cannot open case directory '%s': %s",
                         case_dir, strerror(errno));
    int found = 0, nskip = 0;
    double skip_t[8];
    char skipped[512] = "";
    struct dirent *e;
    while ((e = readdir(d))) {
        double v;
        if (!time_dir_value(e->d_name, &v))
            continue;
        char path[4096];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", case_dir, e->d_name);
        if (stat(path, &st) != 0 || !S_ISDIR(st.st_mode))
            continue;
        const char *lack = missing_file(path, need);
        if (lack) {
            /* Remembered to be reported if newer than the one chosen. */
            if (nskip < 8) {
                size_t k = strlen(skipped);
                /* "a|b" names its first form, the usual one */
                snprintf(skipped + k, sizeof skipped - k, "%s%s (no %.*s)",
                         nskip ? ", " : "", e->d_name,
                         (int)strcspn(lack, "|"), lack);
                skip_t[nskip] = v;
            }
            nskip++;
            continue;
        }
        if (!found || v > *t) {
            *t = v;
            snprintf(name, n, "%s", e->d_name);
            found = 1;
        }
    }
    closedir(d);
    if (!found)
        return sim_error(SIM_ERR_IO, "no time directory in case '%s'%s%s%s",
                         case_dir, nskip ? " that holds every cloud of the "
                         "run; skipped " : "", skipped, nskip > 8 ? ", ..."
                         : "");
    int newer = 0;
    for (int k = 0; k < nskip && k < 8; k++)
        newer += skip_t[k] > *t;
    if (newer)
        log_warn("latestTime: %s chosen; newer time directories that do not "
                 "hold every cloud of the run are skipped: %s", name,
                 skipped);
    return SIM_OK;
}

int time_clean_debris(const char *case_dir)
{
    DIR *d = opendir(case_dir);
    if (!d)
        return sim_error(SIM_ERR_IO, "cannot open case directory '%s': %s",
                         case_dir, strerror(errno));
    struct dirent *e;
    int removed = 0;
    while ((e = readdir(d))) {
        double v;
        int is_time = time_dir_value(e->d_name, &v);
        if (!is_time && strncmp(e->d_name, "failed.", 7)
            && strcmp(e->d_name, "."))
            continue;
        char dir[4200];
        snprintf(dir, sizeof dir, "%s/%s", case_dir, e->d_name);
        DIR *sub = opendir(dir);
        if (!sub)
            continue;
        struct dirent *f;
        int files = 0;
        while ((f = readdir(sub))) {
            if (!strcmp(f->d_name, ".") || !strcmp(f->d_name, ".."))
                continue;
            files++;
            /* "<file>.tmp.<pid>" of a writer that no longer runs (killed
             * in the middle of a write: xmlio.c renames on success and
             * unlinks on any error it sees). */
            const char *tmp = strstr(f->d_name, ".tmp.");
            char *end;
            long pid = tmp ? strtol(tmp + 5, &end, 10) : 0;
            if (!tmp || pid <= 0 || *end || (kill((pid_t)pid, 0) == 0
                                             || errno != ESRCH))
                continue;
            char path[4500];
            snprintf(path, sizeof path, "%s/%s", dir, f->d_name);
            if (unlink(path) == 0) {
                log_warn("Removed '%s', left by a run killed while writing",
                         path);
                files--;
                removed++;
            }
        }
        closedir(sub);
        /* An empty time directory is what a failed write leaves (a full
         * disk): latestTime must not take it for a start time. */
        if (is_time && files == 0 && v > 0 && rmdir(dir) == 0) {
            log_warn("Removed the empty time directory '%s'", dir);
            removed++;
        }
    }
    closedir(d);
    return removed;
}

/* Enough significant digits that consecutive write times get distinct
 * names (OpenFOAM raises timePrecision for the same reason). */
static int needed_precision(const struct run_time *t)
{
    if (t->write_control != WRITE_RUN_TIME &&
        t->write_control != WRITE_ADJUSTABLE_RUN_TIME)
        return t->precision;
    double span = fmax(fabs(t->end_time), fabs(t->start_time));
    if (span <= 0 || t->write_interval <= 0)
        return t->precision;
    int p = (int)ceil(log10(span / t->write_interval)) + 2;
    return p > t->precision ? (p > 15 ? 15 : p) : t->precision;
}

static int read_settings(const struct dict *c, struct run_time *t)
{
    int idx;
    long prec;
    TRY(dict_get_word_or(c, "startFrom", start_from_words, 0, &idx));
    t->start_latest = idx == 1;
    TRY(dict_get_scalar_or(c, "startTime", 0.0, &t->start_time));
    TRY(dict_get_scalar(c, "endTime", &t->end_time));
    TRY(dict_get_scalar(c, "deltaT", &t->delta_t));
    if (!(t->delta_t > 0))
        return dict_error(c, "deltaT", SIM_ERR_DICT,
                          "deltaT must be positive, got %g", t->delta_t);
    /* A step that does not move t (deltaT 1e-300) used to fail at step 0
     * with a NaN in the solver that named nothing. Where t + deltaT > t
     * holds up to endTime, the run has fewer than 2^54 steps, which the
     * step counter (long) holds. */
    double t_max = fmax(fabs(t->start_time), fabs(t->end_time));
    if (!(t_max + t->delta_t > t_max))
        return dict_error(c, "deltaT", SIM_ERR_DICT,
                          "deltaT = %g is too small for times up to %g s: "
                          "t + deltaT == t in double precision",
                          t->delta_t, t_max);
    TRY(dict_get_bool_or(c, "adjustTimeStep", 0, &t->adjust));
    TRY(dict_get_scalar_or(c, "maxCo", 0.2, &t->max_co));
    TRY(dict_get_scalar_or(c, "maxDeltaT", 1.0, &t->max_delta_t));
    if (t->adjust && !(t->max_co > 0))
        return dict_error(c, "maxCo", SIM_ERR_DICT,
                          "maxCo must be positive, got %g", t->max_co);
    if (t->adjust && !(t->max_delta_t > 0))
        return dict_error(c, "maxDeltaT", SIM_ERR_DICT,
                          "maxDeltaT must be positive, got %g",
                          t->max_delta_t);
    TRY(dict_get_word_or(c, "writeControl", write_control_words, 0, &idx));
    t->write_control = (enum write_control)idx;
    TRY(dict_get_scalar(c, "writeInterval", &t->write_interval));
    if (!(t->write_interval > 0))
        return dict_error(c, "writeInterval", SIM_ERR_DICT,
                          "writeInterval must be positive, got %g",
                          t->write_interval);
    if (t->write_control == WRITE_TIME_STEP &&
        t->write_interval != floor(t->write_interval))
        return dict_error(c, "writeInterval", SIM_ERR_DICT,
                          "writeInterval is a number of steps with "
                          "writeControl timeStep; got %g",
                          t->write_interval);
    TRY(dict_get_word_or(c, "writeFormat", write_format_words, 1, &idx));
    t->binary = idx == 1;
    TRY(dict_get_label_or(c, "timePrecision", 6, &prec));
    if (prec < 1 || prec > 17)
        return dict_error(c, "timePrecision", SIM_ERR_DICT,
                          "timePrecision must be between 1 and 17, got %ld",
                          prec);
    t->precision = (int)prec;
    TRY(dict_find_dict(c, "functions", &t->functions));
    return SIM_OK;
}

int time_read(const struct dict *c, const char *case_dir,
              const char *const *need, struct run_time *t)
{
    memset(t, 0, sizeof *t);
    TRY(read_settings(c, t));
    time_clean_debris(case_dir);
    if (t->start_latest) {
        char name[64];
        int rc = time_latest(case_dir, need, &t->start_time, name,
                             sizeof name);
        if (rc)
            return dict_error(c, "startFrom", rc, "startFrom latestTime: %s",
                              sim_error_message());
        log_info("Starting from the latest time, %s", name);
    }
    if (t->end_time < t->start_time && !t->start_latest)
        return dict_error(c, "endTime", SIM_ERR_DICT,
                          "endTime (%g) is before startTime (%g)",
                          t->end_time, t->start_time);
    t->precision = needed_precision(t);
    t->value = t->start_time;
    t->dt = t->delta_t;
    /* Write times are counted from 0, as in OpenFOAM, so a restart at
     * 0.35 with writeInterval 0.1 writes next at 0.4. */
    if (t->write_control == WRITE_RUN_TIME ||
        t->write_control == WRITE_ADJUSTABLE_RUN_TIME)
        t->write_index = (long)floor(t->start_time / t->write_interval + 1e-9);
    t->wall0 = app_wall_time();
    t->cpu0 = app_cpu_time();
    t->last_write_clock = 0;
    time_name(t->value, t->precision, t->name, sizeof t->name);
    return SIM_OK;
}

static double eps_time(const struct run_time *t)
{
    return 1e-9 * fmax(t->delta_t, fmin(t->write_interval, t->delta_t));
}

int time_running(const struct run_time *t)
{
    return t->value < t->end_time - eps_time(t);
}

static double next_write_time(const struct run_time *t)
{
    return (double)(t->write_index + 1) * t->write_interval;
}

void time_set_step(struct run_time *t, double dt_wanted)
{
    double dt = t->delta_t;
    if (t->adjust) {
        dt = fmin(dt_wanted, t->max_delta_t);
        if (t->write_control == WRITE_ADJUSTABLE_RUN_TIME) {
            /* Land on the next write time in equal steps, as OpenFOAM's
             * adjustDeltaT does, rather than with one tiny last step. */
            double ttw = next_write_time(t) - t->value;
            if (ttw > 0 && dt > 0) {
                double nsteps = ceil(ttw / dt - 1e-6);
                if (nsteps < 1)
                    nsteps = 1;
                dt = ttw / nsteps;
            }
        }
    }
    double left = t->end_time - t->value;
    if (dt > left - eps_time(t))
        dt = left;
    t->dt = dt;
}

static void update_write_flag(struct run_time *t)
{
    t->write_now = 0;
    switch (t->write_control) {
    case WRITE_TIME_STEP:
        t->write_now = t->step % (long)t->write_interval == 0;
        break;
    case WRITE_RUN_TIME:
    case WRITE_ADJUSTABLE_RUN_TIME: {
        long k = (long)floor(t->value / t->write_interval + 1e-6);
        if (k > t->write_index) {
            t->write_index = k;
            t->write_now = 1;
        }
        break;
    }
    case WRITE_CLOCK_TIME:
    case WRITE_CPU_TIME: {
        double c = t->write_control == WRITE_CLOCK_TIME
                       ? app_wall_time() - t->wall0
                       : app_cpu_time() - t->cpu0;
        if (c - t->last_write_clock >= t->write_interval) {
            t->last_write_clock = c;
            t->write_now = 1;
        }
        break;
    }
    }
    if (!time_running(t))
        t->write_now = 1; /* the end time is always written */
}

void time_increment(struct run_time *t)
{
    t->step++;
    if (!t->adjust && t->dt == t->delta_t)
        t->value = t->start_time + (double)t->step * t->delta_t;
    else
        t->value += t->dt;
    /* Snap to a write time or the end time within round-off. */
    if (t->write_control == WRITE_RUN_TIME ||
        t->write_control == WRITE_ADJUSTABLE_RUN_TIME) {
        double tw = next_write_time(t);
        if (fabs(t->value - tw) < eps_time(t))
            t->value = tw;
    }
    if (fabs(t->value - t->end_time) < eps_time(t))
        t->value = t->end_time;
    update_write_flag(t);
    time_name(t->value, t->precision, t->name, sizeof t->name);
}

void time_dir_path(const struct run_time *t, const char *case_dir,
                   const char *prefix, char *dir, size_t n)
{
    if (!strcmp(case_dir, "."))
        snprintf(dir, n, "%s%s", prefix, t->name);
    else
        snprintf(dir, n, "%s/%s%s", case_dir, prefix, t->name);
}

int time_make_dir(const struct run_time *t, const char *case_dir,
                  const char *prefix, char *dir, size_t n)
{
    time_dir_path(t, case_dir, prefix, dir, n);
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return sim_error(SIM_ERR_IO, "cannot create time directory '%s': %s",
                         dir, strerror(errno));
    return SIM_OK;
}

void time_dir_discard(const char *dir)
{
    if (rmdir(dir) == 0)
        log_warn("Removed the time directory '%s' whose write failed", dir);
}

void time_log_progress(struct run_time *t, const char *extra)
{
    static double last = -1;
    if (!isatty(STDOUT_FILENO)) {
        log_info("Time = %s  deltaT = %.6g  %s", t->name, t->dt,
                 extra ? extra : "");
        return;
    }
    double now = app_wall_time();
    if (last >= 0 && now - last < 1.0 && time_running(t))
        return;
    last = now;
    double el = now - t->wall0;
    double span = t->end_time - t->start_time;
    double frac = span > 0 ? (t->value - t->start_time) / span : 1.0;
    double left = frac > 0 ? el * (1.0 - frac) / frac : 0.0;
    log_info("Time = %s  (%5.1f%%)  deltaT = %.3g  %.1f steps/s  "
             "%.0f s left  %s",
             t->name, 100.0 * frac, t->dt, el > 0 ? t->step / el : 0.0,
             left, extra ? extra : "");
}
