/*
 * pvtu.c — the parallel form of a particle cloud (VTK's XML file formats,
 * "Parallel File Formats": a .pvtu names its pieces, each a .vtu, and
 * describes the arrays they hold). A distributed run writes one piece
 * per rank beside the .pvtu (doc/design.md §8); ParaView opens the .pvtu
 * as one dataset, and vtu_read reads it as the cloud of all pieces in
 * order, so that a restart or vtuInfo need not know how many ranks wrote
 * it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "io/vtu.h"
#include "io/xmlio.h"

int pvtu_write(const char *path, const struct vtu_cloud *layout, int npieces,
               const char *piece_fmt)
{
    struct xml_out o;
    TRY(xml_out_open(&o, path));
    xmlTextWriterPtr w = o.w;
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "VTKFile"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(
                          w, BAD_CAST "type", BAD_CAST "PUnstructuredGrid"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "version",
                                                  BAD_CAST "0.1"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(
                          w, BAD_CAST "byte_order", BAD_CAST "LittleEndian"));
    xml_out_check(&o, xmlTextWriterStartElement(
                          w, BAD_CAST "PUnstructuredGrid"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "GhostLevel",
                                                  BAD_CAST "0"));
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "PPointData"));
    for (int k = 0; k < layout->nfields; k++) {
        const struct vtu_field *f = &layout->fields[k];
        xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "PDataArray"));
        xml_out_check(&o, xmlTextWriterWriteAttribute(
                              w, BAD_CAST "type",
                              BAD_CAST vtu_type_name(f->type)));
        xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "Name",
                                                      BAD_CAST f->name));
        xml_out_check(&o, xmlTextWriterWriteFormatAttribute(
                              w, BAD_CAST "NumberOfComponents", "%d",
                              f->ncomp));
        xml_out_check(&o, xmlTextWriterEndElement(w));
    }
    xml_out_check(&o, xmlTextWriterEndElement(w));
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "PPoints"));
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "PDataArray"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "type",
                                                  BAD_CAST "Float64"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(
                          w, BAD_CAST "NumberOfComponents", BAD_CAST "3"));
    xml_out_check(&o, xmlTextWriterEndElement(w));
    xml_out_check(&o, xmlTextWriterEndElement(w));
    for (int p = 0; p < npieces; p++) {
        char src[256];
        snprintf(src, sizeof src, piece_fmt, p);
        xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "Piece"));
        xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "Source",
                                                      BAD_CAST src));
        xml_out_check(&o, xmlTextWriterEndElement(w));
    }
    return xml_out_commit(&o);
}

/* Piece b's points and fields after a's (same fields, same order). */
static int append(struct vtu_cloud *a, const struct vtu_cloud *b,
                  const char *path, const char *src)
{
    if (b->nfields != a->nfields)
        return sim_error(SIM_ERR_IO, "%s: piece %s has %d arrays, the first "
                         "piece %d", path, src, b->nfields, a->nfields);
    for (int k = 0; k < a->nfields; k++) {
        const struct vtu_field *f = &a->fields[k], *g = &b->fields[k];
        if (strcmp(f->name, g->name) || f->type != g->type
            || f->ncomp != g->ncomp)
            return sim_error(SIM_ERR_IO, "%s: piece %s: array %d is '%s' "
                             "(%s x %d), in the first piece '%s' (%s x %d)",
                             path, src, k, g->name,
                             vtu_type_name(g->type), g->ncomp, f->name,
                             vtu_type_name(f->type),
                             f->ncomp);
    }
    const size_t n = a->n + b->n;
    double *x = sim_realloc(a->points, 3 * (n + 1) * sizeof *x);
    if (!x)
        return SIM_ERR_NOMEM;
    memcpy(x + 3 * a->n, b->points, 3 * b->n * sizeof *x);
    a->points = x;
    for (int k = 0; k < a->nfields; k++) {
        struct vtu_field *f = &a->fields[k];
        const size_t e = vtu_type_size(f->type) * (size_t)f->ncomp;
        char *d = sim_realloc(f->data, e * (n + 1));
        if (!d)
            return SIM_ERR_NOMEM;
        memcpy(d + e * a->n, b->fields[k].data, e * b->n);
        f->data = d;
    }
    a->n = n;
    return SIM_OK;
}

int pvtu_read(const char *path, struct vtu_cloud *c)
{
    xmlDocPtr doc;
    char attr[64];
    memset(c, 0, sizeof *c);
    TRY(xml_in_read(path, &doc));
    xmlNodePtr root = xmlDocGetRootElement(doc), grid = NULL;
    int rc = SIM_OK, pieces = 0;
    if (!root || strcmp((const char *)root->name, "VTKFile")
        || xml_attr(root, "type", attr, sizeof attr) != 1
        || strcmp(attr, "PUnstructuredGrid")
        || !(grid = xml_child(root, "PUnstructuredGrid")))
        rc = sim_error(SIM_ERR_IO, "%s: not a VTK PUnstructuredGrid file",
                       path);
    /* pieces are named relative to the .pvtu's directory */
    char dir[4096] = ".";
    const char *slash = strrchr(path, '/');
    if (slash)
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    for (xmlNodePtr p = grid ? grid->children : NULL; p && !rc; p = p->next) {
        char src[1024], file[5200];
        if (p->type != XML_ELEMENT_NODE
            || strcmp((const char *)p->name, "Piece"))
            continue;
        if (xml_attr(p, "Source", src, sizeof src) != 1 || !src[0]) {
            rc = sim_error(SIM_ERR_IO, "%s: a Piece without Source", path);
            break;
        }
        snprintf(file, sizeof file, "%s/%s", dir, src);
        struct vtu_cloud b;
        rc = vtu_read(file, &b);
        if (!rc && pieces == 0)
            *c = b;
        else if (!rc) {
            rc = append(c, &b, path, src);
            vtu_cloud_free(&b);
        }
        pieces++;
    }
    if (!rc && pieces == 0)
        rc = sim_error(SIM_ERR_IO, "%s: no Piece", path);
    xmlFreeDoc(doc);
    if (rc)
        vtu_cloud_free(c);
    return rc;
}
