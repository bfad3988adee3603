/*
 * reaction.h — the drag averaged over the DEM sub-steps and its reaction on
 * the MPS particles (Xie et al. 2025 eq. 36; doc/theory.md A.7, A.8, A.10
 * steps 4 and 6).
 *
 *   F_bar^d_k = (1/N_sub) sum_s F^d_k(s)
 *   f_A,i     = (1/V_i) sum_k F_bar^d_k w_s(|r_ki|) / sum_j w_s(|r_kj|)  (36)
 *
 * so that sum_i V_i f_A,i = sum_k F_bar^d_k to round-off (check E1-13).
 */
#ifndef MPSDEM_COUPLING_REACTION_H
#define MPSDEM_COUPLING_REACTION_H

#include <stdint.h>

struct coupling_pairs;

/* Running sum of the per-grain drag over the sub-steps of one fluid step.
 * The struct owns sum (3 n); no allocation after coupling_drag_mean_init. */
struct coupling_drag_mean {
    int n, cap;
    long count;       /* sub-steps accumulated since the last reset */
    double *sum;      /* 3 n [N]                                   */
};

/* Size for n grains (grows, never shrinks) and reset. */
int coupling_drag_mean_init(struct coupling_drag_mean *m, int n);
void coupling_drag_mean_reset(struct coupling_drag_mean *m);
/* Add one sub-step's drag F (3 n [N]). */
void coupling_drag_mean_add(struct coupling_drag_mean *m, const double *F);
/* mean (3 n) = sum / count; SIM_ERR_INPUT when nothing was added. */
int coupling_drag_mean_get(const struct coupling_drag_mean *m, double *mean);
void coupling_drag_mean_free(struct coupling_drag_mean *m);

/*
 * Reaction per unit volume on every MPS particle of the last pair build
 * (eq. 36): fA (3 np) [N/m^3], from the averaged drag Fbar (3 ng) [N].
 *   mask   (may be NULL = all) particles that take a share, the same mask
 *          as the interpolation (fluid and wall by default, A0-13)
 *   Vp     MPS particle volume V_i = dp^3 (dp^2 in 2-D) [m^3]
 *   phi    (may be NULL = 1) per-particle fluid volume fractions: V_i =
 *          phi_i Vp (genParticles grainVolume scale)
 *   n_orphan (may be NULL) grains with no particle to take their force:
 *          their drag is lost to the fluid (a dry grain has none anyway)
 * Particles outside mask get fA = 0. Uses P->gwork as scratch (no
 * allocation).
 */
int coupling_reaction(struct coupling_pairs *P, const uint8_t *mask,
                      const double *Fbar, double Vp, const double *phi,
                      double *fA, int *n_orphan);

/* A cloud spread over ranks (particles/halo.h): each grain's weight sum
 * W_k = sum_j w_s(|r_kj|) over the particles of mask (ng), summed over
 * the ranks by the caller, then the same reaction with those sums. */
void coupling_reaction_weights(const struct coupling_pairs *P,
                               const uint8_t *mask, double *W);
int coupling_reaction_given(struct coupling_pairs *P, const double *W,
                            const uint8_t *mask, const double *Fbar,
                            double Vp, const double *phi, double *fA,
                            int *n_orphan);

#endif
