/* error.c — thread-local error message and traceback (see error.h). */
#include "core/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MSG_SIZE 4096
#define TRACE_SIZE 4096

static _Thread_local char msg_buf[MSG_SIZE];
static _Thread_local char trace_buf[TRACE_SIZE];

#define SIM_ERR_TEXT_(name, text) text,
static const char *const err_text[] = { SIM_ERR_LIST(SIM_ERR_TEXT_) };
#undef SIM_ERR_TEXT_

const char *sim_strerror(int code)
{
    if (code < 0 || code >= SIM_ERR_COUNT)
        return "unknown error";
    return err_text[code];
}

int sim_error(int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg_buf, sizeof msg_buf, fmt, ap);
    va_end(ap);
    trace_buf[0] = '\0';
    return code;
}

const char *sim_error_message(void) { return msg_buf; }
const char *sim_error_trace(void) { return trace_buf; }

void sim_error_clear(void)
{
    msg_buf[0] = '\0';
    trace_buf[0] = '\0';
}

void sim_trace(const char *file, int line, const char *func, int code)
{
    size_t used = strlen(trace_buf);
    if (used + 1 >= sizeof trace_buf)
        return;
    if (msg_buf[0] == '\0')     /* a code without a message: say what it is */
        snprintf(msg_buf, sizeof msg_buf, "%s", sim_strerror(code));
    snprintf(trace_buf + used, sizeof trace_buf - used, "    in %s (%s:%d)\n",
             func, file, line);
}

void *sim_malloc(size_t nbytes)
{
    void *p = malloc(nbytes ? nbytes : 1);
    if (!p)
        sim_error(SIM_ERR_NOMEM, "cannot allocate %zu bytes", nbytes);
    return p;
}

void *sim_calloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size ? size : 1);
    if (!p)
        sim_error(SIM_ERR_NOMEM, "cannot allocate %zu x %zu bytes", n, size);
    return p;
}

void *sim_realloc(void *p, size_t nbytes)
{
    void *q = realloc(p, nbytes ? nbytes : 1);
    if (!q)
        sim_error(SIM_ERR_NOMEM, "cannot reallocate to %zu bytes", nbytes);
    return q;
}

char *sim_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = sim_malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

int sim_reserve(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap && *p)
        return SIM_OK;
    size_t n = need + need / 2 + 16;
    void *q = sim_realloc(*p, n * size);
    if (!q)
        return SIM_ERR_NOMEM;
    *p = q;
    *cap = n;
    return SIM_OK;
}
