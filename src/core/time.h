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

/* Read controlDict (startFrom latestTime looks into case_dir). Errors name
 * the file and line: endTime < startTime, deltaT <= 0, writeInterval <= 0,
 * no time directory for latestTime. */
int time_read(const struct dict *control, const char *case_dir,
              struct run_time *t);

/* Name of time t with `precision` significant digits. */
const char *time_name(double t, int precision, char *buf, size_t n);

/* Newest time directory of the case (a directory whose name is a number);
 * SIM_ERR_IO when there is none. */
int time_latest(const char *case_dir, double *t, char *name, size_t n);

/* Non-zero while the run has not reached endTime. */
int time_running(const struct run_time *t);

/* Set the next step: dt_wanted (ignored unless adjust; then bounded by
 * maxDeltaT), shortened to land exactly on the next write time
 * (adjustableRunTime) and on endTime. */
void time_set_step(struct run_time *t, double dt_wanted);

/* Advance: value += dt (snapped to write times / endTime), step++, update
 * write_now and name. */
void time_increment(struct run_time *t);

/* Create "<case>/<name>/" for the current time; path into dir. */
int time_make_dir(const struct run_time *t, const char *case_dir, char *dir,
                  size_t n);

/* Progress: one line per step when stdout is not a terminal; at most one
 * line per second, with % of endTime, steps/s and time left, when it is.
 * `extra` is appended (solver iterations, residuals...). */
void time_log_progress(struct run_time *t, const char *extra);

#endif
