/*
 * channel_checksum.c — the frame checksum (channel.h).
 *
 * Definition: the n bytes are read as little-endian 64-bit words w_k, the
 * last one zero-padded; word k feeds lane k mod 4 with the round
 *     h <- rotl(h + w * P2, 31) * P1
 * (the round of xxHash64, whose constants these are); the lanes are then
 * combined, n is mixed in, and the result is avalanched. Four independent
 * lanes let the multiplies overlap, so the sum runs near memory speed
 * (a frame of 10^6 grains is 80 MB). It detects corruption, not attacks.
 * test/unit/coupling checks this loop against a word-at-a-time version.
 */
#include "coupling/channel.h"

#include <string.h>

#define P1 0x9E3779B185EBCA87ULL
#define P2 0xC2B2AE3D27D4EB4FULL
#define P3 0x165667B19E3779F9ULL

static inline uint64_t rotl(uint64_t x, int r)
{
    return (x << r) | (x >> (64 - r));
}

static inline uint64_t round64(uint64_t h, uint64_t w)
{
    return rotl(h + w * P2, 31) * P1;
}

uint64_t channel_checksum(const void *p, size_t n, uint64_t seed)
{
    const unsigned char *b = p;
    uint64_t h0 = seed + P1 + P2, h1 = seed + P2, h2 = seed, h3 = seed - P1;
    size_t nw = n / 8, k = 0;
    uint64_t w[4];

    for (; k + 4 <= nw; k += 4) {
        memcpy(w, b + 8 * k, sizeof w);
        h0 = round64(h0, w[0]);
        h1 = round64(h1, w[1]);
        h2 = round64(h2, w[2]);
        h3 = round64(h3, w[3]);
    }
    uint64_t *lane[4] = { &h0, &h1, &h2, &h3 };
    for (; k < nw; k++) {
        memcpy(w, b + 8 * k, 8);
        *lane[k % 4] = round64(*lane[k % 4], w[0]);
    }
    if (n % 8) {
        w[0] = 0;
        memcpy(w, b + 8 * nw, n % 8);
        *lane[nw % 4] = round64(*lane[nw % 4], w[0]);
    }
    uint64_t h = rotl(h0, 1) + rotl(h1, 7) + rotl(h2, 12) + rotl(h3, 18);
    h ^= (uint64_t)n;
    h ^= h >> 33;
    h *= P2;
    h ^= h >> 29;
    h *= P3;
    h ^= h >> 32;
    return h;
}
