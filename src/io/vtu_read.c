/*
 * vtu_read.c — read a VTK XML UnstructuredGrid (or PolyData) particle cloud
 * (vtu.h).
 *
 * Accepted: one Piece; Points as Float64 or Float32 x 3; PointData arrays of
 * Float64, Float32 (widened to Float64), Int64, Int32 or UInt8 with 1..9
 * components; format ascii or inline binary (base64, UInt32 or UInt64
 * header, header and data encoded separately or as one stream, whitespace
 * ignored); FieldData TimeValue. Not accepted, with a message saying so:
 * appended data, compression, big-endian data, several pieces.
 *
 * Every array length is checked against NumberOfPoints before anything of
 * that size is allocated, so a corrupted count cannot exhaust memory.
 */
#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"
#include "io/base64.h"
#include "io/vtu.h"
#include "io/xmlio.h"

#if __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "vtu_read.c reads byte_order=LittleEndian into host memory"
#endif

/* Types as stored in the file; FLOAT32 is widened on reading. */
enum src_type { SRC_FLOAT64, SRC_INT64, SRC_INT32, SRC_UINT8, SRC_FLOAT32 };
static const char *const src_names[] = { "Float64", "Int64", "Int32", "UInt8",
                                         "Float32", NULL };
static const size_t src_sizes[] = { 8, 8, 4, 1, 4 };

/* What is known about the file while reading it. */
struct reader {
    const char *path;
    size_t header_size; /* 4 (UInt32) or 8 (UInt64) */
};

/* An array being decoded: where it is, what it should hold. */
struct array {
    const char *what; /* "DataArray 'velocity'" for messages */
    enum src_type src;
    size_t count; /* values expected (points x components) */
};

static enum vtu_type dst_of(enum src_type s)
{
    return s == SRC_FLOAT32 ? VTU_FLOAT64 : (enum vtu_type)s;
}

static int bad(const struct reader *r, const struct array *a, const char *fmt,
               const char *detail)
{
    char text[256];
    snprintf(text, sizeof text, fmt, detail);
    return sim_error(SIM_ERR_IO, "%s: %s: %s", r->path, a->what, text);
}

/* ---- ascii ----------------------------------------------------------------- */

static int parse_one(const struct reader *r, const struct array *a,
                     const char **s, void *out, size_t i)
{
    char *end;
    errno = 0;
    if (a->src == SRC_FLOAT64 || a->src == SRC_FLOAT32) {
        double v = strtod(*s, &end);
        /* glibc flags subnormal results with ERANGE too: only overflow is
         * an error. */
        if (end == *s || (errno == ERANGE && isinf(v)))
            goto bad_value;
        ((double *)out)[i] = v;
    } else {
        long long v = strtoll(*s, &end, 10);
        if (end == *s || errno == ERANGE)
            goto bad_value;
        if (a->src == SRC_INT64)
            ((int64_t *)out)[i] = v;
        else if (a->src == SRC_INT32 && v >= INT32_MIN && v <= INT32_MAX)
            ((int32_t *)out)[i] = (int32_t)v;
        else if (a->src == SRC_UINT8 && v >= 0 && v <= 255)
            ((uint8_t *)out)[i] = (uint8_t)v;
        else
            goto bad_value;
    }
    if (*end && !isspace((unsigned char)*end))
        goto bad_value;
    *s = end;
    return SIM_OK;
bad_value: {
        char tok[40];
        size_t k = strcspn(*s, " \t\r\n");
        snprintf(tok, sizeof tok, "%.*s", (int)(k < 32 ? k : 32), *s);
        char fmt[96];
        snprintf(fmt, sizeof fmt, "value %zu, '%%s', is not a valid %s", i,
                 src_names[a->src]);
        return bad(r, a, fmt, tok);
    }
}

