/*
 * freesurface.c — free-surface detection (Xie et al. 2025 eqs. 14-16;
 * doc/theory.md A.5 with the adopted A0-06/A0-07):
 *
 *   (14) <n>_i < beta n0                      beta  = 0.8
 *   (15) <F>_i = (d/n0) sum_j r_ij/|r_ij| w_ij / eps_j
 *   (16) |<F>_i| > alpha |F0|                 alpha = 0.9
 *
 * A fluid particle is on the surface if (14) holds, or if (16) holds and
 * <n>_i < fs_n_max n0 (0.97). |F0| is |F| of a particle on a flat surface of
 * the initial lattice (A0-06: the "internal particle" of Xie et al. 2025
 * would give 0).
 * Inside a porous region (eps_i < 1, coupled runs) only (14) applies, with
 * its own threshold betaPorous (default 0.8, the paper's beta): there the
 * neighbour weights 1/eps_j (or phi_j/eps_j) change as the grains move,
 * <n>_i wanders a few per cent about n0 and the neighbourhoods lose their
 * symmetry; (16), or a beta close to 1 as the tutorials use for still
 * water, then flags interior particles of a bed (a third of them in a
 * settling bed of 2.7 mm beads at dp = 5 mm), each a Dirichlet p = 0 that
 * drains the pressure of the whole column. A real surface there still has
 * <n> well below n0.
 * With volume fractions (genParticles grainVolume scale) inv_eps holds
 * phi_i/eps_i, about 1 in a bed: the porous branch is then taken only
 * where a particle holds more water than its pores (phi > eps, a bed
 * compacting around it), and the rest of a bed takes (14) with beta and
 * (16); taking betaPorous wherever eps < 1 instead lets the water column
 * ring while the bed lands (the experiment is in
 * tutorials/mpsDem/multipleParticleSedimentation/README.md, "Free-surface
 * test in the bed").
 * Wall particles are never free surface; a wall particle with no fluid
 * neighbour within the number-density radius is "dry" and gets p = 0 too,
 * so that the PPE does not carry the whole dry tank wall (whose rows would
 * only be tied to the fluid through a long chain of wall particles). So
 * does a wall particle whose number density satisfies (14) (Koshizuka and
 * Oka 1996 apply the surface test to wall particles): one beside the
 * free surface would otherwise get a large negative pressure from the
 * density term of (12) and pull the fluid into the corner.
 * Both use the number-density radius.
 */
#include <math.h>

#include "mps/mps.h"
#include "particles/operators/operators.h"

void mps_free_surface(struct mps_solver *s)
{
    struct mps_particles *P = &s->P;
    const struct neighbour_list in = neighbour_inner(&s->nl); /* w_n */
    const struct neighbour_list *nl = &in;
    const struct mps_settings *S = &s->S;
    const double n0 = s->Ln.n0, f0 = s->Ln.f0, c = P->dim / n0;
    const struct pop_weights W = mps_w(s, MPS_W_N);
    const double *ie = P->inv_eps;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < P->n; i++) {
        uint8_t flag = MPS_INNER;
        double nd = P->nd[i];
        if (P->type[i] == MPS_FLUID) {
            if (ie && ie[i] > 1.0) {
                if (nd < S->beta_porous)
                    flag = MPS_SURFACE;
            } else if (nd < S->beta) {
                flag = MPS_SURFACE;
            } else if (nd < S->fs_n_max) {
                double F[3];
                pop_surface_vector_row(nl, &W, P->x, ie, i, F);
                double mag = c * sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
                if (mag > S->alpha * f0)
                    flag = MPS_SURFACE;
            }
        } else if (P->type[i] == MPS_WALL) {
            flag = MPS_DRY_WALL;
            const int64_t k0 = nl->start[i], k1 = neighbour_row_end(nl, i);
            const double *w = pop_weights_of(&W, nl, i, k0, k1);
            for (int64_t k = k0; k < k1 && nd >= S->beta; k++)
                if (w[k - k0] > 0 && P->type[nl->j[k]] == MPS_FLUID) {
                    flag = MPS_INNER;
                    break;
                }
        }
        P->fs[i] = flag;
    }
}
