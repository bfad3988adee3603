/* app.c — command line, log header, fatal errors and timing (see app.h). */
#include "core/app.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/dict.h"
#include "core/error.h"
#include "core/files.h"
#include "core/log.h"
#include "core/version.h"

double app_wall_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double app_cpu_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double app_peak_memory(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru))
        return 0;
    return 1024.0 * (double)ru.ru_maxrss; /* Linux: kB */
}

void app_log_peak_memory(long n)
{
    double b = app_peak_memory();
    log_info("    peak memory           %.0f MB (%.2f kB per particle)",
             b / 1e6, n > 0 ? b / 1e3 / (double)n : 0.0);
}

static void usage(const char *name, const char *description,
                  const struct app_option *opts, int allow_args)
{
    printf("Usage: %s [OPTIONS]%s\n\n%s\n\nOptions:\n", name,
           allow_args ? " [ARGS]" : "", description);
    printf("  %-22s %s\n", "-case DIR", "case directory (default: .)");
    for (int i = 0; opts && opts[i].flag; i++) {
        char f[64];
        snprintf(f, sizeof f, "%s%s%s", opts[i].flag,
                 opts[i].takes_arg ? " " : "",
                 opts[i].takes_arg ? opts[i].argname : "");
        printf("  %-22s %s\n", f, opts[i].help);
    }
    printf("  %-22s %s\n", "-help", "print this message and exit");
}

static void die_usage(const char *name, const char *fmt, const char *arg)
{
    fprintf(stderr, "\n--> FATAL ERROR: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n    (%s -help lists the options)\n\n", name);
    exit(1);
}

static void print_header(const struct app *a)
{
    char host[256] = "?", date[64];
    time_t now = time(NULL);
    gethostname(host, sizeof host);
    strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S", localtime(&now));
    int threads = 1;
#ifdef _OPENMP
    threads = omp_get_max_threads();
#endif
    log_info("/*---------------------------------------------------------------"
             "------------*\\");
    log_info("  mpsdem %s  |  %s", MPSDEM_VERSION, a->name);
    log_info("  Build   : git %s", mpsdem_git_revision);
    log_info("  Case    : %s", a->case_abs);
    log_info("  Date    : %s", date);
    log_info("  Host    : %s   PID : %d   Threads : %d", host, (int)getpid(),
             threads);
    log_info("\\*--------------------------------------------------------------"
             "-------------*/\n");
}

void app_init(struct app *a, const char *name, const char *description,
              int argc, char **argv, const struct app_option *opts,
              int allow_args)
{
    /* A log redirected to a file is block-buffered by default, so a run
     * that is killed or crashes loses its last 4 KB, the lines that tell
     * where and why it stopped. The solvers print one line per step, so a
     * write per line costs nothing measurable. Before any output. */
    setvbuf(stdout, NULL, _IOLBF, 0);
    memset(a, 0, sizeof *a);
    a->name = name;
    a->case_dir = ".";
    a->wall0 = app_wall_time();
    a->cpu0 = app_cpu_time();
    a->args = calloc((size_t)argc + 1, sizeof *a->args);
    if (!a->args)
        die_usage(name, "%s", "out of memory");

    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (!strcmp(s, "-help") || !strcmp(s, "--help") || !strcmp(s, "-h")) {
            usage(name, description, opts, allow_args);
            exit(0);
        }
        if (!strcmp(s, "-case")) {
            if (i + 1 >= argc)
                die_usage(name, "option %s needs a directory", s);
            a->case_dir = argv[++i];
            continue;
        }
        const struct app_option *o = NULL;
        for (int k = 0; opts && opts[k].flag; k++)
            if (!strcmp(s, opts[k].flag))
                o = &opts[k];
        if (o) {
            if (o->takes_arg && i + 1 >= argc)
                die_usage(name, "option %s needs an argument", s);
            *o->value = o->takes_arg ? argv[++i] : "";
            continue;
        }
        if (s[0] == '-' && s[1] != '\0')
            die_usage(name, "unknown option '%s'", s);
        if (!allow_args)
            die_usage(name, "unexpected argument '%s'", s);
        a->args[a->nargs++] = argv[i];
    }

    struct stat st;
    if (stat(a->case_dir, &st) != 0 || !S_ISDIR(st.st_mode))
        die_usage(name, "case directory '%s' does not exist", a->case_dir);
    if (!realpath(a->case_dir, a->case_abs))
        snprintf(a->case_abs, sizeof a->case_abs, "%s", a->case_dir);
    print_header(a);
}

