/*
 * rng.h — the random numbers of genParticles' random packings: SplitMix64
 * (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number
 * generators", OOPSLA 2014), the generator lattice_jitter already uses,
 * here as a sequential stream. A packing is made by one thread in one
 * order, so the same seed gives the same grains on any machine.
 */
#ifndef MPSDEM_GENPARTICLES_RNG_H
#define MPSDEM_GENPARTICLES_RNG_H

#include <math.h>
#include <stdint.h>

struct gen_rng {
    uint64_t state;
};

static inline void gen_rng_seed(struct gen_rng *g, uint64_t seed)
{
    g->state = seed;
}

static inline uint64_t gen_rng_next(struct gen_rng *g)
{
    uint64_t z = (g->state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1), 53 random bits. */
static inline double gen_rng_uniform(struct gen_rng *g)
{
    return (double)(gen_rng_next(g) >> 11) * 0x1.0p-53;
}

/* Standard normal (Box & Muller 1958, Ann. Math. Stat. 29, 610-611); the
 * first uniform is taken in (0, 1] so that the logarithm is finite. */
static inline double gen_rng_normal(struct gen_rng *g)
{
    double u1 = 1.0 - gen_rng_uniform(g), u2 = gen_rng_uniform(g);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
}

#endif
