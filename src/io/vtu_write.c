/*
 * vtu_write.c — write a particle cloud as a VTK XML UnstructuredGrid
 * (vtu.h; layout in toolchain.md §3).
 *
 * The skeleton goes through libxml2's xmlTextWriter; array payloads are
 * produced here, in chunks, and handed over with xmlTextWriterWriteRaw:
 * binary payloads as our own unbroken base64 of the UInt64 byte count
 * followed, separately padded, by the data; ascii payloads as %.17g (exact
 * for doubles) or exact integers. Chunks hold a multiple of 3 bytes, so the
 * base64 of consecutive chunks concatenates without inner padding, and a
 * multiple of 8, so no element straddles two chunks.
 */
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "io/base64.h"
#include "io/vtu.h"
#include "io/xmlio.h"

#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "vtu_write.c writes byte_order=LittleEndian from host memory"
#endif

#define CHUNK (24 * 2048) /* bytes, multiple of 3 and of 8            */
#define TEXT_FLUSH 65536  /* ascii text is handed over past this size */

static const char *const type_names[] = { "Float64", "Int64", "Int32",
                                          "UInt8" };
static const size_t type_sizes[] = { 8, 8, 4, 1 };

/* A payload: borrowed bytes, or bytes made on demand (the cell arrays). */
struct payload {
    enum vtu_type type;
    int ncomp;
    size_t nbytes;
    const unsigned char *data;                  /* or NULL and gen  */
    void (*gen)(size_t first, size_t count, unsigned char *out);
};

static void gen_connectivity(size_t first, size_t count, unsigned char *out)
{
    int64_t *v = (int64_t *)(void *)out;
    for (size_t i = 0; i < count; i++)
        v[i] = (int64_t)(first + i);
}

static void gen_offsets(size_t first, size_t count, unsigned char *out)
{
    int64_t *v = (int64_t *)(void *)out;
    for (size_t i = 0; i < count; i++)
        v[i] = (int64_t)(first + i + 1); /* end offsets (VTK XML 1.0) */
}

static void gen_types(size_t first, size_t count, unsigned char *out)
{
    (void)first;
    memset(out, 1, count); /* VTK_VERTEX */
}

struct emitter {
    struct xml_out *o;
    char *text; /* TEXT_FLUSH + 64 bytes       */
    size_t len;
    unsigned char *chunk; /* CHUNK bytes (generated data) */
};

static void emit_flush(struct emitter *e)
{
    if (e->len == 0)
        return;
    e->text[e->len] = '\0';
    xml_out_check(e->o, xmlTextWriterWriteRaw(e->o->w, BAD_CAST e->text));
    e->len = 0;
}

static void emit_ascii(struct emitter *e, const struct payload *p,
                       const unsigned char *bytes, size_t first, size_t count)
{
    /* A line per point for vectors, eight values a line for scalars. */
    size_t per_line = p->ncomp > 1 ? (size_t)p->ncomp : 8;

    for (size_t i = 0; i < count; i++) {
        char *s = e->text + e->len;
        int k;
        switch (p->type) {
        case VTU_FLOAT64: {
            double v;
            memcpy(&v, bytes + 8 * i, 8);
            k = sprintf(s, "%.17g", v);
            break;
        }
        case VTU_INT64: {
            int64_t v;
            memcpy(&v, bytes + 8 * i, 8);
            k = sprintf(s, "%" PRId64, v);
            break;
        }
        case VTU_INT32: {
            int32_t v;
            memcpy(&v, bytes + 4 * i, 4);
            k = sprintf(s, "%" PRId32, v);
            break;
        }
        default:
            k = sprintf(s, "%u", (unsigned)bytes[i]);
            break;
        }
        e->len += (size_t)k;
        e->text[e->len++] = (first + i + 1) % per_line ? ' ' : '\n';
        if (e->len >= TEXT_FLUSH)
            emit_flush(e);
    }
}