static int parse_ascii(const struct reader *r, const struct array *a,
                       const char *text, void *out)
{
    const char *s = text;
    size_t i;
    char num[32];

    for (i = 0;; i++) {
        while (isspace((unsigned char)*s))
            s++;
        if (*s == '\0')
            break;
        if (i == a->count) {
            snprintf(num, sizeof num, "%zu", a->count);
            return bad(r, a, "more values than the %s expected "
                       "(NumberOfPoints x NumberOfComponents)", num);
        }
        TRY(parse_one(r, a, &s, out, i));
    }
    if (i != a->count) {
        char msg[96];
        snprintf(msg, sizeof msg, "%zu values where %zu were expected "
                 "(truncated?)", i, a->count);
        return bad(r, a, "%s", msg);
    }
    return SIM_OK;
}

/* ---- binary ---------------------------------------------------------------- */

/* Copy the base64 text without whitespace; returns its length. */
static size_t strip_space(const char *text, char *out)
{
    size_t n = 0;
    for (const char *s = text; *s; s++)
        if (!isspace((unsigned char)*s))
            out[n++] = *s;
    out[n] = '\0';
    return n;
}

static int decode(const struct reader *r, const struct array *a,
                  const char *b64, size_t len, unsigned char *out,
                  size_t *outlen)
{
    size_t where;
    if (b64_decode(b64, len, out, &where) == 0) {
        *outlen = where;
        return SIM_OK;
    }
    char msg[96];
    if (len % 4)
        snprintf(msg, sizeof msg, "base64 text of length %zu is not a "
                 "multiple of 4 (truncated?)", len);
    else
        snprintf(msg, sizeof msg, "invalid base64 character '%c' at offset "
                 "%zu", b64[where], where);
    return bad(r, a, "%s", msg);
}

/* Decode header and data. The header (byte count) may have been encoded on
 * its own, padded (what we and VTK write), or together with the data: a
 * padded header group tells the two apart. */
static int decode_binary(const struct reader *r, const struct array *a,
                         const char *b64, size_t len, unsigned char **bytes,
                         size_t *nbytes)
{
    size_t hs = r->header_size, hchars = b64_encoded_len(hs), got;
    unsigned char hbuf[12];
    uint64_t declared = 0;
    unsigned char *buf;
    int rc;

    if (len < hchars)
        return bad(r, a, "%s", "binary data shorter than its header");
    buf = sim_malloc(3 * (len / 4) + 3);
    if (!buf)
        return SIM_ERR_NOMEM;
    if (b64[hchars - 1] == '=') { /* header padded: encoded on its own */
        TRY_GOTO(rc, decode(r, a, b64, hchars, hbuf, &got), fail);
        TRY_GOTO(rc, decode(r, a, b64 + hchars, len - hchars, buf, &got),
                 fail);
        memcpy(&declared, hbuf, hs);
    } else {
        TRY_GOTO(rc, decode(r, a, b64, len, buf, &got), fail);
        if (got < hs) {
            rc = bad(r, a, "%s", "binary data shorter than its header");
            goto fail;
        }
        memcpy(&declared, buf, hs);
        memmove(buf, buf + hs, got - hs);
        got -= hs;
    }
    if (declared != got) {
        char msg[128];
        snprintf(msg, sizeof msg, "header declares %" PRIu64 " bytes but "
                 "%zu follow (truncated or corrupted)", declared, got);
        rc = bad(r, a, "%s", msg);
        goto fail;
    }
    *bytes = buf;
    *nbytes = got;
    return SIM_OK;
fail:
    free(buf);
    return rc;
}

