/*
 * contact.h — DEM contact laws assembled from named sub-models
 * (doc/design.md C5, LAMMPS granular_model, LIGGGHTS): normal, damping,
 * tangential, rolling, twisting, and the tangential stiffness choice
 * (tangentialStiffness).
 *
 * Geometry is computed once per contact (contact_geom); the sub-models only
 * turn geometry into forces, always in the same order:
 *
 *   normal      elastic force F_el(delta) and the stiffnesses it implies
 *               (kt from the tangentialStiffness ratio, doc/theory.md A0-21)
 *   damping     eta^n, eta^t from the restitution coefficient (A0-22)
 *   tangential  spring + Coulomb slider (eqs. 20, 22), history per contact
 *   rolling     resisting torque from the rolling velocity (A0-23)
 *   twisting    resisting torque from the twisting velocity (A0-23)
 *
 * Notation and sign convention (doc/theory.md A.6): for grains k and l the unit
 * normal n points from k to l (for a wall: from the grain into the wall);
 * delta = R_k + R_l - |x_l - x_k| > 0 in contact; the contact-point relative
 * velocity is v_kl = (v_k - v_l) + (R_k w_k + R_l w_l) x n, its normal part
 * vn = v_kl.n is positive while the grains approach. The force on k is
 *   F_k = -(F_el + eta^n vn) n + F_t ,
 * the force on l is -F_k (Newton's third law holds by construction).
 *
 * Material (single material, doc/theory.md A.6 and A0-09/A0-10):
 *   E* = E / (2 (1 - nu^2)),  R* = R_k R_l/(R_k + R_l) (wall: R_k),
 *   m* = m_k m_l/(m_k + m_l) (wall: m_k),
 *   chi = (4/3) E* sqrt(R*)  — eq. (21) generalised to unequal radii; for
 *   two equal spheres it is (sqrt 2/3) E/(1 - nu^2) sqrt(R).
 */
#ifndef MPSDEM_DEM_CONTACT_H
#define MPSDEM_DEM_CONTACT_H

#include <stddef.h>

/* Material constants, derived once from E, nu, rho, mu, e. */
struct contact_coeffs {
    double E, nu, rho;  /* Young's modulus [Pa], Poisson ratio, density [kg/m^3] */
    double mu;          /* Coulomb friction coefficient                  */
    double e;           /* normal restitution coefficient, (0, 1]        */
    double estar;       /* E/(2(1 - nu^2)) [Pa]                          */
    double beta;        /* -ln e / sqrt(ln^2 e + pi^2), eqs. (23)-(24)   */
    double kn_linear;   /* >0: fixed linear stiffness [N/m] overriding chi */
    double mu_roll;     /* rolling friction coefficient (constantTorque) */
    double eta_roll;    /* rolling viscosity [N m s] (viscous)           */
    double eta_twist;   /* twisting viscosity [N m s] (twisting viscous) */
    /* Set by contact_law_init from the selected sub-models: */
    double ratio_t;     /* chi^t/chi^n: kt = ratio_t chi delta^(p-1) for a
                           normal law F = chi delta^p (A0-08, A0-21);
                           mindlin 2p(1 - nu)/(2 - nu), xie2025 1/(2 + nu) */
    double zeta;        /* damping ratio: eta = 2 zeta sqrt(k m*) with k the
                           tangent normal (tangential) stiffness (A0-22)   */
    double hertz_tn;    /* sqrt(kt/kn) of the Hertz law = sqrt(ratio_t/1.5),
                           so that eta^t = eta^n hertz_tn without a sqrt */
};

/* One contact seen from grain k. */
struct contact_geom {
    double n[3];     /* unit normal k -> l (or k -> wall)                */
    double delta;    /* overlap [m], > 0                                 */
    double vn;       /* approach speed v_kl.n [m/s]                      */
    double vt[3];    /* tangential part of v_kl [m/s]                    */
    double wrel[3];  /* w_k - w_l [rad/s] (wall: w_k)                    */
    double rstar;    /* effective radius [m]                             */
    double mstar;    /* effective mass [kg]                              */
    double chi;      /* (4/3) E* sqrt(R*) [N/m^1.5], cached per pair for
                        the fused law (contact_fused.h); the generic
                        sub-models compute it from rstar themselves     */
};

