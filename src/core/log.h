/*
 * log.h — what a program says, in OpenFOAM's manner.
 *
 * Everything goes to standard output (so that `> log.<app> 2>&1` keeps the
 * order), except FATAL ERROR blocks, which also go to standard error.
 * Warnings read "--> WARNING: <text>" and are counted, so that a program
 * can report at the end how many it gave.
 */
#ifndef MPSDEM_CORE_LOG_H
#define MPSDEM_CORE_LOG_H

#include <stdio.h>

void log_info(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void log_warn(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Number of warnings given so far. */
long log_warning_count(void);

/* Silence log_info (tests); warnings still print. */
void log_set_quiet(int quiet);

#endif
