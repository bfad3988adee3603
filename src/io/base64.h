/*
 * base64.h — RFC 4648 base64 without line breaks, as VTK's XML readers want
 * it (doc/libraries.md §3: libxml2's own encoder wraps lines, which
 * ParaView 5.11 cannot read).
 */
#ifndef MPSDEM_IO_BASE64_H
#define MPSDEM_IO_BASE64_H

#include <stddef.h>

/* Characters needed for n bytes, without the terminating NUL. */
static inline size_t b64_encoded_len(size_t n) { return 4 * ((n + 2) / 3); }

/* Encode n bytes of in into out (b64_encoded_len(n) + 1 bytes, NUL
 * terminated, '=' padded). Returns the number of characters written. */
size_t b64_encode(const void *in, size_t n, char *out);

/* Decode len characters (no whitespace; len a multiple of 4; '=' only as the
 * one or two last characters) into out, which must hold 3 * len / 4 bytes.
 * Returns 0 and sets *outlen, or -1 when the text is not base64, with
 * *outlen set to the offset of the first bad character. */
int b64_decode(const char *in, size_t len, unsigned char *out,
               size_t *outlen);

#endif
