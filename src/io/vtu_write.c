/*
 * vtu_write.c — write a particle cloud as a VTK XML UnstructuredGrid
 * (vtu.h; layout in doc/libraries.md §3).
 *
 * The skeleton goes through libxml2's xmlTextWriter; array payloads are
 * produced here, in chunks, and handed over with xmlTextWriterWriteRaw:
 * binary payloads as our own unbroken base64 of the UInt64 byte count
 * followed, separately padded, by the data; ascii payloads as %.17g (exact
 * for doubles) or exact integers. Chunks hold a multiple of 3 bytes, so the
 * base64 of consecutive chunks concatenates without inner padding, and a
 * multiple of 8, so no element straddles two chunks. The ascii text is the
 * same whatever the number of threads.
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

#define CHUNK (24 * 2048)   /* bytes, multiple of 3 and of 8          */
#define ASCII_BLOCK 65536   /* values formatted in parallel at once    */
#define ASCII_SLICES 16     /* pieces of a block (threads share them)  */
#define ASCII_CHARS 26      /* room per value: 24 characters + blank   */
#define TEXT_SIZE (ASCII_BLOCK * ASCII_CHARS) /* > b64 of one CHUNK    */


/* A payload: borrowed bytes, or values made on demand (the cell arrays:
 * connectivity i, end offsets i + 1, cell types VTK_VERTEX = 1). */
enum gen { GEN_NONE, GEN_INDEX, GEN_INDEX1, GEN_ONE };

struct payload {
    enum vtu_type type;
    int ncomp;
    size_t nbytes;
    const unsigned char *data; /* or NULL and gen */
    enum gen gen;
};

/* Bytes [first, first + count) of element index, for generated payloads. */
static void generate(const struct payload *p, size_t first, size_t count,
                     unsigned char *out)
{
    if (p->gen == GEN_ONE) {
        memset(out, 1, count);
        return;
    }
    for (size_t i = 0; i < count; i++) {
        int64_t v = (int64_t)(first + i) + (p->gen == GEN_INDEX1);
        memcpy(out + 8 * i, &v, 8);
    }
}

struct emitter {
    struct xml_out *o;
    char *text;           /* base64 of one chunk, or ascii of one block */
    unsigned char *chunk; /* CHUNK bytes (generated data)               */
};

/* Value i of p as text; returns its length (at most 24 characters). */
static int format_value(const struct payload *p, size_t i, char *s)
{
    unsigned char b[8];
    const unsigned char *v = b;
    size_t es = vtu_type_size(p->type);

    if (p->data)
        v = p->data + es * i;
    else
        generate(p, i, 1, b);
    switch (p->type) {
    case VTU_FLOAT64: {
        double x;
        memcpy(&x, v, 8);
        return sprintf(s, "%.17g", x);
    }
    case VTU_INT64: {
        int64_t x;
        memcpy(&x, v, 8);
        return sprintf(s, "%" PRId64, x);
    }
    case VTU_INT32: {
        int32_t x;
        memcpy(&x, v, 4);
        return sprintf(s, "%" PRId32, x);
    }
    default:
        return sprintf(s, "%u", (unsigned)v[0]);
    }
}

/* ascii: values [first, first + count) into s, each followed by a blank or,
 * at the end of a point (eight values for scalars), a newline. */
static size_t format_range(const struct payload *p, size_t first,
                           size_t count, char *s)
{
    size_t per_line = p->ncomp > 1 ? (size_t)p->ncomp : 8, len = 0;
    for (size_t i = first; i < first + count; i++) {
        len += (size_t)format_value(p, i, s + len);
        s[len++] = (i + 1) % per_line ? ' ' : '\n';
    }
    return len;
}

/* printf("%.17g") costs about a microsecond a value: blocks of values are
 * formatted by all threads, each into its own slice of the text buffer,
 * and handed to the writer in order. */
static void emit_ascii(struct emitter *e, const struct payload *p)
{
    size_t nval = p->nbytes / vtu_type_size(p->type);

    for (size_t b0 = 0; b0 < nval && !e->o->failed; b0 += ASCII_BLOCK) {
        size_t nb = nval - b0 < ASCII_BLOCK ? nval - b0 : ASCII_BLOCK;
        size_t len[ASCII_SLICES];
#pragma omp parallel for schedule(static)
        for (int t = 0; t < ASCII_SLICES; t++) {
            size_t a = nb * (size_t)t / ASCII_SLICES;
            size_t b = nb * (size_t)(t + 1) / ASCII_SLICES;
            len[t] = format_range(p, b0 + a, b - a,
                                  e->text + a * ASCII_CHARS);
        }
        for (int t = 0; t < ASCII_SLICES; t++) {
            size_t a = nb * (size_t)t / ASCII_SLICES;
            if (len[t])
                xml_out_check(e->o, xmlTextWriterWriteRawLen(
                                        e->o->w, BAD_CAST(e->text + a *
                                                          ASCII_CHARS),
                                        (int)len[t]));
        }
    }
}

static void emit_binary(struct emitter *e, const struct payload *p)
{
    size_t esize = vtu_type_size(p->type);
    uint64_t header = p->nbytes;
    char hb[16];

    b64_encode(&header, sizeof header, hb);
    xml_out_check(e->o, xmlTextWriterWriteRaw(e->o->w, BAD_CAST hb));
    for (size_t off = 0; off < p->nbytes && !e->o->failed; off += CHUNK) {
        size_t len = p->nbytes - off < CHUNK ? p->nbytes - off : CHUNK;
        const unsigned char *bytes = p->data ? p->data + off : e->chunk;
        if (!p->data)
            generate(p, off / esize, len / esize, e->chunk);
        b64_encode(bytes, len, e->text);
        xml_out_check(e->o, xmlTextWriterWriteRaw(e->o->w, BAD_CAST e->text));
    }
}

static void emit_payload(struct emitter *e, const struct payload *p,
                         int binary)
{
    if (binary) {
        emit_binary(e, p);
    } else {
        xml_out_check(e->o, xmlTextWriterWriteRaw(e->o->w, BAD_CAST "\n"));
        emit_ascii(e, p);
    }
}

static void write_array(struct emitter *e, const char *name,
                        const struct payload *p, int binary)
{
    xmlTextWriterPtr w = e->o->w;

    xml_out_check(e->o, xmlTextWriterStartElement(w, BAD_CAST "DataArray"));
    xml_out_check(e->o, xmlTextWriterWriteAttribute(
                            w, BAD_CAST "type",
                            BAD_CAST vtu_type_name(p->type)));
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
                             c->n * (size_t)f->ncomp * vtu_type_size(f->type),
                             f->data, GEN_NONE };
        write_array(e, f->name, &p, binary);
    }
    xml_out_check(e->o, xmlTextWriterEndElement(w));
}

static void write_geometry(struct emitter *e, const struct vtu_cloud *c,
                           int binary)
{
    xmlTextWriterPtr w = e->o->w;
    struct payload pts = { VTU_FLOAT64, 3, 24 * c->n,
                           (const unsigned char *)c->points, GEN_NONE };
    struct payload conn = { VTU_INT64, 1, 8 * c->n, NULL, GEN_INDEX };
    struct payload offs = { VTU_INT64, 1, 8 * c->n, NULL, GEN_INDEX1 };
    struct payload types = { VTU_UINT8, 1, c->n, NULL, GEN_ONE };

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
    struct emitter e = { &o, NULL, NULL };
    xmlTextWriterPtr w;
    int rc;

    TRY(check_cloud(path, c));
    e.text = sim_malloc(TEXT_SIZE + 1);
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