static void emit_payload(struct emitter *e, const struct payload *p,
                         int binary)
{
    size_t esize = type_sizes[p->type];

    if (binary) {
        uint64_t header = p->nbytes;
        char hb[16];
        b64_encode(&header, sizeof header, hb);
        xml_out_check(e->o, xmlTextWriterWriteRaw(e->o->w, BAD_CAST hb));
    } else {
        xml_out_check(e->o, xmlTextWriterWriteRaw(e->o->w, BAD_CAST "\n"));
    }
    for (size_t off = 0; off < p->nbytes && !e->o->failed; off += CHUNK) {
        size_t len = p->nbytes - off < CHUNK ? p->nbytes - off : CHUNK;
        const unsigned char *bytes = p->data ? p->data + off : e->chunk;
        if (!p->data)
            p->gen(off / esize, len / esize, e->chunk);
        if (binary) {
            b64_encode(bytes, len, e->text);
            xml_out_check(e->o,
                          xmlTextWriterWriteRaw(e->o->w, BAD_CAST e->text));
        } else {
            emit_ascii(e, p, bytes, off / esize, len / esize);
        }
    }
    emit_flush(e);
}

static void write_array(struct emitter *e, const char *name,
                        const struct payload *p, int binary)
{
    xmlTextWriterPtr w = e->o->w;

    xml_out_check(e->o, xmlTextWriterStartElement(w, BAD_CAST "DataArray"));
    xml_out_check(e->o, xmlTextWriterWriteAttribute(
                            w, BAD_CAST "type", BAD_CAST type_names[p->type]));
    if (name)
        xml_out_check(e->o, xmlTextWriterWriteAttribute(w, BAD_CAST "Name",
                                                        BAD_CAST name));
    if (p->ncomp > 1)
        xml_out_check(e->o, xmlTextWriterWriteFormatAttribute(
                                w, BAD_CAST "NumberOfComponents", "%d",
                                p->ncomp));
    xml_out_check(e->o, xmlTextWriterWriteAttribute(
                            w, BAD_CAST "format",
                            BAD_CAST(binary ? "binary" : "ascii")));
    emit_payload(e, p, binary);
    xml_out_check(e->o, xmlTextWriterEndElement(w));
}

static int check_cloud(const char *path, const struct vtu_cloud *c)
{
    if (c->n > 0 && !c->points)
        return sim_error(SIM_ERR_INTERNAL, "%s: cloud of %zu points without "
                         "coordinates", path, c->n);
    if (c->nfields < 0 || (c->nfields > 0 && !c->fields))
        return sim_error(SIM_ERR_INTERNAL, "%s: bad field table", path);
    if (c->n > SIZE_MAX / 72)
        return sim_error(SIM_ERR_INTERNAL, "%s: %zu points is too many", path,
                         c->n);
    for (int i = 0; i < c->nfields; i++) {
        const struct vtu_field *f = &c->fields[i];
        if (f->name[0] == '\0' || memchr(f->name, '\0', sizeof f->name) == NULL)
            return sim_error(SIM_ERR_INTERNAL, "%s: field %d has no name",
                             path, i);
        if ((unsigned)f->type > VTU_UINT8 || f->ncomp < 1 || f->ncomp > 9)
            return sim_error(SIM_ERR_INTERNAL, "%s: field '%s': bad type %d "
                             "or component count %d", path, f->name,
                             (int)f->type, f->ncomp);
        if (c->n > 0 && !f->data)
            return sim_error(SIM_ERR_INTERNAL, "%s: field '%s' has no data",
                             path, f->name);
        for (int j = 0; j < i; j++)
            if (strcmp(c->fields[j].name, f->name) == 0)
                return sim_error(SIM_ERR_INTERNAL, "%s: two fields called "
                                 "'%s'", path, f->name);
    }
    return SIM_OK;
}

/* The first field with ncomp components, for ParaView's default colouring. */
static const char *first_with(const struct vtu_cloud *c, int ncomp)
{
    for (int i = 0; i < c->nfields; i++)
        if (c->fields[i].ncomp == ncomp)
            return c->fields[i].name;
    return NULL;
}

static void write_time(struct xml_out *o, double time)
{
    xmlTextWriterPtr w = o->w;
    xml_out_check(o, xmlTextWriterStartElement(w, BAD_CAST "FieldData"));
    xml_out_check(o, xmlTextWriterStartElement(w, BAD_CAST "DataArray"));
    xml_out_check(o, xmlTextWriterWriteAttribute(w, BAD_CAST "type",
                                                 BAD_CAST "Float64"));
    xml_out_check(o, xmlTextWriterWriteAttribute(w, BAD_CAST "Name",
                                                 BAD_CAST "TimeValue"));
    xml_out_check(o, xmlTextWriterWriteAttribute(
                         w, BAD_CAST "NumberOfTuples", BAD_CAST "1"));
    xml_out_check(o, xmlTextWriterWriteAttribute(w, BAD_CAST "format",
                                                 BAD_CAST "ascii"));
    xml_out_check(o, xmlTextWriterWriteFormatString(w, "%.17g", time));
    xml_out_check(o, xmlTextWriterEndElement(w));
    xml_out_check(o, xmlTextWriterEndElement(w));
}

