/*
 * time.h — run time control from system/controlDict, as OpenFOAM's Time:
 *
 *   startFrom       startTime | latestTime;   // latestTime: newest time directory
 *   startTime       0;          // [s]
 *   endTime         1;          // [s]
 *   deltaT          1e-4;       // [s] fixed step, or initial step when adjustable
 *   adjustTimeStep  no;         // yes: the solver proposes dt from maxCo etc.
 *   maxCo           0.2;        // Courant number limit (solver-defined use)
 *   maxDeltaT       1;          // [s] upper bound of an adjustable step
 *   writeControl    adjustableRunTime; // timeStep | runTime | adjustableRunTime
 *                                      // | clockTime | cpuTime
 *   writeInterval   0.05;       // [s], or steps for timeStep
 *   writeFormat     binary;     // binary | ascii
 *   timePrecision   6;          // significant digits of time names
 *   functions       { ... }     // function objects (functionObject.h)
 *
 * Time names carry no floating-point noise: write times are computed as
 * startTime + k*writeInterval, not accumulated, and printed with
 * timePrecision significant digits ("0", "0.05", "1e-05", "2.5").
 */
#ifndef MPSDEM_CORE_TIME_H
#define MPSDEM_CORE_TIME_H

#include <stddef.h>

struct dict;

enum write_control {
    WRITE_TIME_STEP, WRITE_RUN_TIME, WRITE_ADJUSTABLE_RUN_TIME,
    WRITE_CLOCK_TIME, WRITE_CPU_TIME
};

struct run_time {
    /* settings */
    double start_time, end_time, delta_t;
    int start_latest;          /* startFrom latestTime                    */
    int adjust;                /* adjustTimeStep                          */
    double max_co, max_delta_t;
    enum write_control write_control;
    double write_interval;
    int binary;                /* writeFormat binary                      */
    int precision;             /* timePrecision                           */
    const struct dict *functions; /* the functions {} sub-dict, or NULL   */
    /* state */
    double value;              /* current time                            */
    double dt;                 /* step being / just taken                 */
    long step;                 /* steps taken in this run                 */
    long write_index;          /* last write interval reached             */
    int write_now;             /* the step just taken ends at a write     */
    double wall0, cpu0;        /* clocks at the start of the run          */
    double last_write_clock;   /* clockTime/cpuTime write control         */
    char name[64];             /* time name of value                      */
};

/* Read controlDict (startFrom latestTime looks into case_dir for the newest
 * time directory that holds every file of `need`, a NULL-terminated list
 * such as { "fluid.vtu", "dem.vtu", NULL } for a coupled run; an entry
 * "fluid.vtu|fluid.pvtu" takes either file, after time_clean_debris). Errors name the file and line: endTime < startTime,
 * deltaT <= 0, writeInterval <= 0, no time directory for latestTime. */
int time_read(const struct dict *control, const char *case_dir,
              const char *const *need, struct run_time *t);

/* Name of time t with `precision` significant digits. */
const char *time_name(double t, int precision, char *buf, size_t n);

/* Newest time directory of the case (a directory whose name is a number)
 * that holds every file of `need` (NULL: any); newer ones without them are
 * named in a warning (a run whose peer died writes only its own cloud).
 * SIM_ERR_IO when there is none. Failure dumps (failed.<t>/) are never
 * time directories. */
int time_latest(const char *case_dir, const char *const *need, double *t,
                char *name, size_t n);

/* Remove the debris of killed or failed runs from the case: "*.tmp.<pid>"
 * files of writers that no longer run, in the case root, the time
 * directories and failed.* dumps, and empty time directories other than
 * 0. Returns how many were removed; each is logged. */
int time_clean_debris(const char *case_dir);

/* Non-zero while the run has not reached endTime. */
int time_running(const struct run_time *t);

/* Set the next step: dt_wanted (ignored unless adjust; then bounded by
 * maxDeltaT), shortened to land exactly on the next write time
 * (adjustableRunTime) and on endTime. */
void time_set_step(struct run_time *t, double dt_wanted);

/* Advance: value += dt (snapped to write times / endTime), step++, update
 * write_now and name. */
void time_increment(struct run_time *t);

/* Create "<case>/<prefix><name>/" for the current time (prefix "" for a
 * time directory, "failed." for the state a failure leaves to inspect,
 * which latestTime never takes); path into dir. */
int time_make_dir(const struct run_time *t, const char *case_dir,
                  const char *prefix, char *dir, size_t n);
/* Its path alone (the ranks of a distributed run that do not create it). */
void time_dir_path(const struct run_time *t, const char *case_dir,
                   const char *prefix, char *dir, size_t n);

/* Remove dir if it is empty: after a write into it failed. */
void time_dir_discard(const char *dir);

/* Progress: one line per step when stdout is not a terminal; at most one
 * line per second, with % of endTime, steps/s and time left, when it is.
 * `extra` is appended (solver iterations, residuals...). */
void time_log_progress(struct run_time *t, const char *extra);

#endif
