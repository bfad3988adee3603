/*
 * xmlio.h — the thin libxml2 adapter shared by the VTU and PVD code: atomic
 * output through a temporary file, and parsing with libxml2's messages
 * turned into our SIM_ERR_IO (doc/design.md C6: every libxml2 call is wrapped
 * once). Internal to src/io.
 */
#ifndef MPSDEM_IO_XMLIO_H
#define MPSDEM_IO_XMLIO_H

#include <stdio.h>

#include <libxml/tree.h>
#include <libxml/xmlwriter.h>

/* An XML file being written as "<path>.tmp.<pid>" and renamed on commit. */
struct xml_out {
    const char *path; /* final name (borrowed)                     */
    char *tmp;        /* temporary name, owned                     */
    FILE *fp;
    xmlTextWriterPtr w;
    int failed;       /* a writer call failed: commit will refuse  */
};

/* Create the temporary file and a writer on it with the XML declaration
 * written. On failure nothing is left on disk. */
int xml_out_open(struct xml_out *o, const char *path);

/* Finish the document, flush, close and rename onto path. On any failure
 * the temporary file is removed and the old file (if any) is untouched. */
int xml_out_commit(struct xml_out *o);

/* Give up: close and remove the temporary file. Safe after a failed open. */
void xml_out_abort(struct xml_out *o);

/* Record the result of a writer call (libxml2 returns < 0 on failure); the
 * error is reported once, at commit. Returns rc < 0. */
static inline int xml_out_check(struct xml_out *o, int rc)
{
    if (rc < 0)
        o->failed = 1;
    return rc < 0;
}

/* Parse path into a DOM tree (huge text nodes allowed, no network). A
 * missing file or malformed XML is SIM_ERR_IO: "path: line N: <libxml2's
 * message>". Release with xmlFreeDoc. */
int xml_in_read(const char *path, xmlDocPtr *doc);

/* The first child element of parent called name, or NULL. */
xmlNodePtr xml_child(xmlNodePtr parent, const char *name);

/* Copy attribute name of node into buf (NUL terminated). Returns 1 when
 * present, 0 when absent, -1 when longer than n - 1 characters. */
int xml_attr(xmlNodePtr node, const char *name, char *buf, size_t n);

#endif
