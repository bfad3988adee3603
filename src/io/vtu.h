/*
 * vtu.h — particle clouds as VTK XML UnstructuredGrid (.vtu) files and .pvd
 * collections, the files ParaView opens.
 *
 * Layout written (VTK XML 1.0, header_type UInt64, little endian): Points
 * (Float64 x 3; 2-D clouds have z = 0), one VTK_VERTEX cell per point, and
 * PointData arrays of any number of fields, each Float64, Int64, Int32 or
 * UInt8 with 1..9 components. format="ascii" writes %.17g (exact round trip);
 * format="binary" writes our own base64 of (UInt64 byte count)(data), each
 * part padded separately, without line breaks — libxml2's base64 writer
 * breaks lines and ParaView 5.11 then fails (doc/libraries.md §3).
 *
 * Writers go through a temporary file in the same directory and rename(2),
 * so a crash never leaves a truncated file under the final name.
 */
#ifndef MPSDEM_IO_VTU_H
#define MPSDEM_IO_VTU_H

#include <stddef.h>
#include <stdint.h>

enum vtu_type { VTU_FLOAT64, VTU_INT64, VTU_INT32, VTU_UINT8 };

struct vtu_field {
    char name[64];
    enum vtu_type type;
    int ncomp;  /* components per point, 1 (scalar) or 3 (vector), ... */
    void *data; /* n*ncomp values of `type`, point-major               */
};

struct vtu_cloud {
    size_t n;                 /* number of points                    */
    double *points;           /* 3n coordinates, x y z per point     */
    int nfields;
    struct vtu_field *fields; /* nfields entries                     */
    double time;              /* written as FieldData TimeValue      */
};

/* Write c to path. binary: 1 for base64 binary, 0 for ascii. The cloud's
 * arrays are borrowed, not freed. */
int vtu_write(const char *path, const struct vtu_cloud *c, int binary);

/* "Float64", "Int64", "Int32", "UInt8", and bytes per value. */
const char *vtu_type_name(enum vtu_type t);
size_t vtu_type_size(enum vtu_type t);

/* Read a file written by vtu_write (or any vtu with one piece of point data
 * in ascii or inline base64 binary, UInt32 or UInt64 headers), or a .pvtu
 * of such pieces (pvtu_read). Allocates
 * every array; release with vtu_cloud_free. A truncated or corrupted file is
 * SIM_ERR_IO with the file name and what was wrong. */
int vtu_read(const char *path, struct vtu_cloud *c);

/* Free what vtu_read (or vtu_cloud_add_field) allocated and zero *c. */
void vtu_cloud_free(struct vtu_cloud *c);

/* The field called name, or NULL. */
const struct vtu_field *vtu_find(const struct vtu_cloud *c, const char *name);
/* Same, but an error naming the file/field when it is missing or has the
 * wrong type or component count (type < 0 or ncomp <= 0: not checked). */
int vtu_require(const struct vtu_cloud *c, const char *file, const char *name,
                int type, int ncomp, const struct vtu_field **out);

/* SIM_ERR_INPUT naming the file, the array (Points, TimeValue or the point
 * field), the point (and its id) when a floating-point value is infinite
 * or NaN. vtu_read accepts such values (vtuInfo shows a failed state);
 * a program starting from a file calls this. */
int vtu_check_finite(const struct vtu_cloud *c, const char *file);

/* Append a field with freshly allocated, zeroed storage (owned by the cloud
 * only if the cloud came from vtu_read or was built with this function). */
int vtu_cloud_add_field(struct vtu_cloud *c, const char *name,
                        enum vtu_type type, int ncomp, void **data);

/* Add (or replace, for the same time) the data set `file` (path relative to
 * the .pvd's directory) at `time` in the collection `pvd_path`, creating it
 * if needed; entries stay sorted by time. Rewritten atomically. */
/* The parallel form (pvtu.c): a .pvtu naming npieces pieces
 * (piece_fmt % p, relative to the .pvtu, e.g. "fluid_%d.vtu") that hold
 * the arrays of layout (names, types, components; its data unused). */
int pvtu_write(const char *path, const struct vtu_cloud *layout, int npieces,
               const char *piece_fmt);
/* Every piece of a .pvtu in order as one cloud (vtu_read does this for a
 * path ending in .pvtu). The pieces must hold the same arrays. */
int pvtu_read(const char *path, struct vtu_cloud *c);

int pvd_add(const char *pvd_path, double time, const char *file);

/* Drop entries with time > t_max (a restart from an earlier time). */
int pvd_truncate(const char *pvd_path, double t_max);

#endif