static int parse_binary(const struct reader *r, const struct array *a,
                        const char *text, void *out)
{
    size_t want = a->count * src_sizes[a->src], len, nbytes = 0;
    unsigned char *bytes = NULL;
    char *copy = NULL, msg[128];
    const char *b64;
    int rc;

    /* Our files have no whitespace inside the base64, except around it:
     * then decode in place instead of copying. */
    while (isspace((unsigned char)*text))
        text++;
    len = strlen(text);
    while (len > 0 && isspace((unsigned char)text[len - 1]))
        len--;
    if (strcspn(text, " \t\r\n\v\f") >= len) {
        b64 = text;
    } else {
        copy = sim_malloc(len + 1);
        if (!copy)
            return SIM_ERR_NOMEM;
        len = strip_space(text, copy);
        b64 = copy;
    }
    TRY_GOTO(rc, decode_binary(r, a, b64, len, &bytes, &nbytes), out);
    if (nbytes != want) {
        snprintf(msg, sizeof msg, "holds %zu bytes, but NumberOfPoints and "
                 "NumberOfComponents ask for %zu", nbytes, want);
        rc = bad(r, a, "%s", msg);
        goto out;
    }
    if (a->src == SRC_FLOAT32) {
        for (size_t i = 0; i < a->count; i++) {
            float f;
            memcpy(&f, bytes + 4 * i, 4);
            ((double *)out)[i] = f;
        }
    } else {
        memcpy(out, bytes, nbytes);
    }
out:
    free(copy);
    free(bytes);
    return rc;
}

/* ---- DataArray ------------------------------------------------------------- */

/* The text of a DataArray without copying it when it is one text node. */
static const char *array_text(xmlNodePtr node, xmlChar **copy)
{
    xmlNodePtr c = node->children;
    *copy = NULL;
    if (!c)
        return "";
    if (!c->next && (c->type == XML_TEXT_NODE || c->type == XML_CDATA_SECTION_NODE))
        return (const char *)c->content;
    *copy = xmlNodeGetContent(node);
    return *copy ? (const char *)*copy : "";
}

/* Read one DataArray of n tuples. On success *data is allocated (n*ncomp
 * values of dst_of(src)) and *type, *ncomp set. */
static int read_array(const struct reader *r, xmlNodePtr node,
                      const char *what, size_t n, int *ncomp,
                      enum vtu_type *type, void **data)
{
    char attr[64];
    struct array a = { what, SRC_FLOAT64, 0 };
    int binary = 0, k;
    xmlChar *copy;
    const char *text;
    int rc;

    *data = NULL;
    if (xml_attr(node, "type", attr, sizeof attr) != 1)
        return sim_error(SIM_ERR_IO, "%s: %s: missing type", r->path, what);
    for (k = 0; src_names[k] && strcmp(src_names[k], attr); k++)
        ;
    if (!src_names[k])
        return sim_error(SIM_ERR_IO, "%s: %s: unsupported type '%s' (valid: "
                         "Float64 Float32 Int64 Int32 UInt8)", r->path, what,
                         attr);
    a.src = (enum src_type)k;
    *ncomp = 1;
    if (xml_attr(node, "NumberOfComponents", attr, sizeof attr) == 1) {
        char *end;
        long v = strtol(attr, &end, 10);
        if (*end || v < 1 || v > 9)
            return sim_error(SIM_ERR_IO, "%s: %s: NumberOfComponents '%s' "
                             "is not 1..9", r->path, what, attr);
        *ncomp = (int)v;
    }
    if (xml_attr(node, "NumberOfTuples", attr, sizeof attr) == 1 &&
        strtoull(attr, NULL, 10) != n)
        return sim_error(SIM_ERR_IO, "%s: %s: NumberOfTuples %s differs from "
                         "NumberOfPoints %zu", r->path, what, attr, n);
    if (xml_attr(node, "format", attr, sizeof attr) == 1) {
        if (strcmp(attr, "binary") == 0)
            binary = 1;
        else if (strcmp(attr, "ascii") != 0)
            return sim_error(SIM_ERR_IO, "%s: %s: format '%s' is not "
                             "supported (ascii or inline binary only)",
                             r->path, what, attr);
    }
    a.count = n * (size_t)*ncomp;
    text = array_text(node, &copy);
    /* A value takes at least 2 characters in ascii, 4/3 bytes in base64:
     * refuse before allocating for a count the text cannot hold. */
    if ((binary ? strlen(text) / 4 * 3 / src_sizes[a.src]
                : strlen(text) / 2 + 1) < a.count) {
        xmlFree(copy);
        return sim_error(SIM_ERR_IO, "%s: %s: too little data for %zu values "
                         "(NumberOfPoints %zu; truncated?)", r->path, what,
                         a.count, n);
    }
    *type = dst_of(a.src);
    *data = sim_malloc(a.count * vtu_type_size(*type));
    if (!*data) {
        xmlFree(copy);
        return SIM_ERR_NOMEM;
    }
    rc = binary ? parse_binary(r, &a, text, *data)
                : parse_ascii(r, &a, text, *data);
    xmlFree(copy);
    if (rc != SIM_OK) {
        free(*data);
        *data = NULL;
    }
    return rc;
}

