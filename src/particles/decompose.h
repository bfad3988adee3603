/*
 * decompose.h — domain decomposition of a particle cloud for distributed
 * runs (doc/design.md, "Distributed runs"): which subdomain (rank) owns
 * each particle, and what each one would have to receive from the others
 * every step (its halo).
 *
 * Recursive coordinate bisection (Berger and Bokhari 1987, IEEE Trans.
 * Comput. C-36:570-580): a set of particles for k subdomains is cut
 * across its longest extent at the particle that leaves floor(k/2)/k of
 * its weight below, and each side is cut again for floor(k/2) and
 * ceil(k/2) subdomains, down to one. Boxes are not stored: a subdomain is
 * its particles.
 *
 * Halo of subdomain a at radius rc: the particles of other subdomains
 * within rc of a particle of a (those whose values a's operators read),
 * counted once each; its neighbours are the subdomains they belong to
 * (one message each way per exchange).
 */
#ifndef MPSDEM_PARTICLES_DECOMPOSE_H
#define MPSDEM_PARTICLES_DECOMPOSE_H

#include <stddef.h>
#include <stdint.h>

/* part[i] in [0, nparts) for the n particles at x (x y z interleaved; in
 * 2-D z is ignored). weight: per particle, or NULL for 1 each; a particle
 * of weight 0 is owned all the same (by the side its position falls on).
 * Fails with SIM_ERR_INPUT for nparts < 1 or a non-finite position. */
int decompose_rcb(int dim, const double *x, const double *weight, int n,
                  int nparts, int32_t *part);

/* The same, also recording the cuts, so that any position can be given
 * its subdomain later (decompose_owner: particles that move migrate).
 * cuts: room for nparts - 1 (pre-order: a set's cut, then those of its
 * lower side, then those of its upper side). A cut lies midway between
 * the last particle below and the first above; part[] is the bisection's
 * own answer, which decompose_owner repeats except for particles on a cut
 * plane (they go up). */
struct decompose_cut { int axis; double value; };
int decompose_rcb_cuts(int dim, const double *x, const double *weight, int n,
                       int nparts, int32_t *part, struct decompose_cut *cuts);

/* The subdomain whose region holds position x (x < value: lower side). */
int decompose_owner(const struct decompose_cut *cuts, int nparts,
                    const double *x);

/* system/decomposeParDict (OpenFOAM's name; decomposePar and the
 * distributed solvers read it):
 *   numberOfSubdomains  N;      // >= 1
 *   method              rcb;    // the only method
 *   balance             fluid;  // fluid: fluid particles weigh 1, walls
 *                               // and dummies 0; all: 1 each
 *   maxImbalance        1.2;    // a distributed run cuts the regions
 *                               // afresh when its largest rank's weight
 *                               // exceeds the mean by this factor (> 1;
 *                               // 0: never)
 * Errors cite the file and line. */
struct dict;
struct decompose_settings {
    long nparts;
    int balance_all;
    double max_imbalance;
};
int decompose_settings_read(const struct dict *d, struct decompose_settings *s);

struct decompose_part {
    long owned;        /* particles                                   */
    double weight;     /* their weight                                */
    long halo;         /* particles of others within rc of one of its */
    int neighbours;    /* subdomains those belong to                  */
};

/* The per-subdomain counts above for partition part at radius rc
 * (nparts entries of out). */
int decompose_halo(int dim, const double *x, const double *weight, int n,
                   const int32_t *part, int nparts, double rc,
                   struct decompose_part *out);

#endif