const char *app_path(const struct app *a, const char *rel, char *buf,
                     size_t n)
{
    if (!strcmp(a->case_dir, "."))
        snprintf(buf, n, "%s", rel);
    else
        snprintf(buf, n, "%s/%s", a->case_dir, rel);
    return buf;
}

int app_read_dict(const struct app *a, const char *rel, struct dict **out)
{
    char path[4096];
    app_path(a, rel, path, sizeof path);
    return dict_read(path, out);
}

int app_read_dict_optional(const struct app *a, const char *rel,
                           struct dict **out)
{
    char path[4200];
    *out = NULL;
    if (access(app_path(a, rel, path, sizeof path), F_OK) != 0)
        return SIM_OK;
    return app_read_dict(a, rel, out);
}

int app_lock_case(const struct app *a)
{
    char rel[256], path[4400];
    snprintf(rel, sizeof rel, ".%s.lock", a->name);
    app_path(a, rel, path, sizeof path);
    /* The descriptor stays open (and locked) for the life of the process. */
    int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd < 0)
        return sim_error(SIM_ERR_IO, "cannot open the case lock '%s': %s",
                         path, strerror(errno));
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
        int e = errno;
        char pid[32] = "";
        ssize_t k = pread(fd, pid, sizeof pid - 1, 0);
        pid[k > 0 ? k : 0] = '\0';
        pid[strcspn(pid, "\n")] = '\0';
        close(fd);
        if (e == EWOULDBLOCK)
            return sim_error(SIM_ERR_IO, "%s is already running on case "
                             "'%s' (pid %s, lock %s): wait for it or stop "
                             "it; nothing of its output was touched",
                             a->name, a->case_abs, pid[0] ? pid : "?", path);
        return sim_error(SIM_ERR_IO, "cannot lock '%s': %s", path,
                         strerror(e));
    }
    char pid[32];
    int n = snprintf(pid, sizeof pid, "%ld\n", (long)getpid());
    if (ftruncate(fd, 0) != 0 || pwrite(fd, pid, (size_t)n, 0) != n)
        log_warn("could not write the pid into the case lock '%s'", path);
    return SIM_OK;
}

void app_fatal(const struct app *a, int rc)
{
    const char *msg = sim_error_message();
    const char *trace = sim_error_trace();
    if (!msg[0])
        msg = sim_strerror(rc);
    for (int k = 0; k < 2; k++) {
        FILE *f = k ? stderr : stdout;
        fprintf(f, "\n--> FATAL ERROR in %s (%s)\n    %s\n", a->name,
                sim_strerror(rc), msg);
        if (trace[0])
            fprintf(f, "\n    Traceback:\n%s", trace);
        fprintf(f, "\n    %s exiting\n\n", a->name);
        fflush(f);
        /* Logs redirected with 2>&1 would show the block twice. */
        if (isatty(STDOUT_FILENO) == isatty(STDERR_FILENO)) {
            struct stat so, se;
            if (!fstat(STDOUT_FILENO, &so) && !fstat(STDERR_FILENO, &se) &&
                so.st_ino == se.st_ino && so.st_dev == se.st_dev)
                break;
        }
    }
    free(a->args);
    exit(1);
}

void app_log_times(const struct app *a)
{
    log_info("ExecutionTime = %.2f s  ClockTime = %.0f s\n",
             app_cpu_time() - a->cpu0, app_wall_time() - a->wall0);
}

int app_write_used_parameters(const struct app *a)
{
    char dir[4096], path[4200];
    app_path(a, "postProcessing/usedParameters", dir, sizeof dir);
    TRY(files_mkdir_p(dir));
    snprintf(path, sizeof path, "%s/%s", dir, a->name);
    return params_write(path, 1);
}

int app_end(const struct app *a)
{
    log_info("End\n");
    fflush(stdout);
    free(a->args);
    return 0;
}
