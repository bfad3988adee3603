/* base64.c — RFC 4648 base64 encoder and strict decoder (see base64.h). */
#include "io/base64.h"

#include <stdint.h>

static const char enc_table[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

size_t b64_encode(const void *in_, size_t n, char *out)
{
    const unsigned char *in = in_;
    size_t i = 0, o = 0;

    for (; i + 2 < n; i += 3) {
        uint32_t v = (uint32_t)in[i] << 16 | (uint32_t)in[i + 1] << 8 | in[i + 2];
        out[o++] = enc_table[v >> 18];
        out[o++] = enc_table[v >> 12 & 63];
        out[o++] = enc_table[v >> 6 & 63];
        out[o++] = enc_table[v & 63];
    }
    if (i < n) {
        uint32_t v = (uint32_t)in[i] << 16;
        if (i + 1 < n)
            v |= (uint32_t)in[i + 1] << 8;
        out[o++] = enc_table[v >> 18];
        out[o++] = enc_table[v >> 12 & 63];
        out[o++] = i + 1 < n ? enc_table[v >> 6 & 63] : '=';
        out[o++] = '=';
    }
    out[o] = '\0';
    return o;
}

/* 0..63 for a base64 character, 255 otherwise. */
static const unsigned char dec_table[256] = {
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,  62, 255, 255, 255,  63,
     52,  53,  54,  55,  56,  57,  58,  59,  60,  61, 255, 255, 255, 255, 255, 255,
    255,   0,   1,   2,   3,   4,   5,   6,   7,   8,   9,  10,  11,  12,  13,  14,
     15,  16,  17,  18,  19,  20,  21,  22,  23,  24,  25, 255, 255, 255, 255, 255,
    255,  26,  27,  28,  29,  30,  31,  32,  33,  34,  35,  36,  37,  38,  39,  40,
     41,  42,  43,  44,  45,  46,  47,  48,  49,  50,  51, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
};

/* Decode the quad at in into out (3 bytes); 0, or -1 when a character is
 * not base64. */
static inline int quad(const unsigned char *in, unsigned char *out)
{
    unsigned a = dec_table[in[0]], b = dec_table[in[1]];
    unsigned c = dec_table[in[2]], d = dec_table[in[3]];
    uint32_t v = a << 18 | b << 12 | c << 6 | d;
    out[0] = (unsigned char)(v >> 16);
    out[1] = (unsigned char)(v >> 8 & 255);
    out[2] = (unsigned char)(v & 255);
    return (a | b | c | d) > 63 ? -1 : 0;
}

/* Offset of the first non-base64 character of the quad at in. */
static size_t first_bad(const unsigned char *in)
{
    size_t k = 0;
    while (k < 3 && dec_table[in[k]] <= 63)
        k++;
    return k;
}

int b64_decode(const char *in_, size_t len, unsigned char *out, size_t *outlen)
{
    const unsigned char *in = (const unsigned char *)in_;
    size_t o = 0, i = 0;
    int pad;

    if (len % 4 != 0) {
        *outlen = len;
        return -1;
    }
    if (len == 0) {
        *outlen = 0;
        return 0;
    }
    for (; i + 4 < len; i += 4, o += 3)
        if (quad(in + i, out + o)) {
            *outlen = i + first_bad(in + i);
            return -1;
        }
    /* The last quad may end in "=" or "==". */
    pad = in[i + 3] == '=' ? (in[i + 2] == '=' ? 2 : 1) : 0;
    {
        unsigned char q[4] = { in[i], in[i + 1], pad == 2 ? 'A' : in[i + 2],
                               pad ? 'A' : in[i + 3] };
        unsigned char b[3];
        if (quad(q, b)) {
            *outlen = i + first_bad(q);
            return -1;
        }
        for (int k = 0; k < 3 - pad; k++)
            out[o++] = b[k];
    }
    *outlen = o;
    return 0;
}