/* Normal elastic law. */
struct contact_normal_ops {
    const char *name;
    const char *reference;
    /* p of F_el = chi delta^p (1 linear, 1.5 Hertz): the damping's
     * restitution mapping and the tangential stiffness ratio depend on it */
    double exponent;
    /* Elastic force magnitude fel [N] (>= 0, repulsive), tangent stiffness
     * kn = dF_el/d delta [N/m] (damping and the stability bound use it), and
     * the tangential spring stiffness kt = ratio_t chi delta^(p-1) [N/m]
     * (eq. 22 with the ratio of tangentialStiffness, A0-21). */
    void (*eval)(const struct contact_coeffs *c, const struct contact_geom *g,
                 double *fel, double *kn, double *kt);
};

/* Damping coefficients. */
struct contact_damping_ops {
    const char *name;
    const char *reference;
    /* Damping ratio zeta(e, p) cached in contact_coeffs.zeta by
     * contact_law_init (p the normal law's exponent); NULL: zeta = 0. */
    double (*zeta)(double e, double p);
    /* eta^n, eta^t [kg/s] from the stiffnesses kn, kt. */
    void (*eval)(const struct contact_coeffs *c, const struct contact_geom *g,
                 double kn, double kt, double *eta_n, double *eta_t);
};

/* Tangential law with history. The history h is the tangential spring
 * delta^t [m] stored at the last accepted time; tau is the time elapsed
 * since then. The law returns the force on k (ft) and the spring it implies
 * now (hnew), rotated onto the current tangent plane and limited by the
 * slider; an integrator copies hnew into h when it accepts a step. */
struct contact_tangential_ops {
    const char *name;
    const char *reference;
    int history;     /* doubles of history per contact: 0 or 3 */
    void (*eval)(const struct contact_coeffs *c, const struct contact_geom *g,
                 double fn, double kt, double eta_t, const double h[3],
                 double tau, double hnew[3], double ft[3]);
};

/* Rolling resistance: torque on k (l receives -m). fel is the elastic
 * normal force F_el(delta) [N] (no dashpot, A0-23). */
struct contact_rolling_ops {
    const char *name;
    const char *reference;
    void (*eval)(const struct contact_coeffs *c, const struct contact_geom *g,
                 double fel, double m[3]);
};

/* Twisting resistance (rotation about n): torque on k (l receives -m),
 * same arguments as the rolling law; the result is added to mroll. */
struct contact_twisting_ops {
    const char *name;
    const char *reference;
    void (*eval)(const struct contact_coeffs *c, const struct contact_geom *g,
                 double fel, double m[3]);
};

/* Tangential stiffness: the ratio chi^t/chi^n for a normal law of
 * exponent p and Poisson ratio nu (kt = ratio chi delta^(p - 1)). */
struct contact_stiffness_ops {
    const char *name;
    const char *reference;
    double (*ratio)(double nu, double p);
};

/* The assembled law. The members after c were added later and may be
 * left NULL (zero-initialised): NULL means the default, `mindlin`
 * stiffness and `none` twisting. contact_law_init fills the derived
 * members of c; call it after choosing the sub-models. */
struct contact_law {
    const struct contact_normal_ops *normal;
    const struct contact_damping_ops *damping;
    const struct contact_tangential_ops *tangential;
    const struct contact_rolling_ops *rolling;
    struct contact_coeffs c;
    const struct contact_stiffness_ops *stiffness;
    const struct contact_twisting_ops *twisting;
};

