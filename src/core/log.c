/* log.c — see log.h. */
#include "core/log.h"

#include <stdarg.h>

static int quiet;
static long nwarn;

void log_set_quiet(int q) { quiet = q; }
long log_warning_count(void) { return nwarn; }

void log_info(const char *fmt, ...)
{
    if (quiet)
        return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stdout, fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
}

void log_warn(const char *fmt, ...)
{
    va_list ap;
    #pragma omp atomic
    nwarn++;
    fputs("--> WARNING: ", stdout);
    va_start(ap, fmt);
    vfprintf(stdout, fmt, ap);
    va_end(ap);
    fputc('\n', stdout);
    fflush(stdout);
}