static void write_point_data(struct emitter *e, const struct vtu_cloud *c,
                             int binary)
{
    xmlTextWriterPtr w = e->o->w;
    const char *scalars = first_with(c, 1), *vectors = first_with(c, 3);

    xml_out_check(e->o, xmlTextWriterStartElement(w, BAD_CAST "PointData"));
    if (scalars)
        xml_out_check(e->o, xmlTextWriterWriteAttribute(
                                w, BAD_CAST "Scalars", BAD_CAST scalars));
    if (vectors)
        xml_out_check(e->o, xmlTextWriterWriteAttribute(
                                w, BAD_CAST "Vectors", BAD_CAST vectors));
    for (int i = 0; i < c->nfields; i++) {
        const struct vtu_field *f = &c->fields[i];
        struct payload p = { f->type, f->ncomp,
                             c->n * (size_t)f->ncomp * type_sizes[f->type],
                             f->data, NULL };
        write_array(e, f->name, &p, binary);
    }
    xml_out_check(e->o, xmlTextWriterEndElement(w));
}

static void write_geometry(struct emitter *e, const struct vtu_cloud *c,
                           int binary)
{
    xmlTextWriterPtr w = e->o->w;
    struct payload pts = { VTU_FLOAT64, 3, 24 * c->n,
                           (const unsigned char *)c->points, NULL };
    struct payload conn = { VTU_INT64, 1, 8 * c->n, NULL, gen_connectivity };
    struct payload offs = { VTU_INT64, 1, 8 * c->n, NULL, gen_offsets };
    struct payload types = { VTU_UINT8, 1, c->n, NULL, gen_types };

    xml_out_check(e->o, xmlTextWriterStartElement(w, BAD_CAST "Points"));
    write_array(e, NULL, &pts, binary);
    xml_out_check(e->o, xmlTextWriterEndElement(w));
    xml_out_check(e->o, xmlTextWriterStartElement(w, BAD_CAST "Cells"));
    write_array(e, "connectivity", &conn, binary);
    write_array(e, "offsets", &offs, binary);
    write_array(e, "types", &types, binary);
    xml_out_check(e->o, xmlTextWriterEndElement(w));
}

int vtu_write(const char *path, const struct vtu_cloud *c, int binary)
{
    struct xml_out o;
    struct emitter e = { &o, NULL, 0, NULL };
    xmlTextWriterPtr w;
    int rc;

    TRY(check_cloud(path, c));
    e.text = sim_malloc(b64_encoded_len(CHUNK) + TEXT_FLUSH + 64);
    e.chunk = sim_malloc(CHUNK);
    if (!e.text || !e.chunk) {
        rc = SIM_ERR_NOMEM;
        goto out;
    }
    TRY_GOTO(rc, xml_out_open(&o, path), out);
    w = o.w;
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "VTKFile"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "type",
                                                  BAD_CAST "UnstructuredGrid"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "version",
                                                  BAD_CAST "1.0"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(
                          w, BAD_CAST "byte_order", BAD_CAST "LittleEndian"));
    xml_out_check(&o, xmlTextWriterWriteAttribute(w, BAD_CAST "header_type",
                                                  BAD_CAST "UInt64"));
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "UnstructuredGrid"));
    write_time(&o, c->time);
    xml_out_check(&o, xmlTextWriterStartElement(w, BAD_CAST "Piece"));
    xml_out_check(&o, xmlTextWriterWriteFormatAttribute(
                          w, BAD_CAST "NumberOfPoints", "%zu", c->n));
    xml_out_check(&o, xmlTextWriterWriteFormatAttribute(
                          w, BAD_CAST "NumberOfCells", "%zu", c->n));
    write_point_data(&e, c, binary);
    write_geometry(&e, c, binary);
    TRY_GOTO(rc, xml_out_commit(&o), out); /* closes every open element */
out:
    free(e.text);
    free(e.chunk);
    return rc;
}
