/*
 * dem.h — the DEM library: spheres with translation and rotation (doc/theory.md
 * A.6, eqs. 17-18), contact laws assembled from sub-models (contact.h),
 * analytic walls (wall.h), a Verlet-skin half neighbour list with contact
 * history (particles/neighbour_half.h), and time
 * integrators selected by name (integrator.h).
 *
 * Storage is structure-of-arrays; vectors are interleaved (3 doubles per
 * grain, z = 0 in 2-D) so that clouds are written without copies. Nothing is
 * allocated inside the time loop except when the neighbour list or the
 * number of contacts outgrows its capacity.
 *
 * The coupling interface (used by the MPS-DEM coupling): before advancing to
 * a coupling time the caller may set, per grain, an external force and the
 * fluid velocity and porosity at the grain centre; the drag law (a function
 * pointer, evaluated with the grain's *current* velocity at every force
 * evaluation, doc/theory.md A.8 [P]) turns them into a force; after the advance
 * dem_mean_drag() returns the drag averaged over the interval, for the
 * reaction force of eq. (36).
 */
#ifndef MPSDEM_DEM_DEM_H
#define MPSDEM_DEM_DEM_H

#include <stddef.h>
#include <stdint.h>

#include "dem/contact/contact.h"
#include "dem/walls/wall.h"
#include "particles/neighbour_half.h"
#include "particles/store.h"

/* Loops over fewer grains than this run on one thread. */
#define DEM_OMP_MIN 2000

#define DEM_MAX_PATCHES 64

/* Drag law supplied by the coupling: for grains 0..n-1 with radius r, velocity
 * v (3n), fluid velocity uf (3n) and porosity eps (n), write the drag force
 * fd (3n) [N]. Non-zero return: error code (error.h). */
typedef int (*dem_drag_fn)(void *ctx, size_t n, const double *r,
                           const double *v, const double *uf,
                           const double *eps, double *fd);

struct dem_coupling {
    const double *fext;   /* 3n external force [N], or NULL            */
    const double *uf;     /* 3n fluid velocity [m/s], or NULL          */
    const double *eps;    /* n porosity, or NULL                       */
    dem_drag_fn drag;     /* NULL: no drag                             */
    void *drag_ctx;
    double *fd;           /* 3n drag at the last force evaluation      */
    double *fd_sum;       /* 3n time integral of the applied drag [N s]*/
    double sum_time;      /* length of the integral [s]                */
};

struct dem_stats {
    long steps;           /* accepted steps                            */
    long rejected;        /* rejected steps (error test failures)      */
    long stab_limited;    /* steps limited by the stability bound      */
    long fevals;          /* force evaluations (integrator stages)     */
    long hist_evals;      /* extra evaluations to commit histories
                             (arkode: the Coulomb projection)          */
    long rebuilds;        /* neighbour-list builds                     */
    long removed;         /* grains removed (left the domain)          */
};