/* ---- file structure -------------------------------------------------------- */

static int read_header(struct reader *r, xmlNodePtr root, xmlNodePtr *grid)
{
    char attr[64];

    if (!root || strcmp((const char *)root->name, "VTKFile") != 0)
        return sim_error(SIM_ERR_IO, "%s: not a VTK XML file (no VTKFile "
                         "element)", r->path);
    if (xml_attr(root, "type", attr, sizeof attr) != 1 ||
        (strcmp(attr, "UnstructuredGrid") && strcmp(attr, "PolyData")))
        return sim_error(SIM_ERR_IO, "%s: VTKFile type must be "
                         "UnstructuredGrid or PolyData", r->path);
    *grid = xml_child(root, attr);
    if (!*grid)
        return sim_error(SIM_ERR_IO, "%s: no %s element", r->path, attr);
    if (xml_attr(root, "compressor", attr, sizeof attr) != 0)
        return sim_error(SIM_ERR_IO, "%s: compressed data is not supported",
                         r->path);
    if (xml_attr(root, "byte_order", attr, sizeof attr) == 1 &&
        strcmp(attr, "LittleEndian") != 0)
        return sim_error(SIM_ERR_IO, "%s: byte_order '%s' is not supported",
                         r->path, attr);
    r->header_size = 4;
    if (xml_attr(root, "header_type", attr, sizeof attr) == 1) {
        if (strcmp(attr, "UInt64") == 0)
            r->header_size = 8;
        else if (strcmp(attr, "UInt32") != 0)
            return sim_error(SIM_ERR_IO, "%s: header_type '%s' is not UInt32 "
                             "or UInt64", r->path, attr);
    }
    if (xml_child(*grid, "AppendedData") || xml_child(root, "AppendedData"))
        return sim_error(SIM_ERR_IO, "%s: appended data is not supported",
                         r->path);
    return SIM_OK;
}

static int read_time(const struct reader *r, xmlNodePtr grid, double *time)
{
    xmlNodePtr fd = xml_child(grid, "FieldData");
    *time = 0;
    for (xmlNodePtr c = fd ? fd->children : NULL; c; c = c->next) {
        char name[64];
        int ncomp;
        enum vtu_type type;
        void *data;
        if (c->type != XML_ELEMENT_NODE ||
            xml_attr(c, "Name", name, sizeof name) != 1 ||
            strcmp(name, "TimeValue") != 0)
            continue;
        TRY(read_array(r, c, "FieldData 'TimeValue'", 1, &ncomp, &type, &data));
        if (type == VTU_FLOAT64 && ncomp == 1)
            *time = *(double *)data;
        free(data);
        if (type != VTU_FLOAT64 || ncomp != 1)
            return sim_error(SIM_ERR_IO, "%s: TimeValue is not one "
                             "floating-point value", r->path);
    }
    return SIM_OK;
}

static int read_points(const struct reader *r, xmlNodePtr piece,
                       struct vtu_cloud *c)
{
    xmlNodePtr pts = xml_child(piece, "Points"), da;
    int ncomp;
    enum vtu_type type;

