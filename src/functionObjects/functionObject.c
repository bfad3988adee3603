/*
 * functionObject.c — selection, scheduling and output files of function
 * objects (see functionObject.h). The types themselves live in fo_*.c.
 */
#include "functionObjects/functionObject.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/dict.h"
#include "core/error.h"
#include "core/files.h"
#include "core/log.h"
#include "core/time.h"

enum fo_control { FO_TIME_STEP, FO_RUN_TIME, FO_WRITE_TIME };

static const char *const control_words[] = {
    "timeStep", "runTime", "adjustableRunTime", "writeTime", NULL};

struct fo_entry {
    const char *name;
    const struct fo_ops *ops;
    void *data;
    enum fo_control control;
    double interval;     /* steps or seconds                         */
    double t_start, t_end;
    long last_index;     /* runTime: last interval index executed    */
    FILE *out;
};

struct fo_list {
    int n;
    struct fo_entry *e;
};

static const struct fo_ops *find_type(const struct fo_ops *const *const *tables,
                                      const char *type)
{
    for (int t = 0; tables[t]; t++)
        for (int i = 0; tables[t][i]; i++)
            if (!strcmp(tables[t][i]->name, type))
                return tables[t][i];
    return NULL;
}

static int unknown_type(const struct dict *d, const char *type,
                        const struct fo_ops *const *const *tables)
{
    char valid[1024] = "";
    size_t used = 0;
    for (int t = 0; tables[t]; t++)
        for (int i = 0; tables[t][i] && used < sizeof valid - 64; i++)
            used += snprintf(valid + used, sizeof valid - used, " %s",
                             tables[t][i]->name);
    return dict_error(d, "type", SIM_ERR_DICT,
                      "unknown function object type '%s'; valid:%s", type,
                      valid);
}

static int read_schedule(const struct dict *d, struct fo_entry *e)
{
    int idx;
    TRY(dict_get_word_or(d, "writeControl", control_words, 0, &idx));
    e->control = idx == 0 ? FO_TIME_STEP : idx == 3 ? FO_WRITE_TIME
                                                    : FO_RUN_TIME;
    TRY(dict_get_scalar_or(d, "writeInterval", 1.0, &e->interval));
    if (e->control != FO_WRITE_TIME && !(e->interval > 0))
        return dict_error(d, "writeInterval", SIM_ERR_DICT,
                          "writeInterval must be positive, got %g",
                          e->interval);
    if (e->control == FO_TIME_STEP && e->interval != floor(e->interval))
        return dict_error(d, "writeInterval", SIM_ERR_DICT,
                          "writeInterval counts steps with writeControl "
                          "timeStep; got %g", e->interval);
    TRY(dict_get_scalar_or(d, "timeStart", -HUGE_VAL, &e->t_start));
    TRY(dict_get_scalar_or(d, "timeEnd", HUGE_VAL, &e->t_end));
    if (e->t_end < e->t_start)
        return dict_error(d, "timeEnd", SIM_ERR_DICT,
                          "timeEnd (%g) is before timeStart (%g)", e->t_end,
                          e->t_start);
    e->last_index = -1;
    return SIM_OK;
}

static int open_output(struct fo_entry *e, const struct fo_scene *s,
                       const char *case_dir, double start_time,
                       int precision)
{
    char tname[64], dir[4096], path[4200];
    time_name(start_time, precision, tname, sizeof tname);
    if (!strcmp(case_dir, "."))
        snprintf(dir, sizeof dir, "postProcessing/%s/%s", e->name, tname);
    else
        snprintf(dir, sizeof dir, "%s/postProcessing/%s/%s", case_dir,
                 e->name, tname);
    TRY(files_mkdir_p(dir));
    const char *file = e->ops->file && e->ops->file[0] ? e->ops->file
                                                        : e->ops->name;
    snprintf(path, sizeof path, "%s/%s.dat", dir, file);
    e->out = fopen(path, "w");
    if (!e->out)
        return sim_error(SIM_ERR_IO, "cannot write '%s': %s", path,
                         strerror(errno));
    int rc = e->ops->header(e->data, s, e->out);
    if (rc != SIM_OK || fflush(e->out) != 0) {
        fclose(e->out);
        e->out = NULL;
        return rc != SIM_OK ? rc : sim_error(SIM_ERR_IO, "cannot write '%s'",
                                             path);
    }
    return SIM_OK;
}