struct dem {
    /* grains: the arrays below (x ... id, acc, alpha, cpl.fd, cpl.fd_sum)
     * are registered by name in st (particles/store.h), which grows,
     * compacts and writes them; n repeats st.n */
    struct store st;
    size_t n;
    double *x, *v, *w;            /* 3n position [m], velocity, spin [rad/s] */
    double *r, *m, *inv_m, *inv_i;/* radius, mass, 1/m, 1/I (I = 2/5 m R^2)  */
    int32_t *group;
    int64_t *id;
    double *acc, *alpha;          /* 3n scratch: accelerations at last eval  */
    /* physics */
    double gravity[3];
    struct contact_law law;
    struct dem_wall *walls;
    int nwalls;
    struct wall_motion *motions;  /* per patch (DEM_MAX_PATCHES), or NULL */
    int npatches;
    char patch_names[DEM_MAX_PATCHES][64];
    double patch_force[3 * DEM_MAX_PATCHES]; /* force ON each patch [N]    */
    /* domain: grains outside [lo, hi] are counted (and removed if asked) */
    int have_domain, remove_outside;
    double dom_lo[3], dom_hi[3];
    /* neighbours and contact history */
    struct neighbour_half nl;
    double *hist;                 /* 3 per candidate pair                   */
    double *pair_c;               /* 2 per pair: chi, m* (constant while
                                     the list lives)                       */
    size_t hist_cap;
    double *whist;                /* 3 per grain and wall                   */
    double *wall_chi;             /* per grain: chi of a wall contact       */
    size_t *wstart;               /* n + 1: walls near each grain (CSR), */
    int *wlist;                   /* built with the neighbour list        */
    uint32_t *wgrain;             /* the grain of each wlist entry        */
    size_t wlist_cap;
    int use_wlist;                /* 1: only listed walls are checked; an
                                     integrator sets it when no grain can
                                     travel skin/2 between list checks */
    size_t whist_cap, wchi_cap;
    double *tbuf;                 /* per-thread force/torque accumulation   */
    size_t *old_start;            /* rebuild scratch: the previous list     */
    uint32_t *old_j;
    double *old_h;
    size_t old_rows_cap, old_pairs_cap;
    size_t tbuf_cap;
    /* results of the last force evaluation */
    double omega2_max;            /* max kn/m* over active contacts [1/s^2] */
    long ncontacts, nwall_contacts;
    double rmin, rmax;
    double rho_min_mass;          /* smallest grain mass [kg]               */
    double dt_rayleigh;           /* eq. (38) for rmin [s]                  */
    double dt_stable;             /* fixed-step bound: dt_rayleigh, and for
                                     the linear law also 2/omega of its
                                     stiffest contact [s]                  */
    /* time and book-keeping */
    double t;
    double h_next;                /* adaptive step to start with, 0: estimate;
                                     saved at writes so a restart repeats the
                                     continuous run */
    size_t omp_min;               /* fewer grains: force loop on 1 thread */
    double kick;                  /* != 0: dem_forces ends with
                                     v += kick a, w += kick alpha (Verlet) */
    /* Springs as ODE state (arkode): when spring_in is set, dem_forces
     * takes the tangential springs from it (3 per pair slot of the
     * neighbour list, then 3 per grain and wall: the layout of hist and
     * whist) with tau = 0, and writes d(delta^t)/dt into spring_rate,
     * 0 for a slot not in contact (doc/theory.md A.6). */
    const double *spring_in;
    double *spring_rate;
    /* Slip phases (arkode; same slot layout, dem_forces.c,
     * doc/theory.md A0-24): slip_mode marks the slots found sliding at
     * the last committing evaluation (which updates it, the slipping ones
     * with dem_slip_rates); while set the slot slides. slip_g, when set,
     * receives per slot the switching function (dem_forces.c slip_after,
     * dem_slip_rates): in stick 1 - (the larger of the stick force and
     * the spring's force)/(mu |F^n|), in slip positive while the stick
     * force from the spring at the limit would be outside the cone or the
     * spring would leave it; HUGE_VAL out of contact. Its zero from above
     * starts or ends a phase, an event the integrator locates. slip_fn,
     * when set, receives F^n (0 out of contact): where it changes sign the
     * limit mu |F^n| has a kink, also an event. */
    unsigned char *slip_mode;
    double *slip_g;
    double *slip_fn;
    /* acc, alpha, cpl.fd and the histories are those of the current x, v,
     * w (set by a committing dem_forces); cleared by every change from
     * outside the integrator (dem_setup, grain removal, a new coupling
     * state, dem_invalidate_forces), so that Verlet re-evaluates only
     * then. */
    int forces_valid;
    /* Set by integrator auto for one advance (integrator_auto.c): the
     * advance may return before t_end, at the end of the first step that
     * ends with a contact (DEM_STOP_CONTACT: arkode) or without one
     * (DEM_STOP_FREE: verlet), a contact within stop_horizon counting
     * (dem_contact_near); d->t tells where it stopped. 0: run to t_end. */
    int stop_when;
    double stop_horizon;          /* with stop_when: a contact this close
                                     in time counts (dem_contact_near) [s] */
    struct dem_coupling cpl;
    struct dem_stats stats;
};

enum { DEM_STOP_CONTACT = 1, DEM_STOP_FREE = 2 };

void dem_init(struct dem *d);
void dem_free(struct dem *d);

/* Make room for n grains (keeps the first min(n, old n)); new grains are
 * zero with id = their index. */
int dem_resize(struct dem *d, size_t n);

/* After x, v, w, r (and id/group) are set: masses from rho, derived
 * constants, the Rayleigh step, a fresh neighbour list (keeping histories
 * only if ids are unchanged is the caller's business: this clears them). */
int dem_setup(struct dem *d);

