/*
 * error.h — error codes, messages and tracebacks shared by every library.
 *
 * Libraries never exit: they return one of the codes below and, where there is
 * something to say, set a message with sim_error() first (the message of an
 * input error starts with "file:line:col: "). TRY() propagates a failure and
 * records one traceback line per level, as PETSc's PetscCall does. Only an
 * application decides to stop (app_fatal() in app.h).
 *
 * The message and the trace live in thread-local storage; the first
 * sim_error() after a success replaces the previous message.
 */
#ifndef MPSDEM_CORE_ERROR_H
#define MPSDEM_CORE_ERROR_H

#include <stddef.h>

#define SIM_ERR_LIST(X)                                                  \
    X(SIM_OK,           "success")                                       \
    X(SIM_ERR_IO,       "file input/output error")                       \
    X(SIM_ERR_PARSE,    "syntax error in a dictionary")                  \
    X(SIM_ERR_DICT,     "invalid or missing dictionary entry")           \
    X(SIM_ERR_INPUT,    "invalid input")                                 \
    X(SIM_ERR_NOMEM,    "allocation failed")                             \
    X(SIM_ERR_SOLVER,   "linear or nonlinear solver failed")             \
    X(SIM_ERR_NUMERIC,  "non-finite or out-of-range value")              \
    X(SIM_ERR_EXTERNAL, "SUNDIALS/SuiteSparse/libxml2 error")            \
    X(SIM_ERR_PEER,     "coupling peer failed or disagreed")             \
    X(SIM_ERR_TIMEOUT,  "timed out")                                     \
    X(SIM_ERR_INTERRUPT,"interrupted by a signal")                       \
    X(SIM_ERR_INTERNAL, "internal error")

#define SIM_ERR_ENUM_(name, text) name,
enum sim_err { SIM_ERR_LIST(SIM_ERR_ENUM_) SIM_ERR_COUNT };
#undef SIM_ERR_ENUM_

/* Text of a code ("allocation failed"); never NULL. */
const char *sim_strerror(int code);

/* Set the current message (printf format) and return code, so that
 * `return sim_error(SIM_ERR_DICT, "%s: ...", loc);` reads naturally. */
int sim_error(int code, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* The current message, or "" when none was set. */
const char *sim_error_message(void);

/* The traceback recorded by TRY(), one "    in func (file:line)" per line. */
const char *sim_error_trace(void);

/* Forget message and trace (after an error was handled). */
void sim_error_clear(void);

/* Append one traceback line; used by TRY(). */
void sim_trace(const char *file, int line, const char *func, int code);

#define TRY(call)                                                        \
    do {                                                                 \
        int rc_ = (call);                                                \
        if (rc_ != SIM_OK) {                                             \
            sim_trace(__FILE__, __LINE__, __func__, rc_);                \
            return rc_;                                                  \
        }                                                                \
    } while (0)

/* Like TRY but jumps to a cleanup label with rc set (Linux goto style). */
#define TRY_GOTO(rc, call, label)                                        \
    do {                                                                 \
        (rc) = (call);                                                   \
        if ((rc) != SIM_OK) {                                            \
            sim_trace(__FILE__, __LINE__, __func__, (rc));               \
            goto label;                                                  \
        }                                                                \
    } while (0)

/* Allocation helpers that set SIM_ERR_NOMEM with the size asked for. */
void *sim_malloc(size_t nbytes);
void *sim_calloc(size_t n, size_t size);
void *sim_realloc(void *p, size_t nbytes);
char *sim_strdup(const char *s);

/* Make *p hold at least `need` elements of `size` bytes; *cap counts them.
 * Grows by 1.5x, so that slowly rising counts do not reallocate each step;
 * on failure the old storage stays valid and SIM_ERR_NOMEM is returned. */
int sim_reserve(void **p, size_t *cap, size_t need, size_t size);

/* Grow the array p to hold count elements, or return SIM_ERR_NOMEM from
 * the calling function (the old storage stays valid and owned by p). */
#define SIM_GROW(p, count)                                               \
    do {                                                                 \
        void *q_ = sim_realloc((p), (size_t)(count) * sizeof *(p));      \
        if (!q_)                                                         \
            return SIM_ERR_NOMEM;                                        \
        (p) = q_;                                                        \
    } while (0)

#endif
