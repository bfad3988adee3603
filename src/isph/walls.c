/*
 * walls.c — the wall and dummy layers of `wall dummyLayers` (doc/theory.md
 * S0-13, S0-17; Adami, Hu and Adams 2012, J. Comput. Phys. 231,
 * 7057-7075): the dummies' anchors, the evaluation of the wall and dummy
 * rows after clipping the water's negative pressure, and the particles
 * kept off the walls. The rows themselves are assemble()'s
 * (isph_solver.c).
 */
#include <math.h>

#include "isph/isph_solver.h"

/* The nearest wall particle of every dummy within the kernel's support
 * (walls do not move); -1 for a dummy out of every wall particle's reach
 * (deep in a corner), which no water particle reaches either. */
void isph_find_anchors(struct isph_solver *s)
{
    for (int a = 0; a < s->n; a++) {
        s->anchor[a] = -1;
        if (s->type[a] != ISPH_DUMMY)
            continue;
        double best = INFINITY;
        for (int64_t k = s->nl.start[a]; k < s->nl.start[a + 1]; k++) {
            int b = s->nl.j[k];
            if (s->type[b] == ISPH_WALL && s->nl.r[k] < best)
                best = s->nl.r[k], s->anchor[a] = b;
        }
    }
}

/* clipNegativePressure (S0-17): the water's p < 0 set to 0, then the
 * walls' and dummies' rows (their pressure extrapolated from the water,
 * unit diagonal) evaluated again with it, walls first: above the
 * waterline they keep their hydrostatic p < 0, so still water stays
 * still, while under a thin tongue they no longer pass on the water's
 * suction. */
void isph_clip_negative(struct isph_solver *s)
{
    const struct csr_matrix *A = &s->A;
    for (int a = 0; a < s->n; a++)
        if (s->type[a] == ISPH_FLUID)
            s->p[a] = fmax(s->p[a], 0);
    if (s->S.wall != ISPH_WALL_DUMMY) /* Neumann rows are not evaluations */
        return;
    for (int pass = ISPH_WALL; pass <= ISPH_DUMMY; pass++)
        for (int a = 0; a < s->n; a++) {
            if (s->type[a] != pass)
                continue;
            double v = s->b[a];
            for (int64_t e = A->rowptr[a] + 1; e < A->rowptr[a + 1]; e++)
                v -= A->val[e] * s->p[A->col[e]];
            s->p[a] = v / A->val[A->rowptr[a]];
        }
}

/* wall dummyLayers (S0-13): the walls are impermeable. A water particle
 * that ends a step less than dl/2 from the wall line of the wall particle
 * it stands over (|tangential offset| < dl/2) is put back at dl/2 and
 * loses the part of its velocity into the wall: where the pressure is
 * nearly zero (the tip of a surge on a dry floor) nothing else stops a
 * particle falling into the floor. Counted in the log (`pushedBack`).
 * Within 1.5 dl of the wall line the sediment loses its velocity into
 * the wall (u_s.n = U.n = 0, D.5): the model has no normal stress of
 * the sediment, and the grains arriving at the floor would drag the
 * first rows of water into it. Where that row carries sediment (alpha_s
 * above the trace of S0-11) its water loses its normal velocity too,
 * either way: the wall holds the row's grains, so no drag holds its
 * water against the pressure gradient that carries the suspension's
 * weight above it, and the corrected divergence, a central difference
 * that skips the particle's own velocity, lets it rise (a settling
 * suspension rose from the floor at 0.37 cm/s instead of 0.11). */
void isph_keep_off_walls(struct isph_solver *s)
{
    const double half = 0.5 * s->S.dl;
    long pushed = 0;
#pragma omp parallel for schedule(static) reduction(+ : pushed)
    for (int a = 0; a < s->n; a++) {
        if (s->type[a] != ISPH_FLUID)
            continue;
        double *xa = s->x + 3 * a, *ua = s->u + 3 * a, *us = s->us + 3 * a;
        for (int64_t k = s->nl.start[a]; k < s->nl.start[a + 1]; k++) {
            int b = s->nl.j[k];
            if (s->type[b] != ISPH_WALL)
                continue;
            const double *nb = s->normal + 3 * b, *xb = s->x + 3 * b;
            double dx = xa[0] - xb[0], dy = xa[1] - xb[1];
            double d = dx * nb[0] + dy * nb[1]; /* < 0: on the water side */
            double t = fabs(-dx * nb[1] + dy * nb[0]);
            if (t >= half || d <= -3 * half)
                continue;
            double sn = us[0] * nb[0] + us[1] * nb[1];
            if (sn > 0) { /* the first row: no sediment into the wall */
                us[0] -= sn * nb[0];
                us[1] -= sn * nb[1];
            }
            if (s->alpha[a] >= ISPH_ALPHA_TRACE) {
                double fn = ua[0] * nb[0] + ua[1] * nb[1];
                ua[0] -= fn * nb[0];
                ua[1] -= fn * nb[1];
            }
            if (d <= -half)
                continue;
            xa[0] -= (d + half) * nb[0];
            xa[1] -= (d + half) * nb[1];
            double un = ua[0] * nb[0] + ua[1] * nb[1];
            if (un > 0) {
                ua[0] -= un * nb[0];
                ua[1] -= un * nb[1];
            }
            pushed++;
        }
    }
    s->n_pushed += pushed;
}