/* Result of one contact evaluation. */
struct contact_result {
    double f[3];     /* total force on k [N]                              */
    double ft[3];    /* its tangential part [N] (torque R_k n x ft on k)  */
    double mroll[3]; /* rolling torque on k [N m]                         */
    double fn;       /* normal force magnitude (signed: < 0 is tensile)   */
    double kn;       /* tangent normal stiffness [N/m]                    */
    double kt;       /* tangential spring stiffness [N/m]                 */
    double eta_t;    /* tangential dashpot [kg/s] (the slip phases of
                        dem_forces.c rebuild the uncapped stick force)   */
};

/* The Coulomb cone of tangential_coulomb.c bounds the elastic force too:
 * slip where kt^2 |delta^t|^2 > CONTACT_SPRING_CONE (mu F^n)^2. The
 * margin (1e-12 on kt |delta^t|) keeps a spring just put at the limit,
 * which rounding may leave an ulp outside, from counting as outside. */
#define CONTACT_SPRING_CONE (1.0 + 2e-12)

/* Registries (contact_register.c), NULL-terminated. */
extern const struct contact_normal_ops *const contact_normal_table[];
extern const struct contact_damping_ops *const contact_damping_table[];
extern const struct contact_tangential_ops *const contact_tangential_table[];
extern const struct contact_rolling_ops *const contact_rolling_table[];
extern const struct contact_twisting_ops *const contact_twisting_table[];
extern const struct contact_stiffness_ops *const contact_stiffness_table[];

extern const struct contact_normal_ops contact_normal_linear;
extern const struct contact_normal_ops contact_normal_hertz;
extern const struct contact_damping_ops contact_damping_none;
extern const struct contact_damping_ops contact_damping_restitution;
extern const struct contact_damping_ops contact_damping_restitution_constant;
extern const struct contact_damping_ops contact_damping_xie2025;
extern const struct contact_damping_ops contact_damping_tsuji;
extern const struct contact_tangential_ops contact_tangential_none;
extern const struct contact_tangential_ops contact_tangential_coulomb;
extern const struct contact_rolling_ops contact_rolling_none;
extern const struct contact_rolling_ops contact_rolling_constant_torque;
extern const struct contact_rolling_ops contact_rolling_viscous;
extern const struct contact_twisting_ops contact_twisting_none;
extern const struct contact_twisting_ops contact_twisting_viscous;
extern const struct contact_stiffness_ops contact_stiffness_mindlin;
extern const struct contact_stiffness_ops contact_stiffness_xie2025;

/* Fill the material constants of c (estar, beta) from E, nu, rho, mu, e
 * (already set); those that depend on the sub-models are contact_law_init's;
 * SIM_ERR_INPUT with a message naming the bad value otherwise:
 * E <= 0, nu outside (-1, 0.5), e outside (0, 1], mu < 0, rho <= 0. */
int contact_coeffs_init(struct contact_coeffs *c);

/* contact_coeffs_init, then the members of law->c that depend on the
 * selected sub-models (ratio_t, zeta, hertz_tn). SIM_ERR_INPUT as above. */
int contact_law_init(struct contact_law *law);

/* Exact restitution of the spring-dashpot F = chi delta^p + 2 zeta
 * sqrt(p chi delta^(p-1) m*) d(delta)/dt (no tensile cut-off): the
 * rebound/impact speed ratio, which depends on zeta and p only, from the
 * dimensionless impact ODE (damping_restitution.c), and its inverse. */
double contact_restitution_of_zeta(double zeta, double p);
double contact_zeta_of_restitution(double e, double p);

/* Effective stiffness chi = (4/3) E* sqrt(R*) [N/m^1.5]. */
double contact_chi(const struct contact_coeffs *c, double rstar);

/* Evaluate the law for one contact (g->delta > 0). h: history (may be NULL
 * when the tangential law keeps none), hnew: where the new history goes. */
void contact_eval(const struct contact_law *law, const struct contact_geom *g,
                  const double *h, double tau, double *hnew,
                  struct contact_result *out);

/* Rayleigh time step, eq. (38) with the corrected coefficient 0.1631:
 *   dt_R = pi R_min / (0.1631 nu + 0.8766) sqrt(2 rho (1 + nu) / E). */
double contact_rayleigh_step(const struct contact_coeffs *c, double rmin);

#endif
