/*
 * app.h — what every program (solver or utility) does around its physics:
 * command line (-case DIR, -help, program options), the log header, case
 * paths, reading case dictionaries, timing lines, and the one place where a
 * program stops on an error (app_fatal).
 *
 * Typical main():
 *
 *     struct app app;
 *     app_init(&app, "demSolid", "DEM solver", argc, argv, NULL);
 *     struct dict *control;
 *     int rc = app_read_dict(&app, "system/controlDict", &control);
 *     if (rc) app_fatal(&app, rc);
 *     ...
 *     return app_end(&app);
 */
#ifndef MPSDEM_CORE_APP_H
#define MPSDEM_CORE_APP_H

#include <stddef.h>

struct dict;

/* A program option beyond -case/-help, e.g. { "-entry", 1, "KEY", "print KEY" }.
 * After app_init, *value holds the argument (or "" for a flag without one)
 * when the option was given, and stays NULL otherwise. */
struct app_option {
    const char *flag;    /* "-entry"                                 */
    int takes_arg;       /* 1 when the next argument is its value    */
    const char *argname; /* shown in -help, e.g. "KEY"               */
    const char *help;    /* one line                                 */
    const char **value;  /* out                                      */
};

struct app {
    const char *name;        /* program name                             */
    const char *case_dir;    /* as given with -case (default ".")         */
    char case_abs[4096];     /* absolute case path                       */
    int nargs;               /* positional arguments left after options  */
    char **args;
    double wall0, cpu0;      /* clocks at start                          */
};

/* Parse the command line, check the case directory, print the header
 * (program, version, git revision, case, date, host, pid, threads).
 * -help prints the usage and exits 0; a bad option or a missing case
 * directory prints a FATAL ERROR and exits 1. `opts` ends with a NULL flag;
 * it may be NULL. allow_args: accept positional arguments (else error). */
void app_init(struct app *a, const char *name, const char *description,
              int argc, char **argv, const struct app_option *opts,
              int allow_args);

/* Take the case for this program before it touches any output: an
 * exclusive flock(2) on "<case>/.<program>.lock", held until the process
 * ends (the kernel drops it on any exit, a kill included, so a lock is
 * never stale). A second start of the same program on the same case gets
 * SIM_ERR_IO with a message naming the running pid, and must leave before
 * it truncates a log, a .pvd or a postProcessing file of the first. */
int app_lock_case(const struct app *a);

/* "<case>/<rel>" into buf (without a "./" prefix for the default case). */
const char *app_path(const struct app *a, const char *rel, char *buf,
                     size_t n);

/* Read a case dictionary, e.g. "system/controlDict". */
int app_read_dict(const struct app *a, const char *rel, struct dict **out);

/* The same for a dictionary a case may leave out (system/couplingDict):
 * *out = NULL and SIM_OK when the file does not exist. */
int app_read_dict_optional(const struct app *a, const char *rel,
                           struct dict **out);

/* Print the FATAL ERROR block (message, traceback) to stdout and stderr and
 * exit(1). */
void app_fatal(const struct app *a, int rc) __attribute__((noreturn));

/* "ExecutionTime = 1.23 s  ClockTime = 2 s" (CPU of the process, wall). */
void app_log_times(const struct app *a);
double app_wall_time(void);  /* seconds, monotonic */
double app_cpu_time(void);   /* process CPU seconds */
double app_peak_memory(void); /* the process's peak resident set [B] */
/* "    peak memory  X MB (Y kB per particle)" for the final statistics of
 * a solver of n particles */
void app_log_peak_memory(long n);

/* Write the parameters this program read, defaults included, to
 * postProcessing/usedParameters/<program> (one file per program, so that
 * the two programs of a coupled case keep theirs) and to the log. */
int app_write_used_parameters(const struct app *a);

/* Print "End" and return the exit status 0 (for `return app_end(&a);`). */
int app_end(const struct app *a);

#endif
