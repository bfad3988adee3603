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

/* 0..63 for a base64 character, -1 otherwise. */
static int dec_char(unsigned char c)
{
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    if (c == '+')
        return 62;
    if (c == '/')
        return 63;
    return -1;
}

int b64_decode(const char *in, size_t len, unsigned char *out, size_t *outlen)
{
    size_t o = 0;

    if (len % 4 != 0) {
        *outlen = len;
        return -1;
    }
    for (size_t i = 0; i < len; i += 4) {
        int last = i + 4 == len;
        int pad = 0, q[4];
        for (int k = 0; k < 4; k++) {
            unsigned char c = (unsigned char)in[i + k];
            if (c == '=' && last && k >= 2 && (k == 3 || in[i + 3] == '=')) {
                q[k] = 0;
                pad++;
                continue;
            }
            q[k] = dec_char(c);
            if (q[k] < 0 || pad) {
                *outlen = i + k;
                return -1;
            }
        }
        uint32_t v = (uint32_t)q[0] << 18 | (uint32_t)q[1] << 12 |
                     (uint32_t)q[2] << 6 | (uint32_t)q[3];
        out[o++] = (unsigned char)(v >> 16);
        if (pad < 2)
            out[o++] = (unsigned char)(v >> 8 & 255);
        if (pad < 1)
            out[o++] = (unsigned char)(v & 255);
    }
    *outlen = o;
    return 0;
}