static int create_entry(const struct dict *fd, const char *key,
                        const struct fo_ops *const *const *tables,
                        const struct fo_scene *s, const char *case_dir,
                        double start_time, int precision, struct fo_entry *e,
                        int *enabled)
{
    const struct dict *d;
    const char *type;
    if (!dict_is_dict(fd, key))
        return dict_error(fd, key, SIM_ERR_DICT,
                          "function object '%s' must be a sub-dictionary "
                          "{ type ...; }", key);
    TRY(dict_get_dict(fd, key, &d));
    TRY(dict_get_bool_or(d, "enabled", 1, enabled));
    /* `cloud fluid|dem;` (optional): in a coupled case both programs read
     * the same controlDict; an entry for the other program's cloud is
     * skipped like a disabled one, its type unchecked. */
    const char *cloud;
    TRY(dict_get_string_or(d, "cloud", "", &cloud));
    if (cloud[0] && s->cloud_name && strcmp(cloud, s->cloud_name) != 0) {
        *enabled = 0;
        for (int i = 0; i < dict_size(d); i++)
            dict_mark_used(d, dict_key_at(d, i));
        return SIM_OK;
    }
    TRY(dict_get_string(d, "type", &type));
    e->name = key;
    e->ops = find_type(tables, type);
    if (!e->ops)
        return unknown_type(d, type, tables);
    TRY(read_schedule(d, e));
    if (!*enabled) {    /* a disabled entry's keys are not "unused" */
        for (int i = 0; i < dict_size(d); i++)
            dict_mark_used(d, dict_key_at(d, i));
        return SIM_OK;
    }
    log_info("Selecting function object %s for %s", e->ops->name, key);
    TRY(e->ops->create(d, s, &e->data));
    int rc = open_output(e, s, case_dir, start_time, precision);
    if (rc != SIM_OK) {     /* the entry is not kept: release it here */
        e->ops->destroy(e->data);
        e->data = NULL;
    }
    return rc;
}

int fo_list_create(const struct dict *functions,
                   const struct fo_ops *const *const *tables,
                   const struct fo_scene *s, const char *case_dir,
                   double start_time, int precision, struct fo_list **out)
{
    struct fo_list *l = sim_calloc(1, sizeof *l);
    if (!l)
        return SIM_ERR_NOMEM;
    int n = functions ? dict_size(functions) : 0;
    l->e = sim_calloc((size_t)n + 1, sizeof *l->e);
    if (!l->e) {
        free(l);
        return SIM_ERR_NOMEM;
    }
    for (int i = 0; i < n; i++) {
        int enabled = 1;
        struct fo_entry *e = &l->e[l->n];
        int rc = create_entry(functions, dict_key_at(functions, i), tables, s,
                              case_dir, start_time, precision, e, &enabled);
        if (rc == SIM_OK && enabled)
            l->n++;
        else if (rc == SIM_OK) {
            memset(e, 0, sizeof *e);
        } else {
            fo_list_free(l);
            sim_trace(__FILE__, __LINE__, __func__, rc);
            return rc;
        }
    }
    *out = l;
    return SIM_OK;
}

/* Is entry e due at (time, step)? mark: record a runTime entry's
 * interval as done. */
static int is_due(struct fo_entry *e, double time, long step, double dt,
                  int write_time, int mark)
{
    /* Half a step of slack so that a schedule edge is not missed by
     * round-off in the solver's time. */
    double slack = 0.5 * dt;
    if (time < e->t_start - slack || time > e->t_end + slack)
        return 0;
    switch (e->control) {
    case FO_TIME_STEP:
        return step % (long)e->interval == 0;
    case FO_WRITE_TIME:
        return write_time;
    case FO_RUN_TIME: {
        long k = (long)floor(time / e->interval + 1e-6);
        if (k <= e->last_index)
            return 0;
        if (mark)
            e->last_index = k;
        return 1;
    }
    }
    return 0;
}

int fo_list_due(struct fo_list *l, double time, long step, double dt,
                int write_time)
{
    for (int i = 0; l && i < l->n; i++)
        if (is_due(&l->e[i], time, step, dt, write_time, 0))
            return 1;
    return 0;
}

int fo_list_execute(struct fo_list *l, const struct fo_scene *s,
                    int write_time)
{
    for (int i = 0; i < l->n; i++) {
        struct fo_entry *e = &l->e[i];
        if (!is_due(e, s->time, s->step, s->dt, write_time, 1))
            continue;
        int rc = e->ops->execute(e->data, s, e->out);
        if (rc != SIM_OK) {
            sim_trace(__FILE__, __LINE__, e->name, rc);
            return rc;
        }
        if (fflush(e->out) != 0)
            return sim_error(SIM_ERR_IO, "function object %s: write failed: "
                             "%s", e->name, strerror(errno));
    }
    return SIM_OK;
}

void fo_list_free(struct fo_list *l)
{
    if (!l)
        return;
    for (int i = 0; i < l->n; i++) {
        if (l->e[i].ops && l->e[i].data)
            l->e[i].ops->destroy(l->e[i].data);
        if (l->e[i].out)
            fclose(l->e[i].out);
    }
    free(l->e);
    free(l);
}