/* Force evaluation at state (x, v, w) at time t, tau = t - t_accepted for
 * the tangential springs (0 with d->spring_in set: the springs are then
 * given). Writes accelerations acc (3n) and angular accelerations alpha
 * (3n), patch forces and omega2_max. With commit set the state is
 * accepted: the springs it implies (rotated onto the tangent plane,
 * limited by the slider, 0 out of contact) replace the stored histories
 * hist, whist; otherwise (a Runge-Kutta stage) they are left alone. The
 * neighbour list must be valid for x. */
int dem_forces(struct dem *d, double t, const double *x, const double *v,
               const double *w, double tau, int commit, double *acc,
               double *alpha);

/* Slip phases (arkode): for every slot with mode set, in contact, the
 * second condition that keeps it sliding (doc/theory.md A0-24), the rate
 * D of kt |s| - mu |F^n| along the stick flow from the spring at the
 * limit, made dimensionless (D/(mu |F^n| omega_n)): g[slot] becomes
 * max(g[slot], D) (g may be NULL) and mode_next[slot] is set where D > 0
 * (mode_next may be NULL). x, v, w, acc: the state and the accelerations
 * of dem_forces at it; spring: the springs in the layout of spring_in
 * (their directions are used). Returns SIM_OK. */
int dem_slip_rates(struct dem *d, const double *x, const double *v,
                   const double *w, const double *acc, const double *spring,
                   const unsigned char *mode, double *g,
                   unsigned char *mode_next);

/* Put the moving and removed walls where their motions have them at time
 * t (position, velocity, removal). dem_forces does it at its time, and
 * dem_setup at d->t. */
void dem_walls_at(struct dem *d, double t);

/* The grains, their histories or the coupling inputs were changed from
 * outside the integrator: forces kept from the last evaluation are stale. */
void dem_invalidate_forces(struct dem *d);

/* Rebuild the neighbour list if x moved more than skin/2 since the last
 * build; histories follow their pairs. Returns SIM_OK. */
int dem_update_neighbours(struct dem *d, const double *x);

/* Rebuild now (at a write time, so that the state a restart starts from
 * is exactly the continuing run's: same list, same reference positions). */
int dem_rebuild_neighbours(struct dem *d);

/* Non-zero when the last committing evaluation found a contact, or when
 * at the state (x, v) it was at some grain could touch another or a wall
 * within d->stop_horizon at the speeds it has (a gap below (|v_i| +
 * |v_j|) horizon, at most half the skin): the test of integrator auto's
 * stretches (d->stop_when). The neighbour list must be valid for x; a
 * pair it does not hold (farther than the skin at the build) is not seen
 * until it touches. */
int dem_contact_near(const struct dem *d, const double *x, const double *v);

/* Overlap statistics for the start-up check: number of pairs (and wall
 * contacts) overlapping by more than frac of the smaller radius, and the
 * largest relative overlap. */
void dem_overlap_stats(struct dem *d, double frac, long *count,
                       double *max_rel);

/* Count grains outside the domain and, if d->remove_outside, remove them
 * (histories of remaining pairs are kept). Returns the number outside. */
long dem_check_domain(struct dem *d);

/* Contact step limits: Rayleigh step (eq. 38) and 2/omega of the stiffest
 * contact at the last evaluation; 0 when no contact is active. */
double dem_contact_step(const struct dem *d);

/* Total kinetic energy, translation + rotation [J]. */
double dem_kinetic_energy(const struct dem *d);

/* Coupling, before advancing to the next coupling time: per-grain external
 * force fext (3n) [N], fluid velocity uf (3n) [m/s] and porosity eps (n) at
 * the grain centres, and the drag law evaluated with the grains' current
 * velocity at every force evaluation (every sub-step and stage). Any may be
 * NULL (no external force / no drag). The arrays are borrowed and must stay
 * valid and unchanged during the advance. */
void dem_coupling_set(struct dem *d, const double *fext, const double *uf,
                      const double *eps, dem_drag_fn drag, void *drag_ctx);

/* Coupling: drag averaged over the last advance (3n) into fd; returns the
 * averaging time. Resets the accumulator. With verlet the average is the
 * trapezoid sum of the drag at the step ends (what the velocities
 * received); with arkode it is the drag impulse integrated in the state
 * with the Runge-Kutta weights. Either way m dv = (m g + F_ext + <F_d>) T
 * holds to round-off for a grain without contacts. */
double dem_mean_drag(struct dem *d, double *fd);

#endif