    da = xml_child(pts, "DataArray");
    if (!da)
        return sim_error(SIM_ERR_IO, "%s: missing Points (or its DataArray)",
                         r->path);
    TRY(read_array(r, da, "Points", c->n, &ncomp, &type,
                   (void **)&c->points));
    if (type != VTU_FLOAT64 || ncomp != 3)
        return sim_error(SIM_ERR_IO, "%s: Points must be Float64 or Float32 "
                         "with 3 components", r->path);
    return SIM_OK;
}

static int read_fields(const struct reader *r, xmlNodePtr piece,
                       struct vtu_cloud *c)
{
    xmlNodePtr pd = xml_child(piece, "PointData");

    for (xmlNodePtr x = pd ? pd->children : NULL; x; x = x->next) {
        char name[64], what[96];
        struct vtu_field *f;
        int got;

        if (x->type != XML_ELEMENT_NODE)
            continue;
        if (strcmp((const char *)x->name, "DataArray") != 0)
            return sim_error(SIM_ERR_IO, "%s: unexpected <%s> in PointData",
                             r->path, (const char *)x->name);
        got = xml_attr(x, "Name", name, sizeof name);
        if (got != 1 || name[0] == '\0')
            return sim_error(SIM_ERR_IO, "%s: a PointData array has %s name",
                             r->path, got < 0 ? "too long a" : "no");
        if (vtu_find(c, name))
            return sim_error(SIM_ERR_IO, "%s: two PointData arrays called "
                             "'%s'", r->path, name);
        f = sim_realloc(c->fields, (size_t)(c->nfields + 1) * sizeof *f);
        if (!f)
            return SIM_ERR_NOMEM;
        c->fields = f;
        f = &c->fields[c->nfields];
        memset(f, 0, sizeof *f);
        strcpy(f->name, name);
        snprintf(what, sizeof what, "DataArray '%s'", name);
        TRY(read_array(r, x, what, c->n, &f->ncomp, &f->type, &f->data));
        c->nfields++;
    }
    return SIM_OK;
}

static int read_piece(const struct reader *r, xmlNodePtr grid,
                      struct vtu_cloud *c)
{
    xmlNodePtr piece = xml_child(grid, "Piece");
    char attr[64], *end;
    unsigned long long n;

    if (!piece)
        return sim_error(SIM_ERR_IO, "%s: no Piece", r->path);
    for (xmlNodePtr x = piece->next; x; x = x->next)
        if (x->type == XML_ELEMENT_NODE &&
            strcmp((const char *)x->name, "Piece") == 0)
            return sim_error(SIM_ERR_IO, "%s: several pieces are not "
                             "supported", r->path);
    if (xml_attr(piece, "NumberOfPoints", attr, sizeof attr) != 1)
        return sim_error(SIM_ERR_IO, "%s: Piece without NumberOfPoints",
                         r->path);
    errno = 0;
    n = strtoull(attr, &end, 10);
    if (*end || end == attr || attr[0] == '-' || errno ||
        n > SIZE_MAX / 72)
        return sim_error(SIM_ERR_IO, "%s: NumberOfPoints '%s' is not a "
                         "valid count", r->path, attr);
    c->n = (size_t)n;
    TRY(read_points(r, piece, c));
    TRY(read_fields(r, piece, c));
    return SIM_OK;
}

int vtu_read(const char *path, struct vtu_cloud *c)
{
    const size_t len = strlen(path);
    if (len > 5 && !strcmp(path + len - 5, ".pvtu"))
        return pvtu_read(path, c);
    struct reader r = { path, 4 };
    xmlDocPtr doc;
    xmlNodePtr grid = NULL;
    int rc;

    memset(c, 0, sizeof *c);
    TRY(xml_in_read(path, &doc));
    TRY_GOTO(rc, read_header(&r, xmlDocGetRootElement(doc), &grid), out);
    TRY_GOTO(rc, read_time(&r, grid, &c->time), out);
    TRY_GOTO(rc, read_piece(&r, grid, c), out);
out:
    xmlFreeDoc(doc);
    if (rc != SIM_OK)
        vtu_cloud_free(c);
    return rc;
}
