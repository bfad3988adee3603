/*
 * pvd.c — ParaView collections (.pvd): one DataSet per written time, sorted
 * by time, file paths relative to the .pvd (vtu.h; doc/libraries.md §3).
 *
 * The collection is read with libxml2, edited in memory and rewritten
 * atomically, so a crash leaves either the old or the new collection. A
 * collection that does not parse, or whose DataSets lack a finite
 * timestep or a file, is an error: it is never silently replaced.
 *
 * Two times are "the same" when they differ by less than 1e-10 of their
 * magnitude: a restarted run recomputes t = t0 + k dt and may differ from
 * the first run in the last bits.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/error.h"
#include "io/vtu.h"
#include "io/xmlio.h"

struct entry {
    double time;
    char *file;
    char *group; /* kept as read; "" when absent */
    char *part;  /* kept as read; "0" when absent */
};

struct collection {
    int n, cap;
    struct entry *e;
};

static void collection_free(struct collection *c)
{
    for (int i = 0; i < c->n; i++) {
        free(c->e[i].file);
        free(c->e[i].group);
        free(c->e[i].part);
    }
    free(c->e);
    memset(c, 0, sizeof *c);
}

static int same_time(double a, double b)
{
    return fabs(a - b) <= 1e-10 * fmax(fabs(a), fabs(b));
}

/* Insert keeping the order by time; entries of equal time keep file order. */
static int collection_insert(struct collection *c, double time,
                             const char *file, const char *group,
                             const char *part)
{
    struct entry e = { time, sim_strdup(file), sim_strdup(group),
                       sim_strdup(part) };
    int i;

    if (!e.file || !e.group || !e.part)
        goto nomem;
    if (c->n == c->cap) {
        int cap = c->cap ? 2 * c->cap : 16;
        struct entry *p = sim_realloc(c->e, (size_t)cap * sizeof *p);
        if (!p)
            goto nomem;
        c->e = p;
        c->cap = cap;
    }
    for (i = c->n; i > 0 && c->e[i - 1].time > time; i--)
        c->e[i] = c->e[i - 1];
    c->e[i] = e;
    c->n++;
    return SIM_OK;
nomem:
    free(e.file);
    free(e.group);
    free(e.part);
    return SIM_ERR_NOMEM;
}

static int read_dataset(const char *path, xmlNodePtr ds, struct collection *c)
{
    char ts[64], group[256] = "", part[64] = "0", *end, *file;
    double t;
    int rc;

    if (xml_attr(ds, "timestep", ts, sizeof ts) != 1)
        return sim_error(SIM_ERR_IO, "%s: line %d: DataSet without a "
                         "timestep", path, (int)ds->line);
    t = strtod(ts, &end);
    if (end == ts || *end || !isfinite(t))
        return sim_error(SIM_ERR_IO, "%s: line %d: timestep '%s' is not a "
                         "finite number", path, (int)ds->line, ts);
    if (xml_attr(ds, "group", group, sizeof group) < 0 ||
        xml_attr(ds, "part", part, sizeof part) < 0)
        return sim_error(SIM_ERR_IO, "%s: line %d: group or part attribute "
                         "too long", path, (int)ds->line);
    file = (char *)xmlGetProp(ds, BAD_CAST "file");
    if (!file || !file[0]) {
        xmlFree(file);
        return sim_error(SIM_ERR_IO, "%s: line %d: DataSet without a file",
                         path, (int)ds->line);
    }
    rc = collection_insert(c, t, file, group, part);
    xmlFree(file);
    return rc;
}

/* Load an existing collection; a missing file is an empty collection. */
static int collection_read(const char *path, struct collection *c)
{
    xmlDocPtr doc;
    xmlNodePtr root, coll;
    char type[64];
    int rc = SIM_OK;

    memset(c, 0, sizeof *c);
    if (access(path, F_OK) != 0 && errno == ENOENT)
        return SIM_OK;
    TRY(xml_in_read(path, &doc));
    root = xmlDocGetRootElement(doc);
    if (!root || strcmp((const char *)root->name, "VTKFile") != 0 ||
        xml_attr(root, "type", type, sizeof type) != 1 ||
        strcmp(type, "Collection") != 0 ||
        !(coll = xml_child(root, "Collection"))) {
        rc = sim_error(SIM_ERR_IO, "%s: not a ParaView collection (expected "
                       "<VTKFile type=\"Collection\"><Collection>)", path);
        goto out;
    }
    for (xmlNodePtr x = coll->children; x; x = x->next) {
        if (x->type != XML_ELEMENT_NODE)
            continue;
        if (strcmp((const char *)x->name, "DataSet") != 0) {
            rc = sim_error(SIM_ERR_IO, "%s: line %d: unexpected <%s> in "
                           "Collection", path, (int)x->line,
                           (const char *)x->name);
            goto out;
        }
        TRY_GOTO(rc, read_dataset(path, x, c), out);
    }
out:
    xmlFreeDoc(doc);
    if (rc != SIM_OK)
        collection_free(c);
    return rc;
}

static int collection_write(const char *path, const struct collection *c)
{
    struct xml_out o;
    xmlTextWriterPtr w;

    TRY(xml_out_open(&o, path));
    w = o.w;
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "VTKFile"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "type",
                                                  BAD_CAST "Collection"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "version",
                                                  BAD_CAST "0.1"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(
                          w, BAD_CAST "byte_order", BAD_CAST "LittleEndian"));
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "Collection"));
    for (int i = 0; i < c->n; i++) {
        const struct entry *e = &c->e[i];
        xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "DataSet"));
        xml_out_check(&o, xmlTextWriterWriteFormatAttribute(
                              w, BAD_CAST "timestep", "%.17g", e->time));
        xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "group",
                                                      BAD_CAST e->group));
        xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "part",
                                                      BAD_CAST e->part));
        xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "file",
                                                      BAD_CAST e->file));
        xml_out_check(&o, xmlTextWriterEndElement(w));
    }
    return xml_out_commit(&o);
}

int pvd_add(const char *pvd_path, double time, const char *file)
{
    struct collection c;
    int rc, k = 0;

    if (!isfinite(time))
        return sim_error(SIM_ERR_INTERNAL, "%s: cannot add time %g", pvd_path,
                         time);
    TRY(collection_read(pvd_path, &c));
    /* Replace what was written for this time (part 0) before. */
    for (int i = 0; i < c.n; i++) {
        struct entry *e = &c.e[i];
        if (same_time(e->time, time) && strcmp(e->part, "0") == 0) {
            free(e->file);
            free(e->group);
            free(e->part);
            continue;
        }
        c.e[k++] = *e;
    }
    c.n = k;
    TRY_GOTO(rc, collection_insert(&c, time, file, "", "0"), out);
    TRY_GOTO(rc, collection_write(pvd_path, &c), out);
out:
    collection_free(&c);
    return rc;
}

int pvd_truncate(const char *pvd_path, double t_max)
{
    struct collection c;
    int rc, k = 0;

    TRY(collection_read(pvd_path, &c));
    if (c.n == 0 && access(pvd_path, F_OK) != 0) {
        collection_free(&c);
        return SIM_OK; /* nothing written yet: nothing to drop */
    }
    for (int i = 0; i < c.n; i++) {
        struct entry *e = &c.e[i];
        if (e->time > t_max && !same_time(e->time, t_max)) {
            free(e->file);
            free(e->group);
            free(e->part);
            continue;
        }
        c.e[k++] = *e;
    }
    c.n = k;
    TRY_GOTO(rc, collection_write(pvd_path, &c), out);
out:
    collection_free(&c);
    return rc;
}
